#pragma once
// Where the sun's view map should look: the square in light space around what one camera
// sees. A grid of CPU rays through the scene's RayGrid finds the visible surfaces; their
// light-space footprint, widened by a margin and snapped to a coarse lattice (so a slowly
// moving camera does not make the shadow edges crawl), is the fit. Surfaces between the rays
// and dynamic objects may fall outside it; the lighting then uses the whole-scene map.
#include "passes/RenderView.h"
#include "scene/RayGrid.h"

#include <glm/glm.hpp>
#include <optional>

namespace pb::render {

// A square [min, min + size]^2 in the light's view space (x, y; world units).
struct LightSquare {
    glm::dvec2 min{0.0};
    double size = 0.0;
};

// `lightFromWorld` maps world positions into the light's view space (z along the light);
// `sceneSquare` is the whole-scene map's square, which the fit never exceeds. Returns nothing
// when no ray hits the scene (the view sees only sky): the whole-scene map then serves alone.
std::optional<LightSquare> fitShadowToView(const scene::RayGrid& grid, const RenderView& view,
                                           const glm::dmat4& lightFromWorld,
                                           const LightSquare& sceneSquare);

} // namespace pb::render
