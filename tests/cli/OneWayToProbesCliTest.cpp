// One way to get probes (issue 44, item 6): `bench` once placed its probes before it looked in
// its cache, so a cache hit still paid for the placement and its lattice search, and it asked
// the placement for other things than `bake` did: `bench --scene rooms` baked 6,384 probes at
// spacing 0.302 while `bake --scene rooms` baked 5,643 at 0.337. Both now obtain probes through
// probes/obtain/ObtainProbes.h: the same options give the same bytes, and a hit places nothing.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

std::string fileBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The one probe file in the bench's cache folder.
fs::path onlyProbeFile(const fs::path& cache) {
    fs::path found;
    int count = 0;
    for (const auto& e : fs::directory_iterator(cache))
        if (e.path().extension() == ".pbp") found = e.path(), ++count;
    EXPECT_EQ(count, 1) << cache;
    return found;
}

CommandResult benchCornell(const fs::path& cache) {
    return runProbebench({"bench", "--scene", "cornell", "--cache-dir", cache.string(),
                          "--profiles", "reference", "--frames", "1", "--width", "32", "--height",
                          "18", "--no-cache-model", "--json", (cache / "bench.json").string(),
                          "--mkdir"}); // the JSON goes into the cache folder, made by this run
}

} // namespace

TEST(OneWayToProbesCli, BenchAndBakeWithTheSameOptionsWriteTheSameBytes) {
    const fs::path dir = outputDir() / "one_way_to_probes";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // The bench bakes as `bake --rays 128 --noise-target 0.015` does (bench/runner/ProbeCache.h),
    // auto placement.
    const fs::path baked = dir / "bake.pbp";
    const CommandResult bake = runProbebench({"bake", "--scene", "cornell", "--rays", "128",
                                              "--noise-target", "0.015", "--out", baked.string()});
    ASSERT_EQ(bake.exitCode, 0) << bake.output;
    const CommandResult first = benchCornell(dir / "cache");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("placed "), std::string::npos) << first.output;
    const fs::path cached = onlyProbeFile(dir / "cache");
    ASSERT_FALSE(cached.empty());
    const std::string a = fileBytes(baked), b = fileBytes(cached);
    ASSERT_GT(a.size(), 1000u);
    EXPECT_TRUE(a == b) << "bake wrote " << a.size() << " bytes, bench's cache " << b.size()
                        << " (" << cached << ")";
    EXPECT_TRUE(fs::exists(cached.string() + ".placement.json")) << "the placement cache";
}

TEST(OneWayToProbesCli, ABenchCacheHitPlacesNothing) {
    const fs::path cache = outputDir() / "one_way_to_probes_hit";
    fs::remove_all(cache);
    const CommandResult first = benchCornell(cache);
    ASSERT_EQ(first.exitCode, 0) << first.output;
    ASSERT_NE(first.output.find("placed "), std::string::npos) << first.output;
    const fs::path file = onlyProbeFile(cache);
    const auto written = fs::last_write_time(file);
    const CommandResult again = benchCornell(cache);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(again.output.find("placed "), std::string::npos) << "it placed again:\n" << again.output;
    EXPECT_EQ(again.output.find("baking "), std::string::npos) << again.output;
    EXPECT_EQ(fs::last_write_time(file), written) << "the cached file was written again";
}
