// The bench runner on a real GL context (no timings asserted): the section timer gives one
// non-negative exclusive time per pass by both methods, the fetch floor draws cleanly, the
// irradiance-only scene reads back exactly the GI the lighting applied, and a tiny plan runs
// with unsupported variants reported instead of thrown.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "bench/gate_gl/GateTiming.h"
#include "bench/runner/FetchFloorPass.h"
#include "bench/runner/IrradianceScene.h"
#include "bench/runner/SectionTimer.h"
#include "bench/runner/SessionRunner.h"
#include "core/Error.h"
#include "frame/FrameRenderer.h"
#include "frame/Readback.h"
#include "passes/GiApplyPass.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace pb::test {
namespace {

using BenchRunnerTest = GlTest;

render::RenderView smallView(const scene::Scene& s, int w = 64, int h = 36) {
    return render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), w, h);
}

render::GiOptions gi(const std::vector<std::string>& sets = {}) {
    render::GiOptions o;
    o.probes = &giTestProbes(probes::StorageFormat::Rgba16f);
    for (const auto& kv : sets)
        o.profile.applyOverride(kv);
    return o;
}

void expectOneSectionPerPass(const render::FrameRenderer& r, const bench::SectionTimer& t) {
    std::vector<std::string> passes, timed;
    for (const auto& p : r.passes())
        passes.push_back(p->name());
    double sum = 0;
    for (const auto& [name, ms] : t.sections()) {
        timed.push_back(name);
        EXPECT_GE(ms, 0.0) << name;
        sum += ms;
    }
    EXPECT_EQ(timed, passes);
    EXPECT_LE(sum, t.frameMs() + 1e-6) << "exclusive times never exceed the frame";
}

TEST_F(BenchRunnerTest, SectionTimerTimesEveryPassByBothMethods) {
    const scene::Scene& s = giTestScene();
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi());
    r.render(smallView(s)); // compile first
    const gl::DriverQuirks quirks = gl::detectDriverQuirks();
    bench::TimingChoice cpu = bench::chooseTiming("cpu", caps(), quirks);
    EXPECT_EQ(cpu.name, "cpu-finish");
    bench::SectionTimer cpuTimer(cpu, caps().es);
    cpuTimer.beginFrame();
    r.render(smallView(s), &cpuTimer);
    ASSERT_TRUE(cpuTimer.endFrame());
    expectOneSectionPerPass(r, cpuTimer);

    bench::TimingChoice cpuTime = bench::chooseTiming("cpu-time", caps(), quirks);
    EXPECT_TRUE(cpuTime.processCpuTime);
    bench::SectionTimer cpuTimeTimer(cpuTime, caps().es);
    cpuTimeTimer.beginFrame();
    r.render(smallView(s), &cpuTimeTimer);
    ASSERT_TRUE(cpuTimeTimer.endFrame());
    expectOneSectionPerPass(r, cpuTimeTimer);
    EXPECT_THROW(bench::chooseTiming("sundial", caps(), quirks), Error);

    // auto follows the driver quirk: a software rasterizer is timed with the CPU clock.
    bench::TimingChoice automatic = bench::chooseTiming("auto", caps(), quirks);
    if (quirks.timerQueriesUntrustworthy) {
        EXPECT_EQ(automatic.name, "cpu-finish");
    }
    if (!caps().timerQuery) GTEST_SKIP() << "no timer queries on this context";
    bench::TimingChoice query = bench::chooseTiming("query", caps(), quirks);
    EXPECT_EQ(query.flushBracketed, quirks.timerQueriesNeedFlush);
    bench::SectionTimer queryTimer(query, caps().es);
    queryTimer.beginFrame();
    r.render(smallView(s), &queryTimer);
    if (queryTimer.endFrame()) expectOneSectionPerPass(r, queryTimer);
}

TEST_F(BenchRunnerTest, FetchFloorDrawsFromTheFramesTexturesWithoutGlErrors) {
    const scene::Scene& s = giTestScene();
    for (const char* res : {"full", "half"}) {
        SCOPED_TRACE(res);
        auto o = gi({std::string("gi.resolution=") + res});
        render::FrameRenderer r(s, render::defaultFrameSettings(s), o);
        r.render(smallView(s));
        bench::FetchFloorPass floor(o.profile);
        floor.execute(r, smallView(s));
        floor.execute(r, smallView(s));
        checkNoGlErrors("fetch floor");
        // The frame is untouched by it: rendering again gives the same image.
        image::Image8 before = r.readOutput();
        r.render(smallView(s));
        EXPECT_EQ(r.readOutput().pixels, before.pixels);
    }
}

