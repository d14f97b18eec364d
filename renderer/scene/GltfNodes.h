#pragma once
#include "scene/GltfContext.h"

namespace pb::scene::gltf {

// Walks the node hierarchy of the default scene: instances (meshes converted on first use),
// cameras as views, KHR_lights_punctual lights (the first directional one becomes the sun),
// the dynamic flag from node extras or `dynamicNodes` (names; an unknown one is an error).
void traverseNodes(Context& ctx, const std::vector<std::string>& dynamicNodes);

} // namespace pb::scene::gltf
