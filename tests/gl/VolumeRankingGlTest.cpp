// The volume ranking's loss (CPU rays + CPU sampler, costmodel/VolumeRanking.h) against the
// same quantity rendered: the relative MSE of the GI irradiance the lighting applies (the
// bench's irradiance-only scene) with the volume omitted, on the GPU. Synthetic probes over
// `rooms` (a root over the house, a brighter child over the sunlit room, a child over the dark
// room), viewed from inside the sunlit room where no surface lies on a box face (on such a
// surface the shading volume flips with the last bit of the position, on the CPU and GPU alike).
#include "gl/GiSyntheticProbes.h"
#include "gl/GlTestFixture.h"

#include "bench/runner/IrradianceScene.h"
#include "costmodel/VolumeRanking.h"
#include "frame/FrameRenderer.h"
#include "metrics/ImageMetrics.h"
#include "scene/SceneLoader.h"

namespace pb::test {
namespace {

using VolumeRankingGlTest = GlTest;

TEST_F(VolumeRankingGlTest, CpuLossMatchesTheRenderedIrradianceError) {
    const scene::Scene s = scene::makeBuiltinScene("rooms");
    const probes::ProbeSet set = syntheticProbes(
        {syntheticVolume("house", {0.0f, 1.3f, 0.0f}, {4.3f, 1.6f, 2.8f}, {9, 4, 6}),
         syntheticVolume("dark", {2.075f, 1.3f, 0.0f}, {2.025f, 1.35f, 2.55f}, {5, 4, 6}, "house"),
         syntheticVolume("sunlit", {-2.025f, 1.3f, 0.0f}, {2.05f, 1.35f, 2.55f}, {5, 4, 6},
                         "house")},
        [](int v, const glm::vec3& d, const glm::ivec3& c) {
            // Varies with direction and probe, so omitting a volume changes every pixel it shades.
            const float k = v == 2 ? 3.0f : 1.0f;
            return k * glm::vec3(1.0f + 0.5f * d.y, 1.0f + 0.1f * float(c.x), 0.8f + 0.3f * d.x);
        },
        probes::StorageFormat::Rgba32f);
    const scene::View view{"west", {-1.0f, 1.4f, 0.8f}, {-4.0f, 1.1f, -0.3f}, 60.0f};
    const int w = 96, h = 54;
    const render::FrameSettings settings = render::defaultFrameSettings(s);

    costmodel::RankingInputs in;
    in.scene = &s;
    in.probes = &set;
    in.views = {view};
    in.width = w;
    in.height = h;
    in.ambientUp = settings.ambientUp;
    in.ambientDown = settings.ambientDown;
    const probes::VolumeRanks ranks = costmodel::rankVolumes(in);

    const scene::Scene white = bench::irradianceOnlyScene(s);
    auto irradiance = [&](const std::string& lod) {
        render::GiOptions o;
        o.probes = &set;
        o.profile.set("gi.target_format", "rgba32f");
        o.profile.set("gi.volume_lod", lod);
        render::FrameRenderer r(white, settings, o);
        r.render(render::makeRenderView(view, white.worldBounds(), w, h));
        return r.readRadiance(); // x pi on both sides cancels in the relative MSE
    };
    const image::ImageF all = irradiance("all");
    for (size_t v : {size_t(1), size_t(2)}) {
        SCOPED_TRACE(set.volumes[v].name);
        const double rendered =
            metrics::relativeMse(irradiance("omit:" + set.volumes[v].name), all);
        EXPECT_NEAR(ranks.volumes[v].loss, rendered, 0.01 * rendered + 1e-6);
    }
    EXPECT_EQ(ranks.volumes[1].loss, 0.0) << "the dark room is behind the camera";
    EXPECT_GT(ranks.volumes[2].loss, 0.05);
}

} // namespace
} // namespace pb::test
