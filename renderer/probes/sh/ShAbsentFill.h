#pragma once
// Sparse bakes' absent probes for the SH technique (issue 19): sparse storage keeps no SH for a
// probe it left out, so its coefficients are zero, and under gi.sh_leak=none (which ignores
// validity) a lookup blended them in as black. Absence is not a leak choice: every lookup, in
// every mode, reads an absent probe as its NEAREST STORED valid probe's coefficients - the
// stand-in DDGI's free-space fill already uses (AbsentProbeFill.h) - and a lookup's validity
// follows DDGI's lookup states: an absent probe outside geometry is valid (it stands in for
// the dense bake's probe), one inside geometry stays invalid, as in the dense bake.
// Why this and not "absent weighs 0 even under none": measured against the dense bake at
// mid-air points (bench/results/2026-11-25-sh-technique-2.md), the stand-in is closer and
// costs the `none` lookup nothing (no weight fetch, no divide); it is done at upload
// (GpuShTextures) and in the CPU sampler (ShSampler) from this one function.
#include "probes/ProbeSet.h"

#include <glm/glm.hpp>
#include <vector>

namespace pb::probes {

// What an SH lookup reads for one volume: the states (absent probes outside geometry made
// valid, AbsentProbeFill's lookupStates) and the coefficients (probe-major, 9 per probe; an
// absent probe's are its nearest stored valid probe's; all zero when the volume stores none).
// Dense volumes come back unchanged.
struct ShLookupVolume {
    std::vector<ProbeState> states;
    std::vector<glm::vec3> sh;
};

ShLookupVolume shLookupVolume(const ProbeVolume& v, const std::vector<ProbeState>& states,
                              const std::vector<glm::vec3>& sh, float backfaceThreshold);

} // namespace pb::probes
