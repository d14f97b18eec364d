// `probebench bake --volumes auto|auto-uniform [--probe-budget-mib X] [--write-volumes F]`:
// the placement as a user sees it - deterministic files, the write/read round trip (same
// bake input hash), the budget, sparse candidates in the memory report, one-line errors.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The JSON document of a command's output (notes on stderr come first, one per line).
nlohmann::json jsonOf(const std::string& output) {
    return nlohmann::json::parse(output.substr(output.find('{')));
}

void expectOneLineError(const CommandResult& r, const std::string& mentions) {
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_FALSE(r.crashed);
    std::string text = r.output;
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    EXPECT_EQ(text.find('\n'), std::string::npos) << "not one line:\n" << r.output;
    EXPECT_NE(text.find(mentions), std::string::npos) << r.output;
}

} // namespace

TEST(BakePlacementCli, WritesTheSameVolumesFileEveryTimeAndReadsItBack) {
    fs::path dir = outputDir();
    fs::path a = dir / "a.toml", b = dir / "b.toml", c = dir / "c.toml";
    auto r1 = runProbebench(
        {"bake", "--scene", "courtyard", "--spacing", "0.8", "--write-volumes", a.string()});
    ASSERT_EQ(r1.exitCode, 0) << r1.output;
    EXPECT_NE(r1.output.find("placement: adaptive"), std::string::npos) << r1.output;
    auto r2 = runProbebench(
        {"bake", "--scene", "courtyard", "--spacing", "0.8", "--write-volumes", b.string()});
    ASSERT_EQ(r2.exitCode, 0) << r2.output;
    const std::string text = readText(a);
    EXPECT_EQ(text, readText(b)) << "auto placement must be deterministic";
    EXPECT_NE(text.find("parent = \"auto\""), std::string::npos) << text;
    // Read back and written again: byte-identical.
    auto r3 = runProbebench(
        {"bake", "--scene", "courtyard", "--volumes", a.string(), "--write-volumes", c.string()});
    ASSERT_EQ(r3.exitCode, 0) << r3.output;
    EXPECT_EQ(text, readText(c));
    EXPECT_FALSE(fs::exists(dir / "none.pbp"));
}

TEST(BakePlacementCli, FileRoundTripBakesTheIdenticalPlacement) {
    fs::path dir = outputDir();
    fs::path toml = dir / "placed.toml";
    const std::vector<std::string> cheap{"--rays", "8", "--bounces", "1", "--json", "--force"};
    auto bakeAuto = std::vector<std::string>{"bake",        "--scene", "courtyard",
                                             "--spacing",   "0.8",     "--write-volumes",
                                             toml.string(), "--out",   (dir / "a.pbp").string()};
    bakeAuto.insert(bakeAuto.end(), cheap.begin(), cheap.end());
    auto r1 = runProbebench(bakeAuto);
    ASSERT_EQ(r1.exitCode, 0) << r1.output;
    auto bakeFile = std::vector<std::string>{"bake",
                                             "--scene",
                                             "courtyard",
                                             "--volumes",
                                             toml.string(),
                                             "--out",
                                             (dir / "b.pbp").string(),
                                             "--sparse"}; // as --volumes auto stores
    bakeFile.insert(bakeFile.end(), cheap.begin(), cheap.end());
    auto r2 = runProbebench(bakeFile);
    ASSERT_EQ(r2.exitCode, 0) << r2.output;
    auto j1 = jsonOf(r1.output), j2 = jsonOf(r2.output);
    EXPECT_EQ(j1["input_hash"], j2["input_hash"]) << "the volumes file is the same placement";
    EXPECT_EQ(j1["volumes"].size(), j2["volumes"].size());
    EXPECT_EQ(j1["placement"]["mode"], "adaptive");
    EXPECT_EQ(j2["placement"]["mode"], "file");
    EXPECT_GT(j1["volumes"].size(), 1u);
}

