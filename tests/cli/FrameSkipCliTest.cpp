// `probebench render --verbose` names every pass and resource the frame skipped, one line each,
// with why (renderer/README.md "What the frame skips"); --json carries the same list.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

const fs::path& nestedRoomsProbes() {
    static const fs::path file =
        bakeNestedRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_nested_skip_cli.pbp");
    return file;
}

std::vector<std::string> render(const fs::path& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", "--width", "64",         "--height",
                                     "36",     "--out",   out.string(), "--verbose"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

bool hasLine(const std::string& output, const std::string& line) {
    return ("\n" + output).find("\n" + line) != std::string::npos;
}

} // namespace

TEST(FrameSkipCli, VerboseListsEverySkipWithItsReason) {
    const fs::path dir = outputDir();
    auto cornell = runProbebench(render(dir / "c.png", {"--scene", "cornell"}));
    ASSERT_EQ(cornell.exitCode, 0) << cornell.output;
    EXPECT_TRUE(hasLine(cornell.output, "skipped pass shadow (no shadow map): the sun is off"))
        << cornell.output;
    EXPECT_TRUE(hasLine(cornell.output, "skipped GI passes: no probes")) << cornell.output;

    auto rooms = runProbebench(
        render(dir / "r.png", {"--scene", "rooms", "--view", "sunlit_room", "--probes",
                               nestedRoomsProbes().string(), "--set", "gi.dynamic=sh", "--set",
                               "gi.volume_lod=omit:dark_room"}));
    ASSERT_EQ(rooms.exitCode, 0) << rooms.output;
    EXPECT_FALSE(hasLine(rooms.output, "skipped pass shadow")) << "rooms has a sun";
    EXPECT_TRUE(hasLine(rooms.output, "skipped pass gi-dynamic-sh: gi.dynamic=sh but the scene "
                                      "has no dynamic objects"))
        << rooms.output;
    EXPECT_TRUE(hasLine(rooms.output, "skipped volume 'dark_room' (")) << rooms.output;
    EXPECT_NE(rooms.output.find("gi.volume_lod=omit:dark_room; never uploaded"), std::string::npos);

    // Above the house looking up: no volume in the frustum, so no GI pass this frame.
    auto sky = runProbebench(
        render(dir / "s.png", {"--scene", "rooms", "--camera", "0,30,0,0,60,0.1,60", "--probes",
                               nestedRoomsProbes().string(), "--set", "gi.resolution=half"}));
    ASSERT_EQ(sky.exitCode, 0) << sky.output;
    EXPECT_TRUE(hasLine(sky.output, "skipped passes gi-apply, upsample this frame: none of the 3 "
                                    "loaded volume(s) is in the view frustum"))
        << sky.output;
}

TEST(FrameSkipCli, JsonCarriesTheSkips) {
    const fs::path dir = outputDir();
    auto r =
        runProbebench({"render", "--scene", "rooms", "--camera", "0,30,0,0,60,0.1,60", "--width",
                       "64", "--height", "36", "--probes", nestedRoomsProbes().string(), "--out",
                       (dir / "j.png").string(), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto json = nlohmann::json::parse(r.output.substr(r.output.find("\n{") + 1));
    EXPECT_TRUE(json["gi"]["skipped_this_frame"].get<bool>());
    EXPECT_TRUE(json["gi"]["pass"].is_null());
    EXPECT_TRUE(json["skipped"].is_array());
}