// radiance * pi of the irradiance-only scene = the GI target's irradiance where a volume fully
// covers the pixel (weight 1): the bench's "linear GI irradiance" is the GI and nothing else.
TEST_F(BenchRunnerTest, IrradianceSceneReadsBackTheAppliedGi) {
    const scene::Scene& s = giTestScene();
    const scene::Scene white = bench::irradianceOnlyScene(s);
    auto o = gi({"gi.target_format=rgba32f"});
    render::FrameRenderer r(white, render::defaultFrameSettings(s), o);
    r.render(smallView(white));
    image::ImageF radiance = r.readRadiance();
    const gl::Texture* target = nullptr;
    for (const auto& p : r.passes())
        if (auto* g = dynamic_cast<const render::GiApplyPass*>(p.get())) target = g->target();
    ASSERT_NE(target, nullptr);
    image::ImageF e = render::readFloat(*target);
    ASSERT_EQ(e.width, radiance.width);
    int compared = 0;
    for (int y = 0; y < e.height; ++y)
        for (int x = 0; x < e.width; ++x) {
            if (e.at(x, y, 3) < 0.9999f) continue;
            ++compared;
            for (int c = 0; c < 3; ++c) {
                float expect = e.at(x, y, c), got = radiance.at(x, y, c) * glm::pi<float>();
                ASSERT_NEAR(got, expect, 2e-3f * std::max(expect, 0.05f)) << x << "," << y;
            }
        }
    EXPECT_GT(compared, e.width * e.height / 2);
}

// Sessions of one size share one set of interleaved rounds: every profile's row has the same
// reference measurement (no row compares two moments of the machine), each round times its
// frames after an untimed switch frame, and that frame is kept apart.
TEST_F(BenchRunnerTest, SessionsOfOneSizeShareTheirRoundsAndTimeSteadyFrames) {
    const scene::Scene& s = giTestScene();
    profile::PlatformProfile ref, a, b;
    ref.name = "reference";
    a.name = "a";
    a.switches.set("gi.loops", "split");
    b.name = "b";
    b.switches.set("gi.probe_order", "slice_first");
    bench::BenchPlan plan = bench::makeBenchPlan({a, b}, ref, {true, 48, 27});
    bench::RunnerInputs in{&s, &giTestProbes(probes::StorageFormat::Rgba16f),
                           *s.findView("sunlit_room"), render::defaultFrameSettings(s),
                           &debugOutput()};
    bench::RunnerOptions o;
    o.frames = 3;
    o.rounds = 2;
    o.warmup = 1;
    o.fetchFloor = false;
    o.timing = bench::chooseTiming("cpu", caps(), gl::detectDriverQuirks());
    o.es = caps().es;
    std::vector<std::string> lines;
    o.progress = [&](const std::string& l) { lines.push_back(l); };
    const auto sessions = bench::runBenchPlan(plan, in, o);
    ASSERT_EQ(sessions.size(), 2u);
    const bench::VariantResult& refA = sessions[0].reference();
    const bench::VariantResult& refB = sessions[1].reference();
    ASSERT_TRUE(refA.ok() && refB.ok());
    EXPECT_EQ(refA.frameSamples, refB.frameSamples) << "one measurement of the reference";
    EXPECT_EQ(refA.roundMedians, refB.roundMedians);
    for (const auto& session : sessions)
        for (const auto& v : session.variants) {
            SCOPED_TRACE(v.variant.id);
            ASSERT_TRUE(v.ok()) << v.error;
            EXPECT_EQ(v.frameSamples.size(), 6u);      // rounds x frames, steady frames only
            EXPECT_EQ(v.switchFrameSamples.size(), 2u); // one per round, apart
            EXPECT_EQ(v.roundMedians.size(), 2u);
        }
    // The reference appears in both sessions' rounds once: 1 reference + 2 profiles + their
    // reverted (= reference) and applied (= the profile's) variants: 3 distinct variants.
    bool one = false;
    for (const std::string& l : lines)
        one = one || l.find("building 3 variant(s)") != std::string::npos;
    EXPECT_TRUE(one) << "the two sessions were not timed together";
    EXPECT_EQ(sessions[0].machineBefore.valid, true);
}

