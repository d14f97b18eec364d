#include "platforms/GlfwPlatform.h"
#include "platforms/EsSemantics.h"
#include "platforms/GlEntryPoints.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>

namespace pb::platform {
namespace {

std::string lastGlfwError; // GLFW reports through a callback, not a return value

void onGlfwError(int code, const char* text) {
    char codeText[32];
    std::snprintf(codeText, sizeof codeText, " (GLFW error 0x%X)", static_cast<unsigned>(code));
    lastGlfwError = std::string(text ? text : "unknown") + codeText;
}

struct ContextRequest {
    GlApi api;
    int major, minor;
};

bool envSet(const char* name) {
    const char* v = std::getenv(name);
    return v && *v;
}

GLADapiproc loadGlfwGlFunction(const char* name) {
    return reinterpret_cast<GLADapiproc>(glfwGetProcAddress(name));
}

} // namespace

GlfwPlatform::GlfwPlatform(const PlatformOptions& options) {
    if (options.device >= 0) throw PlatformError("glfw: --device applies to the egl platform only");
    // GLFW 3.3 has no headless platform; without this check glfwInit fails with a vaguer
    // "X11: Failed to open display".
    if (!envSet("DISPLAY") && !envSet("WAYLAND_DISPLAY"))
        throw PlatformUnavailable("glfw: no DISPLAY set; the glfw backend needs an X server: "
                                  "run it under `xvfb-run -a probebench ...` on a headless "
                                  "machine, or use --platform egl");
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) throw PlatformError("glfw: glfwInit failed: " + lastGlfwError);

    const ContextRequest requests[] = {
        {GlApi::GLCore, 4, 5}, {GlApi::GLCore, 3, 3}, {GlApi::GLES, 3, 2}, {GlApi::GLES, 3, 0}};
    for (const ContextRequest& r : requests) {
        glfwDefaultWindowHints();
        if (r.api == GlApi::GLCore) {
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        } else {
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        }
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, r.major);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, r.minor);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debugContext ? GLFW_TRUE : GLFW_FALSE);
        window_ = glfwCreateWindow(options.width, options.height, options.windowTitle.c_str(),
                                   nullptr, nullptr);
        if (window_) {
            api_ = r.api;
            description_ = std::string("GLFW ") + glfwGetVersionString() + ", " +
                           std::to_string(options.width) + "x" + std::to_string(options.height) +
                           " window, " + (r.api == GlApi::GLCore ? "OpenGL core " : "OpenGL ES ") +
                           std::to_string(r.major) + "." + std::to_string(r.minor) + " context";
            break;
        }
    }
    if (!window_) {
        std::string error = lastGlfwError;
        glfwTerminate();
        throw PlatformError("glfw: glfwCreateWindow failed for GL core 4.5/3.3 and ES 3.2/3.0: " +
                            error);
    }
    glfwMakeContextCurrent(window_);
    // Frame times are measured, so never wait for vertical sync.
    glfwSwapInterval(0);
    const int loaded =
        api_ == GlApi::GLCore ? gladLoadGL(loadGlfwGlFunction) : gladLoadGLES2(loadGlfwGlFunction);
    if (!loaded) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw PlatformError(std::string("glfw: ") +
                            (api_ == GlApi::GLCore ? "gladLoadGL" : "gladLoadGLES2") +
                            " found no GL entry points");
    }
    claimGlEntryPoints(this);
    // Mesa's windows (GLX and EGL) are sRGB-capable, so on desktop GL this also sRGB-encodes
    // writes to the window; a presenter blitting a display-ready image must disable
    // GL_FRAMEBUFFER_SRGB for that blit (README.md).
    if (api_ == GlApi::GLCore) enableEsSemantics();
}

GlfwPlatform::~GlfwPlatform() {
    glfwDestroyWindow(window_);
    glfwTerminate();
    releaseGlEntryPoints(this);
}

void GlfwPlatform::makeCurrent() {
    glfwMakeContextCurrent(window_);
    if (ownsGlEntryPoints(this)) return;
    const bool loaded =
        api_ == GlApi::GLCore ? gladLoadGL(loadGlfwGlFunction) : gladLoadGLES2(loadGlfwGlFunction);
    if (!loaded) throw PlatformError("glfw: reloading the GL entry points failed");
    claimGlEntryPoints(this);
}

void GlfwPlatform::pollEvents(InputState& input) {
    glfwPollEvents();
    auto down = [this](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; };
    input.forward = down(GLFW_KEY_W);
    input.back = down(GLFW_KEY_S);
    input.left = down(GLFW_KEY_A);
    input.right = down(GLFW_KEY_D);
    input.down = down(GLFW_KEY_Q);
    input.up = down(GLFW_KEY_E);
    input.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
    if (down(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window_, GLFW_TRUE);
    input.quit = glfwWindowShouldClose(window_);

    // Mouse look only while the left button is held; the first held frame sets the anchor so
    // the camera does not jump to wherever the cursor was.
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    const bool held = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    input.mouseDx = held && dragging_ ? x - lastX_ : 0;
    input.mouseDy = held && dragging_ ? y - lastY_ : 0;
    dragging_ = held;
    lastX_ = x;
    lastY_ = y;
}

void GlfwPlatform::swapBuffers() {
    glfwSwapBuffers(window_);
}

void GlfwPlatform::framebufferSize(int& w, int& h) const {
    glfwGetFramebufferSize(window_, &w, &h);
}

} // namespace pb::platform
