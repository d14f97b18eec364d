#include "probes/ProbeSet.h"

namespace pb::probes {

int ProbeSet::findScenario(const std::string& name) const {
    for (size_t i = 0; i < scenarios.size(); ++i)
        if (scenarios[i].name == name) return int(i);
    return -1;
}

std::size_t ProbeSet::probeCount() const {
    std::size_t n = 0;
    for (const ProbeVolume& v : volumes)
        n += std::size_t(v.probeCount());
    return n;
}

std::size_t ProbeSet::invalidCount() const {
    std::size_t n = 0;
    for (const auto& s : states)
        for (const ProbeState& p : s)
            n += p.valid ? 0 : 1;
    return n;
}

std::size_t ProbeSet::storedCount() const {
    std::size_t n = 0;
    for (const auto& s : states)
        for (const ProbeState& p : s)
            n += p.stored ? 1 : 0;
    return n;
}

} // namespace pb::probes
