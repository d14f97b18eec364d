// Option names that mean one thing (issue 25, item 9): `probe --eye-dir` (a direction; --view
// names a view of the scene everywhere else), and `--frames` explained apart in both helps.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

TEST(OptionNamesCli, ProbeTakesEyeDirAndNamesTheRename) {
    const fs::path probes = bakeNestedRooms(outputDir() / "rooms.pbp");
    const CommandResult r = runProbebench({"probe", "--probes", probes.string(), "--at", "0,1,0",
                                           "--normal", "0,1,0", "--eye-dir", "0,0,1", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j =
        nlohmann::json::parse(r.output.substr(r.output.find('{')), nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << r.output;
    EXPECT_EQ(j["eye_dir"], nlohmann::json({0.0, 0.0, 1.0})) << j.dump();
    EXPECT_FALSE(j.contains("view"));

    const CommandResult old = runProbebench({"probe", "--probes", probes.string(), "--at",
                                             "0,1,0", "--normal", "0,1,0", "--view", "0,0,1"});
    EXPECT_EQ(old.exitCode, 2) << old.output;
    EXPECT_EQ(old.output.rfind("probebench: error: --view: unknown option of 'probe'; renamed "
                               "'--eye-dir'",
                               0),
              0u)
        << old.output;
}

TEST(OptionNamesCli, BothHelpsSayWhatFramesMeans) {
    const CommandResult render = runProbebench({"render", "--help"});
    const CommandResult bench = runProbebench({"bench", "--help"});
    ASSERT_EQ(render.exitCode, 0);
    ASSERT_EQ(bench.exitCode, 0);
    EXPECT_NE(render.output.find("not to time"), std::string::npos) << render.output;
    EXPECT_NE(render.output.find("`bench --frames` is the timed frames"), std::string::npos);
    EXPECT_NE(bench.output.find("Timed frames per variant per round"), std::string::npos);
    EXPECT_NE(bench.output.find("`render --frames` is frames to show or play"),
              std::string::npos)
        << bench.output;
}
