// The benchmark's view on the probes the benchmark bakes: the worst-case finder reaches full
// coverage (every pixel needs GI) on every built-in scene with `--volumes auto` placement (the
// bench's default bake), and on `rooms` with bench/volumes/rooms_nested.toml (run.sh's bake),
// where every pixel lies in at least two volumes so gi.multi_volume has work to show.
#include "support/TestEnv.h"

#include "probes/placement/AutoPlacement.h"
#include "probes/store/VolumeFile.h"
#include "scene/SceneLoader.h"
#include "views/WorstCaseView.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

TEST(BenchView, WorstCaseIsFullyCoveredWithTheBenchsAutoVolumes) {
    for (const char* name : {"cornell", "rooms", "courtyard"}) {
        SCOPED_TRACE(name);
        const scene::Scene s = scene::loadScene(name, {});
        probes::AutoPlacementRequest req; // adaptive, as bench::benchProbes bakes by default
        probes::ProbeSet set;
        set.volumes = probes::placeAutoVolumes(s, req).volumes;
        const views::WorstCase wc = views::findWorstCaseView(s, set, 320, 180);
        EXPECT_DOUBLE_EQ(wc.coverage.fraction, 1.0);
    }
}

TEST(BenchView, RoomsNestedVolumesCoverTheWorstCaseTwice) {
    const scene::Scene s = scene::loadScene("rooms", {});
    probes::ProbeSet set;
    set.volumes =
        probes::loadVolumeFile((sourceDir() / "bench/volumes/rooms_nested.toml").string()).volumes;
    ASSERT_EQ(set.volumes.size(), 3u);
    const views::WorstCase wc = views::findWorstCaseView(s, set, 320, 180);
    EXPECT_DOUBLE_EQ(wc.coverage.fraction, 1.0);
    EXPECT_GE(wc.coverage.meanOverlap, 2.0) << "every pixel: the house and a room";
    // At the run's size too (the bench searches small, then measures every variant's own size).
    const views::Coverage big = views::measureCoverage(s, set, wc.view, 512, 288);
    EXPECT_DOUBLE_EQ(big.fraction, 1.0);
}

} // namespace
} // namespace pb::test
