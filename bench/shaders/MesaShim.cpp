#include "MesaShim.h"

#include "core/Error.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pb::shaders {
namespace {

namespace fs = std::filesystem;

const char* kBuildHint = "build them with scripts/mesa-shim.sh (about 10 min on 2 cores)";

std::string envOr(const char* name, const std::string& fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : fallback;
}

} // namespace

std::string mesaShimRoot() {
    return envOr("PB_MESA_SHIM_ROOT", "/var/cache/probebench/mesa-shim");
}

MesaShimInstall readMesaShim(const std::string& dir) {
    std::ifstream in(fs::path(dir) / "complete");
    if (!in)
        throw Error("Mesa shim install " + dir + ": not complete (no 'complete' file); " +
                    kBuildHint);
    MesaShimInstall install;
    install.dir = dir;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key, value;
        words >> key >> value;
        if (key == "mesa") install.mesaVersion = value;
        if (key == "drivers") {
            std::stringstream list(value);
            for (std::string d; std::getline(list, d, ',');)
                if (!d.empty()) install.drivers.push_back(d);
        }
    }
    if (install.mesaVersion.empty() || install.drivers.empty())
        throw Error("Mesa shim install " + dir +
                    ": its 'complete' file names no Mesa version "
                    "or drivers; rebuild with scripts/mesa-shim.sh");
    return install;
}

MesaShimInstall findMesaShim() {
    if (const char* dir = std::getenv("PB_MESA_SHIM_DIR"); dir && *dir) return readMesaShim(dir);
    const std::string root = mesaShimRoot();
    std::vector<std::string> complete;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(root, ec))
        if (e.is_directory() && fs::exists(e.path() / "complete"))
            complete.push_back(e.path().string());
    if (complete.empty())
        throw Error("the weak GPUs' compilers are not built (no complete install under " + root +
                    "); " + kBuildHint);
    std::sort(complete.begin(), complete.end());
    return readMesaShim(complete.back());
}

std::string targetUnavailableReason(const ShaderTarget& target, const MesaShimInstall& install) {
    if (std::find(install.drivers.begin(), install.drivers.end(), target.driver) ==
        install.drivers.end())
        return "its driver (" + target.driver + ") is not in the install at " + install.dir;
    if (!fs::exists(fs::path(install.dir) / "lib" / target.shim))
        return "its shim " + target.shim + " is missing from " + install.dir + "/lib";
    return "";
}

std::vector<std::string> targetEnvironment(const ShaderTarget& target,
                                           const MesaShimInstall& install) {
    const std::string lib = (fs::path(install.dir) / "lib").string();
    const std::string ldPath = envOr("LD_LIBRARY_PATH", "");
    std::vector<std::string> env = {
        "LD_LIBRARY_PATH=" + lib + (ldPath.empty() ? "" : ":" + ldPath),
        "LIBGL_DRIVERS_PATH=" + lib + "/dri",
        "LD_PRELOAD=" + lib + "/" + target.shim,
        "EGL_PLATFORM=surfaceless",
        "GALLIUM_THREAD=0",
        "MESA_SHADER_CACHE_DISABLE=true",
        // A software fallback would compile on llvmpipe and report nothing of the target.
        "LIBGL_ALWAYS_SOFTWARE=0",
    };
    env.insert(env.end(), target.env.begin(), target.env.end());
    return env;
}

} // namespace pb::shaders
