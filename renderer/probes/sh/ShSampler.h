#pragma once
// The CPU reference of the SH technique's lookup (gi.technique=sh_l1|sh_l2): what the GPU
// lookup (shaders/common_sh.glsl, run by gi_ddgi_apply.frag and gi_ddgi_points.frag under
// GI_TECHNIQUE_SH) reproduces with one hardware trilinear fetch per 3D texture.
//
// Steps, in this order:
// 1. Volume choice and edge fade exactly as ProbeSampler (smallest influencing box; roots
//    fade over kEdgeFadeCells cells).
// 2. The same surface bias as DDGI: p + (kBiasNormalWeight n + kBiasViewWeight v)
//    * 0.25 * minCell (ProbeSampler.h), in local space.
// 3. Lattice coordinate g = (p + half) / cell, clamped to [0, counts - 1] per axis (the 3D
//    texture's texel centres sit on the probes, CLAMP_TO_EDGE); base = min(floor g, counts-2),
//    fraction f = g - base (axes with one probe: base 0, f 0).
// 4. Leak mode (gi.sh_leak):
//    Sparse bakes' absent probes are read as their nearest stored probe in every mode
//    (ShAbsentFill.h), so absence never darkens a lookup.
//    none           trilinear blend of the 8 probes' coefficients, valid or not;
//    weight         Enlighten: invalid probes weigh 0; coefficients premultiplied by the
//                   weight and the weight are blended together, then divided;
//    validity_mask  APV: the cell's 8-bit mask of valid corners; f is nudged (nudgeToValid)
//                   so the one trilinear fetch gives every invalid corner weight 0.
//    No valid weight (all corners invalid): irradiance 0, weight 0.
// 5. Irradiance from the blended coefficients (shIrradiance, first 4 or 9), times the fade.
// No visibility test: this is the leak the testbed measures against DDGI.
#include "probes/ProbeSampler.h"
#include "probes/sh/ShAbsentFill.h"
#include "probes/sh/ShApvEncoding.h"
#include "probes/sh/ShIrradiance.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pb::probes {

enum class ShLeak { None, Weight, ValidityMask };

struct ShSampleOptions {
    int coefficients = kShL1Coefficients; // 4: sh_l1, 9: sh_l2
    ShLeak leak = ShLeak::None;
    bool edgeFade = true;
    // L1 as the APV encoding stores it (ShApvEncoding.h): blend the encoded texels, decode
    // with the blended L0. CPU only (no switch, no GPU path): measures the encoding's error.
    bool apv = false;
};

// The trilinear fractions moved the least (sum of |moves|, ties: first in x, y, z order of
// the candidates keep / 0 / 1) so that every corner whose bit is clear in `validMask`
// (corner = x + 2y + 4z) gets weight 0. False when the mask is 0.
bool nudgeToValid(glm::vec3& f, std::uint8_t validMask);

// What one lookup fetched, for the cost model (renderer/costmodel): the GPU pass's fetches
// follow from it (common_sh.glsl). `maskRead`: the cell's validity mask was fetched (weight and
// validity_mask, after the fade test); `coefficientsRead`: the coefficient textures were
// fetched (mask nonzero); `lattice`: the (nudged) lattice coordinate the trilinear fetches sample,
// in probe units (texel centres on probes).
struct ShTrace {
    bool maskRead = false, coefficientsRead = false;
    glm::ivec3 cell{0}; // the mask's texel (the cell's base corner)
    glm::vec3 lattice{0.0f};
};

class ShSampler {
public:
    // Throws pb::Error naming `source` when the set has no SH probes ("re-bake").
    ShSampler(const ProbeSet& set, int scenario, const std::string& source);
    IrradianceSample sample(const glm::vec3& pos, const glm::vec3& normal, const glm::vec3& view,
                            const ShSampleOptions& opt) const;
    // The lookup in one volume (file index), as that volume's draw runs it; `trace` optional.
    IrradianceSample sampleVolume(int volume, const glm::vec3& pos, const glm::vec3& normal,
                                  const glm::vec3& view, const ShSampleOptions& opt,
                                  ShTrace* trace = nullptr) const;
    int selectVolume(const glm::vec3& pos) const;

private:
    struct Frame {
        const ProbeVolume* volume;
        ShLookupVolume lookup;        // states and coefficients with absent probes filled
        std::vector<ShApvTexels> apv; // lookup.sh's L1 encoded, per probe
        glm::mat3 toLocal;
        glm::vec3 invCell, fadeWidth;
        float minCell, boxVolume;
    };
    std::vector<Frame> frames_;
};

// The one-line error for an SH technique on a probe file without SH.
std::string noShMessage(const std::string& source);

} // namespace pb::probes