TEST(BakePlacementCli, BudgetIsRespectedAndSaid) {
    const fs::path dir = outputDir();
    fs::path toml = dir / "budget.toml";
    for (const char* mode : {"auto", "auto-uniform"}) {
        auto r = runProbebench({"bake", "--scene", "courtyard", "--volumes", mode, "--spacing",
                                "0.4", "--probe-budget-mib", "0.5", "--format", "bc6h",
                                "--write-volumes", toml.string(), "--json"});
        ASSERT_EQ(r.exitCode, 0) << r.output;
        auto j = jsonOf(r.output)["placement"];
        EXPECT_LE(j["bytes"].get<double>(), 0.5 * 1024 * 1024) << mode;
        EXPECT_EQ(j["format"], "bc6h");
        EXPECT_NE(r.output.find("note: "), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("--probe-budget-mib 0.5"), std::string::npos) << r.output;
    }
    // A volumes file over the budget is an error, not silently baked.
    auto over = runProbebench({"bake", "--scene", "courtyard", "--volumes", toml.string(),
                               "--probe-budget-mib", "0.01", "--out", (dir / "x.pbp").string()});
    expectOneLineError(over, "--probe-budget-mib");
    EXPECT_FALSE(fs::exists(dir / "x.pbp"));
}

TEST(BakePlacementCli, MemoryReportCountsSparseCandidates) {
    fs::path dir = outputDir();
    fs::path pbp = dir / "uniform.pbp";
    auto bake = runProbebench({"bake", "--scene", "courtyard", "--volumes", "auto-uniform",
                               "--rays", "16", "--bounces", "1", "--out", pbp.string()});
    ASSERT_EQ(bake.exitCode, 0) << bake.output;
    EXPECT_NE(bake.output.find("sparse-storage candidates:"), std::string::npos) << bake.output;
    auto mem = runProbebench({"memory", "--probes", pbp.string(), "--json"});
    ASSERT_EQ(mem.exitCode, 0) << mem.output;
    auto t = jsonOf(mem.output)["total"];
    auto far = t["sparse_candidates"]["far_from_surfaces"].get<std::size_t>();
    auto probes = t["probes"].get<std::size_t>();
    // The courtyard's uniform grid reaches far above its walls: some probes see nothing.
    EXPECT_GT(far, 0u);
    EXPECT_LT(far, probes);
    EXPECT_EQ(t["sparse_candidates"]["needed"].get<std::size_t>(),
              probes - far - t["sparse_candidates"]["invalid"].get<std::size_t>());
    auto text = runProbebench({"memory", "--probes", pbp.string()});
    EXPECT_NE(text.output.find("far from every surface"), std::string::npos) << text.output;
}

// `bake --sparse`: the budget counts what is stored, the file and the memory report hold only
// the stored probes, and the sparse placement uses a finer spacing than dense in the same memory.
TEST(BakePlacementCli, SparseBakeStoresOnlySurfaceProbesWithinTheBudget) {
    const fs::path dir = outputDir();
    auto bakeWith = [&](bool sparse) {
        std::vector<std::string> args{"bake",
                                      "--scene",
                                      "courtyard",
                                      "--volumes",
                                      "auto-uniform",
                                      "--probe-budget-mib",
                                      "1",
                                      "--rays",
                                      "16",
                                      "--bounces",
                                      "1",
                                      "--json",
                                      "--out",
                                      (dir / (sparse ? "sparse.pbp" : "dense.pbp")).string()};
        if (sparse) args.push_back("--sparse");
        return runProbebench(args);
    };
    auto dense = bakeWith(false), sparse = bakeWith(true);
    ASSERT_EQ(dense.exitCode, 0) << dense.output;
    ASSERT_EQ(sparse.exitCode, 0) << sparse.output;
    auto d = jsonOf(dense.output), s = jsonOf(sparse.output);
    EXPECT_EQ(d["stored_probes"], d["probes"]);
    EXPECT_LT(s["stored_probes"].get<std::size_t>(), s["probes"].get<std::size_t>());
    EXPECT_GT(s["probes"].get<std::size_t>(), d["probes"].get<std::size_t>())
        << "the same memory must hold a finer sparse grid";
    EXPECT_LE(s["memory"]["total"]["stored_total"].get<double>(), 1024.0 * 1024.0);
    EXPECT_LT(fs::file_size(dir / "sparse.pbp"),
              s["probes"].get<std::size_t>() * 1536u); // fewer tiles than the grid
    auto text = runProbebench({"memory", "--probes", (dir / "sparse.pbp").string()});
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("sparse storage: " + std::to_string(s["stored_probes"].get<int>()) +
                               " of " + std::to_string(s["probes"].get<int>())),
              std::string::npos)
        << text.output;
}

