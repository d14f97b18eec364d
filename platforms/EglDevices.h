#pragma once
// EGL device enumeration (EGL_EXT_device_enumeration): the list `probebench info --devices`
// prints and `--device N` indexes.
#include "platforms/EglApi.h"
#include "platforms/Platform.h"

#include <vector>

namespace pb::platform {

struct EglDevice {
    EGLDeviceEXT handle = EGL_NO_DEVICE_EXT;
    DeviceInfo info;
};

// Every device in EGL's order; empty when the extension is missing.
std::vector<EglDevice> queryEglDevices(const EglApi& egl);

} // namespace pb::platform