TEST_F(BenchRunnerTest, TinyPlanRunsAndReportsUnsupportedVariants) {
    const scene::Scene& s = giTestScene();
    profile::PlatformProfile ref, low;
    ref.name = "reference";
    ref.switches.set("gi.target_format", "rgba32f");
    low.name = "low";
    low.switches.set("gi.resolution", "half");
    low.switches.set("gi.loops", "split");
    bench::BenchPlan plan = bench::makeBenchPlan({ref, low}, ref, {true, 64, 36});
    bench::RunnerInputs in{&s, &giTestProbes(probes::StorageFormat::Rgba16f),
                           *s.findView("sunlit_room"), render::defaultFrameSettings(s),
                           &debugOutput()};
    bench::RunnerOptions o;
    o.frames = 1;
    o.rounds = 2;
    o.warmup = 1;
    o.timing = bench::chooseTiming("cpu", caps(), gl::detectDriverQuirks());
    o.es = caps().es;
    std::vector<bench::AccuracyPictures> pictures;
    auto sessions = bench::runBenchPlan(plan, in, o, &pictures);
    ASSERT_EQ(sessions.size(), 2u);
    const auto& refVariant = sessions[0].profile();
    ASSERT_TRUE(refVariant.ok()) << refVariant.error;
    EXPECT_EQ(refVariant.frameSamples.size(), 2u);
    EXPECT_EQ(refVariant.roundMedians.size(), 2u);
    EXPECT_EQ(refVariant.switchFrameSamples.size(), 2u);
    EXPECT_TRUE(refVariant.fetchFloor.has_value());
    EXPECT_DOUBLE_EQ(refVariant.accuracy.flipMean, 0.0) << "the reference against itself";
    EXPECT_TRUE(std::isinf(refVariant.accuracy.psnr));
    EXPECT_DOUBLE_EQ(refVariant.accuracy.relativeMseGi, 0.0);
    EXPECT_GT(refVariant.coverage.fraction, 0.0);
    EXPECT_GT(refVariant.giMemoryMiB, 0.0);
    for (const auto& v : sessions[1].variants) {
        SCOPED_TRACE(v.variant.id);
        ASSERT_TRUE(v.ok()) << v.error;
        // Every pass of the reference frame is timed in every variant, and a variant at half
        // resolution also times its upsample pass.
        std::vector<std::string> names;
        for (const auto& sec : v.sections) {
            names.push_back(sec.name);
            EXPECT_EQ(sec.samples.size(), 2u) << sec.name;
        }
        for (const auto& sec : sessions[0].profile().sections)
            EXPECT_NE(std::find(names.begin(), names.end(), sec.name), names.end()) << sec.name;
        const bool half = v.variant.switches.gi.resolution != profile::GiResolution::Full;
        EXPECT_EQ(std::find(names.begin(), names.end(), "upsample") != names.end(), half);
        EXPECT_TRUE(v.accuracy.measured);
    }
    EXPECT_GT(sessions[1].profile().accuracy.relativeMseGi, 0.0) << "half resolution differs";
    for (const auto& d : sessions[1].deltas)
        EXPECT_TRUE(d.measured) << bench::deltaKindName(d.planned.kind) << " "
                                << d.planned.switchKey;
    EXPECT_EQ(pictures[1].flip.width, 64);
    EXPECT_EQ(pictures[1].frame.width, 64);
    EXPECT_EQ(pictures[1].reference.height, pictures[1].frame.height);

    // A variant the renderer rejects (here: a volume the probe file does not have; likewise a
    // switch value not implemented or a format the driver lacks) is reported, not thrown: the
    // rest of the session still runs.
    profile::PlatformProfile broken = low;
    broken.name = "broken";
    broken.switches.set("gi.volume_lod", "omit:no_such_volume");
    bench::BenchPlan plan2 = bench::makeBenchPlan({broken}, ref, {false, 32, 18});
    auto s2 = bench::runBenchPlan(plan2, in, o);
    EXPECT_FALSE(s2[0].profile().ok());
    EXPECT_NE(s2[0].profile().error.find("no_such_volume"), std::string::npos)
        << s2[0].profile().error;
    EXPECT_TRUE(s2[0].reference().ok());
    EXPECT_FALSE(s2[0].deltas[0].measured);
}

} // namespace
} // namespace pb::test

namespace pb::test {
namespace {

// Past its round budget a verdict still unknown gets more rounds within the time budget, and
// stops at it: a noisy runner is given time to decide, never forever.
TEST(GateSequentialTiming, AnUnknownVerdictRunsOnWithinTheTimeBudget) {
    gate::TimingSettings s;
    s.minRounds = 4;
    s.roundStep = 2;
    // Baseline and candidate drawn from the same noise, centred 5% apart: "unknown" for a
    // 3% threshold at these sample sizes (neither clearly different nor inside +-3%).
    auto measure = [](int round) {
        const double noise = (round * 7919 % 13) / 13.0 - 0.5;
        return std::vector<std::pair<double, double>>{{1.0 + 0.2 * noise, 1.05 + 0.2 * noise}};
    };
    const auto quick = gate::runSequential({"q"}, measure, {}, true, s, 0.03, 4, 0.0, {});
    EXPECT_EQ(quick.rounds, 4);
    EXPECT_TRUE(quick.budgetReached);
    EXPECT_EQ(quick.quantities[0].comparison.verdict, gate::TimingVerdict::Unknown);
    const auto longer = gate::runSequential({"q"}, measure, {}, true, s, 0.03, 4, 0.3, {});
    EXPECT_GT(longer.rounds, 4) << "no rounds past the round budget within the time budget";
    EXPECT_LE(longer.rounds, gate::kMaxRounds);
}

} // namespace
} // namespace pb::test
