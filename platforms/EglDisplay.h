#pragma once
// An initialized EGL display, picked for the egl backend: a device's display
// (EGL_PLATFORM_DEVICE_EXT) or Mesa's surfaceless one.
#include "platforms/EglApi.h"

#include <string>

namespace pb::platform {

class EglDisplay {
public:
    // device >= 0: that EGL device, or a PlatformError naming it. device < 0: the first hardware
    // device that initializes, else the software device, else the surfaceless platform, else the
    // default display; the error lists every attempt when none works.
    explicit EglDisplay(int device);
    ~EglDisplay();
    EglDisplay(const EglDisplay&) = delete;
    EglDisplay& operator=(const EglDisplay&) = delete;

    EGLDisplay handle() const { return display_; }
    const std::string& label() const { return label_; } // e.g. "device 0 (software ...)"
    int major() const { return major_; }
    int minor() const { return minor_; }
    bool hasExtension(const char* name) const;
    std::string vendor() const;

private:
    bool tryInitialize(EGLDisplay display, const std::string& label, std::string& failure);

    EGLDisplay display_ = EGL_NO_DISPLAY;
    std::string label_;
    int major_ = 0, minor_ = 0;
};

} // namespace pb::platform
