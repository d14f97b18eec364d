// Issue 20: re-uploading only the changed probes' tiles (passes/ProbeTileUpload.h) gives the
// GPU exactly what a full upload of the changed probe set gives, and counts its bytes.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/FrameRenderer.h"
#include "passes/ProbeTileUpload.h"
#include "probes/ProbeLayout.h"
#include "probes/StorageFormat.h"

#include <cstring>

namespace pb::test {
namespace {

class ProbeTileUploadTest : public GlTest {};

image::ImageF renderWith(render::FrameRenderer& r) {
    const scene::Scene& s = giTestScene();
    r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 96, 54));
    return r.readRadiance();
}

std::unique_ptr<render::FrameRenderer> rendererFor(const probes::ProbeSet& set) {
    render::GiOptions gi;
    gi.probes = &set;
    const scene::Scene& s = giTestScene();
    return std::make_unique<render::FrameRenderer>(s, render::defaultFrameSettings(s), gi);
}

TEST_F(ProbeTileUploadTest, TileUploadsEqualAFullUploadOfTheChangedSet) {
    for (probes::StorageFormat f :
         {probes::StorageFormat::Rgba16f, probes::StorageFormat::Rgba32f}) {
        probes::ProbeSet set = giTestProbes(f);
        auto renderer = rendererFor(set);
        const image::ImageF before = renderWith(*renderer);

        // Halve every third probe of the root volume (its whole tile, border included).
        std::vector<render::ProbeTile> tiles;
        probes::ProbeTexture& tex = set.irradiance[0][0];
        const float scaleBefore = tex.storageScale;
        for (int p = 0; p < set.volumes[0].probeCount(); p += 3) {
            const glm::ivec3 c = set.volumes[0].probeCoords(p);
            for (int row = 0; row < probes::kIrradianceTile; ++row)
                for (int col = 0; col < probes::kIrradianceTile; ++col) {
                    float* t = tex.at(c.x * probes::kIrradianceTile + col,
                                      c.z * probes::kIrradianceTile + row, c.y);
                    for (int ch = 0; ch < 3; ++ch)
                        t[ch] *= 0.5f;
                }
            tiles.push_back({0, p});
        }
        const std::size_t bytes = render::uploadProbeTiles(*renderer->gpuProbes(), set, 0, tiles);
        const std::size_t texel = f == probes::StorageFormat::Rgba16f ? 8 : 16;
        EXPECT_EQ(bytes, tiles.size() * 64 * texel);
        const image::ImageF updated = renderWith(*renderer);

        // The same set uploaded in full by a fresh renderer.
        probes::quantise(tex, f);
        ASSERT_EQ(tex.storageScale, scaleBefore) << "the test needs the same storage scale";
        auto fresh = rendererFor(set);
        const image::ImageF full = renderWith(*fresh);
        ASSERT_EQ(updated.pixels.size(), full.pixels.size());
        EXPECT_EQ(0, std::memcmp(updated.pixels.data(), full.pixels.data(),
                                 full.pixels.size() * sizeof(float)))
            << probes::formatName(f);
        EXPECT_NE(0, std::memcmp(updated.pixels.data(), before.pixels.data(),
                                 full.pixels.size() * sizeof(float)))
            << "the change must be visible";
    }
}

} // namespace
} // namespace pb::test
