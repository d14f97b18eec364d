// The bake summary's time covers the whole command (issue 17, part 4): a user saw `time: 1.17 s`
// for a bake that took 16.8 s, because the line counted the tracing only. Checked as
// bookkeeping, never as speed: the phases are disjoint intervals of one clock, so the whole is
// at least their sum, and the lattice search lies inside the placement.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

TEST(BakeTimeCli, TheTimeLineCoversTheWholeCommand) {
    const fs::path out = outputDir() / "c.probes";
    const CommandResult r = runProbebench(
        {"bake", "--scene", "cornell", "--rays", "16", "--out", out.string(), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output.substr(r.output.find('{')));
    const double all = j["command_seconds"], load = j["load_seconds"],
                 placement = j["placement_seconds"], search = j["lattice_search_seconds"],
                 bake = j["seconds"], write = j["write_seconds"];
    for (double t : {load, placement, search, bake, write})
        EXPECT_GE(t, 0.0) << j.dump();
    EXPECT_GE(all, load + placement + bake + write) << j.dump();
    EXPECT_GT(search, 0.0) << "the default auto bake searches its lattice: " << j.dump();
    EXPECT_LE(search, placement) << j.dump();

    const CommandResult text = runProbebench(
        {"bake", "--scene", "cornell", "--rays", "16", "--out", out.string(), "--force"});
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("time: "), std::string::npos) << text.output;
    EXPECT_NE(text.output.find(" s in all: scene "), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("(lattice search "), std::string::npos) << text.output;
}

// An --out whose folder does not exist is refused before the placement and the bake: a user
// waited 11 s on cornell (about 85 s on a street scene) to be told the folder was missing.
TEST(BakeTimeCli, AMissingOutputFolderIsRefusedBeforeAnyWork) {
    const fs::path missing = outputDir() / "nodir" / "x.probes";
    const CommandResult r = runProbebench({"bake", "--scene", "cornell", "--out", missing.string()});
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("folder '" + missing.parent_path().string() + "' does not exist"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("placement"), std::string::npos) << "it placed before saying so:\n" << r.output;
    EXPECT_EQ(r.output.find("baking"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(missing.parent_path()));
}
