// probebench info: which GL context the platform gives and what it can do (or the EGL devices).
#include "CommandRegistry.h"
#include "JsonOption.h"
#include "PlatformOptions.h"
#include "gl/Capabilities.h"
#include "platforms/Platform.h"
#include "scene/SceneLoader.h"

#include <iostream>

namespace pb::app {
namespace {

struct InfoOptions {
    platform::PlatformOptions platform;
    JsonOption json;
    bool devices = false;
};

int printDevices(const JsonOption& json) {
    const auto devices = platform::listEglDevices();
    if (json) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& d : devices)
            list.push_back({{"index", d.index},
                            {"name", d.name},
                            {"software", d.software},
                            {"extensions", d.extensions}});
        writeJson(json, list.dump(2) + "\n");
        return 0;
    }
    if (devices.empty()) {
        std::cout << "no EGL devices (libEGL lacks EGL_EXT_device_enumeration); "
                     "--platform egl falls back to the surfaceless platform\n";
        return 0;
    }
    for (const auto& d : devices)
        std::cout << d.index << "  " << (d.software ? "software" : "hardware") << "  " << d.name
                  << "\n";
    return 0;
}

int runInfo(const InfoOptions& o) {
    if (o.devices) return printDevices(o.json);
    const auto p = platform::createPlatform(o.platform);
    const gl::GlCaps caps = gl::queryCaps();
    if (o.json) {
        nlohmann::json j = gl::toJson(caps);
        j["platform"] = {{"name", p->name()}, {"description", p->description()}};
        j["gltf_extensions"] = scene::supportedGltfExtensions();
        writeJson(o.json, j.dump(2) + "\n");
        return 0;
    }
    std::cout << "platform                             " << p->name() << ": " << p->description()
              << "\n"
              << gl::toText(caps) << "(`probebench info --json` lists the extensions)\n";
    std::string gltf;
    for (const auto& e : scene::supportedGltfExtensions())
        gltf += (gltf.empty() ? "" : " ") + e;
    std::cout << "glTF extensions supported           " << gltf << "\n";
    return 0;
}

const RegisterCommand registration{{
    "info",
    "Show the GL platform, driver strings and capabilities (or --devices: the EGL devices)",
    10,
    [](CLI::App& cmd) -> std::function<int()> {
        auto o = std::make_shared<InfoOptions>();
        o->json.add(cmd, "The platform, GL strings and capabilities");
        cmd.add_flag("--devices", o->devices,
                     "List the EGL devices (index, name, software/hardware) and exit; "
                     "no context is created");
        addPlatformOptions(cmd, o->platform);
        return [o] { return runInfo(*o); };
    },
}};

} // namespace
} // namespace pb::app
