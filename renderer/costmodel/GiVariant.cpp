#include "costmodel/GiVariant.h"

namespace pb::costmodel {

const char* fetchKindName(FetchKind k) {
    switch (k) {
    case FetchKind::GBufferDepth:
        return "gbuffer_depth";
    case FetchKind::GBufferNormal:
        return "gbuffer_normal";
    case FetchKind::ProbeState:
        return "probe_state";
    case FetchKind::Visibility:
        return "visibility";
    case FetchKind::ShMask:
        return "sh_mask";
    case FetchKind::ShCoefficients:
        return "sh_coefficients";
    case FetchKind::Irradiance:
        break;
    }
    return "irradiance";
}

std::string GiVariant::name() const {
    return std::string(order == profile::GiProbeOrder::SliceFirst ? "slice_first" : "xyz") + "/" +
           (loops == profile::GiLoops::Split ? "split" : "fused");
}

std::vector<GiVariant> allGiVariants() {
    using O = profile::GiProbeOrder;
    using L = profile::GiLoops;
    return {{O::Xyz, L::Fused},
            {O::Xyz, L::Split},
            {O::SliceFirst, L::Fused},
            {O::SliceFirst, L::Split}};
}

VariantStructure variantStructure(const GiVariant& v) {
    VariantStructure s;
    for (int i = 0; i < 8; ++i)
        // ddgiCorner(i): xyz = x fastest, then y, then z; slice_first = the 4 probes of one
        // local-Y plane (one texture layer) first: x fastest, then z, then y.
        s.cornerOffsets[size_t(i)] = v.order == profile::GiProbeOrder::SliceFirst
                                         ? std::array<int, 3>{i & 1, (i >> 2) & 1, (i >> 1) & 1}
                                         : std::array<int, 3>{i & 1, (i >> 1) & 1, (i >> 2) & 1};
    // ddgiProbeWeight reads the state then the visibility; ddgiProbeIrradiance the irradiance.
    if (v.loops == profile::GiLoops::Split)
        s.loops = {{FetchKind::ProbeState, FetchKind::Visibility}, {FetchKind::Irradiance}};
    else
        s.loops = {{FetchKind::ProbeState, FetchKind::Visibility, FetchKind::Irradiance}};
    return s;
}

int fetchSlot(const VariantStructure& v, int loop, int step, int fetchInLoop) {
    int slot = kGBufferFetchesPerLookup;
    for (int l = 0; l < loop; ++l)
        slot += kProbesPerLookup * int(v.loops[size_t(l)].size());
    return slot + step * int(v.loops[size_t(loop)].size()) + fetchInLoop;
}

int fetchSlotCount(const VariantStructure& v) {
    return fetchSlot(v, int(v.loops.size()) - 1, kProbesPerLookup - 1,
                     int(v.loops.back().size()) - 1) +
           1;
}

int maxFetchesPerLookup(const GiVariant& v) {
    int perProbe = 0;
    for (const auto& loop : variantStructure(v).loops)
        perProbe += int(loop.size());
    return kGBufferFetchesPerLookup + kProbesPerLookup * perProbe;
}

} // namespace pb::costmodel
