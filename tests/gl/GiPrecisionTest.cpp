// gi.precision=fp16 really computes in fp16 on this GL (DESIGN.md: llvmpipe lowers mediump
// only where an expression is mediump end to end), and what it costs in accuracy.
//
// The proof is an overflow: a probe irradiance of 60000 is a finite half (max 65504), but a
// weight above 65504 / 60000 = 1.09 times it is not. Next to a probe that faces the surface
// the lookup's product w * E is 1.14 * 60000: fp16 arithmetic gives Inf, fp32 gives 60000
// back after the normalisation. A pass that only declared mediump (and computed in fp32)
// would return 60000 in both.
#include "gl/GiSyntheticProbes.h"
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/GiPointEvaluator.h"
#include "probes/ProbeSampler.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace pb::test {
namespace {

std::vector<glm::vec4> evaluate(const probes::ProbeSet& set, const std::string& precision,
                                const std::vector<render::GiPoint>& points) {
    render::GpuProbes gpu(set, 0);
    gl::ProgramCache programs;
    profile::Profile prof;
    prof.applyOverride("gi.target_format=rgba32f");
    prof.applyOverride("gi.precision=" + precision);
    render::GiPointEvaluator eval(gpu, prof, programs);
    return eval.evaluate(points);
}

class GiPrecisionTest : public GlBackendTest {};

TEST_P(GiPrecisionTest, Fp16OverflowsWhereFp32DoesNot) {
    // 3x3x3 probes 1 m apart; the centre probe sits at the origin.
    const float kE = 60000.0f;
    const probes::ProbeSet set = syntheticProbes(
        {syntheticVolume("box", glm::vec3(0.0f), glm::vec3(1.0f), glm::ivec3(3))},
        [&](int, const glm::vec3&, const glm::ivec3&) { return glm::vec3(kE); },
        probes::StorageFormat::Rgba32f);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    // 0.3 m below the centre probe, facing it: trilinear 0.95 x wrap 1.2 = 1.14 on one probe.
    const render::GiPoint nearProbe{{0.0f, -0.3f, 0.0f}, up, up};
    // A cell centre: every weight well below 1, the sums stay below 65504.
    const render::GiPoint cellCentre{{0.5f, 0.5f, 0.5f}, up, up};
    const std::vector<render::GiPoint> points{nearProbe, cellCentre};

    const std::vector<glm::vec4> fp32 = evaluate(set, "fp32", points);
    const std::vector<glm::vec4> fp16 = evaluate(set, "fp16", points);
    std::printf("[ fp16 proof ] %s, E = %g: near the probe fp32 %g, fp16 %g; at a cell centre fp32 "
                "%g, fp16 %g\n",
                GetParam().c_str(), double(kE), double(fp32[0].x), double(fp16[0].x),
                double(fp32[1].x), double(fp16[1].x));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(fp32[0][c], kE, kE * 1e-5f);
        EXPECT_NEAR(fp32[1][c], kE, kE * 1e-5f);
        EXPECT_TRUE(std::isinf(fp16[0][c])) << "channel " << c << ": " << fp16[0][c];
        // Not broken everywhere: where no intermediate passes 65504, fp16 is close.
        EXPECT_NEAR(fp16[1][c], kE, kE * 4e-3f) << "channel " << c;
    }
    EXPECT_FLOAT_EQ(fp16[0].w, 1.0f); // the fade is computed in highp, converted exactly
}

// The lossy switch's error against the CPU reference (fp32) on the baked test scene, at the
// cross-check's random points. Reported; bounded loosely (fp16 has an 11-bit mantissa) and
// from below: an error as small as fp32's would mean the fp16 path is not fp16.
TEST_P(GiPrecisionTest, Fp16ErrorAgainstTheReferenceIsReported) {
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba16f);
    const probes::ProbeVolume& root = set.volumes[0];
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::normal_distribution<float> g;
    auto unit = [&] {
        glm::vec3 v(g(rng), g(rng), g(rng));
        return glm::length(v) > 1e-3f ? glm::normalize(v) : glm::vec3(0, 1, 0);
    };
    std::vector<render::GiPoint> pts(5000);
    for (auto& p : pts) {
        p.position = root.toWorld(glm::vec3(u(rng), u(rng), u(rng)) * root.halfExtents);
        p.normal = unit();
        p.view = unit();
    }
    probes::ProbeSampler cpu(set, 0);
    double largest = 0;
    std::vector<probes::IrradianceSample> ref(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        ref[i] = cpu.sample(pts[i].position, pts[i].normal, pts[i].view);
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, double(ref[i].irradiance[c]));
    }
    for (const char* precision : {"fp32", "fp16"}) {
        const std::vector<glm::vec4> gpu = evaluate(set, precision, pts);
        double maxRel = 0, sumRel = 0;
        int n = 0;
        for (size_t i = 0; i < pts.size(); ++i) {
            if (ref[i].weight <= 0) continue;
            for (int c = 0; c < 3; ++c) {
                double rel = std::abs(double(gpu[i][c]) - ref[i].irradiance[c]) /
                             std::max(double(ref[i].irradiance[c]), 1e-3 * largest);
                maxRel = std::max(maxRel, rel);
                sumRel += rel;
                ++n;
            }
        }
        const double meanRel = sumRel / n;
        std::printf("[ precision ] %s, %s vs the CPU reference (fp32): %d channel values, max "
                    "rel %.3g, mean rel %.3g\n",
                    GetParam().c_str(), precision, n, maxRel, meanRel);
        ASSERT_GT(n, 3000);
        if (std::string(precision) == "fp32") {
            EXPECT_LE(maxRel, 1e-3);
        } else {
            EXPECT_LE(meanRel, 1e-2);
            EXPECT_GT(meanRel, 1e-4) << "as exact as fp32: is the fp16 path computing in fp32?";
        }
    }
}

PB_INSTANTIATE_HEADLESS_BACKENDS(GiPrecisionTest);

} // namespace
} // namespace pb::test
