// `probebench bake` says when a scenario's irradiance is stored scaled (probes/StorageScale.h):
// a line per scaled scenario, and `storage_scales` in --json (1 for ordinary light).
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace pb::test;

TEST(BakeStorageScaleCli, ScaledScenariosAreReported) {
    const std::string out = (outputDir() / "glare.pbp").string();
    const std::vector<std::string> cheap = {"--scene", "courtyard", "--volumes", "auto-uniform",
                                            "--rays",  "16",        "--bounces", "1",
                                            "--force", "--out",     out};
    std::vector<std::string> glare = {"bake", "--sun", "off", "--sky", "1e6,1e6,1e6"};
    glare.insert(glare.end(), cheap.begin(), cheap.end());
    auto text = runProbebench(glare);
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("scenario day: irradiance stored x2^-"), std::string::npos)
        << text.output;
    glare.push_back("--json");
    auto json = runProbebench(glare);
    ASSERT_EQ(json.exitCode, 0) << json.output;
    const auto j = nlohmann::json::parse(json.output.substr(json.output.find('{')));
    EXPECT_LT(j["storage_scales"]["day"].get<double>(), 1.0 / 64);

    std::vector<std::string> plain = {"bake", "--json"};
    plain.insert(plain.end(), cheap.begin(), cheap.end());
    auto ordinary = runProbebench(plain);
    ASSERT_EQ(ordinary.exitCode, 0) << ordinary.output;
    const auto k = nlohmann::json::parse(ordinary.output.substr(ordinary.output.find('{')));
    EXPECT_EQ(k["storage_scales"]["day"].get<double>(), 1.0);
}
