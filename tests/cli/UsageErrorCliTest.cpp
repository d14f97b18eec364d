// Parse errors in the README's error contract: one line `probebench: error: <option>: <problem>`,
// exit 2 (usage), for every command; "did you mean" for names; --version.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

// The whole output is exactly one line that starts `probebench: error: <subject>: `.
void expectUsageError(const std::vector<std::string>& args, const std::string& subject,
                      const std::string& problem) {
    const CommandResult r = runProbebench(args);
    std::string shown;
    for (const auto& a : args)
        shown += a + " ";
    EXPECT_EQ(r.exitCode, 2) << shown << "\n" << r.output;
    const std::string head = "probebench: error: " + subject + ": ";
    EXPECT_EQ(r.output.rfind(head, 0), 0u) << shown << "\n" << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << shown << " not one line:\n" << r.output;
    EXPECT_NE(r.output.find(problem), std::string::npos) << shown << "\n" << r.output;
}

TEST(UsageErrorCli, ValueThatDoesNotParse) {
    expectUsageError({"render", "--width", "abc"}, "--width", "'abc' is not an integer");
    expectUsageError({"render", "--width"}, "--width", "needs a value");
    expectUsageError({"bench", "--rounds", "x"}, "--rounds", "'x'");
}

TEST(UsageErrorCli, UnknownCommandSuggestsTheClosest) {
    expectUsageError({"rendr"}, "rendr", "unknown command; did you mean 'render'?");
    expectUsageError({}, "command", "missing (commands: info,");
}

TEST(UsageErrorCli, UnknownOptionComesFirstAndSuggests) {
    // CLI11 used to report the missing --baseline (exit 106) rather than the typo.
    expectUsageError({"gate", "--quik"}, "--quik", "unknown option of 'gate'; did you mean '--quick'?");
    expectUsageError({"render", "--out", "x.png", "--widht", "8"}, "--widht", "did you mean '--width'?");
    expectUsageError({"--verbose", "render"}, "--verbose", "unknown option");
}

TEST(UsageErrorCli, RangeIsASentenceNotThreeHundredDigits) {
    const CommandResult r = runProbebench({"compare", "--ppd", "0", "--test", "a.png",
                                           "--reference", "b.png"});
    expectUsageError({"compare", "--ppd", "0", "--test", "a.png", "--reference", "b.png"},
                     "--ppd", "'0' must be more than 0");
    EXPECT_LT(r.output.size(), 120u) << r.output;
    expectUsageError({"info", "--device", "-1"}, "--device", "must be 0 or more");
}

// A value that parses but is out of range or not one of its choices is a usage error too (issue
// 42: `--width 0` and `--set gi.resolution=halve` exited 1 while the README said 2).
TEST(UsageErrorCli, ValueOutOfRangeOrNotAChoice) {
    const std::string out = (outputDir() / "never.png").string();
    const CommandResult width =
        runProbebench({"render", "--scene", "cornell", "--width", "0", "--out", out});
    EXPECT_EQ(width.exitCode, 2) << width.output;
    EXPECT_EQ(width.output, "probebench: error: --width/--height must be in 1..16384\n");
    expectUsageError({"render", "--scene", "cornell", "--set", "gi.resolution=halve", "--out", out},
                     "--set gi.resolution=halve", "allowed values: full, half, quarter");
    expectUsageError({"bake", "--scene", "cornell", "--free-space", "some", "--out", out},
                     "--free-space", "'some' is not one of stand-ins, ranked, all");
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(UsageErrorCli, MissingRequiredAndChoices) {
    expectUsageError({"compare", "--test", "a.png"}, "--reference", "required by 'compare'");
    expectUsageError({"info", "--platform", "eggl"}, "--platform",
                     "is not one of egl, osmesa, glfw; did you mean 'egl'?");
    expectUsageError({"render", "--out", "x.png", "stray"}, "stray", "unexpected argument");
}

TEST(UsageErrorCli, HelpStillExitsZero) {
    const CommandResult r = runProbebench({"render", "--help"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("--width"), std::string::npos);
}

TEST(UsageErrorCli, VersionNamesCommitBuildEmbreeAndMesa) {
    const CommandResult r = runProbebench({"--version"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* field : {"probebench ", "build type: ", "embree: ", "mesa: ", "GL in use: "})
        EXPECT_NE(r.output.find(field), std::string::npos) << field << " in:\n" << r.output;
    EXPECT_EQ(r.output.find("unknown (not built from a git checkout)"), std::string::npos)
        << r.output; // the tests run in a checkout
}

// Names the user types: one edit off gets a suggestion (exit 1: a valid option, a wrong name).
TEST(UsageErrorCli, DidYouMeanForSceneViewProfileSwitch) {
    const std::string out = (outputDir() / "x.png").string();
    struct Case { std::vector<std::string> args; std::string expected; };
    const std::vector<Case> cases{
        {{"render", "--scene", "rooom", "--out", out}, "did you mean 'rooms'?"},
        {{"render", "--scene", "rooms", "--view", "doorwy", "--out", out}, "did you mean 'doorway'?"},
        {{"render", "--profile", "handheldd", "--out", out}, "did you mean 'handheld'?"},
        {{"render", "--set", "gi.resolutoin=half", "--out", out}, "did you mean 'gi.resolution'?"},
    };
    for (const Case& c : cases) {
        const CommandResult r = runProbebench(c.args);
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_EQ(r.output.rfind("probebench: error: ", 0), 0u) << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
    }
}

} // namespace
} // namespace pb::test
