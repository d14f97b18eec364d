#include "passes/GpuProbes.h"

#include "core/Error.h"
#include "gl/Capabilities.h"
#include "profile/GiVolumeLod.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeSampler.h"
#include "probes/store/SparseLayout.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace pb::render {

namespace {

using probes::StorageFormat;

gl::TextureFormat irradianceFormat(StorageFormat f) {
    return f == StorageFormat::Rgba32f ? gl::TextureFormat::RGBA32F
           : f == StorageFormat::Bc6h  ? gl::TextureFormat::BC6H_UF16
                                       : gl::TextureFormat::RGBA16F;
}
gl::TextureFormat visibilityFormat(StorageFormat f) {
    return f == StorageFormat::Rgba32f ? gl::TextureFormat::RG32F
           : f == StorageFormat::Bc6h  ? gl::TextureFormat::BC6H_UF16
                                       : gl::TextureFormat::RG16F;
}

// Uploads `t.stored` as is: half floats as GL_HALF_FLOAT (the file's bits, never re-rounded
// from float), 32-bit floats as GL_FLOAT, BC6H blocks compressed.
gl::Texture uploadProbeTexture(const probes::ProbeTexture& t, gl::TextureFormat format,
                               StorageFormat storage, const std::string& what) {
    gl::TextureDesc d;
    d.format = format;
    d.width = t.shape.width;
    d.height = t.shape.height;
    d.layers = t.shape.layers;
    d.filter = gl::Filter::Linear; // the sampler's bilinear; tile borders keep it in the tile
    gl::Texture tex = [&] {
        try {
            return gl::Texture(d);
        } catch (const Error& e) { // past the context's limits: say which probe texture
            throw Error(what + ": " + e.what());
        }
    }();
    if (t.stored.size() != gl::textureBytes(format, d.width, d.height, d.layers))
        throw Error(what + ": " + std::to_string(t.stored.size()) + " stored bytes, expected " +
                    std::to_string(gl::textureBytes(format, d.width, d.height, d.layers)));
    if (storage == StorageFormat::Rgba16f) {
        const gl::FormatInfo& fi = gl::formatInfo(format);
        glBindTexture(GL_TEXTURE_2D_ARRAY, tex.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, d.width, d.height, d.layers, fi.format,
                        GL_HALF_FLOAT, t.stored.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    } else {
        tex.upload(t.stored.data());
    }
    tex.label(what);
    return tex;
}

// w is the probe's tile code (SparseLayout.h TileCode): +(code + 1) valid, -(code + 1)
// invalid with a tile, 0 absent (no tile).
gl::Texture uploadStates(const probes::ProbeVolume& v, const std::vector<probes::ProbeState>& s,
                         const probes::TileLayout& tiles) {
    std::vector<float> texels;
    texels.reserve(s.size() * 4);
    for (std::size_t i = 0; i < s.size(); ++i) { // probe index = texel order of (i, k, layer j)
        const probes::ProbeState& p = s[i];
        texels.insert(texels.end(), {p.offset.x, p.offset.y, p.offset.z, tiles.stateW(i, p.valid)});
    }
    gl::TextureDesc d;
    d.format = gl::TextureFormat::RGBA32F;
    d.width = v.counts.x;
    d.height = v.counts.z;
    d.layers = v.counts.y;
    d.filter = gl::Filter::Nearest;
    gl::Texture tex(d);
    tex.upload(texels.data());
    return tex;
}

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
    : format_(set.format()), technique_(technique) {
    if (scenario < 0 || size_t(scenario) >= set.scenarios.size() ||
        size_t(scenario) >= set.irradiance.size())
        throw Error("probe set: no scenario #" + std::to_string(scenario));
    scenario_ = set.scenarios[size_t(scenario)].name;
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
        const std::string what = "probe volume '" + v.name + "'";
        GpuProbeVolume g;
        g.name = v.name;
        g.fileIndex = vi;
        g.root = parents[size_t(vi)] < 0;
        if (isShTechnique(technique)) {
            g.sh = uploadShVolume(set, scenario, vi, technique, shLeak, what);
            fillParameters(g, v);
            volumes_.push_back(std::move(g));
            continue;
        }
        if (set.states[size_t(vi)].size() != size_t(v.probeCount()))
            throw Error(what + ": probe state count does not match its grid");
        // Sparse volumes upload only their stored tiles, packed; dense ones as they are. The
        // irradiance texture holds the irradiance-only probes' tiles after the stored ones; the
        // visibility texture ends with the stored ones (SparseLayout.h irradianceSlots). The
        // cost model replays the same layout (costmodel/FetchStream.cpp).
        // Absent probes outside geometry read their nearest stored probe's tile and position
        // (probes/AbsentProbeFill.h), as the CPU sampler does.
        const std::vector<int> fill =
            probes::fillSources(v, set.states[size_t(vi)], set.settings.backfaceThreshold);
        const probes::TileLayout tiles = probes::tileLayout(v, set.states[size_t(vi)], fill);
        g.sparse = tiles.sparse;
        g.packedCounts = tiles.packedCounts;
        g.tileBits = glm::ivec2(tiles.code.columnBits, tiles.code.rowBits);
        probes::ProbeTexture scratch;
        const std::vector<int> visibilitySlots = probes::packedSlots(set.states[size_t(vi)]);
        auto packed = [&](const probes::ProbeTexture& t, int tile) -> const probes::ProbeTexture& {
            if (!tiles.sparse) return t;
            const bool irradiance = tile == probes::kIrradianceTile;
            scratch = probes::packTiles(
                t, irradiance ? tiles.slots : visibilitySlots, v.counts,
                irradiance ? tiles.packedCounts : tiles.visibilityPackedCounts, tile, format_);
            return scratch;
        };
        g.irradiance = uploadProbeTexture(
            packed(set.irradiance[size_t(scenario)][size_t(vi)], probes::kIrradianceTile),
            irradianceFormat(format_), format_, what + " irradiance");
        // The file stores irradiance x the scenario's storage scale (probes/StorageScale.h).
        g.irradianceDecode = 1.0f / set.irradiance[size_t(scenario)][size_t(vi)].storageScale;
        g.visibility =
            uploadProbeTexture(packed(set.visibility[size_t(vi)], probes::kVisibilityTile),
                               visibilityFormat(format_), format_, what + " visibility");
        g.state = uploadStates(v, probes::lookupStates(v, set.states[size_t(vi)], fill), tiles);
        g.state.label(what + " states");
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
    if (isShTechnique(technique_)) {
        for (std::size_t t = 0; t < g.sh.coefficients.size(); ++t) {
            g.sh.coefficients[t].bind(firstUnit + int(t));
            program.set("u_shCoefficients" + std::to_string(t), firstUnit + int(t));
        }
        g.sh.validity.bind(firstUnit + 7);
        program.set("u_shValidity", firstUnit + 7);
    } else {
        g.irradiance.bind(firstUnit);
        g.visibility.bind(firstUnit + 1);
        g.state.bind(firstUnit + 2);
        program.set("u_ddgiIrradiance", firstUnit);
        program.set("u_ddgiVisibility", firstUnit + 1);
        program.set("u_ddgiState", firstUnit + 2);
    }
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
    if (isShTechnique(technique_)) return; // no DDGI textures
    const gl::TextureDesc &irr = g.irradiance.desc(), &vis = g.visibility.desc();
    const glm::vec2 irrInv(1.0f / float(irr.width), 1.0f / float(irr.height));
    const glm::vec2 visInv(1.0f / float(vis.width), 1.0f / float(vis.height));
    program.set("u_ddgiIrrInvSize", irrInv);
    program.set("u_ddgiVisInvSize", visInv);
    // Per-volume constants of the lookup (common_ddgi.glsl), once per draw instead of per pixel
    // and probe: texel coordinate = tile * TileScale + oct * Oct.xy + Oct.zw.
    using namespace probes;
    const float irrHalf = 0.5f * float(kIrradianceInterior),
                visHalf = 0.5f * float(kVisibilityInterior);
    program.set("u_ddgiIrrTileScale", float(kIrradianceTile) * irrInv);
    program.set("u_ddgiIrrOct", glm::vec4(irrHalf * irrInv, (irrHalf + 1.0f) * irrInv));
    program.set("u_ddgiVisTileScale", float(kVisibilityTile) * visInv);
    program.set("u_ddgiVisOct", glm::vec4(visHalf * visInv, (visHalf + 1.0f) * visInv));
    program.set("u_ddgiMaxBase", glm::vec3(glm::max(g.counts - 2, glm::ivec3(0))));
    program.set("u_ddgiBiasNormal", glm::vec3(kBiasNormalWeight * g.biasDistance));
    program.set("u_ddgiBiasView", glm::vec3(kBiasViewWeight * g.biasDistance));
    // ProbeSampler.h kBehindRampCells; biasDistance = kBiasScale * minCell.
    program.set("u_ddgiBehindInvWidth", kBiasScale / (kBehindRampCells * g.biasDistance));
}

} // namespace pb::render
