#pragma once
// The weak GPUs whose production shader compilers `probebench shaders` runs without the
// hardware: Mesa's drivers behind a drm-shim (a no-op kernel driver preloaded into the
// process), built by scripts/mesa-shim.sh. One row per target, named for the device; the
// driver and the model id behind it are data here and nowhere else.
//
// What the compilers report are their own static estimates for one shader (instructions,
// registers, per-unit cycle bounds, threads or waves in flight, spills): deterministic for a
// Mesa version, comparable within one driver, not timings.
#include <string>
#include <vector>

namespace pb::shaders {

struct ShaderTarget {
    std::string name;   // "mali-g52": what --targets takes
    std::string device; // "Mali-G52 (Bifrost)"
    std::string driver; // Mesa's driver: freedreno, panfrost, v3d, nouveau
    std::string shim;   // the shim library in the install's lib/: "libpanfrost_noop_drm_shim.so"
    std::vector<std::string> env; // "NAME=value": the model id and the statistics switches
    std::string note; // what the reader must know about this compiler's figures; may be empty
};

// Every target, in the order `--list-targets` prints them.
const std::vector<ShaderTarget>& shaderTargets();

// The row named `name`; throws pb::Error naming the closest names.
const ShaderTarget& findShaderTarget(const std::string& name);

// "all", or names separated by commas; duplicates dropped, order kept. Throws pb::Error.
std::vector<ShaderTarget> parseShaderTargets(const std::string& list);

} // namespace pb::shaders
