#pragma once
// Platform profiles from TOML (profiles/*.toml). Keys are dotted paths: the non-switch keys of
// ProfileSettings.h (`[output] width`, `[budget] frame_ms`, ...) and EVERY key of the switch
// table (`[gi] resolution = "half"` is the switch gi.resolution): a new table row is settable
// in profiles with no edit here. `inherit = "NAME"` starts from another profile (found next to
// the file first, then in the search folders; a path ending in .toml is taken relative to the
// file). Unknown keys, wrong TOML types, values out of range and inheritance cycles are
// pb::Errors "FILE:LINE: key 'KEY': problem". GL-free.
#include "profile/PlatformProfile.h"

#include <string>
#include <vector>

namespace pb::profile {

struct ProfileSearch {
    std::vector<std::string> dirs; // searched in order for NAME.toml
    // Allowed `costmodel.cache_preset` values (costmodel::cachePresets() names); empty: any.
    // A list, so this GL-free library need not depend on the cost model.
    std::vector<std::string> cachePresets;
};

// True when `s` names a file rather than a profile in the search folders.
bool looksLikeProfilePath(const std::string& s);

// NAME (searched) or a path to a .toml file.
PlatformProfile loadProfile(const std::string& nameOrPath, const ProfileSearch& search);
PlatformProfile loadProfileFile(const std::string& path, const ProfileSearch& search);
// From text; `path` names it in errors, gives the name (its stem) and the folder `inherit`
// looks in first.
PlatformProfile parseProfileToml(const std::string& text, const std::string& path,
                                 const ProfileSearch& search);

// Stems of the *.toml files in the search folders (the first folder holding a name wins),
// in a stable order: `reference` first, then alphabetical.
std::vector<std::string> profileNames(const ProfileSearch& search);

// The profile as a complete TOML file (every key explicit, no `inherit`): loading it gives the
// same settings.
std::string profileToml(const PlatformProfile& p);

} // namespace pb::profile
