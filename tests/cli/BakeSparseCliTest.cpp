// Which storage `probebench bake` picks (renderer/probes/README.md "Sparse storage"):
// `--volumes auto` stores sparse (only probes at surface cells) unless --dense; auto-uniform
// and volumes files store dense unless --sparse; the two flags exclude each other; the bake
// cache tells the storages apart (the input hash), so switching re-bakes.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

nlohmann::json bakeSparseJsonOf(const CommandResult& r) {
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(r.output.substr(r.output.find('{')));
}

// A quick bake of the courtyard (open sky above walls: plenty of empty air) into `out`.
nlohmann::json bake(const std::string& volumes, const std::string& out,
                    const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{"bake", "--scene",   "courtyard", "--volumes", volumes, "--rays",
                                  "16",   "--bounces", "1",         "--json",    "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return bakeSparseJsonOf(runProbebench(args));
}

// What the written file stores (probebench memory reads it back).
nlohmann::json storedTotal(const std::string& file) {
    return bakeSparseJsonOf(runProbebench({"memory", "--probes", file, "--json"}))["total"];
}

} // namespace

TEST(BakeSparseCli, AutoStoresSparseAndDenseOptsOut) {
    const std::string f = (outputDir() / "bake_sparse_auto.pbp").string();
    fs::remove(f);
    const nlohmann::json sparse = bake("auto", f);
    EXPECT_EQ(sparse["placement"]["storage"], "sparse");
    nlohmann::json stored = storedTotal(f);
    EXPECT_LT(stored["stored_probes"].get<long long>(), stored["probes"].get<long long>())
        << "--volumes auto stored every grid probe of a scene with empty air";
    EXPECT_GT(stored["stored_probes"].get<long long>(), 0);
    EXPECT_GT(stored["indirection"].get<long long>(), 0);

    // The same command with --dense re-bakes (the cached file is the sparse one) and stores all.
    const nlohmann::json dense = bake("auto", f, {"--dense"});
    EXPECT_FALSE(dense["up_to_date"].get<bool>());
    EXPECT_NE(dense["input_hash"], sparse["input_hash"]);
    EXPECT_EQ(dense["placement"]["storage"], "dense");
    stored = storedTotal(f);
    EXPECT_EQ(stored["stored_probes"], stored["probes"]);
    EXPECT_EQ(stored["indirection"].get<long long>(), 0);
    // Both under the same default budget, which the sparse search counts in stored bytes: it
    // affords more grid probes than the dense one.
    const double budget = sparse["placement"]["budget_bytes"].get<double>();
    EXPECT_EQ(dense["placement"]["budget_bytes"].get<double>(), budget);
    EXPECT_LE(sparse["memory"]["total"]["stored_total"].get<double>(), budget);
    EXPECT_LE(stored["stored_total"].get<double>(), budget);
    EXPECT_GT(sparse["probes"].get<long long>(), dense["probes"].get<long long>());

    // Back to the default: re-baked sparse, then up to date.
    EXPECT_FALSE(bake("auto", f)["up_to_date"].get<bool>());
    const nlohmann::json again = bake("auto", f);
    EXPECT_TRUE(again["up_to_date"].get<bool>());
    EXPECT_EQ(again["input_hash"], sparse["input_hash"]);
}

TEST(BakeSparseCli, AutoUniformStoresDenseUnlessSparse) {
    const std::string f = (outputDir() / "bake_sparse_uniform.pbp").string();
    const std::vector<std::string> spacing{"--spacing", "1.5"};
    bake("auto-uniform", f, spacing);
    nlohmann::json stored = storedTotal(f);
    EXPECT_EQ(stored["stored_probes"], stored["probes"]);
    std::vector<std::string> sparse = spacing;
    sparse.push_back("--sparse");
    EXPECT_EQ(bake("auto-uniform", f, sparse)["placement"]["storage"], "sparse");
    stored = storedTotal(f);
    EXPECT_LT(stored["stored_probes"].get<long long>(), stored["probes"].get<long long>());
}

