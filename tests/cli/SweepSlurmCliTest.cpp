// probebench sweep --engine slurm on a real one-node cluster (scripts/slurm-local.sh): the
// merged results equal the local engine's in everything but timings, the split bake merges
// into the single bake's bytes, and a failed array task is re-submitted alone by --resume.
// Skips only when the daemons cannot start here (not root); never under CI=true.
#include "bench/sweep/SweepMerge.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"
#include "support/TinyGltf.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace pb::test {
namespace {
namespace fs = std::filesystem;

std::string sweepSlurmFileText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Starts the cluster in `dir`, points the Slurm commands at it, and stops it by PID at the end.
class LocalCluster {
public:
    explicit LocalCluster(const fs::path& dir) : dir_(dir) {
        const std::string script = (sourceDir() / "scripts/slurm-local.sh").string();
        const CommandResult r = runCommand({script, "start", dir.string()});
        exitCode_ = r.exitCode;
        output_ = r.output;
        if (exitCode_ == 0) ::setenv("SLURM_CONF", (dir / "slurm.conf").c_str(), 1);
    }
    ~LocalCluster() {
        if (exitCode_ != 0) return;
        runCommand({(sourceDir() / "scripts/slurm-local.sh").string(), "stop", dir_.string()});
        ::unsetenv("SLURM_CONF");
    }
    int exitCode() const { return exitCode_; }
    const std::string& output() const { return output_; }

private:
    fs::path dir_;
    int exitCode_ = -1;
    std::string output_;
};

} // namespace

TEST(SweepSlurmCli, SlurmEngineMergesAsTheLocalEngineDoes) {
    const fs::path dir = outputDir();
    // The cluster's folder holds munge's socket: keep its path short (sockets allow ~100 bytes).
    const fs::path clusterDir = fs::temp_directory_path() / ("pb-slurm-" + std::to_string(::getpid()));
    LocalCluster cluster(clusterDir);
    if (cluster.exitCode() == 3) {
        if (underCi()) FAIL() << "the Slurm daemons must start under CI:\n" << cluster.output();
        GTEST_SKIP() << cluster.output();
    }
    ASSERT_EQ(cluster.exitCode(), 0) << cluster.output();

    const std::string plan = (testDataDir() / "sweeps/small.toml").string();
    const CommandResult local = runProbebench({"sweep", "--plan", plan, "--out",
                                               (dir / "local").string(), "--max-parallel", "2"});
    ASSERT_EQ(local.exitCode, 0) << local.output;
    const CommandResult slurm =
        runProbebench({"sweep", "--plan", plan, "--out", (dir / "slurm").string(), "--engine",
                       "slurm", "--poll-seconds", "0.5"});
    ASSERT_EQ(slurm.exitCode, 0) << slurm.output;
    EXPECT_NE(slurm.output.find("submitted job array"), std::string::npos) << slurm.output;

    const nlohmann::json a = nlohmann::json::parse(sweepSlurmFileText(dir / "local/sweep.json"));
    const nlohmann::json b = nlohmann::json::parse(sweepSlurmFileText(dir / "slurm/sweep.json"));
    EXPECT_EQ(a["profiles"].size(), 4u); // 2 profiles x 2 resolutions
    EXPECT_EQ(a["bakes"].size(), 1u);
    EXPECT_TRUE(a["profiles"][2]["accuracy"]["flip_mean"].is_number());
    EXPECT_TRUE(sweep::withoutTimings(a) == sweep::withoutTimings(b))
        << "the engines' merged results differ beyond timings";
    EXPECT_TRUE(fs::exists(dir / "slurm/report.html") && fs::exists(dir / "slurm/summary.md"));

    // The split bake, merged on the cluster, is the single bake's file byte for byte.
    const CommandResult single = runProbebench(
        {"bake", "--scene", "cornell", "--scenario", "day", "--scenario", "night", "--rays", "16",
         "--volumes", "auto-uniform", "--out", (dir / "single.pbp").string()});
    ASSERT_EQ(single.exitCode, 0) << single.output;
    const std::string merged = b["bakes"][0]["file"].get<std::string>();
    EXPECT_TRUE(sweepSlurmFileText(dir / "single.pbp") ==
                sweepSlurmFileText(dir / "slurm" / merged))
        << "the merged split bake is not the single bake's bytes";

    // A failing task: the other task's result stays, --resume submits only the failed index.
    const fs::path later = dir / "later.gltf";
    const fs::path resumePlan = dir / "resume.toml";
    std::ofstream(resumePlan)
        << "name = \"resume\"\n"
        << "[[command]]\nname = \"ok\"\nargs = [\"truth\", \"--scene\", \"cornell\", \"--width\", "
           "\"16\", \"--height\", \"9\", \"--spp\", \"2\", \"--no-cache\", \"--out-hdr\", "
           "\"{out}/jobs/a.pfm\"]\noutput_option = \"--json\"\n"
        << "[[command]]\nname = \"later\"\nargs = [\"truth\", \"--scene\", \"" << later.string()
        << "\", \"--width\", \"16\", \"--height\", \"9\", \"--spp\", \"2\", \"--no-cache\", "
           "\"--out-hdr\", \"{out}/jobs/b.pfm\", \"--camera\", \"0,2,0.3,0,0,0\"]\n"
           "output_option = \"--json\"\n";
    const std::vector<std::string> run = {"sweep", "--plan", resumePlan.string(), "--out",
                                          (dir / "resume").string(), "--engine", "slurm",
                                          "--poll-seconds", "0.5"};
    const CommandResult failed = runProbebench(run);
    EXPECT_EQ(failed.exitCode, 1) << failed.output;
    EXPECT_NE(failed.output.find("job 1 (task 1) failed: exit 1"), std::string::npos)
        << failed.output;
    EXPECT_NE(failed.output.find("file not found"), std::string::npos) << failed.output;
    EXPECT_TRUE(fs::exists(dir / "resume/jobs/0000.json"));
    EXPECT_FALSE(fs::exists(dir / "resume/sweep.json"));
    const auto keptTime = fs::last_write_time(dir / "resume/jobs/0000.json");
    ASSERT_EQ(writeTinyGltf(dir, "later"), later);
    std::vector<std::string> resume = run;
    resume.push_back("--resume");
    const CommandResult resumed = runProbebench(resume);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("(1 task(s): 1)"), std::string::npos) << resumed.output;
    EXPECT_EQ(fs::last_write_time(dir / "resume/jobs/0000.json"), keptTime);
    EXPECT_TRUE(fs::exists(dir / "resume/sweep.json"));
}

} // namespace pb::test
