#pragma once
// The EGL entry points the egl backend uses, loaded once per process from libEGL.so.1 with
// dlopen (core functions by dlsym, extension functions through eglGetProcAddress, as the EGL
// spec requires for extensions).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

namespace pb::platform {

struct EglApi {
    PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
    PFNEGLGETERRORPROC getError = nullptr;
    PFNEGLQUERYSTRINGPROC queryString = nullptr;
    PFNEGLGETDISPLAYPROC getDisplay = nullptr;
    PFNEGLINITIALIZEPROC initialize = nullptr;
    PFNEGLTERMINATEPROC terminate = nullptr;
    PFNEGLBINDAPIPROC bindApi = nullptr;
    PFNEGLCHOOSECONFIGPROC chooseConfig = nullptr;
    PFNEGLCREATECONTEXTPROC createContext = nullptr;
    PFNEGLDESTROYCONTEXTPROC destroyContext = nullptr;
    PFNEGLMAKECURRENTPROC makeCurrent = nullptr;
    PFNEGLGETCURRENTCONTEXTPROC getCurrentContext = nullptr;
    PFNEGLRELEASETHREADPROC releaseThread = nullptr;

    // Extension entry points; nullptr when the client extension is missing.
    PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;             // EGL_EXT_device_enumeration
    PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;   // EGL_EXT_device_query
    PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = nullptr; // EGL_EXT_platform_base

    std::string clientExtensions; // eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)

    bool hasClientExtension(const char* name) const;

    // "EGL_BAD_MATCH" for the last error of this thread.
    std::string lastError() const;
};

// Loads libEGL.so.1 on first use; throws PlatformUnavailable when it is not installed.
const EglApi& eglApi();

// Whether `name` is a whole word of the space-separated extension string `list`.
bool hasExtensionWord(const char* list, const char* name);

std::string eglErrorName(EGLint error);

} // namespace pb::platform
