#include "probes/sh/ShAbsentFill.h"

#include "probes/AbsentProbeFill.h"
#include "probes/sh/ShIrradiance.h"

#include <algorithm>
#include <limits>

namespace pb::probes {

ShLookupVolume shLookupVolume(const ProbeVolume& v, const std::vector<ProbeState>& states,
                              const std::vector<glm::vec3>& sh, float backfaceThreshold) {
    ShLookupVolume out{states, sh};
    // With an infinite threshold every absent probe is "fillable": its nearest stored valid
    // probe, by the same search DDGI's fill uses (so both pick the same stand-in).
    const std::vector<int> nearest = fillSources(v, states, std::numeric_limits<float>::infinity());
    if (nearest.empty() || sh.size() != states.size() * kShL2Coefficients) return out;
    std::vector<int> ddgi(states.size());
    for (std::size_t p = 0; p < states.size(); ++p) {
        ddgi[p] = fillable(states[p], backfaceThreshold) ? nearest[p] : int(p);
        const int s = nearest[p];
        if (states[p].stored || s < 0 || std::size_t(s) == p) continue;
        std::copy_n(sh.begin() + std::ptrdiff_t(std::size_t(s) * kShL2Coefficients),
                    kShL2Coefficients, out.sh.begin() + std::ptrdiff_t(p * kShL2Coefficients));
    }
    out.states = lookupStates(v, states, ddgi);
    return out;
}

} // namespace pb::probes
