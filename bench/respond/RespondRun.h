#pragma once
// The respond measurement (issue 20) as one function both `probebench respond` and `probebench
// bench --respond` call: every update schedule runs the same frames with the probes as the
// update engine (renderer/respond) leaves them, measured against the converged re-bake of the
// changed scene. Construction checks every input (cheap, GL-free) so that a bad event fails in
// one line before anything is traced, rendered or timed; measure() does the work.
#include "image/Image.h"
#include "probes/ProbeSet.h"
#include "profile/PlatformProfile.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pb::gl {
class DebugOutput;
}

namespace pb::bench {

struct RespondSettings {
    std::string probesName; // the probe file, as errors and the JSON name it
    std::string scenario;   // lighting scenario of the probes (empty: the first)
    std::vector<std::string> events;
    std::string timeline; // TOML file of [[event]] spec = "..." (empty: none)
    std::string schedules = "hysteresis,rtxgi,hastened";
    int frames = 150, raysPerUpdate = 256, sampleBakes = 16;
    int width = 160, height = 90;
    float radius = 1.5f;
    std::string cacheDir;    // converged re-bake cache (empty: the probe cache's default)
    bool keepFrames = false; // keep every frame's LDR image (respond --out-dir)
};

// What one measurement runs with: a profile's switches and its update budget.
struct RespondBudget {
    std::string profileName;
    profile::Profile switches;
    int raysPerFrame = 0;              // 0: every marked probe every frame
    long long uploadBytesPerFrame = 0; // 0: no limit
};

// Per schedule, every frame's LDR image (only with keepFrames).
using RespondFrames = std::vector<std::pair<std::string, std::vector<image::Image8>>>;

class RespondRun {
public:
    // Checks the settings, the probe set (dense, not bc6h) and every event against `scene`;
    // throws pb::Error (one line) on the first problem. Nothing is traced or rendered yet.
    RespondRun(scene::Scene scene, probes::ProbeSet set, RespondSettings settings,
               std::function<void(const std::string&)> progress);
    ~RespondRun();
    RespondRun(const RespondRun&) = delete;
    RespondRun& operator=(const RespondRun&) = delete;

    // Runs every schedule with `budget` in the current GL context; GL errors (per `debug`) throw.
    // The view search, sample bakes and converged reference are done on the first call and
    // shared by later ones. Returns respond's JSON (schedules[] with t95_frames, t99_frames, ...).
    nlohmann::json measure(const RespondBudget& budget, gl::DebugOutput& debug,
                           RespondFrames* frames = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace pb::bench
