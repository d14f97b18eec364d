#include "AblationPlan.h"

#include "core/Error.h"
#include "profile/SwitchTable.h"

#include <set>

namespace pb::bench {

const char* roleName(VariantRole r) {
    switch (r) {
    case VariantRole::Profile:
        return "profile";
    case VariantRole::Reference:
        return "reference";
    case VariantRole::Reverted:
        return "reverted";
    case VariantRole::Applied:
        return "applied";
    }
    return "?";
}

const char* deltaKindName(DeltaKind k) {
    switch (k) {
    case DeltaKind::VsReference:
        return "vs_reference";
    case DeltaKind::InProfile:
        return "in_profile";
    case DeltaKind::OnReference:
        return "on_reference";
    }
    return "?";
}

int BenchPlan::variantCount() const {
    int n = 0;
    for (const Session& s : sessions)
        n += int(s.variants.size());
    return n;
}

std::vector<std::string> differingSwitches(const profile::Profile& a, const profile::Profile& b) {
    std::vector<std::string> out;
    for (const profile::SwitchInfo& s : profile::switchTable())
        if (s.get(a) != s.get(b)) out.push_back(s.key);
    return out;
}

namespace {

// Index of the variant with these switches, adding it when new.
int addVariant(Session& s, Variant v) {
    for (size_t i = 0; i < s.variants.size(); ++i)
        if (s.variants[i].switches == v.switches) return int(i);
    s.variants.push_back(std::move(v));
    return int(s.variants.size()) - 1;
}

Session planSession(const profile::PlatformProfile& p, const profile::PlatformProfile& ref,
                    const PlanOptions& o) {
    Session s;
    s.profile = p;
    s.width = o.width > 0 ? o.width : p.width;
    s.height = o.height > 0 ? o.height : p.height;
    const std::string size = std::to_string(s.width) + "x" + std::to_string(s.height);
    s.variants.push_back({p.name, p.name, VariantRole::Profile, "", p.switches});
    const std::string refId = ref.name + "@" + size;
    s.referenceVariant = addVariant(s, {refId, ref.name, VariantRole::Reference, "", ref.switches});
    if (s.referenceVariant != 0)
        s.deltas.push_back({DeltaKind::VsReference, "", "", "", s.referenceVariant, 0});
    if (!o.ablate) return s;
    for (const std::string& key : differingSwitches(ref.switches, p.switches)) {
        const std::string refValue = ref.switches.get(key), value = p.switches.get(key);
        Variant reverted{p.name + " -" + key, "-" + key + " (" + value + " -> " + refValue + ")",
                         VariantRole::Reverted, key, p.switches};
        reverted.switches.set(key, refValue);
        Variant applied{refId + " +" + key, "+" + key + " (" + refValue + " -> " + value + ")",
                        VariantRole::Applied, key, ref.switches};
        applied.switches.set(key, value);
        const int r = addVariant(s, std::move(reverted));
        const int a = addVariant(s, std::move(applied));
        s.deltas.push_back({DeltaKind::InProfile, key, refValue, value, r, 0});
        s.deltas.push_back({DeltaKind::OnReference, key, refValue, value, s.referenceVariant, a});
    }
    return s;
}

} // namespace

BenchPlan makeBenchPlan(const std::vector<profile::PlatformProfile>& profiles,
                        const profile::PlatformProfile& reference, const PlanOptions& o) {
    if (profiles.empty()) throw Error("--profiles: no profile to benchmark");
    if ((o.width > 0) != (o.height > 0)) throw Error("--width and --height go together");
    BenchPlan plan;
    plan.reference = reference;
    std::set<std::string> names;
    for (const profile::PlatformProfile& p : profiles) {
        if (!names.insert(p.name).second)
            throw Error("--profiles: '" + p.name + "' is listed twice");
        plan.sessions.push_back(planSession(p, reference, o));
    }
    return plan;
}

} // namespace pb::bench
