#include "probes/ProbeCounts.h"

#include "core/Error.h"

#include <string>

namespace pb::probes {

std::vector<ProbeCounts> volumeProbeCounts(const ProbeSet& set,
                                           const std::vector<std::size_t>* bakedInvalid) {
    if (bakedInvalid && bakedInvalid->size() != set.states.size())
        throw Error("probe counts: " + std::to_string(bakedInvalid->size()) +
                    " invalid counts for " + std::to_string(set.states.size()) + " volumes");
    // Since probe file version 7 every valid probe sparse storage leaves out is irradiance-only,
    // so the states tell absent from invalid; an older file's absent probes are just invalid.
    bool statesTell = false;
    for (const auto& states : set.states)
        for (const ProbeState& p : states)
            statesTell = statesTell || p.irradianceOnly;
    std::vector<ProbeCounts> out;
    for (std::size_t v = 0; v < set.states.size(); ++v) {
        ProbeCounts c;
        std::size_t invalidStored = 0; // dense files keep invalid probes with their tiles
        std::size_t irradianceOnly = 0;
        for (const ProbeState& p : set.states[v]) {
            ++c.probes;
            c.stored += p.stored ? 1 : 0;
            invalidStored += p.stored && !p.valid ? 1 : 0;
            irradianceOnly += p.irradianceOnly ? 1 : 0;
        }
        if (c.notStored() == 0) { // every probe stored: the states say all
            c.absent = 0;
            c.invalid = invalidStored;
        } else if (bakedInvalid) {
            // Not stored = absent (valid, no surface nearby) + invalid but not stored.
            const std::size_t invalid = (*bakedInvalid)[v];
            if (invalid < invalidStored || invalid - invalidStored > c.notStored())
                throw Error("probe counts: volume " + std::to_string(v) + ": " +
                            std::to_string(invalid) + " invalid probes do not fit its states");
            c.invalid = invalid;
            c.absent = c.notStored() - (invalid - invalidStored);
        } else if (statesTell) {
            c.absent = irradianceOnly;
            c.invalid = invalidStored + (c.notStored() - irradianceOnly);
        }
        out.push_back(c);
    }
    return out;
}

ProbeCounts totalProbeCounts(const std::vector<ProbeCounts>& volumes) {
    ProbeCounts t;
    t.absent = t.invalid = 0;
    for (const ProbeCounts& c : volumes) {
        t.probes += c.probes;
        t.stored += c.stored;
        if (!c.absent || !t.absent)
            t.absent.reset();
        else
            *t.absent += *c.absent;
        if (!c.invalid || !t.invalid)
            t.invalid.reset();
        else
            *t.invalid += *c.invalid;
    }
    return t;
}

} // namespace pb::probes
