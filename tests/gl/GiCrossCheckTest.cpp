// Issue 4's cross-check: the GPU DDGI lookup (common_ddgi.glsl, through the point evaluator
// that runs the apply pass's code) against the CPU reference sampler (probes/ProbeSampler)
// at 10,000 random (position, normal, view) triples over a baked built-in scene with a root
// and a rotated nested volume. fp32 math + RGBA32F target: max relative error <= 1e-3.
// Relative error per channel: |gpu - cpu| / max(|cpu|, 1e-3 * the largest |cpu| of the run)
// (the bake's quantisation-error convention: near-black values are judged absolutely).
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/GiPointEvaluator.h"
#include "probes/ProbeSampler.h"
#include "stress/StressCases.h"

#include <algorithm>
#include <cstdio>
#include <random>

namespace pb::test {
namespace {

struct CheckResult {
    double maxRel = 0, meanRel = 0, maxWeightError = 0;
    int points = 0, covered = 0, inChild = 0, worst = -1;
};

glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        glm::vec3 v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-3f) return glm::normalize(v);
    }
}

// Points uniform over the root box grown by one cell per side (edge fade and outside too).
std::vector<render::GiPoint> randomPoints(const probes::ProbeSet& set, int n, unsigned seed) {
    const probes::ProbeVolume& root = set.volumes[0];
    std::mt19937 rng(seed);
    glm::vec3 ext = root.halfExtents + root.cellSize();
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<render::GiPoint> pts(static_cast<size_t>(n));
    for (auto& p : pts) {
        p.position = root.toWorld(glm::vec3(u(rng), u(rng), u(rng)) * ext);
        p.normal = randomUnit(rng);
        p.view = randomUnit(rng);
    }
    return pts;
}

CheckResult crossCheck(const probes::ProbeSet& set, const profile::Profile& prof, int n) {
    render::GpuProbes gpu(set, 0);
    gl::ProgramCache programs;
    render::GiPointEvaluator eval(gpu, prof, programs);
    std::vector<render::GiPoint> pts = randomPoints(set, n, 20261122);
    std::vector<glm::vec4> g = eval.evaluate(pts);
    probes::ProbeSampler cpu(set, 0);
    std::vector<probes::IrradianceSample> c(pts.size());
    float largest = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        c[i] = cpu.sample(pts[i].position, pts[i].normal, pts[i].view);
        for (int k = 0; k < 3; ++k)
            largest = std::max(largest, std::abs(c[i].irradiance[k]));
    }
    CheckResult r;
    r.points = n;
    const double floor = 1e-3 * largest;
    for (size_t i = 0; i < pts.size(); ++i) {
        double rel = 0;
        for (int k = 0; k < 3; ++k)
            rel = std::max(rel, std::abs(double(g[i][k]) - c[i].irradiance[k]) /
                                    std::max(double(std::abs(c[i].irradiance[k])), floor));
        r.maxWeightError = std::max(r.maxWeightError, std::abs(double(g[i].w) - c[i].weight));
        if (rel > r.maxRel) r.worst = int(i);
        r.maxRel = std::max(r.maxRel, rel);
        r.meanRel += rel / double(n);
        r.covered += c[i].weight > 0 ? 1 : 0;
        r.inChild += c[i].volume == 1 ? 1 : 0;
    }
    return r;
}

class GiCrossCheckTest : public GlBackendTest {};

TEST_P(GiCrossCheckTest, GpuMatchesCpuReferenceAtFp32Rgba32f) {
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba32f);
    ASSERT_EQ(set.volumes.size(), 2u);
    profile::Profile prof;
    prof.applyOverride("gi.target_format=rgba32f");
    CheckResult r = crossCheck(set, prof, 10000);
    std::printf("[ cross-check ] %s, rgba32f probes, fp32, rgba32f target: N = %d (%d inside a "
                "volume, %d in the child), max rel %.3g, mean rel %.3g, max |weight| error %.3g\n",
                GetParam().c_str(), r.points, r.covered, r.inChild, r.maxRel, r.meanRel,
                r.maxWeightError);
    // The rest lie outside the root's fade region or see only invalid probes.
    EXPECT_GT(r.covered, 6000) << "most points must be inside a volume";
    EXPECT_GT(r.inChild, 200) << "the nested volume must be exercised too";
    EXPECT_GT(set.invalidCount(), 0u) << "invalid probes must be exercised too";
    size_t relocated = 0;
    for (const auto& states : set.states)
        for (const auto& s : states)
            relocated += s.offset != glm::vec3(0.0f) ? 1 : 0;
    EXPECT_GT(relocated, 0u) << "relocated probes must be exercised too";
    EXPECT_LE(r.maxRel, 1e-3) << "worst point #" << r.worst;
    EXPECT_LE(r.maxWeightError, 1e-3);
}

