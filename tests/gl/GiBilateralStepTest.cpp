// gi.upsample=bilateral on a hand-made GBuffer: two facing planes side by side with a depth step
// between them, half-resolution GI that is red on the near plane's samples and green on the far
// plane's. Above the plane tolerance (5% of the distance) no pixel may mix the two; below it
// the filter does blend, and bilinear blends regardless - so the test can tell.
#include "gl/GlTestFixture.h"

#include "frame/Readback.h"
#include "passes/GiUpsamplePass.h"
#include "scene/SceneLoader.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pb::test {
namespace {

constexpr int kGiBilateralStepW = 64, kGiBilateralStepH = 32,
              kStepX = 37; // odd: a low-res footprint straddles the step

struct StepResult {
    int mixed = 0;     // pixels with both red and green above 1%
    int wrongSide = 0; // pixels carrying only the other plane's colour
};

class GiBilateralStepTest : public GlTest {
protected:
    // Window depth of a plane facing the camera at view distance z.
    static float windowDepth(const render::RenderView& v, float z) {
        const glm::vec4 clip = v.clipFromRel * glm::vec4(glm::vec3(v.forward) * z, 1.0f);
        return clip.z / clip.w * 0.5f + 0.5f;
    }

    StepResult run(const char* upsample, float nearZ, float farZ) {
        const scene::Scene s = scene::makeBuiltinScene("empty");
        scene::View camera;
        camera.position = {0, 0, 5};
        camera.target = {0, 0, 0};
        scene::Bounds bounds;
        bounds.extend({-10, -10, -10});
        bounds.extend({10, 10, 10});
        const render::RenderView view =
            render::makeRenderView(camera, bounds, kGiBilateralStepW, kGiBilateralStepH);
        render::GpuScene gpu(s);
        render::FrameSettings settings;
        gl::ProgramCache programs;
        render::FrameTargets targets(kGiBilateralStepW, kGiBilateralStepH);
        const gl::DriverQuirks quirks = gl::detectDriverQuirks();

        // GBuffer: normal +Z (octahedral (0,0)) everywhere, flags 0, depth per side.
        targets.gbuffer.framebuffer().bind();
        const float normal[4] = {0, 0, 0, 0}, zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 1, normal);
        glClearBufferfv(GL_COLOR, 3, zero);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, kStepX, kGiBilateralStepH);
        glClearBufferfi(GL_DEPTH_STENCIL, 0, windowDepth(view, nearZ), 0);
        glScissor(kStepX, 0, kGiBilateralStepW - kStepX, kGiBilateralStepH);
        glClearBufferfi(GL_DEPTH_STENCIL, 0, windowDepth(view, farZ), 0);
        glDisable(GL_SCISSOR_TEST);

        profile::Profile p;
        p.set("gi.resolution", "half");
        p.set("gi.upsample", upsample);
        render::GiUpsamplePass pass(p);
        render::FrameContext ctx{gpu, view, settings, programs, targets, quirks, {}, {}, nullptr};
        pass.beginFrame(view, ctx);
        // Low-res texel i was evaluated at GBuffer column i * 2 + jitter.
        gl::TextureDesc d;
        d.format = gl::TextureFormat::RGBA16F;
        d.width = kGiBilateralStepW / 2;
        d.height = kGiBilateralStepH / 2;
        gl::Texture low(d);
        std::vector<float> texels;
        for (int y = 0; y < d.height; ++y)
            for (int x = 0; x < d.width; ++x) {
                const bool nearSide = x * 2 + ctx.giJitter.x < kStepX;
                texels.insert(texels.end(), {nearSide ? 1.0f : 0.0f, nearSide ? 0.0f : 1.0f, 0, 1});
            }
        low.upload(texels.data());
        ctx.gi.enabled = true;
        ctx.gi.irradiance = &low;
        pass.execute(ctx);
        const image::ImageF out = render::readFloat(*ctx.gi.irradiance);

        StepResult r;
        for (int y = 0; y < kGiBilateralStepH; ++y)
            for (int x = 0; x < kGiBilateralStepW; ++x) {
                const float red = out.at(x, y, 0), green = out.at(x, y, 1);
                r.mixed += red > 0.01f && green > 0.01f;
                r.wrongSide += x < kStepX ? red < 0.01f : green < 0.01f;
            }
        return r;
    }
};

TEST_F(GiBilateralStepTest, NeverBlendsAcrossAStepBeyondTheTolerance) {
    // 2.0 -> 2.5: a 25% step (tolerance 5% of the distance).
    StepResult r = run("bilateral", 2.0f, 2.5f);
    EXPECT_EQ(r.mixed, 0);
    EXPECT_EQ(r.wrongSide, 0);
    // Control: bilinear mixes the two along the step on every row.
    r = run("bilinear", 2.0f, 2.5f);
    EXPECT_GE(r.mixed, kGiBilateralStepH);
}

TEST_F(GiBilateralStepTest, BlendsAStepWithinTheTolerance) {
    // 2.0 -> 2.02: 1%, within the tolerance: one surface as far as the filter is concerned.
    const StepResult r = run("bilateral", 2.0f, 2.02f);
    EXPECT_GE(r.mixed, kGiBilateralStepH);
}

} // namespace
} // namespace pb::test
