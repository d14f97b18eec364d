#pragma once
// gi.technique=ddgi on the GPU: per volume two 2D texture arrays exactly in the file's storage
// format (irradiance RGBA16F / RGBA32F / BC6H, visibility RG16F / RG32F / BC6H, one layer per
// probe plane along local Y; sparse volumes pack their stored tiles) and a per-probe state
// array (RGBA32F: relocation offset in local axes, w = the tile indirection: +(code+1) valid,
// -(code+1) invalid, 0 absent, code = the tile's column, row and layer as bit fields
// (SparseLayout.h TileCode); texel (i, k, layer j) like the probe tiles). Read by
// common_ddgi.glsl (ddgiSample) in gi_ddgi_apply.frag and gi_ddgi_points.frag.
#include "passes/GpuTechnique.h"

namespace pb::render {

// GpuProbeVolume::textures of a DDGI volume, in the order of their units.
enum DdgiTexture : std::size_t { kDdgiIrradiance = 0, kDdgiVisibility = 1, kDdgiState = 2 };
constexpr int kDdgiUnitsPerVolume = 3;

class GpuTechniqueDdgi final : public GpuTechnique {
public:
    int unitsPerVolume() const override { return kDdgiUnitsPerVolume; }
    GLenum textureTarget() const override { return GL_TEXTURE_2D_ARRAY; }
    // profile::gpuVolumeBytes: sparse volumes count their packed tiles and the state texture.
    std::size_t volumeBytes(const probes::ProbeSet& set, int vi) const override;
    // Sets g.sparse, packedCounts, tileBits and irradianceDecode (1 / the scenario's storage
    // scale). Absent probes of a sparse volume read their nearest stored probe's tile and
    // position (probes/AbsentProbeFill.h), as the CPU sampler does. Throws pb::Error when the
    // volume's state count does not match its grid or the stored bytes do not match a shape.
    void uploadVolume(GpuProbeVolume& g, const probes::ProbeSet& set, int scenario, int vi,
                      const std::string& what) const override;
    // u_ddgiIrradiance, u_ddgiVisibility, u_ddgiState on firstUnit .. firstUnit + 2.
    void bindTextures(const gl::Program& program, const GpuProbeVolume& g,
                      int firstUnit) const override;
    // The per-volume constants of the lookup (texel-coordinate scales, u_ddgiMaxBase, the
    // bias vectors, the behind-surface ramp), once per draw instead of per pixel and probe.
    void setVolumeUniforms(const gl::Program& program, const GpuProbeVolume& g) const override;
    const char* applyShader() const override { return "gi_ddgi_apply.frag"; }
    const char* pointsShader() const override { return "gi_ddgi_points.frag"; }
    std::string dynamicShUnsupported() const override { return {}; } // DynamicShPass reads it
};

} // namespace pb::render
