#pragma once
// A texture's size against the context's limits, said in one line before the GL is asked:
// probe textures grow with the probe grid, and a weak GPU's limits are smaller than
// llvmpipe's (GL ES 3.0 guarantees 2048 texels, 256 array layers and a 256^3 volume), so a
// probe set that fits here may not fit the target (`probebench shaders` lists it as not run).
#include "gl/Texture.h"

#include <string>

namespace pb::gl {

struct TextureLimits {
    int maxSize = 0;        // GL_MAX_TEXTURE_SIZE: width and height of 2D and array textures
    int maxArrayLayers = 0; // GL_MAX_ARRAY_TEXTURE_LAYERS
    int max3dSize = 0;      // GL_MAX_3D_TEXTURE_SIZE: each side of a volume texture
};

// The current context's limits.
TextureLimits queryTextureLimits();

// "" when `d` fits, else what does not: "300 layers; this GL allows 256
// (GL_MAX_ARRAY_TEXTURE_LAYERS)". GL-free.
std::string textureLimitProblem(const TextureDesc& d, const TextureLimits& limits);

} // namespace pb::gl
