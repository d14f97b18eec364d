#include "PlatformOptions.h"

#include "NumberChecks.h"

namespace pb::app {

void addPlatformOptions(CLI::App& cmd, pb::platform::PlatformOptions& o) {
    cmd.add_option("--platform", o.name,
                   "GL context backend: egl (headless OpenGL ES 3 on a GPU or llvmpipe), "
                   "osmesa (Mesa off-screen, desktop GL core) or glfw (a window; headless "
                   "machines need `xvfb-run -a`)")
        ->check(CLI::IsMember(pb::platform::platformNames()))
        ->capture_default_str()
        ->group("Platform");
    cmd.add_option("--device", o.device,
                   "EGL device index from `probebench info --devices` (egl only; default: the "
                   "first hardware device, else llvmpipe)")
        ->check(numberAtLeastZero(false))
        ->group("Platform");
}

} // namespace pb::app
