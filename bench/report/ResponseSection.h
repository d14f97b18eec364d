#pragma once
// The report's "response to a scene change" section (`bench --respond`): per profile and update
// schedule how many frames the GI takes to settle after the event (t95/t99, respond's figures)
// beside the profile's frame time, with the rays and upload bytes per frame its [update] budget
// allowed. Empty strings when the run had no --respond.
#include "BenchResult.h"

#include <string>

namespace pb::bench {

std::string responseHtml(const BenchResult& r);
std::string responseMarkdown(const BenchResult& r);

} // namespace pb::bench
