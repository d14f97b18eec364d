#pragma once
// KHR_texture_transform, applied once to a primitive's TEXCOORD_0 at load time: the renderer
// and the bake sample textures with the UVs as given, so no shader needs a UV matrix. One
// UV set serves both textures of a material: the base colour's transform wins, and a
// different emissive transform gives one warning. Internal to renderer/scene.
#include "scene/GltfContext.h"

#include <glm/glm.hpp>
#include <optional>

namespace pb::scene::gltf {

// The UV transform (offset * rotation * scale, as the extension defines it) of glTF material
// `material`, or nothing when it has none.
std::optional<glm::mat3> materialUvTransform(Context& ctx, int material);

} // namespace pb::scene::gltf
