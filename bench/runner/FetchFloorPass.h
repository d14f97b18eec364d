#pragma once
// The texture-fetch floor of the GI apply pass: one full-screen draw at the GI target's size and
// format (gi.resolution, gi.target_format) doing a DDGI lookup's 26 fetches per pixel (GBuffer
// depth + normal, 8 x probe state + visibility + irradiance) from the same textures - the
// GBuffer of the frame just rendered and the first-drawn (largest) probe volume - with almost
// no arithmetic (shaders/bench_fetch_floor.frag). What the GI pass costs above it is math,
// branches, discards and extra volume draws. Bench only: not a pass of the frame.
#include "frame/FrameRenderer.h"
#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "profile/Profile.h"

#include <memory>

namespace pb::bench {

class FetchFloorPass {
public:
    static constexpr int kFetchesPerPixel = 2 + 8 * 3;

    explicit FetchFloorPass(const profile::Profile& profile);
    ~FetchFloorPass();
    // Needs a frame rendered by `renderer` with GI (its GBuffer and probes). Leaves no state
    // behind that the frame depends on.
    void execute(render::FrameRenderer& renderer, const render::RenderView& view);

private:
    profile::Profile profile_;
    std::unique_ptr<gl::Texture> target_;
    std::unique_ptr<gl::Framebuffer> fbo_;
};

} // namespace pb::bench
