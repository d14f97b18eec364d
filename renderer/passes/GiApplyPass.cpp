#include "passes/GiApplyPass.h"

#include "core/Error.h"
#include "gl/Capabilities.h"
#include "passes/GiDebugInjection.h"
#include "passes/GiVolumeRaster.h"
#include "profile/GiDynamicReads.h"
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

void requireRenderableTarget(const profile::Profile& profile, const gl::GlCaps& caps) {
    bool renderable = true;
    const char* what = "";
    switch (profile.gi.targetFormat) {
    case profile::GiTargetFormat::Rgba16f:
        renderable = caps.renderRgba16f;
        what = "RGBA16F";
        break;
    case profile::GiTargetFormat::Rgba32f:
        renderable = caps.renderRgba32f;
        what = "RGBA32F";
        break;
    case profile::GiTargetFormat::R11g11b10f:
        renderable = caps.renderR11fG11fB10f;
        what = "R11F_G11F_B10F";
        break;
    }
    if (!renderable)
        throw Error("gi.target_format=" + profile.get("gi.target_format") + " needs " + what +
                    " colour-renderable, which " + caps.renderer + " is not");
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

// One program per draw geometry: the volume's box (gi_volume_box.vert) or a full-screen
// triangle (fullscreen.vert).
struct GiProgramPair {
    const gl::Program* box = nullptr;
    const gl::Program* screen = nullptr;
};

struct GiApplyPass::Draw {
    FrameContext& frame;
    glm::ivec2 gbufferSize, giSize;
    int divisor;
    const gl::Program* applyFullscreen;
    GiProgramPair apply, fill; // stencil only
    // Stencil, eye inside a box drawn with back faces: the raster decides the influence.
    const gl::Program* applyRaster = nullptr;
    const gl::Program* markRaster = nullptr;
    // The raster apply has no discard (no GI_DYNAMIC_SH early-out): it can be its own mark.
    bool rasterApplyMarks = false;
};

namespace {

// Stencil: the eye lies inside the box, drawn with its back faces (depth GEQUAL): a surface
// that passes lies between the eye and the box's exit along its ray, so inside the box. The
// apply then needs no influence test and the mark no shader work (see drawStencil).
bool rasterDecides(const GiVolumeRaster& r) {
    return r.cameraInside && r.backFacesInFrontOfFar && r.eyeInsideBox;
}

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
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
}

} // namespace

