// RebuiltRequest.h: the request a probe set was baked from, rebuilt from the set (its input
// hash proves it), for dense and sparse sets, and refused for another scene. With it, `bench
// --truth` bakes "one bounce pass fewer" - which is the converged bake without its last pass
// only because a fixed count of N passes bakes what the converged bake's first N passes did.
#include "probes/bake/Baker.h"
#include "probes/bake/RebuiltRequest.h"
#include "scene/BuiltinScenes.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace pb;
using namespace pb::probes;

namespace {

BakeRequest smallCornellBake() {
    const scene::Scene s = scene::makeCornellScene();
    BakeRequest req;
    req.volumes = {ProbeVolume{}};
    req.volumes[0].name = "inside";
    req.volumes[0].center = {0.0f, 1.0f, 0.0f};
    req.volumes[0].halfExtents = glm::vec3(0.9f);
    req.volumes[0].counts = {3, 3, 3};
    req.scenarios = {Scenario{"day", s.sun, s.sky}};
    req.settings.raysPerProbe = 32;
    req.settings.noiseTarget = 0.0f;
    return req;
}

} // namespace

TEST(RebuiltRequest, DenseAndSparseSetsGiveBackTheRequestThatBakedThem) {
    const scene::Scene s = scene::makeCornellScene();
    for (const FreeSpace fs : {FreeSpace::StandIns, FreeSpace::Ranked}) {
        for (const bool sparse : {false, true}) {
            if (!sparse && fs != FreeSpace::StandIns) continue; // dense sets keep StandIns
            BakeRequest req = smallCornellBake();
            req.sparse = sparse;
            req.freeSpace = fs;
            req.freeSpaceBudgetBytes = fs == FreeSpace::Ranked ? 200000.0 : 0.0;
            const ProbeSet set = bakeProbes(s, req);
            std::string why;
            const std::optional<BakeRequest> back = rebuiltBakeRequest(s, set, &why);
            ASSERT_TRUE(back.has_value()) << "sparse " << sparse << ": " << why;
            EXPECT_EQ(back->sparse, sparse);
            EXPECT_EQ(bakeInputHash(s, *back), set.inputHash);
            // Baked again, it is the same set: nothing the hash misses was lost on the way.
            EXPECT_EQ(bakeProbes(s, *back).irradiance[0][0].texels, set.irradiance[0][0].texels);
        }
    }
}

TEST(RebuiltRequest, AnotherScenesProbesAreRefusedWithAReason) {
    const ProbeSet set = bakeProbes(scene::makeCornellScene(), smallCornellBake());
    std::string why;
    EXPECT_FALSE(rebuiltBakeRequest(scene::makeBuiltinScene("courtyard"), set, &why).has_value());
    EXPECT_NE(why.find("input hash"), std::string::npos) << why;
}

TEST(RebuiltRequest, NFixedPassesAreTheConvergedBakesFirstN) {
    const scene::Scene s = scene::makeCornellScene();
    BakeRequest req = smallCornellBake();
    req.settings.bounces = 0;
    BakeStats stats;
    const ProbeSet converged = bakeProbes(s, req, &stats);
    ASSERT_EQ(stats.passes.size(), 1u);
    ASSERT_GE(stats.passes[0], 3) << "the Cornell box needs several passes";
    req.settings.bounces = stats.passes[0];
    EXPECT_EQ(bakeProbes(s, req).irradiance[0][0].texels, converged.irradiance[0][0].texels);
    req.settings.bounces = stats.passes[0] - 1;
    EXPECT_NE(bakeProbes(s, req).irradiance[0][0].texels, converged.irradiance[0][0].texels)
        << "the last pass added light";
}
