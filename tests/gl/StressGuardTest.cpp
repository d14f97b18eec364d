// The guards (gi.guard_*) against the stress cases they target (renderer/stress): without the
// guard the case breaks (NaN/Inf, or an image far from the fp32 reference), with it it does
// not; and with every guard as the table gives it, no case of the sweep has a NaN/Inf pixel
// for any default variant. Small frames and bakes: the numbers are the sweep's, not timings.
#include "gl/GlTestFixture.h"

#include "passes/FrameContext.h"
#include "stress/StressSweep.h"
#include "stress/gl/GlStressRenderer.h"

#include <cmath>
#include <cstdio>

namespace pb::test {
namespace {

using stress::StressVariant;

class StressGuardTest : public GlTest {
protected:
    // The case's measurement with `variant` against its reference frame.
    stress::Measurement measure(const std::string& caseName, const StressVariant& variant,
                                int width = 48, int height = 36) {
        stress::CaseOptions o;
        o.width = width;
        o.height = height;
        o.rays = 32;
        o.maxResolution = 64;
        const stress::StressCase c = stress::selectCases(stress::stressCases(o), {caseName})[0];
        const stress::CaseData data = c.build();
        stress::GlStressRenderer renderer(debugOutput());
        const image::ImageF ref = renderer.render(data, stress::referenceVariant()).radiance;
        const stress::RenderedFrame f = renderer.render(data, variant);
        stress::Measurement m = stress::compareRadiance(f.radiance, ref);
        m.nonfiniteGiTexels = f.nonfiniteGiTexels;
        std::string changed;
        for (const std::string& k : variant.differingKeys(StressVariant()))
            changed += " " + k + "=" + variant.get(k);
        std::printf("[ stress ] %s,%s: %lld NaN/Inf pixels (%lld GI texels), median rel %.3g, "
                    "max rel %.3g\n",
                    caseName.c_str(), changed.c_str(), static_cast<long long>(m.nonfinitePixels),
                    static_cast<long long>(m.nonfiniteGiTexels), m.medianRel, m.maxRel);
        return m;
    }
};

StressVariant variant(const std::string& spec, const std::string& exposure,
                      const std::string& clamp) {
    StressVariant v = stress::parseVariantSpec(spec);
    v.set("gi.guard_exposure", exposure);
    v.set("gi.guard_clamp", clamp);
    return v;
}

TEST(PreExposure, IsAPowerOfTwoAndOneNearExposureOne) {
    EXPECT_EQ(render::preExposureScale(1.0f), 1.0f);
    EXPECT_EQ(render::preExposureScale(1.5f), 1.0f);
    EXPECT_EQ(render::preExposureScale(0.6f), 1.0f);
    EXPECT_EQ(render::preExposureScale(2.0f), 2.0f);
    EXPECT_EQ(render::preExposureScale(1e-6f), std::ldexp(1.0f, -19)); // log2 = -19.93
    EXPECT_EQ(render::preExposureScale(1e6f), std::ldexp(1.0f, 19));
    EXPECT_EQ(render::preExposureScale(0.0f), 1.0f);
    EXPECT_EQ(render::preExposureScale(-1.0f), 1.0f);
    EXPECT_EQ(render::preExposureScale(INFINITY), 1.0f);
    EXPECT_EQ(render::preExposureScale(NAN), 1.0f);
}

// Light x 1e-6 at exposure 1e6: radiance 1e-7 is below fp16's smallest normal (6.1e-5); the
// RGBA16F radiance target flushes it, the frame goes black. Pre-exposed, it is ~1.
TEST_F(StressGuardTest, ExposureGuardKeepsDimLightingInRange) {
    const stress::Measurement off = measure("light=1e-06", variant("d", "off", "on"));
    const stress::Measurement on = measure("light=1e-06", variant("d", "on", "on"));
    EXPECT_GT(off.medianRel, 0.5);
    EXPECT_LT(on.medianRel, 0.05); // what is left: the rgba16f probes' denormals
    // r11g11b10f: below its smallest normal the apply pass's "covered" blue floor shows.
    const stress::Measurement r11 =
        measure("light=1e-06", variant("r:gi.target_format=r11g11b10f", "off", "on"));
    const stress::Measurement r11on =
        measure("light=1e-06", variant("r:gi.target_format=r11g11b10f", "on", "on"));
    EXPECT_GT(r11.medianRel, 1.0);
    EXPECT_LT(r11on.medianRel, 0.05);
}

// Light x 1e6, fp16 math on rgba32f probes: the mediump fetch and the fp16 sums overflow.
TEST_F(StressGuardTest, ExposureGuardKeepsBrightLightingFinite) {
    const std::string spec = "f:gi.precision=fp16,probes.format=rgba32f";
    const stress::Measurement off = measure("light=1e+06", variant(spec, "off", "off"));
    const stress::Measurement on = measure("light=1e+06", variant(spec, "on", "off"));
    EXPECT_GT(off.nonfinitePixels, 0);
    EXPECT_EQ(on.nonfinitePixels, 0);
    EXPECT_EQ(on.nonfiniteGiTexels, 0);
    EXPECT_LT(on.medianRel, 0.01);
}

// Light x 1e6 and x 1e-6 with fp16 and BC6H probes: the bake's storage scale
// (probes/StorageScale.h) keeps the stored irradiance inside the format's normals, where it
// used to be clamped to 65504 (median 0.56) or stored as denormals (bc6h: 0.058).
TEST_F(StressGuardTest, StorageScaleKeepsExtremeLightingInTheProbeFormat) {
    for (const char* light : {"light=1e+06", "light=1e-06"})
        for (const char* format : {"rgba16f", "bc6h"}) {
            const stress::Measurement m =
                measure(light, variant(std::string("p:probes.format=") + format, "on", "on"));
            EXPECT_EQ(m.nonfinitePixels, 0) << light << " " << format;
            EXPECT_LT(m.medianRel, 0.05) << light << " " << format;
        }
}

// An emissive of 1e6 at exposure 1 (no pre-exposure can help): fp16 sums next to it pass
// 65504. The clamp stores the format's largest value instead of Inf.
TEST_F(StressGuardTest, ClampGuardKeepsAHotSpotFinite) {
    const stress::Measurement off =
        measure("hot_spot=1e+06", variant("f:gi.precision=fp16", "on", "off"), 64, 48);
    const stress::Measurement on =
        measure("hot_spot=1e+06", variant("f:gi.precision=fp16", "on", "on"), 64, 48);
    EXPECT_GT(off.nonfiniteGiTexels, 0);
    EXPECT_EQ(on.nonfiniteGiTexels, 0);
    EXPECT_EQ(on.nonfinitePixels, 0);
}

// A 1x1 frame at quarter resolution: its one GI texel used to stand for GBuffer pixel (1, 1),
// outside the frame (depth 0: a point on the near plane).
TEST_F(StressGuardTest, QuarterResolutionOfATinyFrameReadsInsideTheGBuffer) {
    const stress::Measurement m =
        measure("resolution=1x1", stress::parseVariantSpec("q:gi.resolution=quarter"));
    EXPECT_EQ(m.pixels, 1);
    EXPECT_LT(m.maxRel, 0.01);
}

// The promise: with the guards on, no NaN or Inf reaches the final image in any case
// for any default variant (the resolution cases capped at 64x64 here).
TEST_F(StressGuardTest, NoCaseHasANonFinitePixelWithTheGuards) {
    stress::CaseOptions o;
    o.width = 24;
    o.height = 18;
    o.rays = 16;
    o.maxResolution = 64;
    stress::SweepOptions so;
    so.variants = stress::defaultVariants();
    so.guards = stress::RunGuards::AsGiven;
    so.analyse = false;
    stress::GlStressRenderer renderer(debugOutput());
    const stress::SweepResult r = stress::runSweep(stress::stressCases(o), so, renderer);
    EXPECT_EQ(r.runs.size(), r.cases.size() * so.variants.size());
    for (const stress::CaseSummary& c : r.cases)
        EXPECT_EQ(c.reference.nonfinitePixels, 0) << c.name;
    for (const stress::StressRun& run : r.runs) {
        EXPECT_TRUE(run.m.error.empty())
            << run.caseName << " " << run.variant << ": " << run.m.error;
        EXPECT_EQ(run.m.nonfinitePixels, 0) << run.caseName << " " << run.variant;
        EXPECT_EQ(run.m.nonfiniteGiTexels, 0) << run.caseName << " " << run.variant;
    }
}

} // namespace
} // namespace pb::test
