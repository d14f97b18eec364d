#include "passes/GpuTechniqueDdgi.h"

#include "core/Error.h"
#include "passes/GpuProbes.h"
#include "probes/AbsentProbeFill.h"
#include "probes/ProbeSampler.h"
#include "probes/store/SparseLayout.h"
#include "profile/GiVolumeLod.h"

namespace pb::render {

namespace {

using probes::StorageFormat;

gl::TextureFormat ddgiIrradianceFormat(StorageFormat f) {
    return f == StorageFormat::Rgba32f ? gl::TextureFormat::RGBA32F
           : f == StorageFormat::Bc6h  ? gl::TextureFormat::BC6H_UF16
                                       : gl::TextureFormat::RGBA16F;
}
gl::TextureFormat ddgiVisibilityFormat(StorageFormat f) {
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

} // namespace

std::size_t GpuTechniqueDdgi::volumeBytes(const probes::ProbeSet& set, int vi) const {
    return profile::gpuVolumeBytes(set, std::size_t(vi));
}

void GpuTechniqueDdgi::uploadVolume(GpuProbeVolume& g, const probes::ProbeSet& set, int scenario,
                                    int vi, const std::string& what) const {
    const probes::ProbeVolume& v = set.volumes[size_t(vi)];
    const StorageFormat format = set.format();
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
        scratch = probes::packTiles(t, irradiance ? tiles.slots : visibilitySlots, v.counts,
                                    irradiance ? tiles.packedCounts : tiles.visibilityPackedCounts,
                                    tile, format);
        return scratch;
    };
    g.textures.clear();
    g.textures.push_back(uploadProbeTexture(
        packed(set.irradiance[size_t(scenario)][size_t(vi)], probes::kIrradianceTile),
        ddgiIrradianceFormat(format), format, what + " irradiance"));
    // The file stores irradiance x the scenario's storage scale (probes/StorageScale.h).
    g.irradianceDecode = 1.0f / set.irradiance[size_t(scenario)][size_t(vi)].storageScale;
    g.textures.push_back(
        uploadProbeTexture(packed(set.visibility[size_t(vi)], probes::kVisibilityTile),
                           ddgiVisibilityFormat(format), format, what + " visibility"));
    g.textures.push_back(
        uploadStates(v, probes::lookupStates(v, set.states[size_t(vi)], fill), tiles));
    g.textures[kDdgiState].label(what + " states");
}

void GpuTechniqueDdgi::bindTextures(const gl::Program& program, const GpuProbeVolume& g,
                                    int firstUnit) const {
    g.textures[kDdgiIrradiance].bind(firstUnit);
    g.textures[kDdgiVisibility].bind(firstUnit + 1);
    g.textures[kDdgiState].bind(firstUnit + 2);
    program.set("u_ddgiIrradiance", firstUnit);
    program.set("u_ddgiVisibility", firstUnit + 1);
    program.set("u_ddgiState", firstUnit + 2);
}

void GpuTechniqueDdgi::setVolumeUniforms(const gl::Program& program,
                                         const GpuProbeVolume& g) const {
    const gl::TextureDesc &irr = g.textures[kDdgiIrradiance].desc(),
                          &vis = g.textures[kDdgiVisibility].desc();
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
