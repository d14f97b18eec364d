#include "BenchResult.h"

namespace pb::bench {

const SectionTiming* VariantResult::section(const std::string& name) const {
    for (const SectionTiming& s : sections)
        if (s.name == name) return &s;
    return nullptr;
}

const DeltaResult* SessionResult::vsReference() const {
    for (const DeltaResult& d : deltas)
        if (d.planned.kind == DeltaKind::VsReference) return &d;
    return nullptr;
}

} // namespace pb::bench
