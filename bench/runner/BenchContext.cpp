#include "BenchContext.h"

#include "BuildInfo.h"

#include <glad/gl.h>

#include <sys/utsname.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace pb::bench {

namespace {

// "Mesa 22.3.6" out of "OpenGL ES 3.2 Mesa 22.3.6"; other vendors put their driver version
// in GL_VERSION in their own way ("4.6.0 NVIDIA 535.54"), so the whole string then.
std::string driverVersion(const std::string& glVersion) {
    if (auto m = glVersion.find("Mesa "); m != std::string::npos) return glVersion.substr(m);
    return glVersion;
}

std::string utcNow() {
    std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

} // namespace

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            auto colon = line.find(':');
            if (colon != std::string::npos)
                return line.substr(line.find_first_not_of(" \t", colon + 1));
        }
    return "unknown";
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    if (!(in >> a >> b >> c)) return "unknown";
    return a + " " + b + " " + c;
}

std::string gitCommit() { return PB_GIT_COMMIT; }

nlohmann::json debugContextFlag(const gl::GlCaps& caps) {
    // GL_CONTEXT_FLAGS exists from ES 3.2 and GL 4.3; before that the context cannot say.
    if (!caps.versionAtLeast(caps.es ? 3 : 4, caps.es ? 2 : 3)) return nullptr;
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    return (flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0;
}

nlohmann::json benchContext(const platform::Platform& platform, const gl::GlCaps& caps) {
    struct utsname u {};
    uname(&u);
    const char* lp = std::getenv("LP_NUM_THREADS");
    return {
        {"platform", platform.name() + ": " + platform.description()},
        {"gl_version", caps.version},
        {"gl_renderer", caps.renderer},
        {"gl_vendor", caps.vendor},
        {"glsl_version", caps.glslVersion},
        {"driver", driverVersion(caps.version)},
        {"software_renderer", caps.software},
        {"cpu", cpuModel()},
        {"cpu_threads", std::thread::hardware_concurrency()},
        {"lp_num_threads", lp ? std::string(lp) : std::string("unset (llvmpipe: one per core)")},
        {"os", std::string(u.sysname) + " " + u.release + " " + u.machine},
        {"commit", gitCommit()},
        // Timing commands ask for a non-debug context: KHR_debug's checks cost time (issue 25).
        {"debug_context", debugContextFlag(caps)},
        {"date", utcNow()},
        {"load_average_start", loadAverage()}};
}

} // namespace pb::bench
