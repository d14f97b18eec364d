#include "probes/ProbeCounts.h"

#include "core/Error.h"
#include "probes/AbsentProbeFill.h"

#include <string>

namespace pb::probes {

std::vector<ProbeCounts> volumeProbeCounts(const ProbeSet& set,
                                           const std::vector<std::size_t>* bakedInvalid) {
    if (bakedInvalid && bakedInvalid->size() != set.states.size())
        throw Error("probe counts: " + std::to_string(bakedInvalid->size()) +
                    " invalid counts for " + std::to_string(set.states.size()) + " volumes");
    std::vector<ProbeCounts> out;
    for (std::size_t v = 0; v < set.states.size(); ++v) {
        ProbeCounts c;
        std::size_t invalidStored = 0; // dense files keep invalid probes with their tiles
        std::size_t irradianceOnly = 0, fillableCount = 0;
        for (const ProbeState& p : set.states[v]) {
            ++c.probes;
            c.stored += p.stored ? 1 : 0;
            invalidStored += p.stored && !p.valid ? 1 : 0;
            irradianceOnly += p.irradianceOnly ? 1 : 0;
            fillableCount += fillable(p, set.settings.backfaceThreshold) ? 1 : 0;
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
        } else {
            // A file read back: a probe not stored is absent when lookups read it - its own
            // irradiance tile, or a stand-in for it because its back-face ratio puts it outside
            // geometry (AbsentProbeFill.h fillable) - and invalid otherwise.
            const std::size_t absent = irradianceOnly + fillableCount;
            c.absent = absent;
            c.invalid = invalidStored + (c.notStored() - absent);
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