// Every stored format is sampled as stored (half bits, BC6H blocks): the CPU reference samples
// the decoded texels, so the GPU must agree as closely as at rgba32f.
TEST_P(GiCrossCheckTest, GpuMatchesCpuForHalfAndBc6hProbes) {
    for (probes::StorageFormat f : {probes::StorageFormat::Rgba16f, probes::StorageFormat::Bc6h}) {
        profile::Profile prof;
        prof.applyOverride("gi.target_format=rgba32f");
        CheckResult r = crossCheck(giTestProbes(f), prof, 2500);
        std::printf("[ cross-check ] %s, %s probes: N = %d, max rel %.3g, mean rel %.3g\n",
                    GetParam().c_str(), probes::formatName(f), r.points, r.maxRel, r.meanRel);
        EXPECT_LE(r.maxRel, 1e-3) << probes::formatName(f) << ", worst point #" << r.worst;
    }
}

// Irradiance far outside fp16's range is stored times a power of two (probes/StorageScale.h):
// the GPU multiplies 1/scale back in - folded into gi.guard_exposure's per-fetch multiply, or
// once per pixel without the guard - and must still match the CPU, which sees true values.
TEST_P(GiCrossCheckTest, StorageScaledProbesMatchTheCpuWithAndWithoutTheExposureGuard) {
    for (float k : {1e6f, 1e-6f}) {
        probes::ProbeSet bright = giTestProbes(probes::StorageFormat::Rgba32f);
        for (probes::ProbeTexture& t : bright.irradiance[0])
            for (std::size_t i = 0; i < t.texels.size(); ++i)
                t.texels[i] *= i % 4 == 3 ? 1.0f : k;
        for (probes::StorageFormat f :
             {probes::StorageFormat::Rgba16f, probes::StorageFormat::Bc6h}) {
            const probes::ProbeSet set = stress::inStorageFormat(bright, f);
            EXPECT_NE(set.irradiance[0][0].storageScale, 1.0f);
            for (const char* guard : {"on", "off"}) {
                profile::Profile prof;
                prof.applyOverride("gi.target_format=rgba32f");
                prof.applyOverride(std::string("gi.guard_exposure=") + guard);
                CheckResult r = crossCheck(set, prof, 1000);
                std::printf("[ cross-check ] %s, light x%g, %s probes, guard %s: max rel %.3g\n",
                            GetParam().c_str(), double(k), probes::formatName(f), guard, r.maxRel);
                EXPECT_LE(r.maxRel, 1e-3) << k << " " << probes::formatName(f) << " " << guard;
            }
        }
    }
}

// Math-identical switches: the same numbers up to float summation order.
TEST_P(GiCrossCheckTest, LoopAndOrderVariantsMatchTheReference) {
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba32f);
    for (const char* sw : {"gi.loops=split", "gi.probe_order=slice_first"}) {
        profile::Profile prof;
        prof.applyOverride("gi.target_format=rgba32f");
        prof.applyOverride(sw);
        CheckResult r = crossCheck(set, prof, 2500);
        std::printf("[ cross-check ] %s, %s: max rel %.3g\n", GetParam().c_str(), sw, r.maxRel);
        EXPECT_LE(r.maxRel, 1e-3) << sw;
    }
}

PB_INSTANTIATE_HEADLESS_BACKENDS(GiCrossCheckTest);

} // namespace
} // namespace pb::test
