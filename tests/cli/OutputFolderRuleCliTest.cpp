// One rule for every command that writes a file (apps/OutputPaths.h prepareOutputParent, issue
// 42 item 5): a missing parent folder is refused before any work, naming the folder, unless
// --mkdir asks for it; then it is created. bench --html and truth --out-hdr used to create the
// folder silently while render refused; every other command's --json failed only when writing.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

struct Case {
    const char* name;
    std::vector<std::string> args; // the command; the output option and path are appended
    const char* option;
    const char* file;
};

std::vector<Case> cases() {
    return {{"bake", {"bake", "--scene", "cornell", "--rays", "8"}, "--out", "x.probes"},
            {"bake_json", {"bake", "--scene", "cornell", "--rays", "8", "--out", "ignored.probes"},
             "--json", "x.json"},
            {"bench", {"bench", "--scene", "cornell", "--rounds", "1"}, "--html", "b.html"},
            {"truth", {"truth", "--scene", "cornell", "--spp", "1", "--width", "8", "--height", "6"},
             "--out-hdr", "t.pfm"},
            {"render", {"render", "--scene", "cornell"}, "--out", "r.png"},
            // Every --json FILE (JsonOption.h): checked once the line is parsed; commands
            // without outputs of their own get --mkdir with it.
            {"profiles_json", {"profiles"}, "--json", "p.json"},
            {"stress_json", {"stress", "--scene", "cornell"}, "--json", "s.json"},
            // The other commands' own outputs: refused before reading any input (the inputs
            // named here do not exist, so any work would fail on them first).
            {"tune", {"tune", "--scene", "cornell", "--budget-ms", "10", "--budget-mib", "64", "--probes", "none.probes"},
             "--out", "t.toml"},
            {"respond", {"respond", "--scene", "cornell", "--probes", "none.probes"}, "--out-dir", "r"},
            {"compare", {"compare", "--test", "none.png", "--reference", "none.png"}, "--heatmap", "h.png"},
            {"sweep", {"sweep", "--plan", "none.toml"}, "--out", "s"},
            {"bake_merge", {"bake-merge", "none.part"}, "--out", "m.probes"}};
}

} // namespace

TEST(OutputFolderRuleCli, EveryCommandRefusesAMissingFolderBeforeAnyWork) {
    for (const Case& c : cases()) {
        const fs::path missing = outputDir() / (std::string("nodir_") + c.name) / c.file;
        std::vector<std::string> args = c.args;
        args.insert(args.end(), {c.option, missing.string()});
        const CommandResult r = runProbebench(args);
        EXPECT_EQ(r.exitCode, 1) << c.name << ": " << r.output;
        EXPECT_NE(r.output.find(std::string(c.option) + ": '" + missing.string() + "': folder '" +
                                missing.parent_path().string() +
                                "' does not exist (--mkdir creates it)"),
                  std::string::npos)
            << c.name << ": " << r.output;
        // Before any work: nothing placed, baked, traced or rendered, and no folder made.
        for (const char* work : {"placement", "baking", "pass 1", "spp", "wrote"})
            EXPECT_EQ(r.output.find(work), std::string::npos)
                << c.name << " worked before refusing (" << work << "):\n" << r.output;
        EXPECT_FALSE(fs::exists(missing.parent_path())) << c.name;
    }
}

TEST(OutputFolderRuleCli, MkdirCreatesTheJsonFolderOfACommandWithoutOtherOutputs) {
    const fs::path made = outputDir() / "made_by_profiles" / "p.json";
    fs::remove_all(outputDir() / "made_by_profiles");
    const CommandResult r = runProbebench({"profiles", "--json", made.string(), "--mkdir"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(made)) << r.output;
}

TEST(OutputFolderRuleCli, MkdirCreatesTheFolder) {
    const fs::path made = outputDir() / "made_by_truth" / "deeper" / "t.pfm";
    fs::remove_all(outputDir() / "made_by_truth");
    const CommandResult r =
        runProbebench({"truth", "--scene", "cornell", "--spp", "1", "--width", "8", "--height", "6",
                       "--cache-dir", (outputDir() / "truth-cache").string(), "--out-hdr",
                       made.string(), "--mkdir"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(made)) << r.output;
}
