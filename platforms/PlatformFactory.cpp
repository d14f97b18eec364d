// createPlatform and platformNames: the one place that knows every backend.
#include "platforms/EglPlatform.h"
#include "platforms/GlfwPlatform.h"
#include "platforms/OsMesaPlatform.h"

namespace pb::platform {

const std::vector<std::string>& platformNames() {
    static const std::vector<std::string> names = {"egl", "osmesa", "glfw"};
    return names;
}

std::unique_ptr<Platform> createPlatform(const PlatformOptions& options) {
    if (options.name == "egl") return std::make_unique<EglPlatform>(options);
    if (options.name == "osmesa") return std::make_unique<OsMesaPlatform>(options);
    if (options.name == "glfw") return std::make_unique<GlfwPlatform>(options);
    throw PlatformError("unknown platform '" + options.name + "' (choose egl, osmesa or glfw)");
}

} // namespace pb::platform
