#include "platforms/EglDevices.h"

namespace pb::platform {
namespace {

std::string deviceString(const EglApi& egl, EGLDeviceEXT device, EGLint name) {
    const char* s = egl.queryDeviceString(device, name);
    if (!s) egl.getError(); // an unsupported name is not an error worth keeping
    return s ? s : "";
}

// The most telling name the driver offers: the renderer (EGL_EXT_device_query_name, e.g.
// NVIDIA), else the DRM node, else what Mesa's software (llvmpipe) device is.
std::string deviceName(const EglApi& egl, EGLDeviceEXT device, const std::string& extensions) {
    const char* ext = extensions.c_str();
    if (hasExtensionWord(ext, "EGL_EXT_device_query_name")) {
        std::string vendor = deviceString(egl, device, EGL_VENDOR);
        std::string renderer = deviceString(egl, device, EGL_RENDERER_EXT);
        if (!renderer.empty()) return vendor.empty() ? renderer : vendor + " " + renderer;
    }
    if (hasExtensionWord(ext, "EGL_EXT_device_drm_render_node")) {
        std::string node = deviceString(egl, device, EGL_DRM_RENDER_NODE_FILE_EXT);
        if (!node.empty()) return node;
    }
    if (hasExtensionWord(ext, "EGL_EXT_device_drm")) {
        std::string node = deviceString(egl, device, EGL_DRM_DEVICE_FILE_EXT);
        if (!node.empty()) return node;
    }
    if (hasExtensionWord(ext, "EGL_MESA_device_software")) return "Mesa software rasterizer";
    return "unknown";
}

} // namespace

std::vector<EglDevice> queryEglDevices(const EglApi& egl) {
    if (!egl.queryDevices || !egl.queryDeviceString) return {};
    EGLint count = 0;
    if (!egl.queryDevices(0, nullptr, &count) || count <= 0) return {};
    std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count));
    if (!egl.queryDevices(count, handles.data(), &count)) return {};
    handles.resize(static_cast<size_t>(count));

    std::vector<EglDevice> devices;
    for (EGLint i = 0; i < count; ++i) {
        EglDevice d;
        d.handle = handles[static_cast<size_t>(i)];
        d.info.index = i;
        d.info.extensions = deviceString(egl, d.handle, EGL_EXTENSIONS);
        d.info.software = hasExtensionWord(d.info.extensions.c_str(), "EGL_MESA_device_software");
        d.info.name = deviceName(egl, d.handle, d.info.extensions);
        devices.push_back(d);
    }
    return devices;
}

std::vector<DeviceInfo> listEglDevices() {
    std::vector<DeviceInfo> out;
    for (const EglDevice& d : queryEglDevices(eglApi()))
        out.push_back(d.info);
    return out;
}

} // namespace pb::platform
