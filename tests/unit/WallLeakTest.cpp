// The leak figure (issue 19) on the built-in `thin_wall` scene: the lit face is lit, and the
// SH technique's leak modes cut the leak of `none`, DDGI's visibility test cuts it too.
#include "studies/common/WallLeak.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/bake/Baker.h"
#include "scene/SceneLoader.h"

#include <cstdio>
#include <gtest/gtest.h>
#include <map>

using namespace pb::probes;

namespace {

const ProbeSet& thinWallBake() {
    static const ProbeSet set = [] {
        const pb::scene::Scene s = pb::scene::makeBuiltinScene("thin_wall");
        BakeRequest r;
        r.volumes = {pb::studies::thinWallVolume()};
        r.scenarios = resolveScenarios({"day"}, {}, s);
        r.settings.raysPerProbe = 128;
        return bakeProbes(s, r);
    }();
    return set;
}

} // namespace

TEST(WallLeak, LeakModesAndVisibilityCutTheLeakOfThePlainShVolume) {
    const ProbeSet& set = thinWallBake();
    std::size_t shInvalid = 0;
    for (const ProbeState& p : set.states[0])
        shInvalid += shProbeValid(p) ? 0 : 1;
    EXPECT_GT(shInvalid, 0u) << "the probes inside the wall must be classified";
    std::map<std::string, pb::studies::WallLeak> by;
    for (const auto& [name, leak] : pb::studies::wallLeakPerTechnique(set)) {
        std::printf("[ leak ] %-20s lit %.4g dark %.4g ratio %.4f\n", name.c_str(), leak.litMean,
                    leak.darkMean, leak.ratio);
        by[name] = leak;
        EXPECT_GT(leak.litMean, 0.0) << name;
    }
    for (const char* l : {"sh_l1", "sh_l2"}) {
        const std::string t = l;
        const double none = by[t + "/none"].ratio;
        EXPECT_GT(none, 0.0) << t << ": the plain SH volume leaks";
        const double best = std::min(by[t + "/weight"].ratio, by[t + "/validity_mask"].ratio);
        EXPECT_LE(best, 0.5 * none) << t << ": a leak mode must cut the leak at least in half";
        EXPECT_LT(by["ddgi"].ratio, none) << "DDGI's visibility test leaks less than no test";
    }
}
