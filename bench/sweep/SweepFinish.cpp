#include "SweepFinish.h"

#include "bench/sweep/SweepMerge.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Hash.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/ProbeFileParts.h"

#include <cstdio>
#include <filesystem>

namespace pb::sweep {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void writeSweepText(const std::string& path, const std::string& text) {
    writeFileAtomic(path, text.data(), text.size());
}

// Each split bake's parts -> its probe file, as `probebench bake-merge` does.
json mergeBakes(const sweep::PlanState& plan, const std::string& outDir) {
    json bakes = json::array();
    for (const sweep::BakeGroup& g : sweep::bakeGroups(plan.jobs)) {
        std::vector<probes::ProbeFilePart> parts;
        std::vector<std::string> paths;
        for (std::size_t j : g.jobs) {
            paths.push_back((fs::path(outDir) / plan.jobs[j].output).string());
            parts.push_back(probes::readProbeFilePart(paths.back()));
        }
        const probes::ProbeSet set = probes::mergeProbeFileParts(parts, paths);
        const std::string file = (fs::path(outDir) / g.merged).string();
        probes::writeProbeFile(file, set);
        const std::vector<unsigned char> bytes = readFileBytes(file);
        char hash[17];
        std::snprintf(hash, sizeof hash, "%016llx",
                      static_cast<unsigned long long>(pb::fnv1a64(bytes.data(), bytes.size())));
        bakes.push_back({{"scene", g.scene},
                         {"parts", g.jobs.size()},
                         {"file", g.merged},
                         {"bytes", bytes.size()},
                         {"fnv1a64", hash}});
    }
    return bakes;
}

} // namespace

void finishSweep(const std::string& outDir) {
    const std::optional<sweep::PlanState> plan = sweep::readPlanState(outDir);
    if (!plan) throw Error(outDir + ": holds no sweep (no sweep-plan.json)");
    for (std::size_t j : sweep::unfinishedJobs(outDir, *plan))
        throw Error("sweep: job " + std::to_string(j) +
                    " has not finished cleanly; nothing merged (--resume runs it again)");
    const json merged = sweep::mergeSweep(*plan, outDir, mergeBakes(*plan, outDir));
    writeSweepText((fs::path(outDir) / kSweepJson).string(), merged.dump(2) + "\n");
    writeSweepText((fs::path(outDir) / kSweepHtml).string(), sweep::sweepHtml(merged));
    writeSweepText((fs::path(outDir) / kSweepMarkdown).string(), sweep::sweepMarkdown(merged));
}

} // namespace pb::sweep
