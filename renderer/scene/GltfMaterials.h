#pragma once
#include "scene/GltfContext.h"

namespace pb::scene::gltf {

// Every glTF material, in order (so glTF material i is Scene::materials[i]), with the
// textures they use decoded to RGBA8.
void convertMaterials(Context& ctx);

} // namespace pb::scene::gltf
