#include "IrradianceScene.h"

#include <set>

namespace pb::bench {

scene::Scene irradianceOnlyScene(const scene::Scene& s) {
    scene::Scene w = s;
    std::set<int> baseTextures;
    for (scene::Material& m : w.materials) {
        m.baseColor = glm::vec4(1.0f, 1.0f, 1.0f, m.baseColor.a);
        m.emissive = glm::vec3(0.0f);
        m.emissiveTexture = -1;
        if (m.baseColorTexture >= 0) baseTextures.insert(m.baseColorTexture);
    }
    // Base colour textures keep only their alpha (cut-outs); rgb white.
    for (int t : baseTextures) {
        std::vector<std::uint8_t>& px = w.textures[size_t(t)].rgba8;
        for (size_t i = 0; i + 3 < px.size(); i += 4)
            px[i] = px[i + 1] = px[i + 2] = 255;
    }
    w.lights.clear();
    w.sun.enabled = false;
    w.sky.radiance = glm::vec3(0.0f);
    return w;
}

} // namespace pb::bench
