// `--allow-external-uris` as a user meets it: a glTF whose buffer lies outside its folder is
// refused with one error line naming the flag, and loads with the flag.
#include "support/RunCommand.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <gtest/gtest.h>

using namespace pb::test;

TEST(ExternalUriCli, OutsideTheFolderNeedsTheFlag) {
    const auto dir = outputDir();
    std::filesystem::create_directories(dir / "asset");
    GltfWriter w;
    w.addTriangleMesh(triangleXY(), {0, 1, 2}, "tri");
    w.addNode({{"mesh", 0}});
    const std::string path = w.write(dir / "asset", "tri");
    std::filesystem::rename(dir / "asset" / "tri.bin", dir / "tri.bin");
    nlohmann::json d = nlohmann::json::parse(std::ifstream(path));
    d["buffers"][0]["uri"] = "../tri.bin";
    const std::string text = d.dump();
    GltfWriter::writeBytes(path, text.data(), text.size());

    const std::string out = (dir / "tri.png").string();
    const auto refused = runProbebench({"render", "--scene", path, "--width", "64", "--height",
                                        "36", "--out", out});
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_NE(refused.output.find("probebench: error: " + path +
                                  ": buffer 0 uri '../tri.bin' climbs out of the asset's folder "
                                  "(--allow-external-uris permits it)\n"),
              std::string::npos)
        << refused.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << "no partial output";

    const auto allowed = runProbebench({"render", "--scene", path, "--allow-external-uris",
                                        "--width", "64", "--height", "36", "--out", out});
    EXPECT_EQ(allowed.exitCode, 0) << allowed.output;
    EXPECT_TRUE(std::filesystem::exists(out));
}
