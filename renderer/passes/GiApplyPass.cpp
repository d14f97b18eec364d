#include "passes/GiApplyPass.h"

#include "core/Error.h"
#include "passes/GiDebugInjection.h"
#include "passes/GiVolumeRaster.h"
#include "profile/SwitchTable.h"

#include <algorithm>

namespace pb::render {

gl::Defines giShaderDefines(const profile::Profile& p, const GpuProbes* probes) {
    gl::Defines d = ddgiConstantDefines();
    for (const auto& [name, value] : profile::shaderDefines(p))
        d[name] = value;
    if (probes && probes->anySparse()) d["DDGI_SPARSE_TILES"] = "";
    return d;
}

gl::TextureFormat giTargetFormat(profile::GiTargetFormat f) {
    switch (f) {
    case profile::GiTargetFormat::Rgba32f:
        return gl::TextureFormat::RGBA32F;
    case profile::GiTargetFormat::R11g11b10f:
        return gl::TextureFormat::R11G11B10F;
    case profile::GiTargetFormat::Rgba16f:
        break;
    }
    return gl::TextureFormat::RGBA16F;
}

struct GiApplyPass::Draw {
    FrameContext& frame;
    glm::ivec2 gbufferSize, giSize;
    int divisor;
    const gl::Program* applyFullscreen;
    const gl::Program* applyBox;
    const gl::Program* fill;
};

namespace {

void drawBox(const FrameTargets& targets) {
    glBindVertexArray(targets.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 36);
    glBindVertexArray(0);
}

// The uniforms every GI program of the frame reads (common_gi_pixel.glsl, the GBuffer).
void setPixelUniforms(const gl::Program& prog, const FrameContext& frame, int divisor) {
    const GBuffer& gb = frame.targets.gbuffer;
    prog.use();
    gb.bindForReading(prog, 0);
    prog.set("u_relFromClip", frame.view.relFromClip);
    prog.set("u_gbufferInvSize", glm::vec2(1.0f / float(gb.width()), 1.0f / float(gb.height())));
    prog.set("u_giDivisor", divisor);
    prog.set("u_giJitter", frame.giJitter); // gi.upsample: where in the footprint to sample
    // r11g11b10f blends the ambient in here: pre-exposed like the irradiance.
    prog.set("u_ambientUp", frame.settings.ambientUp * frame.preExposure);
    prog.set("u_ambientDown", frame.settings.ambientDown * frame.preExposure);
}

void resetState() {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
}

} // namespace

GiApplyPass::GiApplyPass(const GpuProbes& probes, const profile::Profile& profile)
    : probes_(probes), profile_(profile), defines_(giShaderDefines(profile, &probes)) {}

void GiApplyPass::execute(FrameContext& frame) {
    const bool stencil = profile_.gi.multiVolume == profile::GiMultiVolume::Stencil;
    const int div = profile::resolutionDivisor(profile_.gi.resolution);
    const GBuffer& gb = frame.targets.gbuffer;
    GiTargetSpec spec;
    spec.width = std::max(1, gb.width() / div);
    spec.height = std::max(1, gb.height() / div);
    spec.format = giTargetFormat(profile_.gi.targetFormat);
    // Full resolution is read with texelFetch; lower ones are upsampled bilinearly.
    spec.linearFilter = div != 1;
    spec.depthStencil = stencil;
    spec.evaluated = countPixels_;
    targets_.ensure(spec);

    stats_ = {};
    stats_.multiVolume = profile_.get("gi.multi_volume");
    stats_.width = spec.width;
    stats_.height = spec.height;
    stats_.counted = countPixels_;
    if (countPixels_) {
        stats_.evaluations.assign(size_t(spec.width) * size_t(spec.height), 0);
        stats_.shadedBy.assign(stats_.evaluations.size(), -1);
    }

    targets_.bind();
    resetState();
    glClearColor(0, 0, 0, 0); // weight 0 = no volume: the lighting falls back to its ambient
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | (stencil ? GL_STENCIL_BUFFER_BIT : 0u));

    gl::Defines applyDefines = defines_;
    if (countPixels_) applyDefines["GI_COUNT_PIXELS"] = "";
    applyDefines.merge(giDebugInjectionDefines()); // test-only, normally empty
    Draw d{frame,
           {gb.width(), gb.height()},
           {spec.width, spec.height},
           div,
           &frame.programs.get("fullscreen.vert", "gi_ddgi_apply.frag", applyDefines),
           nullptr,
           nullptr};
    std::vector<int> order = probes_.drawOrder(); // largest first
    if (stencil) {
        std::reverse(order.begin(), order.end()); // smallest first
        d.applyBox = &frame.programs.get("gi_volume_box.vert", "gi_ddgi_apply.frag", applyDefines);
        d.fill = &frame.programs.get("gi_volume_box.vert", "gi_stencil_fill.frag", defines_);
        // The GI target's depth: the depth of the GBuffer pixel each texel stands for.
        TimedSection section(frame.timer, "gi-depth-copy");
        const gl::Program& copy = frame.programs.get("fullscreen.vert", "gi_depth_copy.frag", {});
        setPixelUniforms(copy, frame, div);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        drawFullscreenTriangle(frame.targets);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE); // the volume draws only test depth
    }
    for (const gl::Program* p : {d.applyFullscreen, d.applyBox, d.fill})
        if (p) setPixelUniforms(*p, frame, div);

    for (int v : order) {
        const GpuProbeVolume& vol = probes_.volumes()[size_t(v)];
        const GiVolumeRaster r = volumeRaster(vol, frame.view, d.gbufferSize, div, d.giSize);
        GiVolumeStats vs;
        vs.name = vol.name;
        vs.fileIndex = vol.fileIndex;
        vs.culled = !r.visible;
        vs.cameraInside = stencil && r.cameraInside;
        vs.fillPass = stencil && r.visible && !r.cameraInside;
        vs.fullScreen = !stencil || (r.cameraInside && !r.backFacesInFrontOfFar);
        stats_.volumes.push_back(vs);
        if (!r.visible) continue;
        if (countPixels_) {
            const GLfloat zero[4] = {0, 0, 0, 0};
            glClearBufferfv(GL_COLOR, 1, zero);
        }
        if (stencil)
            drawStencil(d, v, r);
        else
            drawNaive(d, v);
        if (countPixels_) countEvaluated(int(stats_.volumes.size()) - 1);
    }

    resetState();
    for (int u = kFirstProbeUnit + GpuProbes::kUnitsPerVolume - 1; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    glActiveTexture(GL_TEXTURE0);
    frame.gi.enabled = true;
    frame.gi.irradiance = targets_.target();
    frame.gi.defines.clear(); // the lighting needs the switches, not the sampler's constants
    for (const auto& [name, value] : profile::shaderDefines(profile_))
        frame.gi.defines[name] = value;
    frame.gi.defines["GI_ENABLED"] = "";
}

