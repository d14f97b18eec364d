// `probebench tune`'s GL-free parts (bench/tune): the switch space from the switch table,
// canonical candidates, exhaustive and coordinate-descent search against a deterministic model
// of time, memory and FLIP (no renders, no timings), the Pareto front, the one-line failure, and
// the written profile loading back to the tuned switches.
#include "bench/tune/BudgetCheck.h"
#include "bench/tune/TuneReport.h"
#include "bench/tune/TuneSearch.h"
#include "bench/tune/TunedProfile.h"
#include "core/Error.h"
#include "profile/ProfileLoader.h"
#include "profile/SwitchTable.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace pb::test {
namespace {

using bench::TuneMeasurement;

// A model frame: GI cost falls with resolution, FLIP rises; formats nudge both; memory from
// the target format (half resolution adds a full-size upsample target, as the renderer does).
struct Model {
    std::vector<std::string> seen; // every candidate measured, in order
    int sessions = 0;

    static double ms(const profile::Profile& p) {
        double gi = p.gi.resolution == profile::GiResolution::Full   ? 8.0
                    : p.gi.resolution == profile::GiResolution::Half ? 3.0
                                                                     : 1.5;
        if (p.gi.targetFormat == profile::GiTargetFormat::R11g11b10f) gi *= 0.9;
        if (p.gi.loops == profile::GiLoops::Split) gi *= 0.95;
        return 4.0 + gi;
    }
    static double flip(const profile::Profile& p) {
        double f = p.gi.resolution == profile::GiResolution::Full   ? 0.0
                   : p.gi.resolution == profile::GiResolution::Half ? 0.03
                                                                    : 0.06;
        if (p.gi.upsample == profile::GiUpsample::Bilateral) f *= 0.7;
        if (p.gi.targetFormat == profile::GiTargetFormat::R11g11b10f) f += 0.004;
        return f;
    }
    static double mib(const profile::Profile& p) {
        const double texel = p.gi.targetFormat == profile::GiTargetFormat::Rgba32f      ? 16
                             : p.gi.targetFormat == profile::GiTargetFormat::R11g11b10f ? 4
                                                                                        : 8;
        const int div = profile::resolutionDivisor(p.gi.resolution);
        const double pixels = 1280.0 * 720.0;
        return 1.0 + texel * (pixels / (div * div) + (div > 1 ? pixels : 0)) / 1048576.0;
    }
    bench::MeasureFn measure() {
        return [this](const std::vector<profile::Profile>& batch) {
            ++sessions;
            std::vector<TuneMeasurement> out;
            for (const profile::Profile& p : batch) {
                seen.push_back(bench::candidateKey(p));
                TuneMeasurement m;
                m.ok = true;
                m.frameMs = ms(p);
                m.flip = flip(p);
                m.relativeMseGi = flip(p) * 2;
                out.push_back(m);
            }
            return out;
        };
    }
};

profile::Profile referenceSwitches() {
    profile::Profile p;
    p.set("gi.target_format", "rgba32f");
    return p;
}

TEST(TuneSpace, ComesFromTheSwitchTableWithEquivalentValuesMergedOnce) {
    const profile::Profile base = referenceSwitches();
    bench::TuneContext ctx; // no dynamic objects, volume_lod "all" only
    const bench::TuneSpace all = bench::makeTuneSpace(base, ctx);
    std::set<std::string> keys;
    for (const auto& a : all.axes) {
        keys.insert(a.key);
        EXPECT_EQ(a.values.front(), profile::findSwitch(a.key)->get(base)) << a.key;
    }
    // Every Choice row with more than one value is searched, except gi.dynamic here and the
    // guards, which are held unless --search names them.
    int guards = 0;
    for (const profile::SwitchInfo& s : profile::switchTable())
        if (s.kind == profile::SwitchKind::Choice && s.choices.size() > 1 &&
            s.key != "gi.dynamic") {
            EXPECT_EQ(keys.count(s.key), bench::isGuard(s.key) ? 0u : 1u) << s.key;
            guards += bench::isGuard(s.key) ? 1 : 0;
        }
    EXPECT_GE(guards, 2) << "gi.guard_exposure and gi.guard_clamp are guards";
    const bench::TuneSpace guard = bench::makeTuneSpace(base, ctx, {"gi.guard_exposure"});
    ASSERT_EQ(guard.axes.size(), 1u);
    EXPECT_EQ(guard.axes[0].key, "gi.guard_exposure");
    EXPECT_FALSE(keys.count("gi.dynamic")) << "no dynamic objects: the SH pass is skipped";
    EXPECT_FALSE(keys.count("gi.volume_lod")) << "one level only";

    const bench::TuneSpace two = bench::makeTuneSpace(base, ctx, {"gi.resolution", "gi.upsample"});
    ASSERT_EQ(two.axes.size(), 2u);
    EXPECT_EQ(two.combinations(), 9u);
    // full (upsample unused) + half x 3 + quarter x 3.
    const auto cands = bench::enumerateSpace(two);
    EXPECT_EQ(cands.size(), 7u);
    EXPECT_EQ(bench::candidateLabel(cands.front(), base), "base");
    EXPECT_THROW(bench::makeTuneSpace(base, ctx, {"gi.resolutoin"}), Error);

    ctx.dynamicObjects = 2;
    ctx.volumeLodValues = {"all", "min_spacing:0.5"};
    const bench::TuneSpace dyn = bench::makeTuneSpace(base, ctx, {"gi.dynamic", "gi.volume_lod"});
    EXPECT_EQ(dyn.combinations(), 4u);
}

TEST(TuneSearch, ABudgetThatExcludesFullResolutionGivesAConfigurationThatFits) {
    const profile::Profile base = referenceSwitches();
    const bench::TuneSpace space = bench::makeTuneSpace(
        base, {}, {"gi.resolution", "gi.upsample", "gi.target_format", "gi.loops"});
    bench::TuneOptions o;
    o.budgetMs = 8.0; // full resolution needs 10.8 ms and more in the model
    o.budgetMiB = 64.0;
    for (int maxExhaustive : {1000, 4}) {
        SCOPED_TRACE(maxExhaustive);
        o.maxExhaustive = maxExhaustive;
        Model model;
        const bench::TuneResult r = bench::runTune(space, Model::mib, model.measure(), o);
        EXPECT_EQ(r.method, maxExhaustive == 1000 ? "exhaustive" : "coordinate descent");
        ASSERT_GE(r.chosen, 0);
        const bench::TuneCandidate& c = r.candidates[size_t(r.chosen)];
        EXPECT_TRUE(c.fits(o));
        EXPECT_LE(c.m.frameMs, o.budgetMs);
        EXPECT_NE(c.switches.gi.resolution, profile::GiResolution::Full);
        // The most accurate that fits: half resolution, bilateral, not the lossy format.
        EXPECT_EQ(c.switches.gi.resolution, profile::GiResolution::Half);
        EXPECT_EQ(c.switches.gi.upsample, profile::GiUpsample::Bilateral);
        EXPECT_NE(c.switches.gi.targetFormat, profile::GiTargetFormat::R11g11b10f);
        for (const auto& cand : r.candidates)
            if (cand.measured && cand.fits(o)) {
                EXPECT_GE(cand.m.flip, c.m.flip);
            }
        if (maxExhaustive == 4) {
            EXPECT_LT(model.seen.size(), bench::enumerateSpace(space).size())
                << "descent measures fewer than all";
        }
    }
}

TEST(TuneSearch, CandidatesOverTheMemoryBudgetAreNeverRendered) {
    const bench::TuneSpace space = bench::makeTuneSpace(
        referenceSwitches(), {}, {"gi.resolution", "gi.upsample", "gi.target_format"});
    bench::TuneOptions o;
    o.budgetMs = 100.0;
    o.budgetMiB = 1.0 + 8.0 * 1280 * 720 / 1048576.0 + 1e-9; // full-res rgba16f fits exactly
    Model model;
    const bench::TuneResult r = bench::runTune(space, Model::mib, model.measure(), o);
    ASSERT_GE(r.chosen, 0);
    EXPECT_GT(r.overMemory, 0u);
    for (const std::string& key : model.seen) {
        auto it = std::find_if(r.candidates.begin(), r.candidates.end(), [&](const auto& c) {
            return bench::candidateKey(c.switches) == key;
        });
        ASSERT_NE(it, r.candidates.end());
        EXPECT_LE(it->memoryMiB, o.budgetMiB) << it->label;
    }
    EXPECT_LE(r.candidates[size_t(r.chosen)].memoryMiB, o.budgetMiB);
    EXPECT_EQ(r.candidates[size_t(r.chosen)].label, "gi.target_format=rgba16f");
    // The front: nothing on it is beaten on all three, everything off it is.
    ASSERT_FALSE(r.pareto.empty());
    for (size_t i = 0; i < r.candidates.size(); ++i) {
        const auto& c = r.candidates[i];
        if (!c.measured) continue;
        bool beaten = false;
        for (const auto& d : r.candidates)
            beaten =
                beaten ||
                (d.measured && d.m.frameMs <= c.m.frameMs && d.memoryMiB <= c.memoryMiB &&
                 d.m.flip <= c.m.flip &&
                 (d.m.frameMs < c.m.frameMs || d.memoryMiB < c.memoryMiB || d.m.flip < c.m.flip));
        const bool onFront = std::find(r.pareto.begin(), r.pareto.end(), int(i)) != r.pareto.end();
        EXPECT_EQ(onFront, !beaten) << c.label;
    }
    EXPECT_NE(bench::paretoTable(r, o).find("*"), std::string::npos);
}

TEST(TuneSearch, NothingFitsIsOneLineWithTheClosestCandidates) {
    const bench::TuneSpace space =
        bench::makeTuneSpace(referenceSwitches(), {}, {"gi.resolution", "gi.target_format"});
    bench::TuneOptions o;
    o.budgetMs = 1.0; // below the model's 4 ms floor
    o.budgetMiB = 64.0;
    Model model;
    bench::TuneResult r = bench::runTune(space, Model::mib, model.measure(), o);
    EXPECT_EQ(r.chosen, -1);
    ASSERT_FALSE(r.closest.empty());
    EXPECT_NE(r.candidates[size_t(r.closest.front())].switches.gi.resolution,
              profile::GiResolution::Full)
        << "the fastest is the nearest miss";
    std::string msg = bench::nothingFitsMessage(r, o);
    EXPECT_EQ(msg.find('\n'), std::string::npos);
    EXPECT_NE(msg.find("closest: gi.resolution=quarter"), std::string::npos) << msg;

    o.budgetMs = 100;
    o.budgetMiB = 0.5; // below every candidate: nothing is rendered at all
    Model none;
    r = bench::runTune(space, Model::mib, none.measure(), o);
    EXPECT_EQ(r.chosen, -1);
    EXPECT_EQ(none.sessions, 0);
    EXPECT_EQ(r.closest.size(), 3u);
    EXPECT_EQ(bench::nothingFitsMessage(r, o).find('\n'), std::string::npos);
    EXPECT_TRUE(bench::tuneJson(r, o)["chosen"].is_null());
}

TEST(TunedProfile, InheritsTheBaseAndLoadsBackToTheTunedSwitches) {
    const profile::ProfileSearch search{{(sourceDir() / "profiles").string()}, {}};
    const profile::PlatformProfile base = profile::loadProfile("handheld", search);
    profile::Profile tuned = base.switches;
    tuned.set("gi.resolution", "quarter");
    tuned.set("gi.upsample", "bilateral");
    bench::TunedProfileInfo info{"handheld", "tuned for a test",      320, 180, 25.0,
                                 3.5,        {"a comment", "another"}};
    const std::string text = bench::tunedProfileToml(base.switches, tuned, info);
    EXPECT_EQ(text.rfind("# a comment\n# another\ninherit = ", 0), 0u) << text;
    EXPECT_NE(text.find("resolution = 'quarter'"), std::string::npos) << text;
    EXPECT_EQ(text.find("precision"), std::string::npos) << "unchanged switches come from the base";
    const std::string path = (outputDir() / "tuned.toml").string();
    const profile::PlatformProfile loaded = profile::parseProfileToml(text, path, search);
    EXPECT_EQ(loaded.switches, tuned);
    EXPECT_EQ(loaded.width, 320);
    EXPECT_EQ(loaded.height, 180);
    EXPECT_DOUBLE_EQ(loaded.frameBudgetMs, 25.0);
    EXPECT_DOUBLE_EQ(loaded.giMemoryBudgetMiB, 3.5);
    EXPECT_EQ(loaded.cachePreset, base.cachePreset);
    ASSERT_FALSE(loaded.inherits.empty());
    EXPECT_EQ(loaded.inherits.front(), "handheld");
}

// A tuned profile whose re-measure misses the budget is a failure (cmd_tune throws with this
// text unless --accept-over-budget), not a note under an exit 0 (issue 25, item 5).
TEST(TuneBudget, ReMeasureOverTheBudgetIsAProblemWithinIsNot) {
    EXPECT_EQ(bench::overBudgetProblem(39.9, 38.0, 40.0), "");
    EXPECT_EQ(bench::overBudgetProblem(40.0, 38.0, 40.0), "");
    const std::string p = bench::overBudgetProblem(48.5, 39.0, 40.0);
    EXPECT_NE(p.find("re-measured 48.50 ms, over the 40 ms budget"), std::string::npos) << p;
    EXPECT_NE(p.find("search measured 39.00 ms"), std::string::npos) << p;
}

} // namespace
} // namespace pb::test
