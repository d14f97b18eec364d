// Sparse probe storage on the GPU (issue 9, item 6): the packed tiles, found through the
// indirection in the probe state texture (GpuProbes.h), sample as the dense layout where
// probes exist, and an absent probe outside geometry is read as its nearest stored probe
// exactly as the CPU sampler reads it (issue 18, probes/AbsentProbeFill.h).
//
// Tolerance: the texels are the same bits, but a packed tile sits elsewhere in a texture of
// another size, so the normalised coordinate (tile + local) / size rounds differently in its
// last bit and GL's limited sub-texel filter precision may round a weight the other way.
// The bound is the one of the math-identical switches (GiFrameTest): 1e-3 relative on the
// RGBA32F GI target; the test prints how many pixels are not bit-identical.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/FrameRenderer.h"
#include "frame/GiPointEvaluator.h"
#include "frame/Readback.h"
#include "passes/GiApplyPass.h"
#include "profile/GiVolumeLod.h"
#include "probes/ProbeSampler.h"
#include "probes/store/SparseStorage.h"
#include "raytrace/StaticTriangles.h"

#include <algorithm>
#include <cstdio>
#include <random>

namespace pb::test {
namespace {

constexpr int kGiSparseW = 160, kGiSparseH = 90;

// giTestProbes (a root and a rotated child over `rooms`, every 7th probe invalid) stored
// sparse: invalid probes and probes at no surface cell left out.
const probes::ProbeSet& sparseProbes() {
    static const probes::ProbeSet set = [] {
        probes::ProbeSet s = giTestProbes(probes::StorageFormat::Rgba16f);
        probes::applySparseStorage(s, raytrace::staticBakeTriangles(giTestScene()));
        return s;
    }();
    return set;
}

// Every `every`-th probe stored (every = 4: enough left-out probes that some lookups meet
// nothing else; rooms has few probes far from a surface), or with every = 0 all but probe 1
// of each volume (its packed grid then has the dense grid's shape). The valid probes left out
// keep nothing (lookups read stand-ins for them) or their irradiance (irradiance-only).
probes::ProbeSet storedEvery(int every,
                             probes::FreeSpace freeSpace = probes::FreeSpace::StandIns) {
    probes::ProbeSet s = giTestProbes(probes::StorageFormat::Rgba16f);
    if (every == 0) // exactly one probe absent: the marked-invalid probes (texels intact) back
        for (auto& states : s.states)
            for (auto& p : states)
                p.valid = true;
    std::vector<std::vector<std::uint8_t>> keep;
    for (const auto& states : s.states) {
        keep.emplace_back(states.size(), every == 0 ? 1 : 0);
        if (every == 0) keep.back()[1] = 0;
        for (std::size_t i = 0; every > 0 && i < states.size(); i += std::size_t(every))
            keep.back()[i] = 1;
    }
    probes::storeOnly(s, keep, freeSpace);
    return s;
}

image::ImageF renderGi(const probes::ProbeSet& set) {
    render::GiOptions gi;
    gi.probes = &set;
    gi.profile.applyOverride("gi.target_format=rgba32f");
    const scene::Scene& s = giTestScene();
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), kGiSparseW,
                                    kGiSparseH));
    for (const auto& p : r.passes())
        if (auto* pass = dynamic_cast<const render::GiApplyPass*>(p.get()))
            return render::readFloat(*pass->target());
    ADD_FAILURE() << "no GI apply pass";
    return {};
}

struct Difference {
    double maxRel = 0;
    std::size_t differing = 0, lit = 0, values = 0;
};

// |a - b| / max(|b|, 1e-3 * max|b|) over RGBA (A is the weight).
Difference compare(const std::vector<float>& a, const std::vector<float>& b) {
    Difference d;
    float largest = 0;
    for (float v : b)
        largest = std::max(largest, std::abs(v));
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        d.maxRel = std::max(d.maxRel, std::abs(double(a[i]) - b[i]) /
                                          std::max(double(std::abs(b[i])), 1e-3 * largest));
        d.differing += a[i] != b[i] ? 1 : 0;
        d.lit += b[i] > 0.0f ? 1 : 0;
    }
    d.values = b.size();
    return d;
}

class GiSparseTest : public GlTest {};

