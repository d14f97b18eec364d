#pragma once
// One scenario of a probe set on the GPU, uploaded by the GI technique of gi.technique
// (GpuTechnique.h: GpuTechniqueDdgi.h exactly in the file's storage format, GpuTechniqueSh.h
// the SH 3D textures), plus the per-volume parameters every technique's lookup reads as
// uniforms (common_ddgi.glsl's volume frame, fade and bias). Volumes left out by
// gi.volume_lod are never created (no GPU memory). Requires a current GL context.
#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "gl/Texture.h"
#include "passes/GpuTechnique.h"
#include "passes/GpuTechniqueDdgi.h"
#include "probes/ProbeSet.h"
#include "profile/VolumeLod.h"

#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

namespace pb::render {

struct GpuProbeVolume {
    std::string name;
    int fileIndex = 0; // index in the probe set
    bool root = true;
    // The technique's textures in the order of their units (GpuTechnique::bindTextures):
    // DDGI's irradiance, visibility, state (GpuTechniqueDdgi.h kDdgiIrradiance ...), the SH
    // technique's coefficient textures then its validity texture (GpuShTextures.h).
    std::vector<gl::Texture> textures;
    // What common_ddgi.glsl needs, computed as the CPU sampler computes it (float).
    glm::dvec3 center{0.0};
    glm::mat3 toLocal{1.0f};
    glm::vec3 half{0.0f}, fadeWidth{0.0f}, invCell{0.0f}, gridOrigin{0.0f}, gridStep{0.0f};
    glm::ivec3 counts{1};
    // Set by the DDGI upload; the defaults below for other techniques (which set the shared
    // uniforms u_ddgiTileBits and u_ddgiIrradianceScale from them all the same).
    glm::ivec3 packedCounts{1}; // the tile grid of the textures (= counts unless sparse)
    bool sparse = false;        // tiles packed, found through the state's w
    glm::ivec2 tileBits{0};     // u_ddgiTileBits: how w's code splits (probes::TileCode)
    float biasDistance = 0, invMaxDistance = 0, boxVolume = 0;
    // 1 / the irradiance's storage scale (probes/StorageScale.h): fetched * this = true E.
    float irradianceDecode = 1.0f;
    std::size_t bytes() const {
        std::size_t total = 0;
        for (const gl::Texture& t : textures)
            total += t.bytes();
        return total;
    }
};

class GpuProbes {
public:
    // Uploads scenario `scenario` of `set` with the technique makeGpuTechnique(technique,
    // shLeak) gives (GpuTechnique.h). Throws pb::Error for a bad scenario index, a GL that
    // cannot sample the set's storage format (rgba32f without float linear filtering, BC6H
    // without BPTC; checked for every technique), invalid volumes, or what the technique's
    // upload refuses (texture bytes that do not match the shapes; a set without SH under
    // sh_l1 / sh_l2, saying to re-bake).
    GpuProbes(const probes::ProbeSet& set, int scenario, const profile::VolumeLod& lod = {},
              profile::GiTechnique technique = profile::GiTechnique::Ddgi,
              profile::GiShLeak shLeak = profile::GiShLeak::None);

    const std::vector<GpuProbeVolume>& volumes() const { return volumes_; }
    std::size_t bytes() const; // GPU memory of everything uploaded
    // Whether a volume stores its tiles packed (sparse): then, and only then, GI shaders are
    // built with the tile indirection (DDGI_SPARSE_TILES, common_ddgi.glsl).
    bool anySparse() const;
    const std::string& scenarioName() const { return scenario_; }
    // The technique the volumes were uploaded for: its shaders, units and dynamic-object
    // support. The passes ask it, never gi.technique.
    const GpuTechnique& technique() const { return *technique_; }
    probes::StorageFormat format() const { return format_; }

    // Indices into volumes() in draw order for "each draw overwrites": largest box first, and
    // among equal boxes the later file index first, so the last draw that covers a pixel is
    // the CPU sampler's choice (smallest box, ties: first in the file).
    std::vector<int> drawOrder() const;

    // Binds volume v's textures to units firstUnit .. firstUnit + unitsPerVolume() - 1 and
    // sets the u_ddgi* volume uniforms and the technique's own of the program in use.
    // `origin` is the origin of the shader's space in world units (the eye for camera-relative
    // rendering, 0 for world space). `irradianceScale` is the frame's pre-exposure
    // (gi.guard_exposure; 1 without it). u_ddgiIrradianceScale gets it times the volume's
    // irradianceDecode (both powers of two: exact), so the storage scale costs no instruction
    // in shaders built with the guard (common_ddgi.glsl).
    void bindVolume(const gl::Program& program, int v, int firstUnit, const glm::dvec3& origin,
                    float irradianceScale = 1.0f) const;
    // DDGI's units (GpuTechniqueDdgi.h), for the passes that run on DDGI probes only
    // (DynamicShPass, ProbeDebugPass, bench's FetchFloorPass).
    static constexpr int kUnitsPerVolume = kDdgiUnitsPerVolume;
    int unitsPerVolume() const { return technique_->unitsPerVolume(); }
    // After a pass's draws: on units `units` - 1 down to 0 (leaving unit 0 active), unbinds
    // GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY and the technique's texture target if it is another.
    void unbindTextures(int units) const;

private:
    std::vector<GpuProbeVolume> volumes_;
    std::string scenario_;
    probes::StorageFormat format_ = probes::StorageFormat::Rgba16f;
    std::unique_ptr<GpuTechnique> technique_;
};

// The sampler's constants (renderer/probes/ProbeSampler.h) as DDGI_* shader defines, so the
// GLSL port can never drift from the CPU reference. Every technique's programs get them
// (giShaderDefines): the SH lookup shares the DDGI surface bias.
gl::Defines ddgiConstantDefines();

} // namespace pb::render
