// The path tracer at direct-only settings (max depth 1) against the rasterizer's direct pass on
// built-in scenes, with the sky black: the rasterizer's hemispherical ambient (a quarter of the
// sky's irradiance, FrameRenderer.cpp) is then 0, and its direct pass is exactly "sun x shadow
// map + punctual lights + emission seen", which is what depth 1 computes with ray-traced
// shadows and pixel-area sampling. The remaining differences are the shadow map (its PCF edge
// and resolution) and anti-aliasing at silhouettes, hence the tolerances.
#include "GlTestFixture.h"
#include "frame/FrameRenderer.h"
#include "metrics/ImageMetrics.h"
#include "passes/RenderView.h"
#include "scene/SceneLoader.h"
#include "truth/PathTracer.h"

#include <gtest/gtest.h>

using namespace pb;

namespace {

struct DirectCase {
    const char* scene;
    const char* view;
};

void PrintTo(const DirectCase& c, std::ostream* os) { *os << c.scene << "/" << c.view; }

double meanLuminance(const image::ImageF& img) {
    double sum = 0.0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            sum += 0.2126 * img.at(x, y, 0) + 0.7152 * img.at(x, y, 1) + 0.0722 * img.at(x, y, 2);
    return sum / (double(img.width) * img.height);
}

// Both as RGB with alpha 1, so relativeMse compares like with like.
image::ImageF rgba(const image::ImageF& in) {
    image::ImageF out;
    out.width = in.width;
    out.height = in.height;
    out.channels = 4;
    out.pixels.assign(size_t(in.width) * size_t(in.height) * 4, 1.0f);
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x)
            for (int c = 0; c < 3; ++c)
                out.at(x, y, c) = in.at(x, y, c);
    return out;
}

class TruthDirect : public test::GlTest, public ::testing::WithParamInterface<DirectCase> {};

} // namespace

TEST_P(TruthDirect, DepthOneMatchesTheRasterizersDirectPass) {
    const DirectCase& c = GetParam();
    scene::Scene s = scene::makeBuiltinScene(c.scene);
    s.sky.radiance = glm::vec3(0.0f);
    const scene::View* view = s.findView(c.view);
    ASSERT_NE(view, nullptr);
    const int w = 160, h = 90;
    render::FrameRenderer renderer(s, render::defaultFrameSettings(s));
    renderer.render(render::makeRenderView(*view, s.worldBounds(), w, h));
    const image::ImageF raster = rgba(renderer.readRadiance());
    checkNoGlErrors("rendering");

    truth::TruthSettings ts;
    ts.width = w;
    ts.height = h;
    ts.spp = 16;
    ts.maxDepth = 1;
    const truth::TruthResult t = truth::renderTruth(s, *view, ts);
    const double relMse = metrics::relativeMse(t.hdr, raster);
    const double meanT = meanLuminance(t.hdr), meanR = meanLuminance(raster);
    const double flip = metrics::ldrFlip(truth::tonemap(t.hdr, s.exposure), renderer.readOutput()).mean;
    RecordProperty("relative_mse", std::to_string(relMse));
    // Stated tolerances: the mean within 5%, the relative MSE below 0.1, LDR-FLIP mean below
    // 0.06. Measured at 160x90 with the view-fitted shadow map (ShadowPass.h):
    // courtyard/courtyard 0.03%, 0.0036, 0.035; courtyard/interior 0.08%, 0.036, 0.0025;
    // rooms/sunlit_room 3.2%, 0.062, 0.006 - a small sun patch whose shadow-mapped edge is a
    // large part of it. A wrong cosine, unit or sun direction costs far more than that.
    EXPECT_NEAR(meanT / meanR, 1.0, 0.05) << "truth " << meanT << ", raster " << meanR;
    EXPECT_LT(relMse, 0.1);
    EXPECT_LT(flip, 0.06);
    std::cout << c.scene << "/" << c.view << ": mean truth " << meanT << " raster " << meanR
              << ", rel. MSE " << relMse << ", FLIP " << flip << "\n";
}

INSTANTIATE_TEST_SUITE_P(Builtin, TruthDirect,
                         ::testing::Values(DirectCase{"courtyard", "courtyard"},
                                           DirectCase{"courtyard", "interior"},
                                           DirectCase{"rooms", "sunlit_room"}),
                         [](const auto& info) {
                             return std::string(info.param.scene) + "_" + info.param.view;
                         });
