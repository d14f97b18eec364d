#include "probes/ProbeLayout.h"

#include "probes/Octahedral.h"
#include "core/ParallelFor.h"

#include <algorithm>

namespace pb::probes {

TextureShape irradianceShape(const glm::ivec3& c) {
    return {c.x * kIrradianceTile, c.z * kIrradianceTile, c.y, kIrradianceChannels};
}

TextureShape visibilityShape(const glm::ivec3& c) {
    return {c.x * kVisibilityTile, c.z * kVisibilityTile, c.y, kVisibilityChannels};
}

ProbeTexture ProbeTexture::make(const TextureShape& s, int threads) {
    ProbeTexture t;
    t.shape = s;
    const std::size_t n = s.floatCount();
    constexpr std::size_t kChunk = std::size_t(1) << 20; // floats: 4 MiB, two huge pages
    if (threads == 1 || n < 2 * kChunk) {
        t.texels.assign(n, 0.0f);
        return t;
    }
    t.texels.resize(n); // unset (HugePageAllocator), zeroed below
    float* texels = t.texels.data();
    parallelFor((n + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, int) {
        const std::size_t lo = chunk * kChunk, hi = std::min(n, lo + kChunk);
        std::fill(texels + lo, texels + hi, 0.0f);
    });
    return t;
}

void fillAllBorders(ProbeTexture& t, int interior) {
    const int tile = interior + 2;
    for (int layer = 0; layer < t.shape.layers; ++layer)
        for (int tz = 0; tz < t.shape.height / tile; ++tz)
            for (int tx = 0; tx < t.shape.width / tile; ++tx)
                fillOctahedralBorder(t.at(tx * tile, tz * tile, layer), t.shape.width,
                                     t.shape.channels, interior);
}

} // namespace pb::probes
