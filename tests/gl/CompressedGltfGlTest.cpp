// The compressed test files (tests/data/gltf: meshopt, Draco, quantized copies of the shared
// Cornell box, made with gltf-transform) render the same image as their uncompressed source,
// within the golden-image tolerance, from the source's default view.
#include "frame/FrameRenderer.h"
#include "gl/GlTestFixture.h"
#include "scene/SceneLoader.h"
#include "support/ImageCompare.h"
#include "support/TestEnv.h"

namespace fs = std::filesystem;
using namespace pb;

namespace {

image::Image8 renderFrom(const scene::Scene& s, const scene::View& view) {
    render::FrameRenderer renderer(s, render::defaultFrameSettings(s));
    renderer.render(render::makeRenderView(view, s.worldBounds(), 320, 180));
    return renderer.readOutput();
}

class CompressedRender : public test::GlTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(CompressedRender, MatchesTheUncompressedSource) {
    PB_REQUIRE_SHARED_SCENES();
    const fs::path file = test::testDataDir() / "gltf" / GetParam();
    ASSERT_TRUE(fs::exists(file)) << file;
    const scene::Scene source =
        scene::loadGltf((test::scenesDir() / "cornell_box" / "CornellBox-Original.gltf").string());
    const scene::Scene compressed = scene::loadGltf(file.string());
    // One camera for both: the compressed file's bounds differ by the quantization step.
    const scene::View& view = source.views.front();
    const image::Image8 expected = renderFrom(source, view);
    const image::Image8 actual = renderFrom(compressed, view);
    checkNoGlErrors("rendering");

    // The frame must show something, or any two frames would match.
    std::size_t lit = 0;
    for (std::size_t i = 0; i + 3 < expected.pixels.size(); i += 4)
        lit += expected.pixels[i] + expected.pixels[i + 1] + expected.pixels[i + 2] > 30;
    EXPECT_GT(lit, expected.pixels.size() / 4 / 4) << "the source frame is mostly black";

    const test::ImageDiff d = test::compareImages(actual, expected, test::kGoldenTolerance);
    if (!test::withinTolerance(d, test::kGoldenTolerance)) {
        const fs::path dir = test::outputDir();
        test::writeFailureImages(dir, actual, expected);
        ADD_FAILURE() << d.describe() << "; actual/expected/diff images in " << dir;
    }
}

INSTANTIATE_TEST_SUITE_P(Files, CompressedRender,
                         ::testing::Values("cornell_meshopt.glb", "cornell_draco.glb",
                                           "cornell_quantize.glb",
                                           "cornell_meshopt_separate.gltf"));

} // namespace
