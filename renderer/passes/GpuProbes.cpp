#include "passes/GpuProbes.h"

#include "core/Error.h"
#include "gl/Capabilities.h"
#include "probes/ProbeSampler.h"
#include "profile/GiVolumeLod.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace pb::render {

namespace {

using probes::StorageFormat;

void fillParameters(GpuProbeVolume& g, const probes::ProbeVolume& v) {
    // The same float expressions as ProbeSampler::init, so both sides round alike.
    g.center = glm::dvec3(v.center);
    g.toLocal = glm::transpose(v.localToWorldRotation());
    g.half = v.halfExtents;
    g.counts = v.counts;
    const glm::vec3 cell = v.cellSize();
    for (int a = 0; a < 3; ++a) {
        bool grid = v.counts[a] > 1;
        g.invCell[a] = grid ? 1.0f / cell[a] : 0.0f;
        g.gridOrigin[a] = grid ? -v.halfExtents[a] : 0.0f;
        g.gridStep[a] = grid ? cell[a] : 0.0f;
    }
    g.fadeWidth = g.root ? probes::kEdgeFadeCells * cell : glm::vec3(0.0f);
    g.biasDistance = probes::kBiasScale * v.minCellSize();
    g.invMaxDistance = 1.0f / v.maxDistance();
    g.boxVolume = v.boxVolume();
}

std::string glslFloat(float v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

} // namespace

bool GpuProbes::anySparse() const {
    return std::any_of(volumes_.begin(), volumes_.end(),
                       [](const GpuProbeVolume& g) { return g.sparse; });
}

gl::Defines ddgiConstantDefines() {
    using namespace probes;
    return {
        {"DDGI_BIAS_NORMAL", glslFloat(kBiasNormalWeight)},
        {"DDGI_BIAS_VIEW", glslFloat(kBiasViewWeight)},
        {"DDGI_WRAP_BIAS", glslFloat(kWrapBias)},
        {"DDGI_BEHIND_FLOOR", glslFloat(kBehindFloor)},
        {"DDGI_CHEBYSHEV_FLOOR", glslFloat(kChebyshevFloor)},
        {"DDGI_VARIANCE_FLOOR", glslFloat(kVarianceFloor)},
        {"DDGI_CRUSH_THRESHOLD", glslFloat(kCrushThreshold)},
        {"DDGI_MIN_TRILINEAR", glslFloat(kMinTrilinear)},
        {"DDGI_IRR_INTERIOR", glslFloat(float(kIrradianceInterior))},
        {"DDGI_IRR_TILE", glslFloat(float(kIrradianceTile))},
        {"DDGI_VIS_INTERIOR", glslFloat(float(kVisibilityInterior))},
        {"DDGI_VIS_TILE", glslFloat(float(kVisibilityTile))},
    };
}

GpuProbes::GpuProbes(const probes::ProbeSet& set, int scenario, const profile::VolumeLod& lod,
                     profile::GiTechnique technique, profile::GiShLeak shLeak)
    : format_(set.format()), technique_(makeGpuTechnique(technique, shLeak)) {
    if (scenario < 0 || size_t(scenario) >= set.scenarios.size() ||
        size_t(scenario) >= set.irradiance.size())
        throw Error("probe set: no scenario #" + std::to_string(scenario));
    scenario_ = set.scenarios[size_t(scenario)].name;
    // Checked for every technique, as before the techniques had a class each (the SH upload
    // reads no DDGI texture, so only the error path of an SH frame on such a GL depends on it).
    if (format_ != StorageFormat::Rgba16f) {
        const gl::GlCaps caps = gl::queryCaps();
        if (format_ == StorageFormat::Rgba32f && !caps.floatLinearFilter)
            throw Error("rgba32f probes need linear filtering of 32-bit float textures "
                        "(OES_texture_float_linear), which this GL lacks");
        if (format_ == StorageFormat::Bc6h && !caps.bptc)
            throw Error("bc6h probes need BPTC textures, which this GL lacks");
    }
    const std::vector<int> parents = probes::validateVolumes(set.volumes, "probe set");
    for (int vi : profile::selectVolumes(set, lod)) {
        const probes::ProbeVolume& v = set.volumes[size_t(vi)];
        GpuProbeVolume g;
        g.name = v.name;
        g.fileIndex = vi;
        g.root = parents[size_t(vi)] < 0;
        technique_->uploadVolume(g, set, scenario, vi, "probe volume '" + v.name + "'");
        fillParameters(g, v);
        volumes_.push_back(std::move(g));
    }
}

std::size_t GpuProbes::bytes() const {
    std::size_t total = 0;
    for (const GpuProbeVolume& v : volumes_)
        total += v.bytes();
    return total;
}

std::vector<int> GpuProbes::drawOrder() const {
    std::vector<float> boxes;
    std::vector<int> files;
    for (const GpuProbeVolume& v : volumes_) {
        boxes.push_back(v.boxVolume);
        files.push_back(v.fileIndex);
    }
    return profile::volumeDrawOrder(boxes, files);
}

void GpuProbes::bindVolume(const gl::Program& program, int v, int firstUnit,
                           const glm::dvec3& origin, float irradianceScale) const {
    const GpuProbeVolume& g = volumes_[size_t(v)];
    technique_->bindTextures(program, g, firstUnit);
    program.set("u_ddgiCenter", glm::vec3(g.center - origin));
    program.set("u_ddgiToLocal", g.toLocal);
    program.set("u_ddgiHalf", g.half);
    program.set("u_ddgiFadeWidth", g.fadeWidth);
    program.set("u_ddgiInvCell", g.invCell);
    program.set("u_ddgiGridOrigin", g.gridOrigin);
    program.set("u_ddgiGridStep", g.gridStep);
    program.set("u_ddgiCounts", g.counts);
    // Dense and sparse volumes alike: the state's w holds the tile's code (SparseLayout.h).
    program.set("u_ddgiTileBits", g.tileBits);
    program.set("u_ddgiBiasDistance", g.biasDistance);
    program.set("u_ddgiInvMaxDistance", g.invMaxDistance);
    program.set("u_ddgiIrradianceScale", irradianceScale * g.irradianceDecode);
    technique_->setVolumeUniforms(program, g);
}

void GpuProbes::unbindTextures(int units) const {
    const GLenum target = technique_->textureTarget();
    for (int u = units - 1; u >= 0; --u) {
        glActiveTexture(GLenum(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
        if (target != GL_TEXTURE_2D && target != GL_TEXTURE_2D_ARRAY) glBindTexture(target, 0);
    }
}

} // namespace pb::render
