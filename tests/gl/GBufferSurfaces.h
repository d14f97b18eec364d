#pragma once
// The surface behind every pixel of a rendered frame, rebuilt from its GBuffer as the GI shaders
// rebuild it (common_gi_pixel.glsl): window depth -> camera-relative point through relFromClip,
// the octahedral normal, and the flags; and the apply pass's GI target. Shared by the tests
// that hold that target against the CPU sampler at the same points.
#include "frame/DepthReadback.h"
#include "frame/FrameRenderer.h"
#include "frame/Readback.h"
#include "passes/GiApplyPass.h"

#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace pb::test {

struct GBufferSurface {
    bool sky = true;
    glm::vec3 world{0.0f}, normal{0.0f, 1.0f, 0.0f};
    glm::vec3 rel{0.0f}; // eye -> surface, camera-relative (the view direction is -rel)
    unsigned flags = 0;  // bit 0: dynamic object (DynamicObjects.h)
};

// The GBuffer's octahedral normal decode (shaders/common_octahedral.glsl, +Z at the centre).
inline glm::vec3 gbufferNormal(float ex, float ey) {
    glm::vec3 n(ex, ey, 1.0f - std::abs(ex) - std::abs(ey));
    if (n.z < 0.0f) {
        float x = (1.0f - std::abs(n.y)) * (n.x >= 0.0f ? 1.0f : -1.0f);
        float y = (1.0f - std::abs(n.x)) * (n.y >= 0.0f ? 1.0f : -1.0f);
        n.x = x, n.y = y;
    }
    return glm::normalize(n);
}

// The GI apply pass's evaluation target of `r`; null when the frame has no GI pass.
inline const gl::Texture* giTarget(const render::FrameRenderer& r) {
    for (const auto& p : r.passes())
        if (auto* gi = dynamic_cast<const render::GiApplyPass*>(p.get())) return gi->target();
    return nullptr;
}

// Row-major, rows top to bottom (as the read-backs), of the frame `r` last rendered with `view`.
inline std::vector<GBufferSurface> gbufferSurfaces(const render::FrameRenderer& r,
                                                   const render::RenderView& view) {
    gl::ProgramCache programs;
    const image::ImageF depth = render::readDepthDistance(*r.targets(), view, programs);
    const image::ImageF normal = render::readFloat(r.targets()->gbuffer.channel(1));
    const image::Image8 flags = render::readRgba8(r.targets()->gbuffer.channel(3));
    const int w = depth.width, h = depth.height;
    std::vector<GBufferSurface> out(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            GBufferSurface& s = out[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            const float d = depth.at(x, y, 1);
            if (d >= 1.0f) continue;
            const int glRow = h - 1 - y;
            const glm::vec4 clip((float(x) + 0.5f) / float(w) * 2.0f - 1.0f,
                                 (float(glRow) + 0.5f) / float(h) * 2.0f - 1.0f, d * 2.0f - 1.0f,
                                 1.0f);
            const glm::vec4 relH = view.relFromClip * clip;
            s.sky = false;
            s.rel = glm::vec3(relH) / relH.w;
            s.world = glm::vec3(glm::dvec3(s.rel) + view.eye);
            s.normal = gbufferNormal(normal.at(x, y, 0), normal.at(x, y, 1));
            s.flags = flags.at(x, y, 0);
        }
    return out;
}

} // namespace pb::test
