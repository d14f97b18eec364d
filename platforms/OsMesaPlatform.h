#pragma once
// Mesa's off-screen software backend: a desktop GL core context (4.5, else 3.3) on llvmpipe,
// made current on a tiny private buffer; the renderer draws into FBOs. Optional: OSMesa is
// gone from Mesa 25.1, so egl stays the primary path.
#include "platforms/Platform.h"

#include <cstdint>
#include <vector>

namespace pb::platform {

class OsMesaPlatform final : public Platform {
public:
    explicit OsMesaPlatform(const PlatformOptions& options);
    ~OsMesaPlatform() override;

    std::string name() const override { return "osmesa"; }
    GlApi api() const override { return GlApi::GLCore; }
    std::string description() const override { return description_; }
    void makeCurrent() override;

private:
    void* context_ = nullptr; // OSMesaContext
    std::vector<std::uint8_t> buffer_;
    std::string description_;
};

} // namespace pb::platform
