#pragma once
// One scenario of a probe set on the GPU, exactly in its stored format: per volume two 2D
// texture arrays (irradiance RGBA16F / RGBA32F / BC6H, visibility RG16F / RG32F / BC6H, one
// layer per probe plane along local Y) and a per-probe state array (RGBA32F: relocation offset
// in local axes, w = the tile indirection: +(code+1) valid, -(code+1) invalid, 0 absent,
// code = the tile's column, row and layer as bit fields (SparseLayout.h TileCode); texel
// (i, k, layer j) like the probe tiles; sparse volumes pack their stored tiles), plus
// the per-volume parameters common_ddgi.glsl reads as uniforms. Volumes left out by
// gi.volume_lod are never created (no GPU memory). Requires a current GL context.
#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "gl/Texture.h"
#include "passes/GpuShTextures.h"
#include "probes/ProbeSet.h"
#include "profile/VolumeLod.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pb::render {

struct GpuProbeVolume {
    std::string name;
    int fileIndex = 0; // index in the probe set
    bool root = true;
    gl::Texture irradiance, visibility, state;
    // What common_ddgi.glsl needs, computed as the CPU sampler computes it (float).
    glm::dvec3 center{0.0};
    glm::mat3 toLocal{1.0f};
    glm::vec3 half{0.0f}, fadeWidth{0.0f}, invCell{0.0f}, gridOrigin{0.0f}, gridStep{0.0f};
    glm::ivec3 counts{1};
    glm::ivec3 packedCounts{1}; // the tile grid of the textures (= counts unless sparse)
    bool sparse = false;        // tiles packed, found through the state's w
    glm::ivec2 tileBits{0};     // u_ddgiTileBits: how w's code splits (probes::TileCode)
    float biasDistance = 0, invMaxDistance = 0, boxVolume = 0;
    // 1 / the irradiance's storage scale (probes/StorageScale.h): fetched * this = true E.
    float irradianceDecode = 1.0f;
    // gi.technique=sh_l1|sh_l2: the SH 3D textures (GpuShTextures.h) instead of the DDGI ones
    // (irradiance, visibility and state are then empty).
    GpuShVolume sh;
    std::size_t bytes() const {
        return irradiance.bytes() + visibility.bytes() + state.bytes() + sh.bytes();
    }
};

class GpuProbes {
public:
    // Throws pb::Error for a bad scenario index, texture bytes that do not match the shapes,
    // or a GL that cannot sample the format (BC6H without BPTC).
    // `technique` sh_l1 / sh_l2 uploads the set's SH probes (GpuShTextures.h, with `shLeak`)
    // instead of the DDGI textures; a set without SH is then a pb::Error saying to re-bake.
    GpuProbes(const probes::ProbeSet& set, int scenario, const profile::VolumeLod& lod = {},
              profile::GiTechnique technique = profile::GiTechnique::Ddgi,
              profile::GiShLeak shLeak = profile::GiShLeak::None);

    const std::vector<GpuProbeVolume>& volumes() const { return volumes_; }
    std::size_t bytes() const; // GPU memory of everything uploaded
    // Whether a volume stores its tiles packed (sparse): then, and only then, GI shaders are
    // built with the tile indirection (DDGI_SPARSE_TILES, common_ddgi.glsl).
    bool anySparse() const;
    const std::string& scenarioName() const { return scenario_; }
    profile::GiTechnique technique() const { return technique_; }
    probes::StorageFormat format() const { return format_; }

    // Indices into volumes() in draw order for "each draw overwrites": largest box first, and
    // among equal boxes the later file index first, so the last draw that covers a pixel is
    // the CPU sampler's choice (smallest box, ties: first in the file).
    std::vector<int> drawOrder() const;

    // Binds volume v's textures to units firstUnit..firstUnit+2 and sets the u_ddgi* uniforms
    // of the program in use. `origin` is the origin of the shader's space in world units (the
    // eye for camera-relative rendering, 0 for world space). `irradianceScale` is the frame's
    // pre-exposure (gi.guard_exposure; 1 without it). u_ddgiIrradianceScale gets it times the
    // volume's irradianceDecode (both powers of two: exact), so the storage scale costs no
    // instruction in shaders built with the guard (common_ddgi.glsl).
    void bindVolume(const gl::Program& program, int v, int firstUnit, const glm::dvec3& origin,
                    float irradianceScale = 1.0f) const;
    static constexpr int kUnitsPerVolume = 3;   // DDGI: irradiance, visibility, state
    static constexpr int kShUnitsPerVolume = 8; // SH: u_shCoefficients0..6, u_shValidity
    int unitsPerVolume() const {
        return technique_ == profile::GiTechnique::Ddgi ? kUnitsPerVolume : kShUnitsPerVolume;
    }

private:
    std::vector<GpuProbeVolume> volumes_;
    std::string scenario_;
    probes::StorageFormat format_ = probes::StorageFormat::Rgba16f;
    profile::GiTechnique technique_ = profile::GiTechnique::Ddgi;
};

// The sampler's constants (renderer/probes/ProbeSampler.h) as DDGI_* shader defines, so the
// GLSL port can never drift from the CPU reference.
gl::Defines ddgiConstantDefines();

} // namespace pb::render
