#pragma once
// `probebench tune`'s search, GL-free: the caller supplies how a batch of candidates is measured
// (one interleaved bench session: pb_bench's runner in the app, a model in the unit tests) and
// their GI memory (deterministic: render::estimateGiMemory), so the search itself is tested
// without GL and without timings.
//
// Search: when the distinct canonical candidates that fit the memory budget number at most
// `maxExhaustive`, every one is measured (exhaustive, in sessions of `sessionSize`). Otherwise
// coordinate descent from the base: for each switch in table order, the current configuration
// and every value of that switch (the rest held) are measured in one session and the best by
// the objective becomes current; passes repeat until one changes nothing (at most
// `maxPasses`). Candidates over the memory budget are never rendered. Objective: fitting both
// budgets first, then the lowest FLIP (ties: relative MSE of the GI, then time); among
// candidates that do not fit, the smallest overshoot max(ms / budget ms, MiB / budget MiB).
// The answer is the best fitting candidate of every measurement made (each candidate's latest).
#include "TuneSpace.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::bench {

struct TuneMeasurement {
    bool ok = false;
    std::string error;  // !ok: why it could not run
    double frameMs = 0; // median frame time on this device
    double flip = 0;    // LDR-FLIP mean vs the reference profile, same frame
    double relativeMseGi = 0;
};

// Measures the candidates in one session (results parallel to the input).
using MeasureFn = std::function<std::vector<TuneMeasurement>(const std::vector<profile::Profile>&)>;
using MemoryFn = std::function<double(const profile::Profile&)>; // GI memory, MiB

struct TuneOptions {
    double budgetMs = 16.7, budgetMiB = 8.0;
    int maxExhaustive = 24; // exhaustive when the candidates within memory are this few
    int maxPasses = 2;      // coordinate descent passes
    int sessionSize = 8;    // candidates per measured session (exhaustive)
    // Where the frame ms come from, for the tables: "this device", or "model: switch-handheld".
    std::string timeSource = "this device";
    std::function<void(const std::string&)> progress;
};

struct TuneCandidate {
    profile::Profile switches; // canonical
    std::string label;         // vs the base
    double memoryMiB = 0;
    bool measured = false;
    TuneMeasurement m;    // the latest measurement
    int measurements = 0; // how many sessions measured it
    bool fitsMemory(const TuneOptions& o) const { return memoryMiB <= o.budgetMiB; }
    bool fits(const TuneOptions& o) const {
        return measured && m.ok && m.frameMs <= o.budgetMs && fitsMemory(o);
    }
};

struct TuneResult {
    std::string method; // "exhaustive" | "coordinate descent"
    std::size_t combinations = 0, distinct = 0, overMemory = 0;
    std::vector<TuneCandidate> candidates; // every candidate considered, first seen first
    int sessions = 0;
    int variantsMeasured = 0; // candidate measurements over all sessions
    int chosen = -1;          // index into candidates; -1: nothing fits
    std::vector<int> closest; // nothing fits: the nearest misses, best first (at most 3)
    std::vector<int> pareto;  // measured candidates no other beats on time, memory and FLIP
};

TuneResult runTune(const TuneSpace& space, const MemoryFn& memory, const MeasureFn& measure,
                   const TuneOptions& options);

// Indices (into candidates) of the measured, runnable candidates that no other one beats on
// all three of frame ms, GI MiB and FLIP (and strictly on one), sorted by frame ms.
std::vector<int> paretoFront3(const std::vector<TuneCandidate>& candidates);

} // namespace pb::bench
