// probebench memory: GPU memory of probe data, from a probe file or for a grid size.
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "core/Error.h"
#include "probes/store/MemoryReport.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/store/ProbeFile.h"

#include <iostream>
#include <nlohmann/json.hpp>

namespace pb::app {
namespace {

using namespace pb::probes;

struct MemoryArgs {
    std::string probes, grid, technique = "ddgi";
    JsonOption json;
};

// gi.technique=sh_l1|sh_l2: the SH 3D textures, a fixed number of bytes per probe (every grid
// probe: the SH volume is a dense lattice), per volume and in all.
int runSh(const MemoryArgs& a, int coefficients) {
    std::vector<ProbeVolume> volumes;
    if (!a.grid.empty()) {
        ProbeVolume v;
        v.name = "grid";
        v.counts = parseGrid(a.grid);
        volumes.push_back(v);
    } else {
        volumes = readProbeFile(a.probes).volumes;
    }
    const std::size_t perProbe = shGpuBytesPerProbe(coefficients);
    nlohmann::json j;
    j["source"] = a.grid.empty() ? a.probes : "grid " + a.grid;
    j["technique"] = a.technique;
    j["bytes_per_probe"] = perProbe;
    std::size_t total = 0, probes = 0;
    for (const ProbeVolume& v : volumes) {
        const std::size_t n = std::size_t(v.probeCount());
        j["volumes"].push_back({{"name", v.name},
                                {"probes", n},
                                {"bytes", n * perProbe},
                                {"mib", double(n * perProbe) / (1024.0 * 1024.0)}});
        total += n * perProbe;
        probes += n;
    }
    j["probes"] = probes;
    j["total_bytes"] = total;
    j["total_mib"] = double(total) / (1024.0 * 1024.0);
    if (a.json) {
        writeJson(a.json, j.dump(2) + "\n");
    } else {
        std::cout << a.technique << ": " << perProbe << " bytes per probe (3D textures)\n";
        for (const auto& v : j["volumes"])
            std::cout << "  " << v["name"].get<std::string>() << ": " << v["probes"] << " probes, "
                      << formatBytes(v["bytes"].get<std::size_t>()) << "\n";
        std::cout << "  total: " << formatBytes(total) << "\n";
    }
    return 0;
}

int runMemory(const MemoryArgs& a) {
    if (a.probes.empty() == a.grid.empty())
        throw Error("give exactly one of --probes FILE or --grid NXxNYxNZ");
    if (a.technique == "sh_l1") return runSh(a, kShL1Coefficients);
    if (a.technique == "sh_l2") return runSh(a, kShL2Coefficients);
    if (a.technique != "ddgi")
        throw UsageError("--technique: unknown value '" + a.technique + "' (ddgi, sh_l1, sh_l2)");
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

const RegisterCommand registerMemory{{
    "memory",
    "Probe memory per volume and in total, uncompressed and BC6H",
    50,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<MemoryArgs>();
        cmd.add_option("--probes", a->probes, "Probe file written by `probebench bake`");
        cmd.add_option("--grid", a->grid, "A volume's probe counts, e.g. 32x8x32 (no bake needed)");
        cmd.add_option("--technique", a->technique,
                       "gi.technique to count: ddgi (default; octahedral textures) or sh_l1 / "
                       "sh_l2 (SH 3D textures)");
        a->json.add(cmd, "The memory report");
        return [a] { return runMemory(*a); };
    },
}};

} // namespace
} // namespace pb::app
