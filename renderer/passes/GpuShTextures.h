#pragma once
// The SH technique's GPU layout (gi.technique=sh_l1|sh_l2), per volume one set of
// GL_TEXTURE_3D textures of the probe lattice (texel (i, j, k) = probe (i, j, k), texel
// centres on the probes, CLAMP_TO_EDGE, hardware trilinear), as Enlighten stores volumes:
//   L1: 3 x RGBA16F, texture c = colour channel c's 4 coefficients (l = 0, 1);
//   L2: + 4 x RGBA16F holding the 5 quadratic coefficients of R, G, B (15 values, channel
//       major, 4 per texel; the 16th is 0);
//   + 1 x R8: gi.sh_leak=none: the probe's validity (255 valid, 0 invalid; unread);
//       weight and validity_mask: per cell (texel = the cell's lowest corner) the 8-bit mask
//       of its valid corners (bit x + 2y + 4z), read with texelFetch. `weight` stores the
//       coefficients premultiplied by the probe's weight (0 or 1), filters them in hardware and
//       divides by the valid corners' trilinear weights summed from the mask in float (a
//       hardware-filtered R8 weight disagreed with the float-filtered lighting on llvmpipe by
//       up to 10% where the weight is small: common_sh.glsl).
// 25 bytes a probe for L1, 57 for L2 (`probebench memory --technique`). The coefficients are
// the bake's, already rounded to half (probes/sh/ShIrradiance.h), so the upload is exact.
// GpuTechniqueSh.h binds them; this file is the layout and its upload.
#include "gl/Texture.h"
#include "probes/ProbeSet.h"
#include "profile/Profile.h"

#include <cstdint>
#include <vector>

namespace pb::render {

// 4 (sh_l1), 9 (sh_l2), 0 (ddgi).
int shCoefficientCount(profile::GiTechnique t);
// GPU bytes per probe of the layout above (0 for ddgi).
std::size_t shBytesPerProbe(profile::GiTechnique t);

// The validity-mask byte of the cell whose lowest corner is `base` (corners past the grid on
// axes with one probe repeat the last probe, as CLAMP_TO_EDGE does).
std::uint8_t shCellMask(const probes::ProbeVolume& v, const std::vector<probes::ProbeState>& s,
                        const glm::ivec3& base);

// Uploads volume `vi` of scenario `scenario`: the 3 (L1) or 7 (L2) RGBA16F coefficient
// textures, then the R8 validity or cell-mask texture, labelled `label` + " sh<t>" and
// " sh validity". Throws pb::Error when the set has no SH (probes::noShMessage) or the GL
// cannot hold a texture (naming `label`).
std::vector<gl::Texture> uploadShVolume(const probes::ProbeSet& set, int scenario, int vi,
                                        profile::GiTechnique technique, profile::GiShLeak leak,
                                        const std::string& label);

} // namespace pb::render
