#include "platforms/EglDisplay.h"
#include "platforms/EglDevices.h"
#include "platforms/Platform.h"

#include <map>
#include <mutex>

namespace pb::platform {
namespace {

// eglGetPlatformDisplay returns the same handle for the same device, and one eglTerminate
// ends every context on it; counting users keeps two platforms on one device independent.
std::mutex displayMutex;
std::map<EGLDisplay, int> displayUsers;

std::string describe(const DeviceInfo& d) {
    return "device " + std::to_string(d.index) + " (" + d.name + ")";
}

} // namespace

EglDisplay::EglDisplay(int device) {
    const EglApi& egl = eglApi();
    std::vector<EglDevice> devices = queryEglDevices(egl);
    const bool devicePlatform =
        egl.getPlatformDisplay && egl.hasClientExtension("EGL_EXT_platform_device");
    auto deviceDisplay = [&](const EglDevice& d) {
        return egl.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, d.handle, nullptr);
    };

    if (device >= 0) {
        if (!devicePlatform || devices.empty())
            throw PlatformError("egl: --device " + std::to_string(device) +
                                " needs EGL_EXT_device_enumeration and EGL_EXT_platform_device, "
                                "which this libEGL lacks");
        if (device >= static_cast<int>(devices.size()))
            throw PlatformError("egl: device " + std::to_string(device) + " does not exist (" +
                                std::to_string(devices.size()) +
                                " EGL device(s); see `probebench info --devices`)");
        const EglDevice& d = devices[static_cast<size_t>(device)];
        std::string failure;
        if (!tryInitialize(deviceDisplay(d), describe(d.info), failure))
            throw PlatformError("egl: " + failure);
        return;
    }

    std::string failures;
    auto attempt = [&](EGLDisplay display, const std::string& label) {
        std::string failure;
        if (tryInitialize(display, label, failure)) return true;
        failures += (failures.empty() ? "" : "; ") + failure;
        return false;
    };
    if (devicePlatform) {
        for (const EglDevice& d : devices)
            if (!d.info.software && attempt(deviceDisplay(d), describe(d.info))) return;
        for (const EglDevice& d : devices)
            if (d.info.software && attempt(deviceDisplay(d), describe(d.info))) return;
    }
    if (egl.getPlatformDisplay && egl.hasClientExtension("EGL_MESA_platform_surfaceless") &&
        attempt(egl.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                "surfaceless platform"))
        return;
    if (attempt(egl.getDisplay(EGL_DEFAULT_DISPLAY), "default display")) return;
    throw PlatformError("egl: no usable display (" + failures + ")");
}

bool EglDisplay::tryInitialize(EGLDisplay display, const std::string& label, std::string& failure) {
    const EglApi& egl = eglApi();
    if (display == EGL_NO_DISPLAY) {
        failure = "eglGetPlatformDisplay failed (" + egl.lastError() + ") on " + label;
        return false;
    }
    EGLint major = 0, minor = 0;
    if (!egl.initialize(display, &major, &minor)) {
        failure = "eglInitialize failed (" + egl.lastError() + ") on " + label;
        return false;
    }
    {
        std::lock_guard lock(displayMutex);
        ++displayUsers[display];
    }
    display_ = display;
    label_ = label;
    major_ = major;
    minor_ = minor;
    return true;
}

EglDisplay::~EglDisplay() {
    if (display_ == EGL_NO_DISPLAY) return;
    std::lock_guard lock(displayMutex);
    if (--displayUsers[display_] == 0) {
        displayUsers.erase(display_);
        eglApi().terminate(display_);
    }
}

bool EglDisplay::hasExtension(const char* name) const {
    return hasExtensionWord(eglApi().queryString(display_, EGL_EXTENSIONS), name);
}

std::string EglDisplay::vendor() const {
    const char* v = eglApi().queryString(display_, EGL_VENDOR);
    return v ? v : "unknown vendor";
}

} // namespace pb::platform
