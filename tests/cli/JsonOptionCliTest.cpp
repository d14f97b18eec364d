// `--json [FILE]` in the commands that used to take only a file (bench, tune, gate, stress;
// issue 25, item 9): `--json` alone, `--json -` and `--json` before another option print JSON
// on stdout, and nothing else goes there (the tables move to stderr); `--json FILE` writes the
// file and keeps the table on stdout.
#include "support/CliBakes.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

struct SplitResult {
    CommandResult run; // its output: stderr only
    std::string out;   // stdout
};

SplitResult runSplit(const std::vector<std::string>& args, const fs::path& stdoutFile) {
    SplitResult r;
    r.run = runProbebenchSplit(args, stdoutFile.string(), r.out);
    return r;
}

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& more) {
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

// Every form of the option on one command: stdout is exactly one JSON document when the JSON
// goes there, and the text for people (`marker`) is on stderr instead; with a file the file
// parses and the text is on stdout. `check` looks at the document.
void expectEveryForm(const std::vector<std::string>& args, const fs::path& dir,
                     const std::string& marker,
                     const std::function<void(const nlohmann::json&)>& check) {
    // `--json` last, `--json -`, and `--json` right before another option (not its file).
    std::vector<std::string> before = args;
    before.insert(before.begin() + 1, "--json");
    const std::vector<std::vector<std::string>> forms{with(args, {"--json"}),
                                                      with(args, {"--json", "-"}), before};
    for (std::size_t n = 0; n < forms.size(); ++n) {
        SCOPED_TRACE("form " + std::to_string(n));
        const SplitResult r = runSplit(forms[n], dir / ("stdout" + std::to_string(n) + ".txt"));
        ASSERT_EQ(r.run.exitCode, 0) << r.run.output << r.out;
        nlohmann::json j;
        ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << "stdout is not JSON:\n" << r.out;
        check(j);
        EXPECT_NE(r.run.output.find(marker), std::string::npos)
            << "the text goes to stderr: " << r.run.output;
    }
    const fs::path file = dir / "out.json";
    const SplitResult r = runSplit(with(args, {"--json", file.string()}), dir / "stdout-file.txt");
    ASSERT_EQ(r.run.exitCode, 0) << r.run.output << r.out;
    std::ifstream in(file);
    ASSERT_TRUE(in) << file;
    check(nlohmann::json::parse(in));
    EXPECT_NE(r.out.find(marker), std::string::npos) << "the text stays on stdout: " << r.out;
}

} // namespace

TEST(JsonOptionCli, StressPrintsJsonOnStdoutOrWritesTheFile) {
    expectEveryForm({"stress", "--width", "16", "--height", "12", "--rays", "8", "--cases",
                     "light=1e+06"},
                    outputDir(), " runs, ",
                    [](const nlohmann::json& j) { EXPECT_EQ(j["command"], "stress"); });
}

TEST(JsonOptionCli, GatePrintsJsonOnStdoutOrWritesTheFile) {
    const fs::path dir = outputDir();
    const fs::path b = dir / "tiny.json";
    const std::string cache = (fs::path(PB_TEST_OUTPUT_DIR) / "gate-probe-cache").string();
    const auto u = runProbebench({"gate", "--baseline", b.string(), "--cache-dir", cache,
                                  "--update", "--no-timing", "--scene", "cornell", "--camera",
                                  "0,1,0.9,0,1.2,-1,80", "--width", "64", "--height", "36",
                                  "--profiles", "reference,handheld"});
    ASSERT_EQ(u.exitCode, 0) << u.output;
    expectEveryForm({"gate", "--baseline", b.string(), "--cache-dir", cache, "--no-timing"}, dir,
                    "handheld", [](const nlohmann::json& j) {
                        EXPECT_TRUE(j.contains("measured")) << j.dump().substr(0, 300);
                    });
}

TEST(JsonOptionCli, BenchPrintsJsonOnStdoutOrWritesTheFile) {
    const std::string cache = (fs::path(PB_TEST_OUTPUT_DIR) / "bench-probe-cache").string();
    expectEveryForm({"bench", "--scene", "cornell", "--profiles", "reference,handheld", "--width",
                     "64", "--height", "36", "--rounds", "2", "--frames", "1", "--warmup", "1",
                     "--cache-dir", cache},
                    outputDir(), "handheld", [](const nlohmann::json& j) {
                        EXPECT_TRUE(j.contains("profiles")) << j.dump().substr(0, 300);
                    });
}

TEST(JsonOptionCli, TunePrintsJsonOnStdoutOrWritesTheFile) {
    const fs::path dir = outputDir();
    const fs::path probes =
        bakeNestedRooms(fs::path(PB_TEST_OUTPUT_DIR) / "rooms_nested_tune_cli.pbp");
    expectEveryForm({"tune", "--scene", "rooms", "--probes", probes.string(), "--width", "64",
                     "--height", "36", "--rounds", "1", "--frames", "1", "--warmup", "1",
                     "--search", "gi.target_format", "--budget-ms", "1000", "--budget-mib", "100",
                     "--out", (dir / "tuned.toml").string()},
                    dir, "Pareto front", [](const nlohmann::json& j) {
                        EXPECT_TRUE(j.contains("remeasure")) << j.dump().substr(0, 300);
                    });
}

// The commands that printed JSON with a flag take the same FILE.
TEST(JsonOptionCli, FlagCommandsWriteTheFileToo) {
    const fs::path dir = outputDir();
    const fs::path file = dir / "profiles.json";
    const SplitResult r = runSplit({"profiles", "--json", file.string()}, dir / "stdout.txt");
    ASSERT_EQ(r.run.exitCode, 0) << r.run.output << r.out;
    std::ifstream in(file);
    ASSERT_TRUE(in) << file;
    EXPECT_GE(nlohmann::json::parse(in).size(), 5u);
    EXPECT_EQ(r.out, "") << "the JSON went to the file";
    const SplitResult dash = runSplit({"profiles", "--json", "-"}, dir / "stdout-dash.txt");
    ASSERT_EQ(dash.run.exitCode, 0) << dash.run.output;
    EXPECT_EQ(nlohmann::json::parse(dash.out), nlohmann::json::parse(std::ifstream(file)));
}