void GiApplyPass::drawNaive(Draw& d, int v) {
    d.applyFullscreen->use();
    probes_.bindVolume(*d.applyFullscreen, v, kFirstProbeUnit, d.frame.view.eye,
                       d.frame.preExposure);
    drawFullscreenTriangle(d.frame.targets);
}

// The talk's scheme. Outside the volume: the fill pass rasterises the box's front faces where
// the surface lies behind them (LEQUAL) and no smaller volume took the pixel ('any' clear),
// its shader discards pixels outside the influence, survivors get 'current'; the full pass
// draws the same faces where 'current' is set and INVERTs both bits ('current' off, 'any'
// on). Inside: no fill; the full pass draws the back faces where the surface lies in front of
// them (GEQUAL) - or, when the box reaches past the far plane (whose clipping would lose
// pixels), a full-screen triangle - where 'any' is clear, and sets 'any' (clearing
// 'current'). So 'any' set implies 'current' clear. A pixel the fill passed but the apply
// shader discarded (the same test on the same position: not expected) keeps a stale
// 'current' with 'any' clear: harmless, the next full pass evaluates it only if it lies in
// that volume - which is then the smallest one containing it.
void GiApplyPass::drawStencil(Draw& d, int v, const GiVolumeRaster& r) {
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    if (!r.cameraInside) {
        {
            TimedSection section(d.frame.timer, "gi-fill");
            d.fill->use();
            d.fill->set("u_clipFromBox", r.clipFromBox);
            probes_.bindVolume(*d.fill, v, kFirstProbeUnit, d.frame.view.eye, d.frame.preExposure);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glCullFace(GL_BACK);
            glDepthFunc(GL_LEQUAL);
            // Passes where 'any' is clear; REPLACE writes the reference through the mask.
            glStencilFunc(GL_NOTEQUAL, int(kStencilAny | kStencilCurrent), kStencilAny);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            glStencilMask(kStencilCurrent);
            drawBox(d.frame.targets);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        glStencilFunc(GL_EQUAL, int(kStencilCurrent), kStencilCurrent);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INVERT);
        glStencilMask(kStencilAny | kStencilCurrent);
        d.applyBox->use();
        d.applyBox->set("u_clipFromBox", r.clipFromBox);
        probes_.bindVolume(*d.applyBox, v, kFirstProbeUnit, d.frame.view.eye, d.frame.preExposure);
        drawBox(d.frame.targets);
    } else {
        // Where 'any' is clear: 'any' on, 'current' off (a stale one included).
        glStencilFunc(GL_NOTEQUAL, int(kStencilAny), kStencilAny);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glStencilMask(kStencilAny | kStencilCurrent);
        if (r.backFacesInFrontOfFar) {
            glCullFace(GL_FRONT);
            glDepthFunc(GL_GEQUAL);
            d.applyBox->use();
            d.applyBox->set("u_clipFromBox", r.clipFromBox);
            probes_.bindVolume(*d.applyBox, v, kFirstProbeUnit, d.frame.view.eye,
                               d.frame.preExposure);
            drawBox(d.frame.targets);
        } else {
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_CULL_FACE);
            d.applyFullscreen->use();
            probes_.bindVolume(*d.applyFullscreen, v, kFirstProbeUnit, d.frame.view.eye,
                               d.frame.preExposure);
            drawFullscreenTriangle(d.frame.targets);
        }
    }
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

// Reads the "evaluated" attachment (cleared before the volume's draws) back and folds it into
// the per-volume count and the per-texel maps.
void GiApplyPass::countEvaluated(int statsIndex) {
    const int w = stats_.width, h = stats_.height;
    std::vector<std::uint8_t> rgba(size_t(w) * size_t(h) * 4);
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    std::int64_t n = 0;
    for (size_t i = 0; i < stats_.evaluations.size(); ++i) {
        if (rgba[i * 4] < 128) continue;
        ++n;
        if (stats_.evaluations[i] < 255) ++stats_.evaluations[i];
        stats_.shadedBy[i] = std::int16_t(statsIndex);
    }
    stats_.volumes[size_t(statsIndex)].evaluatedPixels = n;
}

} // namespace pb::render
