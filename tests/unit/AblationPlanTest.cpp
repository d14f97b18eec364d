// The benchmark's plan, before any GL: every ablation run changes exactly one switch against
// its base, every switch where a profile differs from the reference is ablated both ways, and
// variants with equal switches are measured once.
#include "support/TestEnv.h"

#include "bench/report/AblationPlan.h"
#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "profile/ProfileLoader.h"

#include <gtest/gtest.h>

#include <set>

namespace pb::test {
namespace {

using bench::DeltaKind;

profile::PlatformProfile make(const std::string& name, std::vector<std::string> sets) {
    profile::PlatformProfile p;
    p.name = name;
    p.width = 320;
    p.height = 180;
    for (const auto& kv : sets)
        p.switches.applyOverride(kv);
    return p;
}

profile::PlatformProfile reference() {
    return make("reference", {"gi.target_format=rgba32f"});
}

// Checks the plan's invariants for one session; returns the switch keys it ablates.
std::vector<std::string> checkSession(const bench::Session& s,
                                      const profile::PlatformProfile& ref) {
    std::set<std::string> ids;
    for (const auto& v : s.variants)
        EXPECT_TRUE(ids.insert(v.id).second) << "duplicate variant id " << v.id;
    for (size_t i = 0; i < s.variants.size(); ++i)
        for (size_t j = i + 1; j < s.variants.size(); ++j)
            EXPECT_FALSE(s.variants[i].switches == s.variants[j].switches)
                << s.variants[i].id << " and " << s.variants[j].id << " are the same run";
    EXPECT_EQ(s.variants[0].role, bench::VariantRole::Profile);
    EXPECT_TRUE(s.variants[size_t(s.referenceVariant)].switches == ref.switches);
    std::vector<std::string> keys;
    for (const bench::PlannedDelta& d : s.deltas) {
        const auto& off = s.variants[size_t(d.off)].switches;
        const auto& on = s.variants[size_t(d.on)].switches;
        if (d.kind == DeltaKind::VsReference) {
            EXPECT_EQ(d.off, s.referenceVariant);
            EXPECT_EQ(d.on, 0);
            continue;
        }
        // Exactly one switch changes between the two runs of an ablation delta.
        EXPECT_EQ(bench::differingSwitches(off, on), std::vector<std::string>{d.switchKey})
            << deltaKindName(d.kind) << " " << d.switchKey;
        EXPECT_EQ(off.get(d.switchKey), d.offValue);
        EXPECT_EQ(on.get(d.switchKey), d.onValue);
        EXPECT_EQ(d.offValue, ref.switches.get(d.switchKey)); // "off" = the reference's value
        if (d.kind == DeltaKind::InProfile) {
            EXPECT_EQ(d.on, 0) << "in-profile deltas are against the profile itself";
            keys.push_back(d.switchKey);
        } else {
            EXPECT_EQ(d.off, s.referenceVariant) << "on-reference deltas start from reference";
        }
    }
    return keys;
}

TEST(AblationPlan, EveryDifferingSwitchIsAblatedBothWaysOneSwitchPerRun) {
    auto ref = reference();
    auto p = make("low", {"gi.resolution=half", "gi.loops=split", "gi.probe_order=slice_first"});
    bench::BenchPlan plan = bench::makeBenchPlan({p}, ref, {true, 0, 0});
    ASSERT_EQ(plan.sessions.size(), 1u);
    const bench::Session& s = plan.sessions[0];
    std::vector<std::string> keys = checkSession(s, ref);
    // target_format differs too (reference has rgba32f), in switch-table order.
    EXPECT_EQ(keys, (std::vector<std::string>{"gi.resolution", "gi.target_format", "gi.loops",
                                              "gi.probe_order"}));
    size_t onRef = 0;
    for (const auto& d : s.deltas)
        onRef += d.kind == DeltaKind::OnReference;
    EXPECT_EQ(onRef, keys.size());
    EXPECT_EQ(s.variants.size(), 2u + 2u * keys.size()); // P, ref, one reverted + one applied each
    EXPECT_EQ(s.width, 320);
}

TEST(AblationPlan, WithoutAblationOnlyTheProfileAndTheReference) {
    auto ref = reference();
    bench::BenchPlan plan =
        bench::makeBenchPlan({make("low", {"gi.resolution=half"})}, ref, {false, 64, 36});
    const bench::Session& s = plan.sessions[0];
    EXPECT_EQ(s.variants.size(), 2u);
    ASSERT_EQ(s.deltas.size(), 1u);
    EXPECT_EQ(s.deltas[0].kind, DeltaKind::VsReference);
    EXPECT_EQ(s.width, 64); // the run's size wins over the profile's
    EXPECT_EQ(s.height, 36);
}

TEST(AblationPlan, EqualVariantsAreMeasuredOnce) {
    auto ref = reference();
    // The reference itself: one variant, nothing to compare.
    bench::BenchPlan same = bench::makeBenchPlan({ref}, ref, {true, 0, 0});
    EXPECT_EQ(same.sessions[0].variants.size(), 1u);
    EXPECT_EQ(same.sessions[0].referenceVariant, 0);
    EXPECT_TRUE(same.sessions[0].deltas.empty());
    // One differing switch: reverting it gives the reference, applying it gives the profile.
    auto one = ref;
    one.name = "one";
    one.switches.set("gi.loops", "split");
    bench::BenchPlan plan = bench::makeBenchPlan({one}, ref, {true, 0, 0});
    const bench::Session& s = plan.sessions[0];
    EXPECT_EQ(s.variants.size(), 2u);
    EXPECT_EQ(checkSession(s, ref), std::vector<std::string>{"gi.loops"});
}

TEST(AblationPlan, TheShippedProfilesAblateOneSwitchPerRun) {
    profile::ProfileSearch search;
    search.dirs = {(sourceDir() / "profiles").string()};
    std::vector<profile::PlatformProfile> profiles;
    for (const auto& n : profile::profileNames(search))
        profiles.push_back(profile::loadProfile(n, search));
    auto ref = profile::loadProfile("reference", search);
    bench::BenchPlan plan = bench::makeBenchPlan(profiles, ref, {true, 0, 0});
    for (const bench::Session& s : plan.sessions) {
        SCOPED_TRACE(s.profile.name);
        EXPECT_EQ(s.width, s.profile.width);
        EXPECT_EQ(checkSession(s, ref), bench::differingSwitches(ref.switches, s.profile.switches));
    }
}

TEST(AblationPlan, BadRequestsAreErrors) {
    auto ref = reference();
    EXPECT_THROW(bench::makeBenchPlan({}, ref, {}), Error);
    auto p = make("twice", {});
    EXPECT_THROW(bench::makeBenchPlan({p, p}, ref, {}), Error);
    EXPECT_THROW(bench::makeBenchPlan({p}, ref, {false, 64, 0}), Error);
}

} // namespace
} // namespace pb::test
