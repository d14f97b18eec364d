#pragma once
// The GI apply shader's fetch structure per variant (gi.probe_order x gi.loops), as the cost
// model issues it: which probe corner each loop step visits and which textures each loop
// reads per probe. It mirrors shaders/common_ddgi.glsl + gi_ddgi_apply.frag;
// tests/unit/CostModelShaderTest.cpp parses those sources and fails when they drift apart.
#include "profile/Profile.h"

#include <array>
#include <string>
#include <vector>

namespace pb::costmodel {

enum class FetchKind {
    GBufferDepth,
    GBufferNormal,
    ProbeState,
    Visibility,
    Irradiance,
    ShMask,         // gi.technique=sh_*: the cell's validity mask (ShFetchStream.h)
    ShCoefficients, // gi.technique=sh_*: one coefficient 3D texture, trilinear
};
const char* fetchKindName(FetchKind k);

struct GiVariant {
    profile::GiProbeOrder order = profile::GiProbeOrder::Xyz;
    profile::GiLoops loops = profile::GiLoops::Fused;
    std::string name() const; // "xyz/fused"
};
// xyz/fused, xyz/split, slice_first/fused, slice_first/split.
std::vector<GiVariant> allGiVariants();

struct VariantStructure {
    // Loop step s visits corner offset cornerOffsets[s] in {0,1}^3 (probe = base + offset).
    std::array<std::array<int, 3>, 8> cornerOffsets;
    // Each loop runs over the 8 steps and issues these fetches per probe, in this order.
    // ProbeState is issued for every probe inside the grid, the others for valid probes only.
    std::vector<std::vector<FetchKind>> loops;
};
VariantStructure variantStructure(const GiVariant& v);

// Fetches of the apply shader before any probe: depth for every fragment, the normal for
// fragments inside the volume's influence.
constexpr int kGBufferFetchesPerLookup = 2;
constexpr int kProbesPerLookup = 8;
// At most per pixel and volume: GBuffer + every probe's fetches of every loop.
int maxFetchesPerLookup(const GiVariant& v);

// The shader's fetch instructions in program order: 0 = GBuffer depth, 1 = GBuffer normal,
// then per loop, per step, per fetch of that loop. A SIMD group (warp/wave) issues one slot
// for all its pixels before the next (FetchStream / CostModel).
int fetchSlot(const VariantStructure& v, int loop, int step, int fetchInLoop);
int fetchSlotCount(const VariantStructure& v);

// The ProbeSampler corner index (x + 2y + 4z) of an offset.
inline int samplerCorner(const std::array<int, 3>& off) {
    return off[0] + 2 * off[1] + 4 * off[2];
}

} // namespace pb::costmodel
