// probebench devices: the device files the device model predicts for (profiles/devices/*.toml,
// $PROBEBENCH_DEVICES first): per device its class, stand-in compiler and the rates the model
// divides by. A file that does not load is one line naming it; the others are still listed.
#include "CommandRegistry.h"
#include "DeviceOptions.h"
#include "JsonOption.h"

#include "core/Error.h"

#include <cstdio>
#include <iostream>

namespace pb::app {
namespace {

struct DevicesArgs {
    JsonOption json;
};

int runDevices(const DevicesArgs& a) {
    const std::vector<std::string> dirs = deviceSearchDirs();
    nlohmann::json list = nlohmann::json::array();
    std::vector<std::string> problems;
    std::printf("| device | class | compiler | cores x lanes @ MHz | GFLOP/s fp32 | Gtexel/s | GB/s | L1 / L2 KiB | label |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& name : devicemodel::deviceNames(dirs)) {
        try {
            const devicemodel::DeviceSpec d = devicemodel::findDevice(name, dirs);
            list.push_back(d.toJson());
            const double gflops = 2.0 * d.cores * d.fp32LanesPerCore * d.clockMhz * 1e-3;
            const double gtex = double(d.cores) * d.textureUnitsPerCore * d.clockMhz * 1e-3;
            std::printf("| %s | %s | %s | %d x %d @ %.1f | %.0f | %.1f | %.1f | %llu / %llu | %s |\n",
                        d.name.c_str(), d.deviceClass.c_str(), d.compiler.c_str(), d.cores,
                        d.fp32LanesPerCore, d.clockMhz, gflops, gtex, d.bandwidthGBs,
                        (unsigned long long)(d.l1.sizeBytes / 1024),
                        (unsigned long long)(d.l2.sizeBytes / 1024), d.label.c_str());
        } catch (const Error& e) {
            problems.push_back(e.what());
        }
    }
    for (const std::string& p : problems)
        std::fprintf(stderr, "error: %s\n", p.c_str());
    if (a.json) writeJson(a.json, nlohmann::json{{"devices", list}}.dump(2) + "\n");
    return problems.empty() ? 0 : 1;
}

const RegisterCommand registerDevices{
    {"devices",
     "List the device files the device model predicts for (bench --predict, predict)", 62,
     [](CLI::App& cmd) {
         auto a = std::make_shared<DevicesArgs>();
         a->json.add(cmd, "Every device's figures");
         cmd.footer("Device files: profiles/devices/NAME.toml ($PROBEBENCH_DEVICES, ':'-separated "
                    "folders, first). Every figure's public source is a comment in its file; "
                    "bench/devicemodel/README.md says how the model uses them.");
         return [a] {
             const StdoutToStderr textToStderr(a->json.toStdout());
             return runDevices(*a);
         };
     }}};

} // namespace
} // namespace pb::app