TEST_F(GiSparseTest, SparseSetRendersTheDenseImage) {
    const probes::ProbeSet& dense = giTestProbes(probes::StorageFormat::Rgba16f);
    const probes::ProbeSet& sparse = sparseProbes();
    const std::size_t invalid = dense.invalidCount();
    std::printf("[ sparse ] rooms: %zu of %zu probes stored (%zu invalid in the dense set)\n",
                sparse.storedCount(), dense.probeCount(), invalid);
    ASSERT_LT(sparse.storedCount(), dense.probeCount() - invalid)
        << "no valid probe was left out: the test would not exercise the packing";
    EXPECT_LT(render::GpuProbes(sparse, 0).bytes(), render::GpuProbes(dense, 0).bytes());
    // The memory estimates (gi.volume_lod budgets, the cost model) count what is uploaded.
    EXPECT_EQ(render::GpuProbes(sparse, 0).bytes(),
              profile::gpuVolumeBytes(sparse, 0) + profile::gpuVolumeBytes(sparse, 1));

    const image::ImageF expected = renderGi(dense), got = renderGi(sparse);
    ASSERT_EQ(got.pixels.size(), expected.pixels.size());
    const Difference d = compare(got.pixels, expected.pixels);
    std::printf("[ sparse ] GI target: %zu of %zu values not bit-identical, max rel %.3g\n",
                d.differing, d.values, d.maxRel);
    EXPECT_GT(d.lit, d.values / 4) << "the view must show lit GI";
    EXPECT_LE(d.maxRel, 1e-3);
}

// GPU lookups anywhere in the root box (surfaces, empty air where stand-ins are read, the
// child) of `sparse` against the CPU sampler of the same set (GiCrossCheckTest's metric);
// `standIns`: the points whose CPU lookup read a stand-in for an absent probe;
// `irradianceOnly`: those that read an irradiance-only probe.
Difference againstCpu(const probes::ProbeSet& sparse, int& standIns, int* irradianceOnly = nullptr) {
    const probes::ProbeVolume& root = sparse.volumes[0];
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<render::GiPoint> pts(4000);
    for (auto& p : pts) {
        p.position = root.toWorld(glm::vec3(u(rng), u(rng), u(rng)) * root.halfExtents);
        p.normal = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
        p.view = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
    }
    profile::Profile prof;
    prof.applyOverride("gi.target_format=rgba32f");
    gl::ProgramCache programs;
    render::GpuProbes gpu(sparse, 0);
    render::GiPointEvaluator eval(gpu, prof, programs);
    std::vector<float> a, b;
    for (const glm::vec4& v : eval.evaluate(pts))
        a.insert(a.end(), {v.x, v.y, v.z, v.w});
    const probes::ProbeSampler cpu(sparse, 0);
    standIns = 0;
    if (irradianceOnly) *irradianceOnly = 0;
    for (const render::GiPoint& p : pts) {
        const probes::IrradianceSample c = cpu.sample(p.position, p.normal, p.view);
        b.insert(b.end(), {c.irradiance.x, c.irradiance.y, c.irradiance.z, c.weight});
        standIns += c.filled > 0 ? 1 : 0;
        if (irradianceOnly) *irradianceOnly += c.irradianceOnly > 0 ? 1 : 0;
    }
    return compare(a, b);
}

// Irradiance-only probes (issue 18): their tiles packed after the stored ones, their code
// flagged, no visibility read - as the CPU sampler does.
TEST_F(GiSparseTest, IrradianceOnlyProbesAreReadWithoutVisibilityLikeTheCpuDoes) {
    const probes::ProbeSet quarter = storedEvery(4, probes::FreeSpace::Irradiance);
    const render::GpuProbes gpu(quarter, 0);
    int shorter = 0; // the visibility texture ends with the stored tiles
    for (const auto& v : gpu.volumes()) {
        const int visibility = v.textures[render::kDdgiVisibility].desc().layers,
                  irradiance = v.textures[render::kDdgiIrradiance].desc().layers;
        EXPECT_LE(visibility, irradiance) << v.name;
        shorter += visibility < irradiance ? 1 : 0;
    }
    EXPECT_GT(shorter, 0) << "no visibility texture is smaller than its irradiance texture";
    int standIns = 0, irradianceOnly = 0;
    const Difference d = againstCpu(quarter, standIns, &irradianceOnly);
    std::printf("[ sparse ] every 4th stored: %zu of %zu values not bit-identical, max rel %.3g, "
                "%d of 4000 points read irradiance-only probes\n",
                d.differing, d.values, d.maxRel, irradianceOnly);
    EXPECT_EQ(standIns, 0) << "a probe with irradiance read a stand-in";
    EXPECT_GT(irradianceOnly, 1000) << "too few points read an irradiance-only probe";
    EXPECT_LE(d.maxRel, 1e-3);
}

