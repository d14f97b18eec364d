// probebench volumes: the probe file's volumes, and with --rank their value - the accuracy the
// frame loses when each (with the volumes nested in it) is omitted, in the views that see it,
// against its GPU memory and GI lookups (costmodel/VolumeRanking.h). --write-ranks stores the
// ranking next to the probe file for gi.volume_lod=rank_budget_mib:MIB.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "ProbeOptions.h"
#include "probes/bake/SceneMatch.h"
#include "SceneOptions.h"
#include "core/Error.h"
#include "profile/GiVolumeLod.h"
#include "costmodel/VolumeRanking.h"
#include "frame/FrameRenderer.h"
#include "probes/store/VolumeRanksFile.h"
#include "views/WorstCaseView.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace pb::app {
namespace {

struct VolumesArgs {
    bool force = false; // --probes baked for another scene
    SceneArgs scene;
    std::string probes, scenario, views = "worst-case";
    int width = 320, height = 180;
    JsonOption json;
    bool rank = false, writeRanks = false;
};

double mib(std::uint64_t bytes) {
    return double(bytes) / (1024.0 * 1024.0);
}

int volumesScenarioIndex(const probes::ProbeSet& set, const std::string& name) {
    if (name.empty()) return 0;
    if (int i = set.findScenario(name); i >= 0) return i;
    throw Error("--scenario: '" + name + "' is not in the probe file");
}

// --views: worst-case (searched like the benchmark's), all (the scene's), or names.
std::vector<scene::View> chooseViews(const VolumesArgs& a, const scene::Scene& s,
                                     const probes::ProbeSet& set) {
    if (a.views == "worst-case") {
        std::fprintf(stderr, "volumes: searching the worst-case view at %dx%d\n", a.width,
                     a.height);
        return {views::findWorstCaseView(s, set, a.width, a.height).view};
    }
    if (a.views == "all") {
        if (s.views.empty()) throw Error("--views all: scene '" + s.name + "' has no views");
        return s.views;
    }
    std::vector<scene::View> out;
    std::istringstream in(a.views);
    std::string name;
    while (std::getline(in, name, ','))
        if (!name.empty()) out.push_back(chooseView(s, name, ""));
    if (out.empty()) throw UsageError("--views: expected worst-case, all or view names");
    return out;
}

std::string parentOf(const probes::ProbeVolume& v) {
    return v.parent.empty() ? "-" : v.parent;
}

void printList(const probes::ProbeSet& set, const std::string& file) {
    std::printf("%s: %zu volume(s), %s\n", file.c_str(), set.volumes.size(),
                probes::formatName(set.format()));
    std::printf("  %-20s %-16s %-12s %8s %9s\n", "volume", "parent", "probes", "spacing", "MiB");
    for (std::size_t i = 0; i < set.volumes.size(); ++i) {
        const probes::ProbeVolume& v = set.volumes[i];
        const std::string counts = std::to_string(v.counts.x) + "x" + std::to_string(v.counts.y) +
                                   "x" + std::to_string(v.counts.z);
        std::printf("  %-20s %-16s %-12s %8.3g %9.3f\n", v.name.c_str(), parentOf(v).c_str(),
                    counts.c_str(), v.minCellSize(), mib(profile::gpuVolumeBytes(set, i)));
    }
    std::printf("ranks: %s\n",
                set.ranks ? (probes::volumeRanksPath(file) + " (" + set.ranks->views + ")").c_str()
                          : set.ranksNote.c_str());
}

void printRanking(const probes::ProbeSet& set, const probes::VolumeRanks& r,
                  const std::vector<profile::RankDropStep>& drops) {
    std::printf("volume ranking: scenario '%s', views %s (%dx%d each)\n", r.scenario.c_str(),
                r.views.c_str(), r.width, r.height);
    std::printf("loss = relative MSE of the indirect irradiance over the views' surface pixels "
                "with the volume and its children omitted;\nMiB, lookups: the volume and its "
                "children (lookups per frame at this size, hardware-independent)\n");
    std::printf("  %4s %-20s %-16s %10s %8s %10s %9s %5s %11s %11s\n", "rank", "volume", "parent",
                "loss", "MiB", "loss/MiB", "pixels", "views", "lookups", "saved(stc)");
    int rank = 0;
    for (int i : costmodel::byLoss(r)) {
        const probes::VolumeRank& v = r.volumes[size_t(i)];
        std::printf("  %4d %-20s %-16s %10.4g %8.3f %10.4g %9lld %5d %11lld %11lld\n", ++rank,
                    v.name.c_str(), parentOf(set.volumes[size_t(i)]).c_str(), v.loss, mib(v.bytes),
                    v.valuePerMiB(), static_cast<long long>(v.pixels), v.views,
                    static_cast<long long>(v.lookups), static_cast<long long>(v.lookupsSaved));
    }
    std::printf(
        "gi.volume_lod=rank_budget_mib:MIB drops, in this order (leaves first), until the rest "
        "fits:\n");
    for (const profile::RankDropStep& s : drops)
        std::printf("  %-20s -> %.3f MiB kept\n", set.volumes[size_t(s.volume)].name.c_str(),
                    mib(s.keptBytes));
}

int runVolumes(const VolumesArgs& a) {
    if (a.width < 16 || a.height < 16 || a.width > 4096 || a.height > 4096)
        throw UsageError("--width/--height must be in 16..4096");
    if (!a.rank && (a.writeRanks || a.views != "worst-case"))
        throw Error(std::string(a.writeRanks ? "--write-ranks" : "--views") + ": needs --rank");
    probes::ProbeSet set = probes::readProbeFileWithRanks(a.probes);
    if (!a.rank) {
        if (a.json) {
            nlohmann::json j{{"probes_file", a.probes}, {"volumes", nlohmann::json::array()}};
            for (std::size_t i = 0; i < set.volumes.size(); ++i) {
                const probes::ProbeVolume& v = set.volumes[i];
                j["volumes"].push_back({{"name", v.name},
                                        {"parent", v.parent},
                                        {"counts", {v.counts.x, v.counts.y, v.counts.z}},
                                        {"min_spacing", v.minCellSize()},
                                        {"bytes", profile::gpuVolumeBytes(set, i)}});
            }
            j["ranks"] = set.ranks ? probes::volumeRanksJson(*set.ranks) : nlohmann::json(nullptr);
            writeJson(a.json, j.dump(2) + "\n");
        } else {
            printList(set, a.probes);
        }
        return 0;
    }
    const scene::Scene s = loadSceneWithOverrides(a.scene);
    probes::requireProbesForScene(a.probes, set, s, a.force);
    const render::FrameSettings frame = render::defaultFrameSettings(s);
    costmodel::RankingInputs in;
    in.scene = &s;
    in.probes = &set;
    in.scenario = volumesScenarioIndex(set, a.scenario);
    in.views = chooseViews(a, s, set);
    in.viewsLabel = a.views;
    in.width = a.width;
    in.height = a.height;
    in.ambientUp = frame.ambientUp;
    in.ambientDown = frame.ambientDown;
    std::fprintf(stderr, "volumes: ranking %zu volume(s) over %zu view(s)\n", set.volumes.size(),
                 in.views.size());
    set.ranks = costmodel::rankVolumes(in);
    const std::vector<profile::RankDropStep> drops = profile::rankDropOrder(set);
    if (a.json) {
        nlohmann::json j = probes::volumeRanksJson(*set.ranks);
        j["probes_file"] = a.probes;
        j["drop_order"] = nlohmann::json::array();
        for (const profile::RankDropStep& d : drops)
            j["drop_order"].push_back(
                {{"volume", set.volumes[size_t(d.volume)].name}, {"kept_bytes", d.keptBytes}});
        writeJson(a.json, j.dump(2) + "\n");
    } else {
        printRanking(set, *set.ranks, drops);
    }
    if (a.writeRanks) {
        const std::string path = probes::volumeRanksPath(a.probes);
        probes::writeVolumeRanks(path, *set.ranks);
        (a.json ? std::cerr : std::cout) << "wrote " << path << "\n";
    }
    return 0;
}

const RegisterCommand registerVolumes{
    {"volumes",
     "List a probe file's volumes; --rank: the accuracy each costs when omitted vs its memory", 55,
     [](CLI::App& cmd) {
         auto a = std::make_shared<VolumesArgs>();
         addSceneOptions(cmd, a->scene);
         cmd.add_option("--probes", a->probes, "Probe file (probebench bake)")->required();
         addForceProbesFlag(cmd, a->force);
         cmd.add_option("--scenario", a->scenario,
                        "Lighting scenario the errors are measured in (default: the first)");
         cmd.add_flag("--rank", a->rank,
                      "Rank the volumes: irradiance error (relative MSE over the views' surface "
                      "pixels, CPU sampler) with each volume and its children omitted, against "
                      "GPU memory and GI lookups");
         cmd.add_option("--views", a->views,
                        "--rank: the pixels that count: worst-case (the benchmark's view), all "
                        "(the scene's views) or view names, comma-separated")
             ->capture_default_str();
         cmd.add_option("--width", a->width, "--rank: pixels per view, across")
             ->capture_default_str();
         cmd.add_option("--height", a->height, "--rank: pixels per view, down")
             ->capture_default_str();
         cmd.add_flag("--write-ranks", a->writeRanks,
                      "--rank: store the ranking as FILE.ranks.json next to the probe file, for "
                      "gi.volume_lod=rank_budget_mib:MIB");
         a->json.add(cmd, "The volumes (and ranks)");
         return [a] { return runVolumes(*a); };
     }}};

} // namespace
} // namespace pb::app
