// Each volume's GI draws are scissored to its box's rectangle on the target, and a volume whose
// box misses the frustum (though the corner test keeps it) is skipped (GiVolumeRaster::
// screenRect). Against the unscissored path (GiApplyPass::setScreenRects(false)), on the three
// nested volumes (GiNestedVolumes.h) from every camera, naive and stencil, at every
// gi.resolution: the same GI target bit for bit, every texel shaded by the same volume, no
// volume that shades a texel is skipped, and every texel a volume shades lies in its rectangle.
// The doorway camera (the eye on the middle box's face, looking away from it, as rooms'
// worst-case view) is the skip's case: the corner test keeps that box, its rectangle is empty.
#include "gl/GiNestedVolumes.h"
#include "gl/GlTestFixture.h"

#include "frame/Readback.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace pb::test {
namespace {

constexpr int kGiScreenRectW = 160, kGiScreenRectH = 90;

struct GiFrame {
    image::ImageF gi;
    render::GiPassStats stats;
};

GiFrame renderNested(const scene::View& view, const std::string& multiVolume,
                     const std::string& resolution, bool screenRects) {
    const scene::Scene& s = giTestScene();
    render::GiOptions gi;
    gi.probes = &nestedVolumeProbes();
    gi.profile.applyOverride("gi.target_format=rgba32f");
    gi.profile.applyOverride("gi.multi_volume=" + multiVolume);
    gi.profile.applyOverride("gi.resolution=" + resolution);
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    render::GiApplyPass* pass = r.giApplyPass();
    pass->setCountPixels(true);
    pass->setScreenRects(screenRects);
    r.render(render::makeRenderView(view, s.worldBounds(), kGiScreenRectW, kGiScreenRectH));
    return {render::readFloat(*pass->target()), pass->stats()};
}

const render::GiVolumeStats& byName(const render::GiPassStats& s, const std::string& name) {
    for (const auto& v : s.volumes)
        if (v.name == name) return v;
    ADD_FAILURE() << "no volume " << name;
    return s.volumes.front();
}

std::vector<NestedCamera> cameras() {
    std::vector<NestedCamera> c = nestedCameras();
    // In the doorway on the partition plane x = 0, the middle box's face, looking into the
    // dark room and a little up: the whole frustum lies at x > 0, the middle box at x <= 0.
    c.push_back({"doorway", {"doorway", {0.0f, 0.7f, 0.0f}, {3.0f, 1.5f, 0.0f}, 60.0f}, "", ""});
    return c;
}

class GiScreenRectTest : public GlTest {};

TEST_F(GiScreenRectTest, ScissoredAndSkippedDrawsChangeNoTexel) {
    int skipped = 0, scissored = 0;
    for (const NestedCamera& cam : cameras())
        for (const char* mv : {"naive", "stencil"})
            for (const char* res : {"full", "half", "quarter"}) {
                SCOPED_TRACE(std::string(cam.name) + ", " + mv + ", gi.resolution=" + res);
                const GiFrame all = renderNested(cam.view, mv, res, false);
                const GiFrame rect = renderNested(cam.view, mv, res, true);
                ASSERT_EQ(all.stats.shadedBy.size(), rect.stats.shadedBy.size());
                EXPECT_EQ(all.gi.pixels, rect.gi.pixels) << "the scissor changed a texel";
                EXPECT_EQ(all.stats.shadedBy, rect.stats.shadedBy);
                EXPECT_EQ(all.stats.evaluations, rect.stats.evaluations);
                const int w = rect.stats.width;
                for (const render::GiVolumeStats& a : all.stats.volumes) {
                    const render::GiVolumeStats& b = byName(rect.stats, a.name);
                    // A volume that shades a texel is never skipped.
                    if (a.evaluatedPixels > 0) {
                        EXPECT_FALSE(b.culled) << a.name;
                    }
                    // -1: not drawn, so not counted.
                    EXPECT_EQ(std::max<std::int64_t>(a.evaluatedPixels, 0),
                              std::max<std::int64_t>(b.evaluatedPixels, 0))
                        << a.name;
                    skipped += b.offScreen;
                    EXPECT_EQ(b.offScreen, !a.culled && b.culled) << a.name;
                    if (b.culled) continue;
                    const int* rc = b.screenRect;
                    scissored += (rc[2] - rc[0]) * (rc[3] - rc[1]) < w * rect.stats.height;
                    // Every texel the unscissored draw shaded lies in the rectangle.
                    int outside = 0;
                    for (size_t i = 0; i < all.stats.shadedBy.size(); ++i) {
                        if (all.stats.shadedBy[i] < 0 ||
                            all.stats.volumes[size_t(all.stats.shadedBy[i])].name != a.name)
                            continue;
                        const int x = int(i) % w, y = int(i) / w;
                        outside += x < rc[0] || x >= rc[2] || y < rc[1] || y >= rc[3];
                    }
                    EXPECT_EQ(outside, 0) << a.name << ": shaded texels outside its rectangle";
                }
                if (std::string(cam.name) == "doorway") {
                    // The skip's case: the middle box is kept by the corner test, off screen.
                    EXPECT_FALSE(byName(all.stats, "sunlit_room").culled);
                    EXPECT_TRUE(byName(rect.stats, "sunlit_room").offScreen);
                    EXPECT_GT(byName(rect.stats, "building").evaluatedPixels, 0);
                }
            }
    std::printf("[ rect ] %d volume draw(s) skipped off screen, %d scissored below the target\n",
                skipped, scissored);
    EXPECT_GT(scissored, 0) << "no draw was scissored: the cameras test little";
}

} // namespace
} // namespace pb::test
