#pragma once
// `bench --truth`: the ground truth of the bench's view at every session's size (computed once
// per size, cached by input hash as `probebench truth` caches it), and the report's pictures.
#include "TruthAccuracyCapture.h"
#include "bench/report/AblationPlan.h"
#include "scene/Scene.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace pb::bench {

struct BenchTruthOptions {
    int spp = 64;
    int maxDepth = 32;
    std::string cacheDir;
    std::function<void(const std::string&)> progress; // one line each; may be empty
};

// The truths by size; `info` receives what the JSON's "truth" key shows (spp, depth, per size
// the noise, the time and the cache file). Throws pb::Error as renderTruth does (spp < 1, a
// view that sees nothing).
TruthBySize computeBenchTruth(const scene::Scene& s, const scene::View& view, const BenchPlan& plan,
                              const BenchTruthOptions& o, nlohmann::json* info);

// The direct light's own error (`bench --truth`'s floor): the scene with only the lights the
// rasterizer's direct pass carries - the sun and the punctual lights; the sky black and no
// emission (both reach surfaces only through the probes) - traced at depth 1 is what the frame
// without GI should show. The frame's error against it (shadow map, its bias and filtering,
// unshadowed punctual lights, point-sampled pixels) stays in every probe set's error.
scene::Scene directLightScene(const scene::Scene& s);
// A sun that shines or a punctual light: otherwise the floor is nothing against nothing.
bool hasDirectLight(const scene::Scene& s);

// Delta lights need few samples: the pixel's area and its punctual lights' shadows.
inline constexpr int kDirectTruthSpp = 64;

// The direct-light truth of `direct` (directLightScene) at every session's size: depth 1,
// min(spp, kDirectTruthSpp), cached like the truth; `info` receives spp, depth and the sizes.
TruthBySize computeBenchDirectTruth(const scene::Scene& direct, const scene::View& view,
                                    const BenchPlan& plan, const BenchTruthOptions& o,
                                    nlohmann::json* info);

// Writes per session the truth, reference and profile PNGs and their FLIP heat maps against the
// truth into `dir` (one scale for all: the largest FLIP max against the truth, at least 0.05,
// stored as info["heatmap_scale"]) and records the files in each session's truthPictures.
void writeTruthPictures(std::vector<SessionResult>& sessions, const std::vector<TruthMaps>& maps,
                        const std::string& dir, nlohmann::json& info);

} // namespace pb::bench
