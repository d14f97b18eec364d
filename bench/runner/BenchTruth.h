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

// Writes per session the truth, reference and profile PNGs and their FLIP heat maps against the
// truth into `dir` (one scale for all: the largest FLIP max against the truth, at least 0.05,
// stored as info["heatmap_scale"]) and records the files in each session's truthPictures.
void writeTruthPictures(std::vector<SessionResult>& sessions, const std::vector<TruthMaps>& maps,
                        const std::string& dir, nlohmann::json& info);

} // namespace pb::bench
