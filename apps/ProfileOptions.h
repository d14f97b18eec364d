#pragma once
// --profile NAME|FILE and --set key=value, shared by every command that renders or models a
// frame (render, views, costmodel, bench), so they read and fail the same way everywhere.
#include "profile/PlatformProfile.h"
#include "profile/ProfileLoader.h"

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace pb::app {

struct ProfileArgs {
    std::string profile;           // empty: the switch table's defaults
    std::vector<std::string> sets; // key=value, applied on top of the profile
    const CLI::Option* profileOption = nullptr;
};

// Adds --profile and --set to `cmd`; `setHelp` says what the switches do for this command.
void addProfileOptions(CLI::App& cmd, ProfileArgs& args, const std::string& setHelp);

// Where profiles are found: $PROBEBENCH_PROFILES (folders separated by ':') first, then the
// repository's profiles/ folder (its path is baked in at build time); cache presets from the
// cost model.
profile::ProfileSearch profileSearch();

// The profiles a bench-like command measures: `names` (names or .toml files; empty or "all":
// every profile the search finds), each with every `sets` key=value applied.
std::vector<profile::PlatformProfile> loadProfilesWithSets(const std::vector<std::string>& names,
                                                           const std::vector<std::string>& sets,
                                                           const profile::ProfileSearch& search);

// The profile of --profile (or one named "defaults" with every switch at the table default and
// 1280x720 when none is given) with every --set applied on top.
profile::PlatformProfile resolveProfile(const ProfileArgs& args);

} // namespace pb::app