GiApplyPass::GiApplyPass(const GpuProbes& probes, const profile::Profile& profile,
                         bool dynamicObjects)
    : probes_(probes), profile_(profile), defines_(giShaderDefines(profile, &probes)) {
    requireRenderableTarget(profile, gl::queryCaps());
    if (profile::dynamicPixelsUnfaded(profile, dynamicObjects)) defines_["GI_DYNAMIC_UNFADED"] = "";
}

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
    const bool countInvocations = countPixels_ && invocations_.supported();
    stats_.invocationsCounted = countInvocations;
    stats_.invocationsEarlyTests = !countLate_;
    stats_.invocationsNote = !countPixels_       ? "not counted: counting is off"
                             : !countInvocations ? invocations_.unsupportedReason()
                                                 : "";
    if (countPixels_) {
        stats_.evaluations.assign(size_t(spec.width) * size_t(spec.height), 0);
        stats_.shadedBy.assign(stats_.evaluations.size(), -1);
    }

    // Stencil at full resolution, unjittered: texel = pixel, and the GI target's depth-stencil
    // is a copy of the GBuffer's (see below), whose stencil GBufferPass clears to 0.
    const bool copyDepthStencil = stencil && div == 1 && frame.giJitter == glm::ivec2(0);
    targets_.bind();
    resetState();
    glClearColor(0, 0, 0, 0); // weight 0 = no volume: the lighting falls back to its ambient
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | (stencil && !copyDepthStencil ? GL_STENCIL_BUFFER_BIT : 0u));

    gl::Defines applyDefines = defines_, fillDefines = defines_;
    if (countPixels_) applyDefines["GI_COUNT_PIXELS"] = "";
    if (countInvocations) {
        for (gl::Defines* defines : {&applyDefines, &fillDefines}) {
            (*defines)[gl::kGlslEs310Define] = "";
            (*defines)["GI_COUNT_INVOCATIONS"] = "";
        }
        // The apply writes neither depth nor stencil: early tests are what it gets without
        // the counter. The mark writes stencil after a discard: late in production too.
        if (!countLate_) applyDefines["GI_COUNT_EARLY_TESTS"] = "";
    }
    applyDefines.merge(giDebugInjectionDefines()); // test-only, normally empty
    // The technique's lookup shader (GpuTechnique.h); the stencil marks are technique-neutral.
    const std::string applyShader = probes_.technique().applyShader();
    Draw d{frame,
           {gb.width(), gb.height()},
           {spec.width, spec.height},
           div,
           &frame.programs.get("fullscreen.vert", applyShader, applyDefines),
           {},
           {}};
    std::vector<int> order = probes_.drawOrder(); // largest first
    if (stencil) {
        std::reverse(order.begin(), order.end()); // smallest first
        const auto pair = [&](const char* frag, const gl::Defines& defines) {
            return GiProgramPair{&frame.programs.get("gi_volume_box.vert", frag, defines),
                                 &frame.programs.get("fullscreen.vert", frag, defines)};
        };
        d.apply = pair(applyShader.c_str(), applyDefines);
        d.fill = pair("gi_stencil_fill.frag", fillDefines);
        gl::Defines applyRasterDefines = applyDefines, markRasterDefines = fillDefines;
        applyRasterDefines["GI_INFLUENCE_BY_RASTER"] = "";
        d.rasterApplyMarks = !applyRasterDefines.count("GI_DYNAMIC_SH");
        // The raster mark discards nothing: early tests are its production behaviour.
        if (countInvocations && !countLate_) markRasterDefines["GI_COUNT_EARLY_TESTS"] = "";
        d.applyRaster = &frame.programs.get("gi_volume_box.vert", applyShader, applyRasterDefines);
        d.markRaster = &frame.programs.get("gi_volume_box.vert", "gi_stencil_mark_raster.frag",
                                           markRasterDefines);
        // The GI target's depth: the depth of the GBuffer pixel each texel stands for.
        TimedSection section(frame.timer, "gi-depth-copy");
        if (copyDepthStencil) {
            // Texel = pixel, and both are DEPTH32F_STENCIL8: a blit copies the same depth as
            // the shader below, without running a fragment shader per pixel. Depth AND
            // stencil: Mesa copies a blit of every aspect of one format at one size as
            // memory (depth alone takes its shader blit): 1.1 ms cpu-time at 1280x720 on
            // llvmpipe against 5.2 ms, and it brings the GBuffer's stencil,
            // cleared to 0 and never written (GBufferLayout.h), so 'taken' needs no clear
            // (2.5 ms more): studies/results/2026-11-25-p3-p1.md.
            glBindFramebuffer(GL_READ_FRAMEBUFFER, gb.framebuffer().id());
            glBlitFramebuffer(0, 0, gb.width(), gb.height(), 0, 0, spec.width, spec.height,
                              GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
            targets_.bind();
        } else {
            const gl::Program& copy =
                frame.programs.get("fullscreen.vert", "gi_depth_copy.frag", {});
            setPixelUniforms(copy, frame, div);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            drawFullscreenTriangle(frame.targets);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        glDepthMask(GL_FALSE); // the volume draws only test depth
    }
    for (const gl::Program* p :
         {d.applyFullscreen, d.apply.box, d.fill.box, d.fill.screen, d.applyRaster})
        if (p) setPixelUniforms(*p, frame, div);

    std::vector<GiVolumeRaster> rasters;
    std::vector<bool> drawn;     // in the frustum, and (screenRects_) some texel of it on screen
    std::size_t lastVisible = 0; // stencil: the last volume drawn needs no mark
    for (std::size_t k = 0; k < order.size(); ++k) {
        rasters.push_back(volumeRaster(probes_.volumes()[size_t(order[k])], frame.view,
                                       d.gbufferSize, div, d.giSize));
        drawn.push_back(rasters.back().visible && (!screenRects_ || rasters.back().onScreen()));
        if (drawn.back()) lastVisible = k;
    }
    for (std::size_t k = 0; k < order.size(); ++k) {
        const int v = order[k];
        const GpuProbeVolume& vol = probes_.volumes()[size_t(v)];
        const GiVolumeRaster& r = rasters[k];
        GiVolumeStats vs;
        vs.name = vol.name;
        vs.fileIndex = vol.fileIndex;
        vs.culled = !drawn[k];
        vs.offScreen = r.visible && !drawn[k];
        const glm::ivec4 rect = screenRects_ ? r.screenRect : glm::ivec4(0, 0, d.giSize);
        for (int i = 0; i < 4; ++i)
            vs.screenRect[i] = rect[i];
        vs.cameraInside = stencil && r.cameraInside;
        vs.fillPass = stencil && drawn[k] && k != lastVisible;
        vs.fullScreen = !stencil || (r.cameraInside && !r.backFacesInFrontOfFar);
        vs.rasterInfluence = stencil && drawn[k] && rasterDecides(r);
        vs.markInApply = vs.rasterInfluence && vs.fillPass && d.rasterApplyMarks;
        stats_.volumes.push_back(vs);
        if (!drawn[k]) continue;
        if (countPixels_) {
            const GLfloat zero[4] = {0, 0, 0, 0};
            glClearBufferfv(GL_COLOR, 1, zero);
        }
        if (countInvocations) {
            invocations_.reset(2); // slot 0: the apply, slot 1: the mark
            invocations_.bind(0);
        }
        // Only texels the box can cover: the naive full-screen draw otherwise pays the depth
        // fetch and the influence test on every texel it discards (GiVolumeRaster::screenRect).
        if (screenRects_) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(r.screenRect.x, r.screenRect.y, r.screenRect.z - r.screenRect.x,
                      r.screenRect.w - r.screenRect.y);
        }
        if (stencil)
            drawStencil(d, v, r, k == lastVisible, countInvocations);
        else
            drawNaive(d, v);
        glDisable(GL_SCISSOR_TEST);
        if (countPixels_) countEvaluated(int(stats_.volumes.size()) - 1);
        if (countInvocations) {
            const std::vector<std::int64_t> n = invocations_.read();
            stats_.volumes.back().applyInvocations = n[0];
            stats_.volumes.back().markInvocations = n[1];
        }
    }

    resetState();
    probes_.unbindTextures(kFirstProbeUnit + probes_.unitsPerVolume()); // GBuffer and probes
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

// One stencil bit, 'taken'. Each visible volume, smallest first, draws one geometry - outside
// the box its front faces where the surface lies behind them (LEQUAL); inside, its back faces
// where the surface lies in front of them (GEQUAL), or a full-screen triangle when the box
// reaches past the far plane (whose clipping would lose pixels) - twice:
//   1. apply (gi_ddgi_apply.frag): where 'taken' is clear, with stencil writes off; the shader
//      discards what lies outside the influence;
//   2. mark (gi_stencil_fill.frag: depth and the influence test, no lookup, no colour): sets
//      'taken' on the pixels inside the influence, so no larger volume draws them again. The
//      largest volume, drawn last, needs no mark.
// When the eye lies inside the influence box itself (rasterDecides), both draw that box's back
// faces without the margin, and the depth test GEQUAL alone is the influence test (the
// deferred light-volume trick): the apply skips its influence test (GI_INFLUENCE_BY_RASTER),
// and the mark is an empty shader (gi_stencil_mark_raster.frag) whose tests and stencil write
// run before it - where the discarding mark ran late on every fragment of its draw. Both use
// the same raster, so they agree on every pixel; GiStencilTest still finds naive's owners and
// image exactly. Without GI_DYNAMIC_SH (whose early-out discards) the raster apply discards
// nothing at all (sky fails GEQUAL: back faces lie before the far plane), so it sets 'taken'
// itself (stencil REPLACE, tests still early) and the mark draw is skipped: on llvmpipe each
// depth/stencil-tested full-screen draw costs ~10-15 ms at 1280x720 even with an empty shader.
// Why the apply writes no stencil: a shader that may discard, drawn with stencil writes, gets
// its stencil test after the shader on drivers that cannot know the discard's outcome early
// (llvmpipe among them). The earlier scheme (a fill marking 'current', then an apply that
// INVERTed it) shaded every pixel of each box and threw most of the work away: 2.26x the
// single volume's GI time for 1.00 evaluation per pixel (issue 17). Without writes the test
// runs first and a taken pixel costs no lookup; only the cheap mark shader runs late.
// Counting (GI_COUNT_INVOCATIONS): the counter's atomic write would itself move the tests
// after the shader (llvmpipe does), so the apply's counting variant declares early tests
// (GI_COUNT_EARLY_TESTS) - what the production apply gets - and the mark's does not, being
// late-tested in production too (renderer/README.md "Invocation counter").
void GiApplyPass::drawStencil(Draw& d, int v, const GiVolumeRaster& r, bool last,
                              bool countInvocations) {
    const bool screen = r.cameraInside && !r.backFacesInFrontOfFar;
    const bool byRaster = rasterDecides(r);
    const auto draw = [&](const GiProgramPair& programs) {
        const gl::Program& prog = screen ? *programs.screen : *programs.box;
        prog.use();
        if (!screen) prog.set("u_clipFromBox", byRaster ? r.clipFromInfluence : r.clipFromBox);
        probes_.bindVolume(prog, v, kFirstProbeUnit, d.frame.view.eye, d.frame.preExposure);
        if (screen)
            drawFullscreenTriangle(d.frame.targets);
        else
            drawBox(d.frame.targets);
    };
    glEnable(GL_STENCIL_TEST);
    if (screen) {
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_CULL_FACE);
        glCullFace(r.cameraInside ? GL_FRONT : GL_BACK);
        glDepthFunc(r.cameraInside ? GL_GEQUAL : GL_LEQUAL);
    }
    glStencilFunc(GL_EQUAL, 0, kStencilTaken);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0u);
    // No discard in the raster apply (sky fails the depth test): it can set 'taken' itself,
    // with its tests and write still before the shader - one draw instead of two.
    const bool marksItself = byRaster && !last && d.rasterApplyMarks;
    if (marksItself) {
        glStencilFunc(GL_NOTEQUAL, int(kStencilTaken), kStencilTaken);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glStencilMask(kStencilTaken);
    }
    draw(byRaster ? GiProgramPair{d.applyRaster, nullptr} : d.apply);
    if (!last && !marksItself) {
        TimedSection section(d.frame.timer, "gi-fill");
        if (countInvocations) invocations_.bind(1);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glStencilFunc(GL_ALWAYS, int(kStencilTaken), kStencilTaken);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glStencilMask(kStencilTaken);
        if (byRaster) {
            d.markRaster->use();
            d.markRaster->set("u_clipFromBox", r.clipFromInfluence);
            drawBox(d.frame.targets);
        } else {
            draw(d.fill);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    glStencilMask(0xFFu);
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
