#include "passes/ProbeTileUpload.h"

#include "core/Error.h"
#include "probes/ProbeLayout.h"

#include <glm/gtc/packing.hpp>

namespace pb::render {

std::size_t uploadProbeTiles(const GpuProbes& gpu, const probes::ProbeSet& set, int scenario,
                             const std::vector<ProbeTile>& tiles) {
    using namespace probes;
    const StorageFormat f = gpu.format();
    if (f != StorageFormat::Rgba16f && f != StorageFormat::Rgba32f)
        throw Error(std::string("probe tile updates: ") + formatName(f) +
                    " is not supported (rgba16f or rgba32f)");
    constexpr int T = kIrradianceTile, C = kIrradianceChannels;
    std::vector<const GpuProbeVolume*> byFile(set.volumes.size(), nullptr);
    for (const GpuProbeVolume& g : gpu.volumes()) {
        if (g.sparse) throw Error("probe tile updates: volume '" + g.name + "' is sparse");
        byFile[std::size_t(g.fileIndex)] = &g;
    }
    std::vector<float> f32(T * T * C);
    std::vector<std::uint16_t> f16(T * T * C);
    std::size_t bytes = 0;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (const ProbeTile& t : tiles) {
        const GpuProbeVolume* g = byFile[std::size_t(t.volume)];
        if (!g) continue;
        const ProbeTexture& tex = set.irradiance[std::size_t(scenario)][std::size_t(t.volume)];
        const glm::ivec3 c = set.volumes[std::size_t(t.volume)].probeCoords(t.probe);
        // The GPU copy holds texels * storage scale (its decode undoes it).
        const float scale = 1.0f / g->irradianceDecode;
        for (int row = 0; row < T; ++row)
            for (int col = 0; col < T; ++col) {
                const float* src = tex.at(c.x * T + col, c.z * T + row, c.y);
                for (int ch = 0; ch < C; ++ch)
                    f32[std::size_t((row * T + col) * C + ch)] = ch < 3 ? src[ch] * scale : src[ch];
            }
        glBindTexture(GL_TEXTURE_2D_ARRAY, g->textures[kDdgiIrradiance].id());
        if (f == StorageFormat::Rgba16f) {
            for (std::size_t i = 0; i < f32.size(); ++i)
                f16[i] = glm::packHalf1x16(f32[i]);
            glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, c.x * T, c.z * T, c.y, T, T, 1, GL_RGBA,
                            GL_HALF_FLOAT, f16.data());
            bytes += f16.size() * sizeof(std::uint16_t);
        } else {
            glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, c.x * T, c.z * T, c.y, T, T, 1, GL_RGBA,
                            GL_FLOAT, f32.data());
            bytes += f32.size() * sizeof(float);
        }
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return bytes;
}

} // namespace pb::render
