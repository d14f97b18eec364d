// probebench sweep with the local engine: bad plans and folders fail in one line before any
// job runs, and a failed job leaves the others' results while --resume runs only it.
#include "bench/sweep/SweepState.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"
#include "support/TinyGltf.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace pb::test {
namespace {
namespace fs = std::filesystem;

fs::path writePlan(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
}

// Two cheap jobs (a 16x9 path-traced truth at 2 spp): one of cornell, one of `scene` (a tiny
// glTF quad, seen from above).
std::string truthPlan(const std::string& name, const std::string& scene) {
    std::string plan = "name = \"" + name + "\"\n";
    for (const std::string& s : {std::string("cornell"), scene})
        plan += "[[command]]\nname = \"truth\"\nargs = [\"truth\", \"--scene\", \"" + s +
                "\", \"--width\", \"16\", \"--height\", \"9\", \"--spp\", \"2\", \"--no-cache\", "
                "\"--out-hdr\", \"{out}/jobs/" + fs::path(s).stem().string() + ".pfm\"" +
                // The tiny glTF's quad lies at y = 0: look down at it.
                (s == "cornell" ? "" : ", \"--camera\", \"0,2,0.3,0,0,0\"") +
                "]\noutput_option = \"--json\"\n";
    return plan;
}

// exit 1: the plan or the folder is wrong; 2: an option's value (a usage error).
void sweepExpectOneLineError(const CommandResult& r, const std::string& problem, int exit = 1) {
    EXPECT_EQ(r.exitCode, exit) << r.output;
    EXPECT_EQ(r.output.rfind("probebench: error: ", 0), 0u) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "not one line:\n" << r.output;
    EXPECT_NE(r.output.find(problem), std::string::npos) << r.output;
}

std::string fileText(const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

} // namespace

TEST(SweepCli, BadPlansFailBeforeAnythingRuns) {
    const fs::path dir = outputDir();
    const fs::path empty = writePlan(dir, "empty.toml", "name = \"e\"\n");
    sweepExpectOneLineError(
        runProbebench({"sweep", "--plan", empty.string(), "--out", (dir / "out").string()}),
        "empty.toml: the plan expands to no jobs");
    const fs::path unknown =
        writePlan(dir, "unknown.toml", "name = \"u\"\n[[bench]]\nscenes = [\"cornell\"]\n"
                                       "profiles = [\"reference\"]\nresolutions = [\"64x36\"]\n"
                                       "rounds = 3\n");
    sweepExpectOneLineError(
        runProbebench({"sweep", "--plan", unknown.string(), "--out", (dir / "out").string()}),
        "unknown key 'rounds'");
    EXPECT_FALSE(fs::exists(dir / "out")) << "a refused plan created its output folder";
    sweepExpectOneLineError(runProbebench({"sweep", "--plan", empty.string(), "--out",
                                           (dir / "out").string(), "--engine", "pbs"}),
                            "--engine: expected local or slurm", 2);
}

TEST(SweepCli, AFailedJobKeepsTheOthersAndResumeRunsOnlyIt) {
    const fs::path dir = outputDir(), out = dir / "out";
    const fs::path later = dir / "later.gltf"; // missing until the resume
    const fs::path plan = writePlan(dir, "plan.toml", truthPlan("resume", later.string()));
    const CommandResult first =
        runProbebench({"sweep", "--plan", plan.string(), "--out", out.string()});
    EXPECT_EQ(first.exitCode, 1) << first.output;
    EXPECT_NE(first.output.find("job 1 (task 1) failed: exit 1"), std::string::npos)
        << first.output;
    EXPECT_NE(first.output.find("later.gltf: file not found"), std::string::npos)
        << "the failed job's stderr tail is shown\n" << first.output;
    EXPECT_NE(first.output.find("1 of 2 job(s) failed; the others' results are kept"),
              std::string::npos)
        << first.output;
    EXPECT_TRUE(fs::exists(out / "jobs/0000.json"));
    EXPECT_FALSE(fs::exists(out / "sweep.json")) << "merged with a job missing";
    const std::string job0Status = fileText(sweep::statusPath(out.string(), 0));
    const auto job0Time = fs::last_write_time(out / "jobs/0000.json");

    // The same plan into its own folder without --resume is refused; so is another plan.
    sweepExpectOneLineError(
        runProbebench({"sweep", "--plan", plan.string(), "--out", out.string()}),
        "already holds this plan's results (1 of 2 jobs finished); --resume");
    const fs::path other = writePlan(dir, "other.toml", truthPlan("other", "rooms"));
    sweepExpectOneLineError(
        runProbebench({"sweep", "--plan", other.string(), "--out", out.string(), "--resume"}),
        "holds the results of another plan ('resume'");

    ASSERT_EQ(writeTinyGltf(dir, "later"), later);
    const CommandResult resumed =
        runProbebench({"sweep", "--plan", plan.string(), "--out", out.string(), "--resume"});
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("2 job(s) in 2 task(s), 1 to run"), std::string::npos)
        << resumed.output;
    EXPECT_EQ(fileText(sweep::statusPath(out.string(), 0)), job0Status) << "job 0 ran again";
    EXPECT_EQ(fs::last_write_time(out / "jobs/0000.json"), job0Time);
    const nlohmann::json merged = nlohmann::json::parse(fileText(out / "sweep.json"));
    ASSERT_EQ(merged["jobs"].size(), 2u);
    EXPECT_EQ(merged["jobs"][1]["result"]["width"], 16);
    EXPECT_TRUE(fs::exists(out / "report.html"));
    EXPECT_TRUE(fs::exists(out / "summary.md"));
}

} // namespace pb::test
