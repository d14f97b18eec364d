#pragma once
// What `probebench tune` prints and writes about a search: the Pareto front (frame ms, GI MiB,
// FLIP) as a table for people, the whole search as JSON, and the one-line failure when nothing
// fits. GL-free.
#include "TuneSearch.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pb::bench {

// The Pareto front, fastest first, the chosen candidate marked with '*'.
std::string paretoTable(const TuneResult& r, const TuneOptions& o);
// {method, budgets, counts, chosen, pareto, candidates: [{switches, label, memory_mib,
// measured, frame_ms, flip, relative_mse_gi, fits, on_pareto_front}]}
nlohmann::json tuneJson(const TuneResult& r, const TuneOptions& o);
// "nothing fits 5 ms and 0.5 MiB (searched N, measured M); closest: LABEL (12.3 ms, 0.61 MiB,
// FLIP 0.012), ..." - one line, for pb::Error.
std::string nothingFitsMessage(const TuneResult& r, const TuneOptions& o);

} // namespace pb::bench
