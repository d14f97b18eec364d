#pragma once
// A GI technique's GPU side (docs/ARCHITECTURE.md, "A technique"): what it uploads for each
// probe volume, how a GI program binds it, which shaders run its lookup and which dynamic-object
// lookup it offers. GpuProbes owns one, made by makeGpuTechnique from gi.technique: the one
// place on the GPU side that dispatches on the switch. The GI passes (GiApplyPass,
// DynamicShPass, ProbeDebugPass, frame/GiPointEvaluator) reach the technique only through
// GpuProbes, so a new technique is a new implementation file and a line in makeGpuTechnique;
// no DDGI file changes.
//
// Implementations: GpuTechniqueDdgi.h (gi.technique=ddgi: octahedral irradiance, visibility and
// the probe states) and GpuTechniqueSh.h (sh_l1|sh_l2: the SH 3D textures of GpuShTextures.h).
//
// What every technique shares (GpuProbes): the volume frame in GpuProbeVolume (centre,
// rotation, half extents, fade, grid, bias; common_ddgi.glsl's u_ddgi* volume uniforms, which
// common_sh.glsl reads too), the draw order, the volume selection of gi.volume_lod and the
// apply pass's target, draws and stencil path.
#include "gl/Program.h"
#include "probes/ProbeSet.h"
#include "profile/Profile.h"

#include <cstddef>
#include <memory>
#include <string>

namespace pb::render {

struct GpuProbeVolume;

class GpuTechnique {
public:
    virtual ~GpuTechnique() = default;

    // Texture units one volume's textures take, from the first unit a pass gives bindVolume.
    virtual int unitsPerVolume() const = 0;
    // The texture target of the technique's textures (GL_TEXTURE_2D_ARRAY, GL_TEXTURE_3D): the
    // passes unbind it, with GL_TEXTURE_2D and GL_TEXTURE_2D_ARRAY, after their draws
    // (GpuProbes::unbindTextures).
    virtual GLenum textureTarget() const = 0;
    // GPU bytes uploadVolume allocates for volume `vi` of `set`, computed without GL (the frame's
    // memory estimate, frame/GiMemory).
    virtual std::size_t volumeBytes(const probes::ProbeSet& set, int vi) const = 0;

    // Uploads volume `vi` of scenario `scenario` into g.textures (in the order of their units)
    // and sets g's fields that are the technique's own; GpuProbes has set g's name, fileIndex
    // and root before and fills the shared volume frame after. `what` names the volume in
    // errors and GL labels. Throws pb::Error when the set cannot feed the technique (shapes
    // that do not match, a set without the technique's data) or the GL cannot hold a texture.
    // Requires a current GL context.
    virtual void uploadVolume(GpuProbeVolume& g, const probes::ProbeSet& set, int scenario, int vi,
                              const std::string& what) const = 0;
    // Binds g's textures to units firstUnit .. firstUnit + unitsPerVolume() - 1 and points the
    // program's samplers at them. Called by GpuProbes::bindVolume with `program` in use,
    // before the shared volume uniforms.
    virtual void bindTextures(const gl::Program& program, const GpuProbeVolume& g,
                              int firstUnit) const = 0;
    // Sets the technique's own per-volume uniforms, after the shared ones (program in use).
    virtual void setVolumeUniforms(const gl::Program& program, const GpuProbeVolume& g) const = 0;

    // The fragment shader of the apply pass's lookup draws (gi-apply; the stencil marks and
    // the depth copy are technique-neutral) and of the point lookups (GiPointEvaluator,
    // DynamicShPass). The variant within the file comes from the switch table's defines
    // (GI_TECHNIQUE_*), which every GI program gets (giShaderDefines).
    virtual const char* applyShader() const = 0;
    virtual const char* pointsShader() const = 0;

    // Why gi.dynamic=sh (DynamicShPass, which projects the technique's point lookups at each
    // dynamic object's centre) cannot run on this technique's probes; empty when it can. The
    // frame then lights dynamic objects per pixel instead (FrameRenderer, GiMemory).
    virtual std::string dynamicShUnsupported() const = 0;
};

// The technique of gi.technique (and its options: gi.sh_leak for the SH techniques). Creates
// no GL object.
std::unique_ptr<GpuTechnique> makeGpuTechnique(profile::GiTechnique technique,
                                               profile::GiShLeak shLeak);

} // namespace pb::render
