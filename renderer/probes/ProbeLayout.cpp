#include "probes/ProbeLayout.h"

#include "probes/Octahedral.h"

namespace pb::probes {

TextureShape irradianceShape(const glm::ivec3& c) {
    return {c.x * kIrradianceTile, c.z * kIrradianceTile, c.y, kIrradianceChannels};
}

TextureShape visibilityShape(const glm::ivec3& c) {
    return {c.x * kVisibilityTile, c.z * kVisibilityTile, c.y, kVisibilityChannels};
}

ProbeTexture ProbeTexture::make(const TextureShape& s) {
    ProbeTexture t;
    t.shape = s;
    t.texels.assign(s.floatCount(), 0.0f);
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
