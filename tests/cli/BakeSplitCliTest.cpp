// bake --split scenario + bake-merge as a user runs them: the merged file is the single bake's
// bytes; wrong splits and incomplete merges are one-line errors.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace pb::test {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> bakeArgs(const fs::path& out) {
    return {"bake",  "--scene", "cornell", "--scenario",     "day",       "--scenario",
            "night", "--rays",  "8",       "--volumes",      "auto-uniform", "--spacing",
            "0.5",   "--out",   out.string()};
}

std::string fileBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// exit 1: the parts do not fit; 2: a value that is not of the option's form (a usage error).
void bakeSplitExpectOneLineError(const CommandResult& r, const std::string& problem, int exit = 1) {
    EXPECT_EQ(r.exitCode, exit) << r.output;
    EXPECT_EQ(r.output.rfind("probebench: error: ", 0), 0u) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "not one line:\n" << r.output;
    EXPECT_NE(r.output.find(problem), std::string::npos) << r.output;
}

} // namespace

TEST(BakeSplitCli, MergedPartsAreTheSingleBakesBytes) {
    const fs::path dir = outputDir();
    auto args = [](const fs::path& out) { return bakeArgs(out); };
    ASSERT_EQ(runProbebench(args(dir / "single.pbp")).exitCode, 0);
    for (int p = 0; p < 2; ++p) {
        std::vector<std::string> a = args(dir / ("p" + std::to_string(p) + ".pbpart"));
        for (const std::string& s : {std::string("--split"), std::string("scenario"),
                                     std::string("--part"), std::to_string(p) + "/2"})
            a.push_back(s);
        const CommandResult r = runProbebench(a);
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const CommandResult merged =
        runProbebench({"bake-merge", (dir / "p1.pbpart").string(), (dir / "p0.pbpart").string(),
                       "--out", (dir / "merged.pbp").string()});
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    EXPECT_NE(merged.output.find("merged 2 part(s), 2 scenario(s): day night"), std::string::npos)
        << merged.output;
    EXPECT_TRUE(fileBytes(dir / "single.pbp") == fileBytes(dir / "merged.pbp"));

    bakeSplitExpectOneLineError(runProbebench({"bake-merge", (dir / "p0.pbpart").string(), "--out",
                                               (dir / "x.pbp").string()}),
                                "bake-merge: part 1 of 2 is missing");
    bakeSplitExpectOneLineError(runProbebench({"bake-merge", (dir / "single.pbp").string(), "--out",
                                               (dir / "x.pbp").string()}),
                                "single.pbp: not a probe part file");
    EXPECT_FALSE(fs::exists(dir / "x.pbp"));
}

TEST(BakeSplitCli, WrongSplitsAreOneLineErrors) {
    const fs::path dir = outputDir();
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> a = bakeArgs(dir / "x.pbpart");
        a.insert(a.end(), extra.begin(), extra.end());
        return runProbebench(a);
    };
    bakeSplitExpectOneLineError(
        with({"--split", "volume", "--part", "0/2"}),
        "--split volume: not supported: a bounce pass looks up every volume's");
    bakeSplitExpectOneLineError(with({"--split", "scenario", "--part", "0/3"}),
                                "--part: 3 parts for 2 scenario(s)");
    bakeSplitExpectOneLineError(with({"--split", "scenario", "--part", "2/2"}),
                                "--part: must be I/N");
    bakeSplitExpectOneLineError(with({"--split", "scenario", "--part", "half"}),
                                "--part: expected I/N", 2);
    bakeSplitExpectOneLineError(with({"--split", "scenario"}), "--split: needs --part I/N");
    bakeSplitExpectOneLineError(with({"--part", "0/2"}), "--part: needs --split scenario");
    EXPECT_FALSE(fs::exists(dir / "x.pbpart"));
}

} // namespace pb::test
