#pragma once
// The profile `probebench tune` writes: `inherit` the base profile, then the output size the
// search measured at, the two budgets, and only the switches that differ from the base (the
// profile loader fills the rest from the base, so the file reads as "the base, plus these
// changes"). Header comments record the measurement. Loading it gives the tuned switches
// exactly (tests/unit/TuneTest.cpp). GL-free.
#include "profile/Profile.h"

#include <string>
#include <vector>

namespace pb::bench {

struct TunedProfileInfo {
    std::string inherit;     // the base as `inherit` names it (a name, or a path from the file)
    std::string description; // one line
    int width = 0, height = 0;
    double budgetMs = 0, budgetMiB = 0;
    std::vector<std::string> comments; // header lines, without '#'
};

std::string tunedProfileToml(const profile::Profile& base, const profile::Profile& tuned,
                             const TunedProfileInfo& info);

} // namespace pb::bench
