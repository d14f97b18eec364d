// probebench profiles: the platform profiles (profiles/*.toml and $PROBEBENCH_PROFILES), one
// line each; --show prints one profile fully resolved (inheritance applied) as TOML.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "ProfileOptions.h"
#include "core/Error.h"
#include "profile/ProfileLoader.h"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

namespace pb::app {
namespace {

struct ProfilesArgs {
    JsonOption json;
    std::string show;
};

int runProfiles(const ProfilesArgs& a) {
    const profile::ProfileSearch search = profileSearch();
    if (!a.show.empty()) {
        profile::PlatformProfile p = profile::loadProfile(a.show, search);
        if (a.json)
            writeJson(a.json, p.toJson().dump(2) + "\n");
        else
            std::cout << profile::profileToml(p);
        return 0;
    }
    const std::vector<std::string> names = profile::profileNames(search);
    if (names.empty()) {
        std::string dirs;
        for (const auto& d : search.dirs)
            dirs += (dirs.empty() ? "" : ", ") + d;
        throw Error("no profiles found (searched " + dirs + ")");
    }
    nlohmann::json out = nlohmann::json::array();
    int failed = 0;
    if (!a.json)
        std::printf("%-14s %-10s %9s %9s  %-13s %s\n", "profile", "output", "frame", "GI mem",
                    "cache", "description");
    for (const std::string& name : names) {
        try {
            profile::PlatformProfile p = profile::loadProfile(name, search);
            if (a.json) {
                nlohmann::json j = p.toJson();
                j["summary"] = p.summaryLine();
                out.push_back(j);
                continue;
            }
            std::string size = std::to_string(p.width) + "x" + std::to_string(p.height);
            std::printf("%-14s %-10s %6.4g ms %5.4g MiB  %-13s %s\n", p.name.c_str(), size.c_str(),
                        p.frameBudgetMs, p.giMemoryBudgetMiB, p.cachePreset.c_str(),
                        p.description.c_str());
        } catch (const Error& e) {
            ++failed;
            if (a.json)
                out.push_back({{"name", name}, {"error", e.what()}});
            else
                std::printf("%-14s error: %s\n", name.c_str(), e.what());
        }
    }
    if (a.json)
        writeJson(a.json, out.dump(2) + "\n");
    else
        std::printf("(`probebench profiles --show NAME` prints every setting; --profile NAME|FILE "
                    "on render, views, costmodel, bench)\n");
    if (failed) std::fprintf(stderr, "probebench: error: %d profile(s) failed to load\n", failed);
    return failed ? 1 : 0;
}

const RegisterCommand registerProfiles{
    {"profiles", "List the platform profiles (profiles/*.toml) with a one-line summary", 15,
     [](CLI::App& cmd) {
         auto a = std::make_shared<ProfilesArgs>();
         a->json.add(cmd, "Every setting of every profile");
         cmd.add_option("--show", a->show,
                        "Print one profile (NAME or .toml file) with inheritance applied, as a "
                        "complete TOML file");
         return [a] { return runProfiles(*a); };
     }}};

} // namespace
} // namespace pb::app
