#pragma once
// How much of the sky a scene's surfaces see, for the flat ambient that stands in for the sky's
// light where there is no GI (FrameRenderer's defaultFrameSettings). A constant ambient cannot
// know which surface sees the sky; it can know how much the scene's surfaces see on average, so
// that a closed interior is not lit like an open square (issue 42: the rooms' walls without GI
// looked like the sky).
#include "scene/RayGrid.h"
#include "scene/Scene.h"

namespace pb::scene {

// The mean, over the static visible surfaces as seen from inside the scene's bounds (eyes drawn
// uniformly in the bounds, each looking along a random direction; the front side of a
// single-sided surface, either side of a double-sided one), of the cosine-weighted share of the
// hemisphere whose rays leave the scene without hitting anything: 1 for an open floor, 0 inside
// a closed room. Surfaces no eye sees (the outside of a closed house, whose walls fill its
// bounds) hardly count. `samples` seen points with one ray each, from a fixed seed and without
// libm's trigonometry (the same on every CPU). 0 for a scene without surfaces; 1 when no surface is seen from
// inside the bounds (all face away: nothing encloses anything).
float meanSkyVisibility(const RayGrid& grid, int samples = 4096);
float meanSkyVisibility(const Scene& scene, int samples = 4096);

} // namespace pb::scene