TEST(BakeSparseCli, SparseAndDenseTogetherIsAOneLineError) {
    const fs::path f = outputDir() / "bake_sparse_both.pbp";
    fs::remove(f);
    const CommandResult r =
        runProbebench({"bake", "--scene", "courtyard", "--sparse", "--dense", "--out", f.string()});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_FALSE(r.crashed);
    EXPECT_EQ(r.output.rfind("probebench: error: --dense", 0), 0u) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_FALSE(fs::exists(f));
}

// The summary tells stored, absent (not stored: no surface nearby) and invalid (inside
// geometry) probes apart: a sparse bake's invalid probes are those of the same bake stored
// dense, and the three add up, per volume and in all. A file read back splits them the same
// way from the states (an absent probe keeps its irradiance or lies outside geometry by its
// back-face ratio), and the text says how many absent probes keep a tile (ranked free space).
TEST(BakeSparseCli, SummarySplitsStoredAbsentAndInvalid) {
    const std::string f = (outputDir() / "bake_sparse_counts.pbp").string();
    fs::remove(f);
    const std::vector<std::string> dense{"--spacing", "1.5"};
    const std::vector<std::string> sparse{"--spacing", "1.5", "--sparse"};
    const nlohmann::json d = bake("auto-uniform", f, dense);
    EXPECT_EQ(d["stored_probes"], d["probes"]);
    EXPECT_EQ(d["absent_probes"], 0);
    const long long invalid = d["invalid_probes"].get<long long>();
    ASSERT_GT(invalid, 0) << "no probe inside the courtyard's walls: nothing to tell apart";

    const nlohmann::json s = bake("auto-uniform", f, sparse);
    const long long stored = s["stored_probes"].get<long long>();
    const long long absent = s["absent_probes"].get<long long>();
    EXPECT_EQ(s["invalid_probes"].get<long long>(), invalid);
    EXPECT_GT(absent, 0);
    EXPECT_EQ(stored + absent + invalid, s["probes"].get<long long>());
    long long sums[3] = {0, 0, 0};
    for (const nlohmann::json& v : s["volumes"]) {
        EXPECT_EQ(v["stored"].get<long long>() + v["absent"].get<long long>() +
                      v["invalid"].get<long long>(),
                  v["probes"].get<long long>());
        sums[0] += v["stored"].get<long long>();
        sums[1] += v["absent"].get<long long>();
        sums[2] += v["invalid"].get<long long>();
    }
    EXPECT_EQ(sums[0], stored);
    EXPECT_EQ(sums[1], absent);
    EXPECT_EQ(sums[2], invalid);

    const nlohmann::json again = bake("auto-uniform", f, sparse);
    EXPECT_TRUE(again["up_to_date"].get<bool>());
    EXPECT_EQ(again["stored_probes"].get<long long>(), stored);
    EXPECT_EQ(again["absent_probes"].get<long long>(), absent);
    EXPECT_EQ(again["invalid_probes"].get<long long>(), invalid);
    const long long tiles = s["free_space"]["irradiance_only_probes"].get<long long>();
    ASSERT_GT(tiles, 0) << "no absent probe kept a tile (ranked free space)";
    ASSERT_LT(tiles, absent) << "every absent probe kept a tile: not the ranked mix";

    auto bakeText = [&](bool force) { // the human summary
        std::vector<std::string> args{"bake",   "--scene", "courtyard", "--volumes", "auto-uniform",
                                      "--rays", "16",      "--bounces", "1",         "--out",
                                      f};
        args.insert(args.end(), sparse.begin(), sparse.end());
        if (force) args.push_back("--force");
        const CommandResult r = runProbebench(args);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return r.output;
    };
    const std::string baked = bakeText(true);
    const std::string split = std::to_string(stored) + " stored, " + std::to_string(absent) +
                              " absent (no surface nearby; " + std::to_string(tiles) +
                              " of them keep their irradiance, no visibility), " +
                              std::to_string(invalid) + " invalid (inside geometry";
    EXPECT_NE(baked.find(split), std::string::npos) << baked;
    const std::string readBack = bakeText(false);
    EXPECT_NE(readBack.find(split), std::string::npos) << readBack;
}
