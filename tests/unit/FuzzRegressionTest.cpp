// Replays, in every build, the fuzzers' seed corpus (tests/data/fuzz-seeds/) and every input that once
// crashed, hung or broke the error contract of a reader (tests/data/fuzz-regressions/<target>/,
// found by the fuzzers in fuzz/ or by hand): each must load or give a one-line pb::Error that
// starts with the file's name (fuzz/FuzzInputs.h). A crash or sanitizer report fails the case.
#include "fuzz/FuzzInputs.h"
#include "probes/store/VolumeFile.h"
#include "support/TestEnv.h"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <ostream>
#include <vector>

namespace fs = std::filesystem;
using pb::fuzz::Outcome;

namespace {

using Runner = Outcome (*)(const std::vector<std::uint8_t>&, const fs::path& scratch);

struct Target {
    const char* name; // folder under tests/data/fuzz-seeds and tests/data/fuzz-regressions
    Runner run;
};
void PrintTo(const Target& t, std::ostream* os) {
    *os << t.name;
}

// One row per fuzz target (fuzz/CMakeLists.txt); a new TOML reader adds a row here.
const Target kTargets[] = {
    {"gltf", [](const std::vector<std::uint8_t>& b,
                const fs::path& dir) { return pb::fuzz::runGltfWithBin(b.data(), b.size(), dir); }},
    {"glb", [](const std::vector<std::uint8_t>& b,
               const fs::path& dir) { return pb::fuzz::runGlb(b.data(), b.size(), dir); }},
    {"volume_toml",
     [](const std::vector<std::uint8_t>& b, const fs::path&) {
         return pb::fuzz::runToml(b.data(), b.size(), &pb::probes::parseVolumeToml);
     }},
    {"profile_toml",
     [](const std::vector<std::uint8_t>& b, const fs::path&) {
         return pb::fuzz::runToml(b.data(), b.size(), &pb::fuzz::parseProfileText);
     }},
    {"probe_file", [](const std::vector<std::uint8_t>& b,
                      const fs::path&) { return pb::fuzz::runProbeFile(b.data(), b.size()); }},
};

std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> out;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file() && e.path().filename().string()[0] != '.')
                out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::uint8_t> readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs every file of `dir` through `target`; returns how many loaded.
int replay(const Target& target, const fs::path& dir, const fs::path& scratch) {
    int loaded = 0;
    for (const fs::path& file : filesIn(dir)) {
        SCOPED_TRACE(file.string());
        try {
            loaded += target.run(readAll(file), scratch) == Outcome::Loaded;
        } catch (const pb::fuzz::ContractViolation& e) {
            ADD_FAILURE() << e.what();
        }
    }
    return loaded;
}

class FuzzCorpus : public ::testing::TestWithParam<Target> {};

} // namespace

// The seeds are valid files that reach deep into the readers: at least one per target loads
// (so a format change that silently invalidates them all shows up here).
TEST_P(FuzzCorpus, SeedsLoadOrFailCleanly) {
    const fs::path dir = pb::test::testDataDir() / "fuzz-seeds" / GetParam().name;
    if (filesIn(dir).empty())
        GTEST_SKIP() << "no committed seeds for " << GetParam().name << " (fuzz/run.sh makes them)";
    EXPECT_GT(replay(GetParam(), dir, pb::test::outputDir()), 0)
        << "no seed of " << dir << " loads";
}

// Every target has regression inputs: a missing or empty folder (a renamed target, a lost
// checkout) would otherwise pass without replaying anything.
TEST_P(FuzzCorpus, RegressionInputsLoadOrFailCleanly) {
    const fs::path dir = pb::test::testDataDir() / "fuzz-regressions" / GetParam().name;
    ASSERT_FALSE(filesIn(dir).empty()) << "no regression inputs in " << dir;
    replay(GetParam(), dir, pb::test::outputDir());
}

INSTANTIATE_TEST_SUITE_P(Fuzz, FuzzCorpus, ::testing::ValuesIn(kTargets),
                         [](const ::testing::TestParamInfo<Target>& info) {
                             return std::string(info.param.name);
                         });
