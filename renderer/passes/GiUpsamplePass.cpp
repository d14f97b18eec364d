#include "passes/GiUpsamplePass.h"

namespace pb::render {

namespace {
const char* fragmentShader(profile::GiUpsample mode) {
    switch (mode) {
    case profile::GiUpsample::Bilateral:
        return "gi_upsample_bilateral.frag";
    case profile::GiUpsample::Temporal:
        return "gi_upsample_temporal.frag";
    case profile::GiUpsample::Bilinear:
        break;
    }
    return "gi_upsample_bilinear.frag";
}

} // namespace

// GI at full resolution, plus (temporal) each pixel's surface - distance from the eye,
// confidence, octahedral normal - which the next frame checks its reprojected taps against.
// RGBA16F: half precision is 5e-4 relative, a hundredth of the plane tolerance.
struct GiUpsamplePass::Target {
    Target(gl::TextureFormat format, int w, int h, bool withDistance)
        : gi(gl::nearestTexture(format, w, h)),
          distance(withDistance ? gl::nearestTexture(gl::TextureFormat::RGBA16F, w, h)
                                : gl::Texture()),
          fbo("gi upsample",
              withDistance ? std::vector<const gl::Texture*>{&gi, &distance}
                           : std::vector<const gl::Texture*>{&gi},
              nullptr) {
        gi.label("gi upsample");
        if (withDistance) distance.label("gi upsample surfaces");
    }
    gl::Texture gi;
    gl::Texture distance;
    gl::Framebuffer fbo;
};

camera::CameraState cameraState(const RenderView& view) {
    camera::CameraState c;
    c.eye = view.eye;
    c.forward = view.forward;
    c.clipFromRel = view.clipFromRel;
    c.relFromClip = view.relFromClip;
    c.width = view.width;
    c.height = view.height;
    c.fovYDegrees = view.fovYDegrees;
    c.farPlane = view.farPlane;
    return c;
}

GiUpsamplePass::GiUpsamplePass(const profile::Profile& profile)
    : mode_(profile.gi.upsample), divisor_(profile::resolutionDivisor(profile.gi.resolution)) {}

GiUpsamplePass::~GiUpsamplePass() = default;

const gl::Texture* GiUpsamplePass::output() const {
    return targets_[current_] ? &targets_[current_]->gi : nullptr;
}

std::size_t GiUpsamplePass::bytes() const {
    std::size_t b = 0;
    for (const auto& t : targets_)
        if (t) b += t->gi.bytes() + (t->distance ? t->distance.bytes() : 0);
    return b;
}

void GiUpsamplePass::beginFrame(const RenderView& view, FrameContext& frame) {
    now_ = cameraState(view);
    const bool temporal = mode_ == profile::GiUpsample::Temporal;
    const bool cut =
        !havePrevious_ || resetRequested_ || camera::isCameraCut(previous_, now_, cutRule_);
    frameIndex_ = cut ? 0 : frameIndex_ + 1;
    historyValid_ = temporal && !cut;
    resetRequested_ = false;
    // The non-temporal modes keep sample 0 (the footprint's centre pixel) every frame: a
    // jitter they cannot accumulate would only make the image crawl.
    frame.giJitter = camera::giJitter(divisor_, temporal ? frameIndex_ : 0);
}

void GiUpsamplePass::execute(FrameContext& frame) {
    const gl::Texture* low = frame.gi.irradiance;
    if (!frame.gi.enabled || !low) return; // nothing to upsample (no probes)
    const GBuffer& gb = frame.targets.gbuffer;
    const bool temporal = mode_ == profile::GiUpsample::Temporal;
    const gl::TextureFormat format = low->desc().format;
    const bool sizeChanged = !targets_[0] || targets_[0]->gi.desc().width != gb.width() ||
                             targets_[0]->gi.desc().height != gb.height() ||
                             targets_[0]->gi.desc().format != format;
    if (sizeChanged) { // the history (temporal: ping-pong pair) starts over
        targets_[0] = std::make_unique<Target>(format, gb.width(), gb.height(), temporal);
        targets_[1] =
            temporal ? std::make_unique<Target>(format, gb.width(), gb.height(), true) : nullptr;
        current_ = 0;
        historyValid_ = false;
    }
    const int previous = current_;
    if (temporal) current_ = 1 - current_;
    const Target& out = *targets_[current_];

    out.fbo.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    const gl::Program& prog = frame.programs.get("fullscreen.vert", fragmentShader(mode_));
    prog.use();
    gb.bindForReading(prog, 0);
    low->bind(kLowUnit);
    prog.set("u_giLow", kLowUnit);
    prog.set("u_giLowSize", glm::ivec2(low->desc().width, low->desc().height));
    prog.set("u_giDivisor", divisor_);
    prog.set("u_giJitter", frame.giJitter);
    prog.set("u_relFromClip", frame.view.relFromClip);
    prog.set("u_gbufferInvSize", glm::vec2(1.0f / float(gb.width()), 1.0f / float(gb.height())));
    if (temporal) {
        const Target& history = *targets_[previous];
        history.gi.bind(kHistoryGiUnit);
        history.distance.bind(kHistoryDistanceUnit);
        prog.set("u_historyGi", kHistoryGiUnit);
        prog.set("u_historyDistance", kHistoryDistanceUnit);
        prog.set("u_historyValid", historyValid_ ? 1 : 0);
        prog.set("u_prevClipFromRel", camera::prevClipFromCurrentRel(previous_, now_));
        prog.set("u_prevRelFromClip", previous_.relFromClip);
        prog.set("u_eyeOffset", camera::eyeOffset(previous_, now_));
        prog.set("u_stillCamera", camera::isSameCamera(previous_, now_) ? 1 : 0);
    }
    drawFullscreenTriangle(frame.targets);
    for (int u = kHistoryDistanceUnit; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    previous_ = now_;
    havePrevious_ = true;
    frame.gi.irradiance = &out.gi; // the lighting now reads full resolution
}

} // namespace pb::render
