#include "ShaderPlan.h"

#include <set>

namespace pb::shaders {

std::vector<PlannedVariant> plannedVariants(const bench::BenchPlan& plan, bool fusedTwins) {
    std::vector<PlannedVariant> out;
    std::set<std::string> ids;
    for (const bench::Session& s : plan.sessions)
        for (const bench::Variant& v : s.variants) {
            if (!ids.insert(v.id).second) continue; // the reference recurs in every session
            VariantStatistics meta;
            meta.id = v.id;
            meta.label = v.label;
            meta.profile =
                v.role == bench::VariantRole::Reference ? plan.reference.name : s.profile.name;
            meta.role = bench::roleName(v.role);
            meta.switchKey = v.switchKey;
            out.push_back({meta, v.switches});
            if (!fusedTwins || v.switches.gi.loops != profile::GiLoops::Split) continue;
            VariantStatistics twin = meta;
            twin.id = fusedTwinId(v.id);
            twin.label = v.label + " [fused twin]";
            twin.role = "twin";
            profile::Profile fused = v.switches;
            fused.gi.loops = profile::GiLoops::Fused;
            if (ids.insert(twin.id).second) out.push_back({twin, fused});
        }
    return out;
}

std::vector<SwitchPair> switchPairs(const bench::BenchPlan& plan) {
    std::vector<SwitchPair> out;
    std::set<std::pair<std::string, std::string>> seen;
    for (const bench::Session& s : plan.sessions)
        for (const bench::PlannedDelta& d : s.deltas) {
            if (d.kind == bench::DeltaKind::VsReference) continue;
            const std::string& off = s.variants.at(size_t(d.off)).id;
            const std::string& on = s.variants.at(size_t(d.on)).id;
            if (off == on || !seen.insert({off, on}).second) continue;
            out.push_back({s.profile.name, bench::deltaKindName(d.kind), d.switchKey, d.offValue,
                           d.onValue, off, on});
        }
    return out;
}

} // namespace pb::shaders
