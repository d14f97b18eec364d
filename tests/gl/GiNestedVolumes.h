#pragma once
// Three properly nested probe volumes over the built-in `rooms` scene for the multi-volume GL
// tests (no bake: synthetic probes, each volume with its own colour, so an image also shows
// which volume shaded a pixel): the whole building (root), the sunlit room (middle) and a
// small rotated box over the sun patch (inner). Cameras outside every volume, inside the
// middle one only, and inside the inner one.
#include "gl/GiSyntheticProbes.h"
#include "gl/GiTestProbes.h"

#include "frame/FrameRenderer.h"
#include "passes/GiApplyPass.h"

#include <memory>
#include <string>
#include <vector>

namespace pb::test {

// hugeRoot: the root reaches far past the scene (and the far plane), like a map-wide
// low-density volume; otherwise it just covers the building.
inline probes::ProbeSet makeNestedVolumeProbes(bool hugeRoot) {
    {
        probes::ProbeVolume root =
            hugeRoot
                ? syntheticVolume("building", {0.0f, 1.3f, 0.0f}, {40.0f, 20.0f, 40.0f}, {9, 5, 9})
                : syntheticVolume("building", {0.0f, 1.3f, 0.0f}, {4.3f, 1.6f, 2.8f}, {9, 4, 6});
        // The room's box ends inside the walls around it (x in [-4.1, 0]: 10 cm into the west
        // wall, mid-partition; z 5 cm into the north and south walls), as a user draws one: a
        // box face on a visible wall would make each of its pixels fall to either volume with
        // the last bit of its depth (it used to end on the walls' faces, x = -4, z = +-2.5).
        probes::ProbeVolume middle = syntheticVolume("sunlit_room", {-2.05f, 1.3f, 0.0f},
                                                     {2.05f, 1.4f, 2.55f}, {5, 3, 5}, "building");
        // Holds a patch of floor and the table's corner.
        probes::ProbeVolume inner = syntheticVolume("sun_patch", {-1.7f, 0.5f, 0.2f},
                                                    {0.7f, 0.55f, 0.7f}, {3, 3, 3}, "sunlit_room");
        inner.rotation = probes::rotationFromEulerDegrees({0.0f, 25.0f, 0.0f});
        const std::vector<probes::ProbeVolume> volumes{root, middle, inner};
        // A colour per volume, brighter towards +Y.
        const glm::vec3 colours[3] = {{0.8f, 0.3f, 0.3f}, {0.3f, 0.8f, 0.3f}, {0.3f, 0.3f, 0.8f}};
        return syntheticProbes(
            volumes,
            [&](int v, const glm::vec3& d, const glm::ivec3&) {
                return colours[v] * (1.0f + 0.3f * d.y);
            },
            probes::StorageFormat::Rgba32f);
    }
}

inline const probes::ProbeSet& nestedVolumeProbes(bool hugeRoot = false) {
    static const probes::ProbeSet normal = makeNestedVolumeProbes(false);
    static const probes::ProbeSet huge = makeNestedVolumeProbes(true);
    return hugeRoot ? huge : normal;
}

struct NestedCamera {
    const char* name;
    scene::View view;
    const char* inside; // the innermost volume containing the eye ("" = none)
    const char* culled; // a volume outside the view frustum ("" = none)
};

inline std::vector<NestedCamera> nestedCameras() {
    return {
        // Through the window from outside the building.
        {"outside_all", {"outside_all", {-2.8f, 2.4f, 4.0f}, {-2.0f, 0.0f, 0.5f}, 60.0f}, "", ""},
        {"inside_middle",
         {"inside_middle", {-0.6f, 1.6f, -2.2f}, {-2.8f, 0.9f, 2.5f}, 70.0f},
         "sunlit_room",
         ""},
        // From inside the inner box through the doorway into the dark room (root only).
        {"inside_inner",
         {"inside_inner", {-1.7f, 0.8f, 0.2f}, {3.0f, -0.5f, 0.0f}, 70.0f},
         "sun_patch",
         ""},
        {"looking_away",
         {"looking_away", {-0.6f, 1.6f, -2.2f}, {3.0f, 1.2f, -1.0f}, 60.0f},
         "sunlit_room",
         "sun_patch"},
    };
}

} // namespace pb::test
