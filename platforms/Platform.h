#pragma once
// One small interface for every GL context backend (egl, osmesa, glfw). A backend creates a
// context, makes it current, fills the glad function pointers from its own GetProcAddress and
// tears down. All rendering goes into FBOs owned by the renderer; a backend never leaves GL
// state changed behind the caller.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace pb::platform {

enum class GlApi { GLES, GLCore };

struct PlatformOptions {
    std::string name = "egl";   // egl | osmesa | glfw
    int device = -1;            // egl: EGL device index (-1 = first hardware device, else llvmpipe)
    int width = 1280;           // glfw: window size; others ignore it (they render to FBOs)
    int height = 720;
    bool debugContext = true;   // ask for a KHR_debug-capable context
    std::string windowTitle = "probebench";
};

struct DeviceInfo {
    int index = 0;
    std::string name;           // driver / renderer name when known (e.g. "llvmpipe", "nvidia")
    std::string extensions;     // EGL device extensions
    bool software = false;      // EGL_MESA_device_software
};

// Keyboard and mouse state for the interactive fly camera (glfw only).
struct InputState {
    bool forward = false, back = false, left = false, right = false, up = false, down = false;
    bool fast = false;
    double mouseDx = 0, mouseDy = 0; // pixels moved since the last poll while a button is held
    bool quit = false;
};

class PlatformError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The backend cannot run on this machine at all (its library is not installed, or there is no
// X display for glfw), as opposed to failing on the way. Tests skip on it outside CI.
class PlatformUnavailable : public PlatformError {
public:
    using PlatformError::PlatformError;
};

class Platform {
public:
    virtual ~Platform() = default;
    Platform() = default;
    Platform(const Platform&) = delete;
    Platform& operator=(const Platform&) = delete;

    virtual std::string name() const = 0;        // "egl", "osmesa", "glfw"
    virtual GlApi api() const = 0;               // GLES for egl, GLCore for osmesa / glfw
    virtual std::string description() const = 0; // e.g. "EGL device 0 (surfaceless), llvmpipe"
    virtual void makeCurrent() = 0;

    // Windowed backends only; headless ones keep the defaults.
    virtual bool isWindowed() const { return false; }
    virtual void pollEvents(InputState& input) { (void)input; }
    virtual void swapBuffers() {}
    // Framebuffer size of the window; headless backends return {0,0} (render to FBOs).
    virtual void framebufferSize(int& w, int& h) const { w = h = 0; }
};

// Creates the backend, makes its context current and loads GL entry points.
// Throws PlatformError with a message naming the backend and what failed.
std::unique_ptr<Platform> createPlatform(const PlatformOptions& options);

// EGL devices (EGL_EXT_device_enumeration); empty when the extension is missing.
std::vector<DeviceInfo> listEglDevices();

// The backend names createPlatform accepts.
const std::vector<std::string>& platformNames();

} // namespace pb::platform
