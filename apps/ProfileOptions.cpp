#include "ProfileOptions.h"

#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "profile/ProfileLoader.h"
#include "profile/SwitchTable.h"

#include <cstdlib>
#include <sstream>

#ifndef PB_PROFILES_DIR
#define PB_PROFILES_DIR "profiles"
#endif

namespace pb::app {

void addProfileOptions(CLI::App& cmd, ProfileArgs& a, const std::string& setHelp) {
    a.profileOption =
        cmd.add_option("--profile", a.profile,
                       "Platform profile: a name from `probebench profiles` (reference, pc-high, "
                       "console-base, handheld, pc-low) or a .toml file");
    cmd.add_option("--set", a.sets,
                   "Profile switch key=value on top of --profile (repeatable; `probebench "
                   "render --list-switches` lists them). " +
                       setHelp);
}

profile::ProfileSearch profileSearch() {
    profile::ProfileSearch s;
    if (const char* env = std::getenv("PROBEBENCH_PROFILES")) {
        std::stringstream in(env);
        std::string dir;
        while (std::getline(in, dir, ':'))
            if (!dir.empty()) s.dirs.push_back(dir);
    }
    s.dirs.push_back(PB_PROFILES_DIR);
    for (const costmodel::CacheConfig& c : costmodel::cachePresets())
        s.cachePresets.push_back(c.name);
    return s;
}

namespace {
// A value the switch table refuses for a known switch (out of range, not a choice) is a usage
// error: exit 2. A wrong switch name stays exit 1 with its "did you mean", as every name the
// user types (scene, view, profile).
void applySet(profile::PlatformProfile& p, const std::string& kv) {
    try {
        p.switches.applyOverride(kv);
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        if (profile::findSwitch(kv.substr(0, kv.find('='))) != nullptr) throw UsageError(e.what());
        throw;
    }
}
} // namespace

profile::PlatformProfile resolveProfile(const ProfileArgs& a) {
    profile::PlatformProfile p;
    if (!a.profile.empty()) {
        p = profile::loadProfile(a.profile, profileSearch());
    } else {
        p.name = "defaults";
        p.description = "every switch at the switch table's default";
        p.cachePreset = "pc-high";
    }
    for (const std::string& kv : a.sets)
        applySet(p, kv);
    return p;
}

std::vector<profile::PlatformProfile> loadProfilesWithSets(const std::vector<std::string>& names,
                                                           const std::vector<std::string>& sets,
                                                           const profile::ProfileSearch& search) {
    std::vector<std::string> list = names;
    if (list.empty() || (list.size() == 1 && list[0] == "all"))
        list = profile::profileNames(search);
    std::vector<profile::PlatformProfile> out;
    for (const std::string& n : list) {
        profile::PlatformProfile p = profile::loadProfile(n, search);
        for (const std::string& kv : sets)
            applySet(p, kv);
        out.push_back(std::move(p));
    }
    return out;
}

} // namespace pb::app
