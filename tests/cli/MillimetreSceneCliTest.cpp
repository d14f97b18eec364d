// A scene in millimetres 10 km from the origin (1e7 units out on X and Z): bake and render
// through the command line as a user would, and the lit frame must look like the same room
// at the origin. Auto placement and the default view scale with the bounds (renderer/scene
// README, "Units and axes").
#include "image/Image.h"
#include "support/RunCommand.h"
#include "support/TestEnv.h"
#include "unit/GltfTestWriter.h"

#include <gtest/gtest.h>

using namespace pb::test;

namespace {

// An open-topped room 4 x 2.5 x 3 m in millimetres, faces pointing inwards, plus a 1 m block
// on the floor; `offset` (millimetres) moves it all.
std::string writeRoom(const std::filesystem::path& dir, const std::string& name, double offset) {
    const glm::vec3 lo(0.0f), hi(4000.0f, 2500.0f, 3000.0f);
    std::vector<glm::vec3> p;
    std::vector<std::uint32_t> idx;
    auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) { // counter-clockwise
        const auto base = std::uint32_t(p.size());
        p.insert(p.end(), {a, b, c, d});
        idx.insert(idx.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    };
    quad({lo.x, 0, lo.z}, {lo.x, 0, hi.z}, {hi.x, 0, hi.z}, {hi.x, 0, lo.z});             // floor
    quad({lo.x, 0, lo.z}, {hi.x, 0, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z});       // z=0
    quad({lo.x, 0, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, 0, hi.z});       // z=3
    quad({lo.x, 0, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, 0, hi.z});       // x=0
    quad({hi.x, 0, lo.z}, {hi.x, 0, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z});       // x=4
    const glm::vec3 b0(1500, 0, 1000), b1(2500, 1000, 2000);                              // block
    quad({b0.x, b1.y, b0.z}, {b0.x, b1.y, b1.z}, {b1.x, b1.y, b1.z}, {b1.x, b1.y, b0.z}); // top
    quad({b0.x, 0, b1.z}, {b1.x, 0, b1.z}, {b1.x, b1.y, b1.z}, {b0.x, b1.y, b1.z});
    quad({b0.x, 0, b0.z}, {b0.x, b1.y, b0.z}, {b1.x, b1.y, b0.z}, {b1.x, 0, b0.z});
    quad({b1.x, 0, b0.z}, {b1.x, b1.y, b0.z}, {b1.x, b1.y, b1.z}, {b1.x, 0, b1.z});
    quad({b0.x, 0, b0.z}, {b0.x, 0, b1.z}, {b0.x, b1.y, b1.z}, {b0.x, b1.y, b0.z});
    GltfWriter w;
    w.addTriangleMesh(p, idx, "room");
    w.addNode({{"name", "room"}, {"mesh", 0}, {"translation", {offset, 0.0, offset}}});
    w.doc["materials"] = nlohmann::json::array({{{"doubleSided", true}}});
    w.doc["meshes"][0]["primitives"][0]["material"] = 0;
    return w.write(dir, name);
}

double meanLuminance(const std::string& png) {
    const pb::image::Image8 img = pb::image::readPng(png);
    double sum = 0;
    for (std::size_t i = 0; i + 3 < img.pixels.size(); i += 4)
        sum += img.pixels[i] + img.pixels[i + 1] + img.pixels[i + 2];
    return sum / (3.0 * double(img.width) * double(img.height));
}

// Bakes and renders `scene` with probes; returns the frame's mean 8-bit value.
double bakeAndRender(const std::filesystem::path& dir, const std::string& scene,
                     const std::string& tag) {
    const std::string probes = (dir / (tag + ".probes")).string();
    const std::string png = (dir / (tag + ".png")).string();
    const auto bake = runProbebench({"bake", "--scene", scene, "--volumes", "auto-uniform",
                                     "--rays", "32", "--bounces", "1", "--force", "--out", probes});
    EXPECT_EQ(bake.exitCode, 0) << bake.output;
    const auto render = runProbebench({"render", "--scene", scene, "--probes", probes, "--width",
                                       "160", "--height", "90", "--out", png});
    EXPECT_EQ(render.exitCode, 0) << render.output;
    if (bake.exitCode != 0 || render.exitCode != 0) return -1.0;
    return meanLuminance(png);
}

} // namespace

TEST(MillimetreSceneCli, TenKilometresOutBakesAndRendersLikeAtTheOrigin) {
    const auto dir = outputDir();
    const double near = bakeAndRender(dir, writeRoom(dir, "mm_origin", 0.0), "origin");
    const double far = bakeAndRender(dir, writeRoom(dir, "mm_far", 1e7), "far");
    EXPECT_GT(near, 20.0) << "the room at the origin renders dark";
    EXPECT_NEAR(far, near, 0.05 * near + 1.0) << "10 km out the room renders differently";
}
