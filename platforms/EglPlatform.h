#pragma once
// The default backend: a headless OpenGL ES 3.x context on an EGL device (a GPU, or Mesa's
// llvmpipe), current without any surface; the renderer draws into FBOs.
#include "platforms/EglDisplay.h"
#include "platforms/Platform.h"

#include <memory>

namespace pb::platform {

class EglPlatform final : public Platform {
public:
    explicit EglPlatform(const PlatformOptions& options);
    ~EglPlatform() override;

    std::string name() const override { return "egl"; }
    GlApi api() const override { return GlApi::GLES; }
    std::string description() const override { return description_; }
    void makeCurrent() override;

private:
    void createContext(bool debug);
    bool loadGl(); // fills glad's table through eglGetProcAddress

    std::unique_ptr<EglDisplay> display_;
    EGLContext context_ = EGL_NO_CONTEXT;
    std::string description_;
};

} // namespace pb::platform
