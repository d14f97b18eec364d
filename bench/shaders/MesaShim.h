#pragma once
// Where scripts/mesa-shim.sh installed the compilers, and the environment that makes a
// process compile with one target's driver: the install's libEGL/libGLESv2 and driver folder,
// the target's shim preloaded, the surfaceless EGL platform, Gallium's threaded context off (it
// would drop the synchronous debug callback that carries the statistics) and the shader cache
// off (a cached shader is not compiled, so it reports nothing).
#include "ShaderTargets.h"

#include <string>
#include <vector>

namespace pb::shaders {

struct MesaShimInstall {
    std::string dir;                  // the install folder (holds lib/, lib/dri/, `complete`)
    std::string mesaVersion;          // "22.3.6-1+deb12u2", from `complete`
    std::vector<std::string> drivers; // as built: "freedreno", "panfrost", ...
};

// The root scripts/mesa-shim.sh installs under: $PB_MESA_SHIM_ROOT, else
// /var/cache/probebench/mesa-shim.
std::string mesaShimRoot();

// $PB_MESA_SHIM_DIR when set (must be a complete install), else the complete install under the
// root whose name sorts last. Throws pb::Error saying how to build one when there is none.
MesaShimInstall findMesaShim();

// Reads `dir`/complete; throws pb::Error naming the folder when it is not a complete install.
MesaShimInstall readMesaShim(const std::string& dir);

// Why `target` cannot run from `install` ("" when it can): its driver was not built, or its
// shim library is missing.
std::string targetUnavailableReason(const ShaderTarget& target, const MesaShimInstall& install);

// "NAME=value" entries to add to a child's environment (LD_LIBRARY_PATH is prepended to the
// current one).
std::vector<std::string> targetEnvironment(const ShaderTarget& target,
                                           const MesaShimInstall& install);

} // namespace pb::shaders
