#pragma once
// gi.technique=sh_l1|sh_l2 on the GPU: per volume the SH irradiance volume's 3D textures
// (GpuShTextures.h: 3 (L1) or 7 (L2) RGBA16F coefficient textures and one R8 validity or
// cell-mask texture, 25 / 57 bytes a probe), read by common_sh.glsl (shSample) with one
// hardware trilinear fetch per texture. The lookup is compiled into the DDGI shaders'
// files under GI_TECHNIQUE_SH (gi_ddgi_apply.frag, gi_ddgi_points.frag), so the apply pass's
// target, draws, discard and stencil path are the same for both techniques; it reads
// common_ddgi.glsl's volume uniforms (frame, fade, bias) and no DDGI texture.
#include "passes/GpuTechnique.h"

namespace pb::render {

// Units a volume takes: u_shCoefficients0 .. 6 (L1 binds 0 .. 2) and u_shValidity on the
// eighth, for L1 and L2 alike (the cost model counts the same: costmodel/CostModel.cpp).
constexpr int kShUnitsPerVolume = 8;

class GpuTechniqueSh final : public GpuTechnique {
public:
    // `technique`: ShL1 or ShL2; `leak`: gi.sh_leak (what the validity texture holds and
    // whether the coefficients are premultiplied, GpuShTextures.h).
    GpuTechniqueSh(profile::GiTechnique technique, profile::GiShLeak leak)
        : technique_(technique), leak_(leak) {}

    int unitsPerVolume() const override { return kShUnitsPerVolume; }
    GLenum textureTarget() const override { return GL_TEXTURE_3D; }
    // shBytesPerProbe x the volume's probes (every grid probe has a texel, sparse or not).
    std::size_t volumeBytes(const probes::ProbeSet& set, int vi) const override;
    // g.textures = the coefficient textures, then the validity texture (uploadShVolume).
    // Throws pb::Error when the set has no SH (probes::noShMessage: re-bake).
    void uploadVolume(GpuProbeVolume& g, const probes::ProbeSet& set, int scenario, int vi,
                      const std::string& what) const override;
    // u_shCoefficients<t> on firstUnit + t, u_shValidity on firstUnit + 7.
    void bindTextures(const gl::Program& program, const GpuProbeVolume& g,
                      int firstUnit) const override;
    // None: the lookup needs only the shared volume uniforms.
    void setVolumeUniforms(const gl::Program&, const GpuProbeVolume&) const override {}
    const char* applyShader() const override { return "gi_ddgi_apply.frag"; }
    const char* pointsShader() const override { return "gi_ddgi_points.frag"; }
    // The projection samples DDGI textures this technique does not upload.
    std::string dynamicShUnsupported() const override { return "has no DDGI probes to project"; }

private:
    profile::GiTechnique technique_;
    profile::GiShLeak leak_;
};

} // namespace pb::render
