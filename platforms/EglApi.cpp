#include "platforms/EglApi.h"
#include "platforms/DynamicLibrary.h"
#include "platforms/Platform.h"

#include <cstdio>
#include <cstring>

namespace pb::platform {
namespace {

template <class Fn> Fn extension(const EglApi& egl, const char* name) {
    return reinterpret_cast<Fn>(egl.getProcAddress(name));
}

EglApi load() {
    static const DynamicLibrary lib("egl", {"libEGL.so.1"});
    EglApi egl;
    egl.getProcAddress = lib.require<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    egl.getError = lib.require<PFNEGLGETERRORPROC>("eglGetError");
    egl.queryString = lib.require<PFNEGLQUERYSTRINGPROC>("eglQueryString");
    egl.getDisplay = lib.require<PFNEGLGETDISPLAYPROC>("eglGetDisplay");
    egl.initialize = lib.require<PFNEGLINITIALIZEPROC>("eglInitialize");
    egl.terminate = lib.require<PFNEGLTERMINATEPROC>("eglTerminate");
    egl.bindApi = lib.require<PFNEGLBINDAPIPROC>("eglBindAPI");
    egl.chooseConfig = lib.require<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
    egl.createContext = lib.require<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    egl.destroyContext = lib.require<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    egl.makeCurrent = lib.require<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    egl.getCurrentContext = lib.require<PFNEGLGETCURRENTCONTEXTPROC>("eglGetCurrentContext");
    egl.releaseThread = lib.require<PFNEGLRELEASETHREADPROC>("eglReleaseThread");

    // Client extensions need EGL_EXT_client_extensions; without it this returns null.
    const char* client = egl.queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client)
        egl.clientExtensions = client;
    else
        egl.getError(); // clear the EGL_BAD_DISPLAY it left

    if (egl.hasClientExtension("EGL_EXT_device_enumeration") ||
        egl.hasClientExtension("EGL_EXT_device_base"))
        egl.queryDevices = extension<PFNEGLQUERYDEVICESEXTPROC>(egl, "eglQueryDevicesEXT");
    if (egl.hasClientExtension("EGL_EXT_device_query") ||
        egl.hasClientExtension("EGL_EXT_device_base"))
        egl.queryDeviceString =
            extension<PFNEGLQUERYDEVICESTRINGEXTPROC>(egl, "eglQueryDeviceStringEXT");
    if (egl.hasClientExtension("EGL_EXT_platform_base"))
        egl.getPlatformDisplay =
            extension<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl, "eglGetPlatformDisplayEXT");
    return egl;
}

} // namespace

const EglApi& eglApi() {
    static const EglApi egl = load();
    return egl;
}

bool hasExtensionWord(const char* list, const char* name) {
    if (!list || !name || !*name) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name)) {
        const bool startOk = p == list || p[-1] == ' ';
        const bool endOk = p[n] == '\0' || p[n] == ' ';
        if (startOk && endOk) return true;
    }
    return false;
}

bool EglApi::hasClientExtension(const char* name) const {
    return hasExtensionWord(clientExtensions.c_str(), name);
}

std::string EglApi::lastError() const {
    return eglErrorName(getError());
}

std::string eglErrorName(EGLint error) {
    switch (error) {
    case EGL_SUCCESS:
        return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
        return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
        return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
        return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
        return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
        return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT:
        return "EGL_BAD_DEVICE_EXT";
    default: {
        char buf[32];
        std::snprintf(buf, sizeof buf, "EGL error 0x%04X", static_cast<unsigned>(error));
        return buf;
    }
    }
}

} // namespace pb::platform
