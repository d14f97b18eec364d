// The SH technique's cross-check (issue 19): the GPU lookup (common_sh.glsl, through the point
// evaluator that runs the apply pass's code, hardware trilinear 3D fetches) against the CPU
// reference (probes/sh/ShSampler) at random (position, normal, view) triples over the baked
// built-in scene with a root and a rotated nested volume, for sh_l1 and sh_l2 and every
// gi.sh_leak mode. Same error measure as GiCrossCheckTest: |gpu - cpu| / max(|cpu|, 1e-3 x
// the largest |cpu| of the run), at most 1e-3.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "core/Error.h"
#include "frame/GiPointEvaluator.h"
#include "passes/GpuShTextures.h"
#include "probes/sh/ShSampler.h"
#include "raytrace/StaticTriangles.h"
#include "probes/store/SparseStorage.h"

#include <algorithm>
#include <cstdio>
#include <random>

namespace pb::test {
namespace {

glm::vec3 giShCrossCheckRandomUnit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        glm::vec3 v(g(rng), g(rng), g(rng));
        if (glm::length(v) > 1e-3f) return glm::normalize(v);
    }
}

struct ShCheck {
    double maxRel = 0, maxWeightError = 0;
    int covered = 0, inChild = 0, worst = -1;
};

ShCheck shCrossCheck(const probes::ProbeSet& set, const std::string& technique,
                     const std::string& leak, int n) {
    profile::Profile prof;
    prof.applyOverride("gi.target_format=rgba32f");
    prof.applyOverride("gi.technique=" + technique);
    prof.applyOverride("gi.sh_leak=" + leak);
    render::GpuProbes gpu(set, 0, {}, prof.gi.technique, prof.gi.shLeak);
    gl::ProgramCache programs;
    render::GiPointEvaluator eval(gpu, prof, programs);
    const probes::ProbeVolume& root = set.volumes[0];
    std::mt19937 rng(20261125);
    const glm::vec3 ext = root.halfExtents + root.cellSize();
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<render::GiPoint> pts(static_cast<size_t>(n));
    for (auto& p : pts) {
        p.position = root.toWorld(glm::vec3(u(rng), u(rng), u(rng)) * ext);
        p.normal = giShCrossCheckRandomUnit(rng);
        p.view = giShCrossCheckRandomUnit(rng);
    }
    const std::vector<glm::vec4> g = eval.evaluate(pts);
    const probes::ShSampler cpu(set, 0, "test probes");
    probes::ShSampleOptions o;
    o.coefficients = render::shCoefficientCount(prof.gi.technique);
    o.leak = leak == "weight"          ? probes::ShLeak::Weight
             : leak == "validity_mask" ? probes::ShLeak::ValidityMask
                                       : probes::ShLeak::None;
    std::vector<probes::IrradianceSample> c(pts.size());
    float largest = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        c[i] = cpu.sample(pts[i].position, pts[i].normal, pts[i].view, o);
        for (int k = 0; k < 3; ++k)
            largest = std::max(largest, std::abs(c[i].irradiance[k]));
    }
    ShCheck r;
    const double floor = 1e-3 * largest;
    for (size_t i = 0; i < pts.size(); ++i) {
        double rel = 0;
        for (int k = 0; k < 3; ++k)
            rel = std::max(rel, std::abs(double(g[i][k]) - c[i].irradiance[k]) /
                                    std::max(double(std::abs(c[i].irradiance[k])), floor));
        r.maxWeightError = std::max(r.maxWeightError, std::abs(double(g[i].w) - c[i].weight));
        if (rel > r.maxRel) r.worst = int(i);
        r.maxRel = std::max(r.maxRel, rel);
        r.covered += c[i].weight > 0 ? 1 : 0;
        r.inChild += c[i].volume == 1 && c[i].weight > 0 ? 1 : 0;
    }
    return r;
}

class GiShCrossCheckTest : public GlBackendTest {};

TEST_P(GiShCrossCheckTest, GpuMatchesTheCpuShSamplerForEveryTechniqueAndLeakMode) {
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba16f);
    ASSERT_TRUE(set.hasSh());
    ASSERT_EQ(set.volumes.size(), 2u);
    EXPECT_GT(set.invalidCount(), 0u) << "invalid probes must be exercised";
    for (const char* technique : {"sh_l1", "sh_l2"})
        for (const char* leak : {"none", "weight", "validity_mask"}) {
            const ShCheck r = shCrossCheck(set, technique, leak, 4000);
            std::printf("[ sh cross-check ] %s, %s, %s: %d covered, %d in the child, max rel "
                        "%.3g, max |weight| error %.3g\n",
                        GetParam().c_str(), technique, leak, r.covered, r.inChild, r.maxRel,
                        r.maxWeightError);
            EXPECT_GT(r.covered, 2000) << technique << " " << leak;
            EXPECT_GT(r.inChild, 100) << technique << " " << leak;
            EXPECT_LE(r.maxRel, 1e-3) << technique << " " << leak << " worst #" << r.worst;
            EXPECT_LE(r.maxWeightError, 1e-3) << technique << " " << leak;
        }
}

// A sparse set (absent probes read as their nearest stored one, probes/sh/ShAbsentFill.h): the
// upload and the CPU sampler fill them alike, in every mode.
TEST_P(GiShCrossCheckTest, SparseSetGpuMatchesTheCpuShSampler) {
    probes::ProbeSet set = giTestProbes(probes::StorageFormat::Rgba16f);
    probes::applySparseStorage(set, raytrace::staticBakeTriangles(giTestScene()));
    ASSERT_LT(set.storedCount(), set.probeCount()) << "nothing absent: vacuous";
    for (const char* technique : {"sh_l1", "sh_l2"})
        for (const char* leak : {"none", "weight", "validity_mask"}) {
            const ShCheck r = shCrossCheck(set, technique, leak, 2000);
            std::printf("[ sh cross-check ] %s sparse, %s, %s: %d covered, max rel %.3g\n",
                        GetParam().c_str(), technique, leak, r.covered, r.maxRel);
            EXPECT_GT(r.covered, 1000) << technique << " " << leak;
            EXPECT_LE(r.maxRel, 1e-3) << technique << " " << leak << " worst #" << r.worst;
            EXPECT_LE(r.maxWeightError, 1e-3) << technique << " " << leak;
        }
}

TEST_P(GiShCrossCheckTest, AProbeSetWithoutShIsAOneLineReBakeError) {
    probes::ProbeSet set = giTestProbes(probes::StorageFormat::Rgba16f);
    set.sh.clear();
    try {
        render::GpuProbes gpu(set, 0, {}, profile::GiTechnique::ShL1);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("re-bake"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
}

TEST_P(GiShCrossCheckTest, ShTexturesTakeTheDocumentedBytesPerProbe) {
    const probes::ProbeSet& set = giTestProbes(probes::StorageFormat::Rgba16f);
    std::size_t probes = 0;
    for (const auto& v : set.volumes)
        probes += std::size_t(v.probeCount());
    for (auto t : {profile::GiTechnique::ShL1, profile::GiTechnique::ShL2}) {
        render::GpuProbes gpu(set, 0, {}, t);
        EXPECT_EQ(gpu.bytes(), probes * render::shBytesPerProbe(t));
    }
    EXPECT_LE(render::shBytesPerProbe(profile::GiTechnique::ShL1), 25u);
    EXPECT_LE(render::shBytesPerProbe(profile::GiTechnique::ShL2), 60u);
}

PB_INSTANTIATE_HEADLESS_BACKENDS(GiShCrossCheckTest);

} // namespace
} // namespace pb::test
