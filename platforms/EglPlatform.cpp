#include "platforms/EglPlatform.h"
#include "platforms/GlEntryPoints.h"

#include <glad/gl.h>

#include <vector>

namespace pb::platform {
namespace {

GLADapiproc loadGlFunction(void* api, const char* name) {
    return reinterpret_cast<GLADapiproc>(static_cast<const EglApi*>(api)->getProcAddress(name));
}

} // namespace

EglPlatform::EglPlatform(const PlatformOptions& options) {
    const EglApi& egl = eglApi();
    display_ = std::make_unique<EglDisplay>(options.device);
    const std::string on = " on " + display_->label();

    // Without a surface the context can only be made current with this extension; every
    // pass renders into FBOs, so no surface is needed.
    if (!display_->hasExtension("EGL_KHR_surfaceless_context"))
        throw PlatformError("egl: EGL_KHR_surfaceless_context missing" + on);
    if (!egl.bindApi(EGL_OPENGL_ES_API))
        throw PlatformError("egl: eglBindAPI(EGL_OPENGL_ES_API) failed (" + egl.lastError() + ")" +
                            on);
    createContext(options.debugContext);
    if (!egl.makeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
        std::string error = egl.lastError();
        egl.destroyContext(display_->handle(), context_);
        throw PlatformError("egl: eglMakeCurrent failed (" + error + ")" + on);
    }
    if (!loadGl()) {
        egl.makeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        egl.destroyContext(display_->handle(), context_);
        throw PlatformError("egl: gladLoadGLES2 found no GL ES entry points" + on);
    }
}

bool EglPlatform::loadGl() {
    const EglApi& egl = eglApi();
    if (!gladLoadGLES2UserPtr(loadGlFunction, const_cast<EglApi*>(&egl))) return false;
    claimGlEntryPoints(this);
    return true;
}

// ES 3.2 first (KHR_debug, geometry-free extras), then 3.1 and 3.0: the renderer needs 3.0.
// The debug flag is a wish: a driver refusing it still gets a context without it.
void EglPlatform::createContext(bool debug) {
    const EglApi& egl = eglApi();
    const EGLDisplay dpy = display_->handle();
    const bool egl15 = display_->major() > 1 || display_->minor() >= 5;
    const bool createContextExt = egl15 || display_->hasExtension("EGL_KHR_create_context");

    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!display_->hasExtension("EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE,
                                 EGL_DONT_CARE, EGL_NONE};
        EGLint count = 0;
        if (!egl.chooseConfig(dpy, wanted, &config, 1, &count) || count < 1)
            throw PlatformError("egl: eglChooseConfig found no OpenGL ES 3 config (" +
                                egl.lastError() + ") on " + display_->label());
    }

    std::string lastError;
    for (int minor : {2, 1, 0}) {
        if (minor > 0 && !createContextExt) continue; // only "ES 3" can be asked for then
        for (bool withDebug : {debug, false}) {
            std::vector<EGLint> attribs = {EGL_CONTEXT_MAJOR_VERSION, 3};
            if (createContextExt) attribs.insert(attribs.end(), {EGL_CONTEXT_MINOR_VERSION, minor});
            if (withDebug && egl15)
                attribs.insert(attribs.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
            else if (withDebug && createContextExt)
                attribs.insert(attribs.end(),
                               {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
            attribs.push_back(EGL_NONE);
            context_ = egl.createContext(dpy, config, EGL_NO_CONTEXT, attribs.data());
            if (context_ != EGL_NO_CONTEXT) {
                description_ = "EGL " + std::to_string(display_->major()) + "." +
                               std::to_string(display_->minor()) + " (" + display_->vendor() +
                               "), " + display_->label() + ", OpenGL ES 3." +
                               std::to_string(minor) + (withDebug ? " debug" : "") + " context";
                return;
            }
            lastError = egl.lastError();
            if (!debug) break; // the second round would repeat the first
        }
    }
    throw PlatformError("egl: eglCreateContext failed for OpenGL ES 3.2, 3.1 and 3.0 (" +
                        lastError + ") on " + display_->label());
}

EglPlatform::~EglPlatform() {
    const EglApi& egl = eglApi();
    if (egl.getCurrentContext() == context_)
        egl.makeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    egl.destroyContext(display_->handle(), context_);
    display_.reset();
    egl.releaseThread();
    releaseGlEntryPoints(this);
}

void EglPlatform::makeCurrent() {
    const EglApi& egl = eglApi();
    const bool otherBackendWasCurrent = !ownsGlEntryPoints(this);
    // Mesa skips eglMakeCurrent of the context EGL believes is current, even when another
    // backend (OSMesa) took the thread's GL dispatch meanwhile: release first to force it.
    if (otherBackendWasCurrent && egl.getCurrentContext() == context_)
        egl.makeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (!egl.makeCurrent(display_->handle(), EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        throw PlatformError("egl: eglMakeCurrent failed (" + egl.lastError() + ") on " +
                            display_->label());
    if (otherBackendWasCurrent && !loadGl())
        throw PlatformError("egl: gladLoadGLES2 found no GL ES entry points on " +
                            display_->label());
}

} // namespace pb::platform
