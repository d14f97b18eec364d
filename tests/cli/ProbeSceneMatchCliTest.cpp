// A probe file baked for another scene is refused (issue 25, item 6): `render`, `volumes --rank`
// and `costmodel` with the rooms' probes and the default scene (cornell) used to render, rank
// and count the wrong probes and exit 0. The file's input hash decides; --force overrides.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

void expectRefused(const CommandResult& r, const fs::path& probes) {
    EXPECT_EQ(r.exitCode, 1) << r.output;
    const std::string head = "probebench: error: " + probes.string() + ": not baked for scene 'cornell'";
    EXPECT_NE(r.output.find(head), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;
}

} // namespace

TEST(ProbeSceneMatchCli, RenderRefusesAnotherScenesProbesWritingNothing) {
    const fs::path dir = outputDir();
    const fs::path probes = bakeNestedRooms(dir / "rooms.pbp");
    const fs::path out = dir / "wrong.png";
    expectRefused(runProbebench({"render", "--probes", probes.string(), "--width", "32",
                                 "--height", "24", "--out", out.string()}),
                  probes);
    EXPECT_FALSE(fs::exists(out));

    // Its own scene renders; --force renders the mismatch on purpose.
    auto own = runProbebench({"render", "--scene", "rooms", "--probes", probes.string(),
                              "--width", "32", "--height", "24", "--out", out.string()});
    EXPECT_EQ(own.exitCode, 0) << own.output;
    auto forced = runProbebench({"render", "--probes", probes.string(), "--force", "--width",
                                 "32", "--height", "24", "--out", (dir / "forced.png").string()});
    EXPECT_EQ(forced.exitCode, 0) << forced.output;
}

TEST(ProbeSceneMatchCli, VolumesRankAndCostModelRefuseToo) {
    const fs::path dir = outputDir();
    const fs::path probes = bakeNestedRooms(dir / "rooms.pbp");
    expectRefused(runProbebench({"volumes", "--probes", probes.string(), "--rank", "--width",
                                 "32", "--height", "32"}),
                  probes);
    expectRefused(runProbebench({"costmodel", "--probes", probes.string()}), probes);
    // A listing needs no scene: nothing to check against.
    EXPECT_EQ(runProbebench({"volumes", "--probes", probes.string()}).exitCode, 0);
}

TEST(ProbeSceneMatchCli, ItsOwnSceneIsAccepted) {
    // The hash is recomputed from the file's volumes, scenarios and settings: no false alarm.
    const fs::path dir = outputDir();
    const fs::path probes = bakeNestedRooms(dir / "rooms.pbp");
    // A small frame: the check is the hash, not the counters (1280x720 takes ~40 s).
    auto r = runProbebench({"costmodel", "--scene", "rooms", "--probes", probes.string(),
                            "--width", "64", "--height", "36"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
}
