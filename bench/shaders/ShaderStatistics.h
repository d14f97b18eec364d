#pragma once
// What `probebench shaders` collects: per target, every program each profile variant's frame
// built (deduplicated: a program is its vertex file, fragment file and defines), with the
// driver's statistics per stage; and the plan's single-switch pairs, so each switch's change
// can be read off the same programs. JSON both ways: a worker process (one per target, since
// each needs its own preloaded shim) writes it, the parent reads it.
#include "DriverStatistics.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pb::shaders {

struct ProgramStatistics {
    std::string pass; // the frame section that built it ("gi-apply", "gbuffer", ...)
    std::string vertex, fragment;
    std::string defines; // "A;B=1;..." as gl::definesKey writes it
    std::vector<StageStatistics> stages;
    std::string error; // the driver rejected it (its compile or link log, first line)

    const StageStatistics* stage(const std::string& name) const; // null when not reported
    std::string key() const { return vertex + "|" + fragment + "|" + defines; }
};

struct VariantStatistics {
    std::string id;            // the bench plan's variant id: "handheld", "handheld -gi.loops"
    std::string label;         // "-gi.loops (split -> fused)"
    std::string profile;       // the session's profile name
    std::string role;          // profile, reference, reverted, applied, twin (ShaderPlan.h)
    std::string switchKey;     // reverted/applied: the one switch
    std::string notRun;        // why this target cannot run it ("" when it compiled)
    std::vector<int> programs; // indices into TargetStatistics::programs, in build order
};

// One single-switch pair of the plan: `on` differs from `off` in `switchKey` only.
struct SwitchPair {
    std::string profile; // the session
    std::string kind;    // "in_profile" (P against P with s reverted) or "on_reference"
    std::string switchKey, offValue, onValue;
    std::string offVariant, onVariant; // VariantStatistics ids
};

struct TargetStatistics {
    std::string target, device, driver, note; // the ShaderTarget row
    std::string error; // the target could not run at all (shim, driver, context): one line
    std::string glVersion, glRenderer, glslVersion;
    std::vector<ProgramStatistics> programs;
    std::vector<VariantStatistics> variants;

    const VariantStatistics* variant(const std::string& id) const;
    // The program of `v` in `pass` whose fragment stage has the most instructions: the pass's
    // cost figure. Null when the pass built no program with fragment statistics.
    const ProgramStatistics* heaviestFragment(const VariantStatistics& v,
                                              const std::string& pass) const;
    // The passes `v` built programs in, in build order.
    std::vector<std::string> passes(const VariantStatistics& v) const;
};

struct ShaderStatisticsRun {
    std::string mesaVersion, mesaDir;
    std::string scene, probes;
    std::string camera; // the view every variant rendered (--camera form)
    int width = 0, height = 0;
    std::vector<SwitchPair> pairs;
    std::vector<TargetStatistics> targets;
};

// The id of a variant's gi.loops=fused twin (bench/shaders_gl/ShaderPlan.h).
inline std::string fusedTwinId(const std::string& variantId) { return variantId + " [fused twin]"; }

nlohmann::json toJson(const StageStatistics& s);
nlohmann::json toJson(const TargetStatistics& t);
nlohmann::json toJson(const ShaderStatisticsRun& r);
// Throw pb::Error naming what is malformed.
TargetStatistics targetStatisticsFromJson(const nlohmann::json& j);

} // namespace pb::shaders
