#include "costmodel/ShFetchStream.h"

#include "probes/sh/ShIrradiance.h"

#include <cmath>

namespace pb::costmodel {

int shCoefficientTextures(profile::GiTechnique t) {
    return t == profile::GiTechnique::ShL1 ? 3 : t == profile::GiTechnique::ShL2 ? 7 : 0;
}

probes::ShSampleOptions shSampleOptions(const profile::Profile& p) {
    probes::ShSampleOptions o;
    o.coefficients = p.gi.technique == profile::GiTechnique::ShL2 ? probes::kShL2Coefficients
                                                                  : probes::kShL1Coefficients;
    o.leak = p.gi.shLeak == profile::GiShLeak::Weight         ? probes::ShLeak::Weight
             : p.gi.shLeak == profile::GiShLeak::ValidityMask ? probes::ShLeak::ValidityMask
                                                              : probes::ShLeak::None;
    return o;
}

int shTexelsPerLookup(const profile::Profile& p) {
    return 8 * shCoefficientTextures(p.gi.technique) +
           (p.gi.shLeak == profile::GiShLeak::None ? 0 : 1);
}

int shFetchSlotCount(int coefficientTextures) {
    return kGBufferFetchesPerLookup + 1 + coefficientTextures;
}

void appendShFetches(const probes::ShTrace& trace, const TextureTable::Volume& tex,
                     const glm::ivec3& counts, std::vector<Fetch>& out) {
    const int maskSlot = kGBufferFetchesPerLookup;
    if (trace.maskRead)
        out.push_back({FetchKind::ShMask, tex.shMask, trace.cell.x, trace.cell.z, trace.cell.y,
                       false, maskSlot});
    if (!trace.coefficientsRead) return;
    // The hardware's footprint: i0 = floor(u * size - 0.5) = floor(g); i1 = i0 + 1, clamped.
    glm::ivec3 i0, step;
    for (int a = 0; a < 3; ++a) {
        i0[a] = std::min(std::max(int(std::floor(trace.lattice[a])), 0), counts[a] - 1);
        step[a] = i0[a] + 1 < counts[a] ? 1 : 0;
    }
    for (std::size_t t = 0; t < tex.sh.size(); ++t) {
        Fetch f{FetchKind::ShCoefficients, tex.sh[t], i0.x, i0.z, i0.y, true,
                maskSlot + 1 + int(t)};
        f.trilinear = true;
        f.step = {step.x, step.z, step.y}; // texture axes: x, rows z, layers y
        out.push_back(f);
    }
}

} // namespace pb::costmodel
