// Sweep plans (bench/sweep): deterministic expansion into self-contained jobs, one-line errors
// for bad plans, the output folder's state, and the merge's timing-free view.
#include "bench/sweep/SweepMerge.h"
#include "bench/sweep/SweepPlan.h"
#include "bench/sweep/SweepState.h"
#include "core/Error.h"
#include "support/TestEnv.h"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>

using namespace pb::sweep;

namespace {

const char* kPlan = R"(
name = "t"
[[bench]]
scenes = ["cornell", "rooms"]
profiles = ["reference", "handheld"]
resolutions = ["64x36", "128x72"]
switch_sets = [["gi.resolution=half"], []]
repeat = 2
args = ["--rounds", "1"]

[[bake]]
scenes = ["cornell"]
scenarios = ["day", "night", "dusk"]
parts = 2
args = ["--rays", "16"]

[[command]]
name = "truth"
args = ["truth", "--scene", "cornell"]
output_option = "--json"
)";

std::string planError(const std::string& text) {
    try {
        expandSweepPlan(parseSweepPlan(text, "p.toml"), "p.toml");
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "(no error)";
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

} // namespace

TEST(SweepPlan, ExpandsEveryAxisInAFixedOrder) {
    const std::vector<SweepJob> jobs = expandSweepPlan(parseSweepPlan(kPlan, "p.toml"), "p.toml");
    // 2 scenes x 2 profiles x 2 switch sets x 2 resolutions x 2 repeats, 2 bake parts, 1 command.
    ASSERT_EQ(jobs.size(), 32u + 2u + 1u);
    for (std::size_t i = 0; i < jobs.size(); ++i)
        EXPECT_EQ(jobs[i].index, i);
    // Innermost axis first: repeat, then resolution.
    EXPECT_EQ(jobs[0].labels["repeat"], 0);
    EXPECT_EQ(jobs[1].labels["repeat"], 1);
    EXPECT_EQ(jobs[2].labels["resolution"], "128x72");
    EXPECT_EQ(jobs[0].labels["switches"], nlohmann::json({"gi.resolution=half"}));
    EXPECT_EQ(jobs[16].labels["scene"], "rooms");
    // Every job has its own output file, named in its own arguments.
    std::vector<std::string> outputs;
    for (const SweepJob& j : jobs) {
        outputs.push_back(j.output);
        EXPECT_TRUE(contains(j.args, std::string(kOutPlaceholder) + "/" + j.output)) << j.index;
    }
    std::sort(outputs.begin(), outputs.end());
    EXPECT_EQ(std::unique(outputs.begin(), outputs.end()), outputs.end());
    EXPECT_EQ(jobs[0].args[0], "bench");
    EXPECT_TRUE(contains(jobs[0].args, "--set") && contains(jobs[0].args, "gi.resolution=half"));
    EXPECT_TRUE(contains(jobs[0].args, "--rounds"));
    EXPECT_EQ(jobs[32].kind, "bake-part");
    EXPECT_TRUE(contains(jobs[32].args, "0/2") && contains(jobs[33].args, "1/2"));
    EXPECT_TRUE(contains(jobs[32].args, "dusk"));
    EXPECT_EQ(jobs[34].kind, "command");
    EXPECT_EQ(jobs[34].args.front(), "truth");
    const std::vector<BakeGroup> groups = bakeGroups(jobs);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0].jobs, (std::vector<std::size_t>{32, 33}));
    // The same plan, the same jobs and id; another argument, another id.
    const std::vector<SweepJob> again = expandSweepPlan(parseSweepPlan(kPlan, "p.toml"), "p.toml");
    EXPECT_EQ(planId(jobs), planId(again));
    std::string changed = kPlan;
    changed.replace(changed.find("\"16\""), 4, "\"32\"");
    EXPECT_NE(planId(jobs),
              planId(expandSweepPlan(parseSweepPlan(changed, "p.toml"), "p.toml")));
}