// The default bake's mix (FreeSpace::Ranked, the default budget): some left-out probes keep a
// tile, the rest are read as stand-ins - on the GPU as on the CPU.
TEST_F(GiSparseTest, ARankedMixOfTilesAndStandInsIsReadLikeTheCpuDoes) {
    const probes::ProbeSet quarter = storedEvery(4, probes::FreeSpace::Ranked);
    int standIns = 0, irradianceOnly = 0;
    const Difference d = againstCpu(quarter, standIns, &irradianceOnly);
    std::printf("[ sparse ] every 4th stored, ranked tiles: %zu of %zu values not "
                "bit-identical, max rel %.3g, of 4000 points %d read stand-ins and %d "
                "irradiance-only probes\n",
                d.differing, d.values, d.maxRel, standIns, irradianceOnly);
    EXPECT_GT(standIns, 100) << "too few points read a stand-in";
    EXPECT_GT(irradianceOnly, 100) << "too few points read an irradiance-only probe";
    EXPECT_LE(d.maxRel, 1e-3);
}

// The default storage: the probes left out keep nothing, and both the GPU and the CPU read
// their nearest stored probe in their place.
TEST_F(GiSparseTest, AbsentProbesAreReadAsTheirStandInsLikeTheCpuDoes) {
    const probes::ProbeSet quarter = storedEvery(4);
    int standIns = 0;
    const Difference d = againstCpu(quarter, standIns);
    std::printf("[ sparse ] every 4th stored, no irradiance kept: %zu of %zu values not "
                "bit-identical, max rel %.3g, %d of 4000 points read stand-ins\n",
                d.differing, d.values, d.maxRel, standIns);
    EXPECT_GT(standIns, 1000) << "too few points read a stand-in";
    EXPECT_LE(d.maxRel, 1e-3);
}

// One probe absent per volume: the packed grid has the dense grid's shape, and the shader
// must still go through the indirection (the tiles after the gap moved by one).
TEST_F(GiSparseTest, OneAbsentProbePerVolumeStillUsesTheIndirection) {
    const probes::ProbeSet one = storedEvery(0);
    const render::GpuProbes gpu(one, 0); // named: volumes() refers into it
    ASSERT_TRUE(gpu.anySparse());
    for (const auto& v : gpu.volumes())
        ASSERT_TRUE(v.sparse && v.packedCounts == v.counts) << v.name;
    int standIns = 0;
    const Difference d = againstCpu(one, standIns);
    std::printf("[ sparse ] one absent per volume: max rel %.3g\n", d.maxRel);
    EXPECT_LE(d.maxRel, 1e-3);
}

// A set with a sparse volume builds every volume's lookup with the tile code in w: the fully
// stored root (its own grid, no packing) must find its tiles through w as well.
TEST_F(GiSparseTest, AFullyStoredVolumeOfASparseSetReadsItsTilesThroughTheCode) {
    probes::ProbeSet s = giTestProbes(probes::StorageFormat::Rgba16f);
    for (auto& p : s.states[0])
        p.valid = true; // the root keeps every probe: stored dense
    std::vector<std::vector<std::uint8_t>> keep{std::vector<std::uint8_t>(s.states[0].size(), 1),
                                                std::vector<std::uint8_t>(s.states[1].size(), 0)};
    for (std::size_t i = 0; i < keep[1].size(); i += 3)
        keep[1][i] = 1;
    probes::storeOnly(s, keep);
    const render::GpuProbes gpu(s, 0);
    ASSERT_TRUE(gpu.anySparse());
    ASSERT_FALSE(gpu.volumes()[0].sparse);
    ASSERT_TRUE(gpu.volumes()[1].sparse);
    int standIns = 0;
    const Difference d = againstCpu(s, standIns);
    std::printf("[ sparse ] dense root + sparse child: max rel %.3g\n", d.maxRel);
    EXPECT_LE(d.maxRel, 1e-3);
}

} // namespace
} // namespace pb::test
