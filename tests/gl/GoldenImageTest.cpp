// Golden images of the built-in scenes: render in-process on EGL and compare with
// tests/golden/<scene>_<view>.png. On failure actual/expected/diff PNGs land in
// build/test-output/<test>/. To accept new goldens after an intended change:
//   PB_UPDATE_GOLDENS=1 build/tests/gl_tests --gtest_filter='Golden*'
// (then look at the images and commit them; tests/README.md).
#include "frame/FrameRenderer.h"
#include "gl/GlTestFixture.h"
#include "gl/GoldenCheck.h"
#include "scene/SceneLoader.h"
#include "support/ImageCompare.h"
#include "support/TestEnv.h"

#include <cstdlib>
#include <tuple>

namespace fs = std::filesystem;
using namespace pb;

namespace {

struct GoldenCase {
    const char* scene;
    const char* view;
};
[[maybe_unused]] void PrintTo(const GoldenCase& c, std::ostream* os) {
    *os << c.scene << "/" << c.view;
}

using test::kGoldenTolerance; // support/ImageCompare.h

class Golden : public test::GlTest, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(Golden, MatchesReference) {
    const GoldenCase& c = GetParam();
    scene::Scene s = scene::makeBuiltinScene(c.scene);
    const scene::View* view = s.findView(c.view);
    ASSERT_NE(view, nullptr) << "scene " << c.scene << " lost its view " << c.view;
    render::FrameRenderer renderer(s, render::defaultFrameSettings(s));
    renderer.render(render::makeRenderView(*view, s.worldBounds(), 320, 180));
    image::Image8 actual = renderer.readOutput();
    checkNoGlErrors("rendering");

    fs::path golden = test::goldenDir() / (std::string(c.scene) + "_" + c.view + ".png");
    if (test::updateOrCompareGolden(actual, golden)) GTEST_SKIP() << "golden written: " << golden;
}

INSTANTIATE_TEST_SUITE_P(Builtin, Golden,
                         // cornell is lit by its emissive panel alone: without GI only
                         // the panel shows, so its one golden is the view that sees it.
                         ::testing::Values(GoldenCase{"cornell", "front"},
                                           GoldenCase{"rooms", "sunlit_room"},
                                           GoldenCase{"rooms", "doorway"},
                                           GoldenCase{"courtyard", "default"},
                                           GoldenCase{"courtyard", "interior"},
                                           GoldenCase{"rooms_dynamic", "dynamic"}),
                         [](const auto& info) {
                             return std::string(info.param.scene) + "_" + info.param.view;
                         });

} // namespace