TEST(SweepPlan, BadPlansGiveOneLineErrors) {
    EXPECT_EQ(planError("name = \"t\"\n"),
              "p.toml: the plan expands to no jobs (give a [[bench]], [[bake]] or [[command]] "
              "table with at least one entry per axis)");
    EXPECT_NE(planError("name = \"t\"\n[[bench]]\nscenes = []\nprofiles = [\"a\"]\n"
                        "resolutions = [\"8x8\"]\n")
                  .find("expands to no jobs"),
              std::string::npos);
    const std::string unknown = planError("name = \"t\"\nbogus = 1\n");
    EXPECT_EQ(unknown.rfind("p.toml:2:", 0), 0u) << unknown;
    EXPECT_NE(unknown.find("unknown key 'bogus'"), std::string::npos) << unknown;
    EXPECT_NE(planError("name = \"t\"\n[[bench]]\nscenes = [\"c\"]\nprofiles = [\"a\"]\n"
                        "resolutions = [\"64by36\"]\n")
                  .find("resolution '64by36' must be WxH"),
              std::string::npos);
    EXPECT_NE(planError("name = \"t\"\n[[bake]]\nscenes = [\"c\"]\nscenarios = [\"day\"]\n"
                        "parts = 2\n")
                  .find("2 parts for 1 scenario(s)"),
              std::string::npos);
    EXPECT_NE(planError("[[bench]]\n").find("missing key 'name'"), std::string::npos);
    for (const std::string& e : {planError("name = \"t\"\nbogus = 1\n"), planError("x = [")})
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(SweepPlan, SubstitutesTheOutputFolder) {
    EXPECT_EQ(substituteOut({"--json", "{out}/jobs/0001.json", "{out}{out}"}, "/d"),
              (std::vector<std::string>{"--json", "/d/jobs/0001.json", "/d/d"}));
    EXPECT_EQ(indexRanges({0, 1, 2, 5, 7, 8}), "0-2,5,7-8");
    EXPECT_EQ(indexRanges({3}), "3");
}

TEST(SweepState, UnfinishedJobsAndTasksComeFromTheStatusFiles) {
    const std::string dir = pb::test::outputDir().string();
    PlanState s;
    s.name = "t";
    s.id = "x";
    s.chunk = 2;
    s.jobs = expandSweepPlan(parseSweepPlan(kPlan, "p.toml"), "p.toml");
    s.jobs.resize(5);
    writePlanState(dir, s);
    const std::optional<PlanState> back = readPlanState(dir);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->tasks(), 3u);
    EXPECT_EQ(back->jobs.size(), 5u);
    EXPECT_EQ(back->jobs[3].args, s.jobs[3].args);
    writeJobStatus(dir, {0, 0, "n1", 1.0});
    writeJobStatus(dir, {1, 0, "n1", 1.0});
    writeJobStatus(dir, {2, 3, "n2", 1.0}); // failed
    writeJobStatus(dir, {4, 0, "n2", 1.0});
    EXPECT_EQ(unfinishedJobs(dir, *back), (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(unfinishedTasks(dir, *back), (std::vector<std::size_t>{1}));
    EXPECT_EQ(readJobStatus(dir, 2)->node, "n2");
    EXPECT_FALSE(readJobStatus(dir, 3));
}

TEST(SweepMerge, WithoutTimingsKeepsResultsAndDropsTimes) {
    const nlohmann::json j = {
        {"context", {{"cpu", "x"}}},
        {"seconds", 3.0},
        {"profiles",
         {{{"name", "handheld"},
           {"frame_ms", {{"median", 1.0}}},
           {"gi_memory_mib", 6.7},
           {"budget", {{"frame_ms", 16.6}, {"frame_within", true}, {"gi_memory_within", true}}},
           {"accuracy", {{"flip_mean", 0.03}}},
           {"vs_reference", {{"delta_ms", {{"estimate", 1}}}, {"delta_flip_mean", 0.01},
                             {"noise_flags", nullptr}}}}}},
        {"variants", {{{"passes", {{{"name", "gbuffer"}, {"ms", {{"median", 0.2}}}}}},
                       {"bimodality_coefficient", 0.3},
                       {"gi_over_floor", 2.0}}}},
        {"jobs", {{{"node", "n1"}, {"index", 0}}}}};
    const nlohmann::json expected = {
        {"profiles",
         {{{"name", "handheld"},
           {"gi_memory_mib", 6.7},
           {"budget", {{"gi_memory_within", true}}},
           {"accuracy", {{"flip_mean", 0.03}}},
           {"vs_reference", {{"delta_flip_mean", 0.01}}}}}},
        {"variants", {{{"passes", {{{"name", "gbuffer"}}}}}}},
        {"jobs", {{{"index", 0}}}}};
    EXPECT_EQ(withoutTimings(j), expected);
}

TEST(SweepMerge, RefusesToMergeAnUnfinishedSweep) {
    const std::string dir = pb::test::outputDir().string();
    PlanState s;
    s.name = "t";
    s.id = "x";
    s.jobs = expandSweepPlan(parseSweepPlan(kPlan, "p.toml"), "p.toml");
    s.jobs.resize(2);
    writeJobStatus(dir, {0, 0, "n1", 1.0});
    auto mergeError = [&] {
        try {
            mergeSweep(s, dir, nlohmann::json::array());
        } catch (const pb::Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(mergeError().find("job 0's output is missing"), std::string::npos) << mergeError();
    std::filesystem::create_directories(dir + "/jobs");
    std::ofstream(dir + "/" + s.jobs[0].output) << "{\"profiles\": [], \"variants\": []}";
    EXPECT_NE(mergeError().find("job 1 has not finished cleanly; nothing merged"),
              std::string::npos)
        << mergeError();
}
