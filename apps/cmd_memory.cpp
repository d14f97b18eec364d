// probebench memory: GPU memory of probe data, from a probe file or for a grid size.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "core/Error.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/ProbeFile.h"

#include <iostream>
#include <nlohmann/json.hpp>

namespace pb::app {
namespace {

using namespace pb::probes;

struct MemoryArgs {
    std::string probes, grid;
    JsonOption json;
};

int run(const MemoryArgs& a) {
    if (a.probes.empty() == a.grid.empty())
        throw Error("give exactly one of --probes FILE or --grid NXxNYxNZ");
    MemoryReport r;
    if (!a.grid.empty()) {
        ProbeVolume v;
        v.name = "grid";
        v.counts = parseGrid(a.grid);
        r = memoryReport({v});
    } else {
        ProbeSet set = readProbeFile(a.probes);
        r = memoryReport(set);
    }
    if (a.json) {
        nlohmann::json j = memoryReportJson(r);
        j["source"] = a.grid.empty() ? a.probes : "grid " + a.grid;
        writeJson(a.json, j.dump(2) + "\n");
    } else {
        std::cout << formatMemoryReport(r);
    }
    return 0;
}

const RegisterCommand reg{{
    "memory",
    "Probe memory per volume and in total, uncompressed and BC6H",
    50,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<MemoryArgs>();
        cmd.add_option("--probes", a->probes, "Probe file written by `probebench bake`");
        cmd.add_option("--grid", a->grid, "A volume's probe counts, e.g. 32x8x32 (no bake needed)");
        a->json.add(cmd, "The memory report");
        return [a] { return run(*a); };
    },
}};

} // namespace
} // namespace pb::app
