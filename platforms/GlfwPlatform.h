#pragma once
// A real window for interactive viewing: desktop GL core (4.5, else 3.3), else GLES 3, through
// GLFW. Needs an X server; headless machines run it under `xvfb-run -a`. One window per
// process (GLFW itself is process-global).
#include "platforms/Platform.h"

struct GLFWwindow;

namespace pb::platform {

class GlfwPlatform final : public Platform {
public:
    explicit GlfwPlatform(const PlatformOptions& options);
    ~GlfwPlatform() override;

    std::string name() const override { return "glfw"; }
    GlApi api() const override { return api_; }
    std::string description() const override { return description_; }
    void makeCurrent() override;

    bool isWindowed() const override { return true; }
    void pollEvents(InputState& input) override;
    void swapBuffers() override;
    void framebufferSize(int& w, int& h) const override;

private:
    GLFWwindow* window_ = nullptr;
    GlApi api_ = GlApi::GLCore;
    std::string description_;
    bool dragging_ = false; // left button held at the previous poll
    double lastX_ = 0, lastY_ = 0;
};

} // namespace pb::platform
