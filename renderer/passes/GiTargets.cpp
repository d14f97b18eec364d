#include "passes/GiTargets.h"

namespace pb::render {

namespace {
std::unique_ptr<gl::Texture> makeTexture(gl::TextureFormat f, int w, int h, bool linear) {
    gl::TextureDesc d;
    d.format = f;
    d.width = w;
    d.height = h;
    d.filter = linear ? gl::Filter::Linear : gl::Filter::Nearest;
    return std::make_unique<gl::Texture>(d);
}
} // namespace

void GiTargets::ensure(const GiTargetSpec& spec) {
    if (fbo_ && spec == spec_) return;
    fbo_.reset();
    spec_ = spec;
    target_ = makeTexture(spec.format, spec.width, spec.height, spec.linearFilter);
    depthStencil_ = spec.depthStencil ? makeTexture(gl::TextureFormat::Depth32FStencil8, spec.width,
                                                    spec.height, false)
                                      : nullptr;
    evaluated_ = spec.evaluated ? makeTexture(gl::TextureFormat::R8, spec.width, spec.height, false)
                                : nullptr;
    target_->label("gi evaluation");
    if (depthStencil_) depthStencil_->label("gi evaluation depth-stencil");
    if (evaluated_) evaluated_->label("gi evaluated pixels");
    std::vector<const gl::Texture*> colour{target_.get()};
    if (evaluated_) colour.push_back(evaluated_.get());
    fbo_ = std::make_unique<gl::Framebuffer>("gi evaluation", colour, depthStencil_.get());
}

std::size_t GiTargets::bytes() const {
    std::size_t b = 0;
    for (const auto* t : {target_.get(), depthStencil_.get(), evaluated_.get()})
        b += t ? t->bytes() : 0;
    return b;
}

} // namespace pb::render
