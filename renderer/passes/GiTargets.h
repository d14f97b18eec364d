#pragma once
// The GI evaluation target and what gi.multi_volume=stencil and pixel counting add to it, all
// at the GI target's size (gi.resolution): a DEPTH32F_STENCIL8 of its own for the stencil
// mode (the GBuffer's is full size and is being sampled), and an R8 "evaluated" attachment
// (location 1) while per-volume pixels are counted. Re-created when any of that changes.
#include "gl/Framebuffer.h"
#include "gl/Texture.h"

#include <memory>

namespace pb::render {

struct GiTargetSpec {
    int width = 1, height = 1;
    gl::TextureFormat format = gl::TextureFormat::RGBA16F;
    bool linearFilter = false; // reduced resolutions are upsampled bilinearly
    bool depthStencil = false;
    bool evaluated = false;
    bool operator==(const GiTargetSpec&) const = default;
};

class GiTargets {
public:
    void ensure(const GiTargetSpec& spec);
    void bind() const { fbo_->bind(); }
    const GiTargetSpec& spec() const { return spec_; }
    const gl::Texture* target() const { return target_.get(); }
    const gl::Texture* evaluated() const { return evaluated_.get(); }
    std::size_t bytes() const; // GPU memory of every texture here

private:
    GiTargetSpec spec_;
    std::unique_ptr<gl::Texture> target_, depthStencil_, evaluated_;
    std::unique_ptr<gl::Framebuffer> fbo_;
};

} // namespace pb::render
