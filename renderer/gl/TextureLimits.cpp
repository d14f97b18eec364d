#include "gl/TextureLimits.h"

#include <algorithm>

namespace pb::gl {
namespace {

std::string exceeds(const std::string& what, int value, int limit, const char* name) {
    return what + " " + std::to_string(value) + "; this GL allows " + std::to_string(limit) + " (" +
           name + ")";
}

} // namespace

TextureLimits queryTextureLimits() {
    TextureLimits l;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &l.maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &l.maxArrayLayers);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &l.max3dSize);
    return l;
}

std::string textureLimitProblem(const TextureDesc& d, const TextureLimits& l) {
    if (d.layers > 0 && d.volume) {
        const int side = std::max(d.width, std::max(d.height, d.layers));
        if (side > l.max3dSize)
            return exceeds("a volume side of", side, l.max3dSize, "GL_MAX_3D_TEXTURE_SIZE");
        return "";
    }
    const int side = std::max(d.width, d.height);
    if (side > l.maxSize) return exceeds("a side of", side, l.maxSize, "GL_MAX_TEXTURE_SIZE");
    if (d.layers > l.maxArrayLayers)
        return exceeds("layers", d.layers, l.maxArrayLayers, "GL_MAX_ARRAY_TEXTURE_LAYERS");
    return "";
}

} // namespace pb::gl
