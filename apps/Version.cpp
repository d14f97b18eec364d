#include "Version.h"

#include "bench/runner/BenchContext.h"

#include <embree3/rtcore_config.h>

namespace pb::app {

std::string versionText() {
    return "probebench " + bench::gitCommit() + "\n" +
           "build type: " + PB_BUILD_TYPE + "\n" +
           "embree: " + RTC_VERSION_STRING + " (headers built against)\n" +
           "mesa: " + PB_BUILD_MESA + " (libgl1-mesa-dri where it was built)\n" +
           "GL in use: needs a context, see `probebench info`";
}

} // namespace pb::app
