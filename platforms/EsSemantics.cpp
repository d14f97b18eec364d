#include "platforms/EsSemantics.h"

#include <glad/gl.h>

namespace pb::platform {

void enableEsSemantics() { // call right after gladLoadGL
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    // glad's flags are fresh here: the desktop loader has just run.
    if (GLAD_GL_VERSION_4_3 || GLAD_GL_ARB_ES3_compatibility)
        glEnable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
}

} // namespace pb::platform
