// `bake` re-run with the same inputs: "up to date" comes from the placement cache
// (apps/PlacementCache.h) before any placement or lattice search, which print progress
// while they run (issue 25, item 10). Judged by what the bake says it did, never by time.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

// The JSON document of a command's output (progress and notes on stderr come first).
nlohmann::json bakeUpToDateJsonOf(const std::string& output) {
    return nlohmann::json::parse(output.substr(output.find('{')));
}

bool mentions(const CommandResult& r, const std::string& text) {
    return r.output.find(text) != std::string::npos;
}

std::vector<std::string> bakeUpToDateBakeArgs(const fs::path& out) {
    return {"bake", "--scene", "cornell", "--rays", "16", "--out", out.string(), "--json"};
}

} // namespace

TEST(BakeUpToDateCli, ASecondIdenticalBakeIsUpToDateWithoutPlacingOrSearching) {
    const fs::path out = outputDir() / "c.probes";
    const CommandResult first = runProbebench(bakeUpToDateBakeArgs(out));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_TRUE(mentions(first, "bake: placement 1")) << first.output;
    EXPECT_TRUE(mentions(first, "bake: lattice search 1/")) << first.output;
    const nlohmann::json j1 = bakeUpToDateJsonOf(first.output);
    EXPECT_FALSE(j1["up_to_date"].get<bool>());
    EXPECT_TRUE(j1["placed_this_run"].get<bool>());
    ASSERT_TRUE(j1["placement"].contains("lattice_search")) << j1["placement"].dump();

    const CommandResult second = runProbebench(bakeUpToDateBakeArgs(out));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_FALSE(mentions(second, "bake: placement")) << second.output;
    EXPECT_FALSE(mentions(second, "bake: lattice search")) << second.output;
    const nlohmann::json j2 = bakeUpToDateJsonOf(second.output);
    EXPECT_TRUE(j2["up_to_date"].get<bool>());
    EXPECT_FALSE(j2["placed_this_run"].get<bool>());
    // The summary is the placement the file was baked from.
    EXPECT_EQ(j2["placement"], j1["placement"]);
    EXPECT_EQ(j2["input_hash"], j1["input_hash"]);

    // The same placement with another bake setting: the cache's key matches, the bake's hash
    // does not, so it places and bakes again rather than calling the old file up to date.
    std::vector<std::string> reseeded = bakeUpToDateBakeArgs(out);
    reseeded.insert(reseeded.end(), {"--seed", "2"});
    const CommandResult third = runProbebench(reseeded);
    ASSERT_EQ(third.exitCode, 0) << third.output;
    const nlohmann::json j3 = bakeUpToDateJsonOf(third.output);
    EXPECT_FALSE(j3["up_to_date"].get<bool>());
    EXPECT_TRUE(j3["placed_this_run"].get<bool>());
    EXPECT_NE(j3["input_hash"], j1["input_hash"]);
}

TEST(BakeUpToDateCli, ACacheThatDisagreesWithTheFileIsNotTrusted) {
    const fs::path out = outputDir() / "c.probes";
    ASSERT_EQ(runProbebench(bakeUpToDateBakeArgs(out)).exitCode, 0);
    const fs::path sidecar = out.string() + ".placement.json";
    ASSERT_TRUE(fs::exists(sidecar));
    nlohmann::json cache = nlohmann::json::parse(std::ifstream(sidecar));
    cache["input_hash"] = "0123456789abcdef";
    std::ofstream(sidecar) << cache.dump(2);

    // Placed again (the hash the cache names is not the file's); the file itself still
    // matches, so up to date, and the cache is written right again.
    const CommandResult again = runProbebench(bakeUpToDateBakeArgs(out));
    ASSERT_EQ(again.exitCode, 0) << again.output;
    const nlohmann::json j = bakeUpToDateJsonOf(again.output);
    EXPECT_TRUE(j["placed_this_run"].get<bool>());
    EXPECT_TRUE(j["up_to_date"].get<bool>());
    const CommandResult last = runProbebench(bakeUpToDateBakeArgs(out));
    EXPECT_FALSE(bakeUpToDateJsonOf(last.output)["placed_this_run"].get<bool>()) << last.output;
}
