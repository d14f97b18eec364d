#pragma once
#include "scene/GltfContext.h"

namespace pb::scene::gltf {

// The Scene::primitives of glTF mesh `mesh`, converted on first use (a mesh placed by several
// nodes is stored once). Non-triangle primitives are skipped and counted in `ctx`.
const std::vector<int>& meshPrimitives(Context& ctx, int mesh);

// Scene::materials index of the material for glTF primitives that name none.
int defaultMaterial(Context& ctx);

} // namespace pb::scene::gltf
