#include "gl/DriverQuirks.h"

#include <glad/gl.h>
#include <string>

namespace pb::gl {

DriverQuirks detectDriverQuirks() {
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    std::string version = str(GL_VERSION), renderer = str(GL_RENDERER);
    DriverQuirks q;
    q.windowBlitNeedsSrgbOff = version.rfind("OpenGL ES", 0) != 0;
    q.softwareRenderer = renderer.find("llvmpipe") != std::string::npos ||
                         renderer.find("softpipe") != std::string::npos ||
                         renderer.find("swrast") != std::string::npos;
    q.timerQueriesNeedFlush = renderer.find("llvmpipe") != std::string::npos;
    q.timerQueriesUntrustworthy = q.softwareRenderer;
    return q;
}

} // namespace pb::gl