TEST(BakePlacementCli, BadOptionsGiveOneLineErrors) {
    fs::path dir = outputDir();
    const std::string out = (dir / "p.pbp").string(), toml = (dir / "v.toml").string();
    expectOneLineError(runProbebench({"bake", "--scene", "cornell", "--auto-levels", "9",
                                      "--write-volumes", toml}),
                       "--auto-levels");
    expectOneLineError(runProbebench({"bake", "--scene", "cornell", "--volumes", "auto-uniform",
                                      "--auto-levels", "2", "--out", out}),
                       "--auto-levels");
    expectOneLineError(runProbebench({"bake", "--scene", "cornell", "--auto-max-children", "0",
                                      "--write-volumes", toml}),
                       "--auto-max-children");
    expectOneLineError(runProbebench({"bake", "--scene", "cornell", "--probe-budget-mib", "-1",
                                      "--write-volumes", toml}),
                       "--probe-budget-mib");
    expectOneLineError(runProbebench({"bake", "--scene", "cornell", "--probe-budget-mib", "0.001",
                                      "--write-volumes", toml}),
                       "--probe-budget-mib");
    expectOneLineError(runProbebench({"bake", "--scene", "cornell"}), "--out");
    expectOneLineError(runProbebench({"bake", "--scene", "cornell", "--write-volumes",
                                      (dir / "missing" / "v.toml").string()}),
                       "missing");
    expectOneLineError(runProbebench({"bake", "--scene", "empty", "--write-volumes", toml}),
                       "--volumes auto");
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(toml));
}

TEST(BakePlacementCli, LatticeSearchIsReportedAndCanBeTurnedOff) {
    // `--volumes auto` under a budget ends with the measured lattice search; --write-volumes
    // alone places without baking, so this stays quick.
    const fs::path dir = outputDir();
    auto on = runProbebench({"bake", "--scene", "courtyard", "--probe-budget-mib", "2",
                             "--write-volumes", (dir / "on.toml").string(), "--json"});
    ASSERT_EQ(on.exitCode, 0) << on.output;
    auto search = jsonOf(on.output)["placement"]["lattice_search"];
    ASSERT_TRUE(search.is_object()) << on.output;
    EXPECT_GT(search["trials"].get<int>(), 0);
    EXPECT_LE(search["estimated_error_after"].get<double>(),
              search["estimated_error_before"].get<double>());
    for (const auto& c : search["shift_cells"])
        EXPECT_LE(std::abs(c.get<double>()), 0.4 + 1e-6);
    auto text = runProbebench({"bake", "--scene", "courtyard", "--probe-budget-mib", "2",
                               "--write-volumes", (dir / "text.toml").string()});
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("lattice search: shift"), std::string::npos) << text.output;
    EXPECT_EQ(readText(dir / "on.toml"), readText(dir / "text.toml")) << "not deterministic";

    auto off = runProbebench({"bake", "--scene", "courtyard", "--probe-budget-mib", "2",
                              "--no-lattice-search", "--write-volumes", (dir / "off.toml").string(),
                              "--json"});
    ASSERT_EQ(off.exitCode, 0) << off.output;
    EXPECT_FALSE(jsonOf(off.output)["placement"].contains("lattice_search")) << off.output;
    expectOneLineError(
        runProbebench({"bake", "--scene", "courtyard", "--volumes", "auto-uniform",
                       "--no-lattice-search", "--write-volumes", (dir / "u.toml").string()}),
        "--no-lattice-search applies to --volumes auto only");
    // Without the search only the centres can differ.
    if (search["shift_cells"] == nlohmann::json::array({0.0, 0.0, 0.0})) {
        EXPECT_EQ(readText(dir / "on.toml"), readText(dir / "off.toml"));
    }
}
