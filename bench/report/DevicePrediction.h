#pragma once
// `bench --predict`: the device model's frame time (bench/devicemodel) per profile and per pass on
// a named device, and per switch its predicted delta beside the one measured on this machine
// (llvmpipe or whatever ran the bench). Every figure is labelled "model: <device>"; the
// measured ones are this machine's. GL-free plain data, filled by bench/runner/PredictionRun.h.
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace pb::bench {

struct PredictedPass {
    std::string pass, bound; // bound: alu, texture, memory, rop, draws
    double ms = 0;
    double measuredMs = NAN; // this machine's median for the same section; NaN when none
    nlohmann::json detail;   // devicemodel::PassPrediction::toJson
};

struct PredictedVariant {
    std::string id, label, role; // the bench plan's variant
    double ms = 0;
    double measuredMs = NAN;
    std::vector<PredictedPass> passes;
    std::string error; // why it could not be predicted ("" when it was)
};

struct PredictedDelta {
    std::string kind; // vs_reference, in_profile, on_reference
    std::string switchKey, offValue, onValue;
    std::string offVariant, onVariant;
    double ms = NAN;         // predicted on - off
    double measuredMs = NAN; // this machine's paired shift; NaN when not measured
};

struct PredictedSession {
    std::string profile;
    int width = 0, height = 0;
    bool ownDevice = false; // the profile names this device as its target ([budget] model)
    double budgetMs = 0;    // the profile's frame budget, judged only on its own device
    // On its own device, the profile at its own output size (the budget's frame); when the
    // session runs at another size (bench --width), a second prediction. 0x0: not predicted.
    int ownWidth = 0, ownHeight = 0;
    double ownSizeMs = NAN;
    std::vector<PredictedVariant> variants; // [0] the profile
    std::vector<PredictedDelta> deltas;
    // The frame the budget is judged on: the own-size prediction (NaN when none).
    double budgetFrameMs() const { return ownDevice ? ownSizeMs : NAN; }
    bool overBudget() const { return std::isfinite(budgetFrameMs()) && budgetFrameMs() > budgetMs; }
};

struct DevicePrediction {
    std::string device, label, compiler, mesaVersion;
    nlohmann::json spec; // the device file's figures
    std::string error;   // the device could not be modelled at all
    std::vector<PredictedSession> sessions;
};

nlohmann::json predictionsJson(const std::vector<DevicePrediction>& p);
std::string predictionsMarkdown(const std::vector<DevicePrediction>& p); // "" when empty
std::string predictionsHtml(const std::vector<DevicePrediction>& p);     // "" when empty

} // namespace pb::bench
