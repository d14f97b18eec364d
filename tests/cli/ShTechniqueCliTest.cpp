// The SH technique on the command line (issue 19): `memory --technique` counts the SH 3D
// textures per probe and per volume, and an unknown technique or leak mode is a one-line error.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace pb::test;

namespace {

nlohmann::json memoryJson(const std::string& technique) {
    const CommandResult r =
        runProbebench({"memory", "--grid", "32x8x32", "--technique", technique, "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(r.output.substr(r.output.find('{')));
}

} // namespace

TEST(ShTechniqueCli, MemoryCountsTheShTexturesPerProbeAndPerVolume) {
    const nlohmann::json l1 = memoryJson("sh_l1"), l2 = memoryJson("sh_l2");
    for (const nlohmann::json& j : {l1, l2}) {
        EXPECT_EQ(j["probes"].get<long long>(), 32 * 8 * 32);
        ASSERT_EQ(j["volumes"].size(), 1u);
        EXPECT_EQ(j["volumes"][0]["bytes"].get<long long>(),
                  j["bytes_per_probe"].get<long long>() * 32 * 8 * 32);
        EXPECT_EQ(j["total_bytes"], j["volumes"][0]["bytes"]);
    }
    // The targets, and L2 holds more than L1.
    EXPECT_LE(l1["bytes_per_probe"].get<int>(), 25);
    EXPECT_LE(l2["bytes_per_probe"].get<int>(), 60);
    EXPECT_GT(l2["bytes_per_probe"].get<int>(), l1["bytes_per_probe"].get<int>());
    // DDGI's octahedral textures take far more per probe than either.
    const CommandResult d = runProbebench({"memory", "--grid", "32x8x32", "--json"});
    const nlohmann::json dj = nlohmann::json::parse(d.output.substr(d.output.find('{')));
    EXPECT_GT(dj["total"]["bc6h"]["per_probe"].get<int>(), l2["bytes_per_probe"].get<int>());
}

TEST(ShTechniqueCli, UnknownTechniqueAndLeakModeAreOneLineErrors) {
    const CommandResult m =
        runProbebench({"memory", "--grid", "4x4x4", "--technique", "sh_l3", "--json"});
    EXPECT_NE(m.exitCode, 0);
    EXPECT_NE(m.output.find("--technique"), std::string::npos) << m.output;
    const CommandResult r = runProbebench({"render", "--scene", "rooms", "--set",
                                           "gi.sh_leak=bogus", "--out", "/dev/null"});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("gi.sh_leak"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("validity_mask"), std::string::npos) << r.output;
}
