#pragma once
// The SH technique's fetches as the texture unit sees them (gi.technique=sh_l1|sh_l2,
// shaders/common_sh.glsl): per lookup, after the GBuffer reads,
//   - weight / validity_mask: one texelFetch of the cell's 8-bit mask (R8, 1 texel);
//   - then, unless the mask is 0, one hardware trilinear fetch per coefficient texture
//     (3 RGBA16F for L1, 7 for L2), each the 2x2x2 texels around the (nudged) lattice point:
//     i0 = floor(g), i1 = i0 + 1 per axis, clamped to the grid (CLAMP_TO_EDGE).
// The 3D textures' texel (x, row, layer) is probe (x, z, y), as GpuShTextures uploads them;
// their addresses come from TextureMemory like every other texture's.
#include "costmodel/FetchStream.h"
#include "probes/sh/ShSampler.h"
#include "profile/Profile.h"

#include <vector>

namespace pb::costmodel {

// Coefficient textures per volume: 3 (sh_l1), 7 (sh_l2), 0 (ddgi).
int shCoefficientTextures(profile::GiTechnique t);
// The CPU sampler's options for the profile's technique and gi.sh_leak.
probes::ShSampleOptions shSampleOptions(const profile::Profile& p);
// The nominal texels one lookup reads in the shader: 8 per coefficient texture, + 1 for the
// mask (weight, validity_mask) - the formula the replay's texel counter must match.
int shTexelsPerLookup(const profile::Profile& p);

// Slots (shader instructions in program order): 0 depth, 1 normal, 2 mask, 3.. coefficients.
int shFetchSlotCount(int coefficientTextures);

// Appends one lookup's SH fetches (nothing when the trace read nothing: faded out).
void appendShFetches(const probes::ShTrace& trace, const TextureTable::Volume& textures,
                     const glm::ivec3& counts, std::vector<Fetch>& out);

} // namespace pb::costmodel
