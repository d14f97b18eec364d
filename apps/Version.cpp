#include "Version.h"

#include <embree3/rtcore_config.h>

namespace pb::app {

std::string versionText() {
    return "probebench " + buildCommit() + "\n" +
           "build type: " + buildType() + "\n" +
           "embree: " + RTC_VERSION_STRING + " (headers built against)\n" +
           "mesa: " + buildMesa() + " (libgl1-mesa-dri where it was built)\n" +
           "GL in use: needs a context, see `probebench info`";
}

} // namespace pb::app
