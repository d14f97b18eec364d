#pragma once
// What a benchmark run renders and compares, decided before any GL exists (unit-tested).
//
// One session per profile P, all at P's output size (or the run's --width/--height):
//   - P itself, and `reference` at the same size (the accuracy baseline for that frame and the
//     base of "P vs reference": delta ms and error);
//   - with ablation, for every switch s where P differs from reference (switch-table order):
//       "P -s":   P with only s reverted to the reference value  (delta "in profile": P - it)
//       "ref +s": reference with only s set to P's value          (delta "on reference": it - ref)
// Every delta compares two variants that differ in exactly one switch (or, for P vs
// reference, in the switches that differ). Variants with equal switches are measured once.
// A session's variants are rendered in interleaved rounds (A B C ... A B C ...), so each delta
// is a paired comparison within one run.
#include "profile/PlatformProfile.h"

#include <string>
#include <vector>

namespace pb::bench {

enum class VariantRole { Profile, Reference, Reverted, Applied };
const char* roleName(VariantRole r); // "profile", "reference", "reverted", "applied"

struct Variant {
    std::string id;    // unique in the plan, e.g. "handheld -gi.loops"
    std::string label; // for tables, e.g. "-gi.loops (split -> fused)"
    VariantRole role = VariantRole::Profile;
    std::string switchKey; // Reverted/Applied: the one switch
    profile::Profile switches;
};

enum class DeltaKind { VsReference, InProfile, OnReference };
const char* deltaKindName(DeltaKind k); // "vs_reference", "in_profile", "on_reference"

// on - off: negative delta ms = the "on" side is faster.
struct PlannedDelta {
    DeltaKind kind = DeltaKind::VsReference;
    std::string switchKey;         // empty for VsReference
    std::string offValue, onValue; // the switch's text values (VsReference: empty)
    int off = 0, on = 0;           // indices into Session::variants
};

struct Session {
    profile::PlatformProfile profile; // with the run's overrides applied
    int width = 0, height = 0;
    std::vector<Variant> variants; // [0] = the profile
    int referenceVariant = 0;      // the accuracy baseline (0 when P equals reference)
    std::vector<PlannedDelta> deltas;
};

struct BenchPlan {
    profile::PlatformProfile reference;
    std::vector<Session> sessions;
    int variantCount() const;
};

struct PlanOptions {
    bool ablate = false;
    int width = 0, height = 0; // > 0: every session at this size instead of the profile's
};

// Keys where a and b differ, in switch-table order.
std::vector<std::string> differingSwitches(const profile::Profile& a, const profile::Profile& b);

BenchPlan makeBenchPlan(const std::vector<profile::PlatformProfile>& profiles,
                        const profile::PlatformProfile& reference, const PlanOptions& options);

} // namespace pb::bench
