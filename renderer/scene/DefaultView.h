#pragma once
#include "scene/Scene.h"

namespace pb::scene {

// The "default" view every scene gets first, for any scale and any offset from the origin.
// From the static bounds alone: inside them at 30% of their height, 15% in from the + end of
// the longest horizontal axis, looking back along it about 8 degrees down.
View makeDefaultView(const Bounds& staticBounds);
// The same rule, then checked against the static geometry with a few CPU rays: if that eye
// is in or against something or the view is blocked, the nearest pose (in a fixed search
// order) that sees well. See DefaultView.cpp.
View makeDefaultView(const Scene& scene);
// The same with the scene's ray grid built already (the loaders share one with SkyVisibility).
class RayGrid;
View makeDefaultView(const Scene& scene, const RayGrid& grid);

// What a view sees of the static geometry, from a 16x9 grid of CPU rays across its frustum
// (16:9) and 14 rays all around the eye. The default view is judged by it.
struct ViewCheck {
    float frontFraction = 0; // rays that hit geometry from its front (or double-sided)
    float backFraction = 0;  // rays that hit single-sided geometry from behind
    float skyFraction = 0;   // rays that hit nothing
    float nearFraction = 0;  // rays that hit within 5% of the scene's long side
    float medianDepth = 0;   // of the hits, in units of the scene's long side (0 = none)
    float centreDepth = 0;   // free distance along the centre ray, same units (capped at 2)
    bool insideClosedMesh = false; // most rays all around the eye hit back faces
    bool eyeClear = false;         // nothing within 2% of the long side around the eye
    // Frame rays whose front-facing hit receives light directly: it emits, or it sees the
    // sun, the sky, a punctual light (within range) or an emissive triangle. A view of an
    // enclosed scene lit only from inside must see some of what the light reaches.
    float litFraction = 0;
    bool sceneHasLight = false; // the scene has a sun, sky, punctual light or emitter
    // Mostly front faces, not sky-only, not inside a mesh or against something, an open depth
    // range (the median hit is not right in front of the eye, the centre sees 30% of the
    // scene's length).
    bool good() const {
        return eyeClear && !insideClosedMesh && frontFraction >= 0.5f && skyFraction <= 0.5f &&
               backFraction <= 0.1f && nearFraction <= 0.25f && medianDepth >= 0.1f &&
               centreDepth >= 0.3f && (!sceneHasLight || litFraction >= 0.1f);
    }
};
ViewCheck checkView(const Scene& scene, const View& view);

// `base`, or `base_2`, `base_3`, ... whichever no view of `scene` uses yet.
std::string uniqueViewName(const Scene& scene, const std::string& base);

} // namespace pb::scene
