#pragma once
// The small scene every stress case starts from, built in code: a closed 4 x 2.5 x 4 m room
// (single-sided walls 25 cm thick, so probes inside them bake invalid) with a window the sun
// shines through, a block on the floor and a dim emissive ceiling panel, seen from a corner
// so that every pixel is a surface that needs GI. One probe volume spans the interior.
//
// Every coordinate is a multiple of 1/8 m (box centres and half sizes of 1/16 m), so the
// scene moved 1e6 units from the origin (float spacing 1/16 there) keeps every vertex, box
// centre, probe and camera position exact: an offset case differs from the origin only by
// the precision the pipeline loses, never by a moved input.
//
// The knobs (StressSceneParams) are what the cases sweep: a uniform scale (probe spacing),
// a translation, a factor on every light with the exposure following it, a thin partition
// wall, the probe counts, a mesh with broken normals.
#include "probes/ProbeVolume.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>

namespace pb::stress {

struct StressSceneParams {
    double scale = 1.0;      // uniform: positions and probe spacing (room 4 m at 1)
    glm::dvec3 offset{0.0};  // added after scaling (world units)
    double lightScale = 1.0; // sun, sky, emissive; the exposure is divided by it
    bool exposureFollowsLight = true;
    double hotSpot = 0.0;            // > 0: a small emissive panel of this radiance, exposure 1
    double partition = 0.0;          // > 0: a wall this thick (metres at scale 1) splits the room
    glm::ivec3 probeCounts{5, 3, 5}; // spacing 1 m x 1.25 m x 1 m at scale 1
    bool badNormals = false;         // a prop whose normals are zero or NaN (a bad mesh)
};

struct StressScene {
    scene::Scene scene;
    probes::ProbeVolume volume; // the probe grid over the interior
    scene::View view;
    float exposure = 1.0f;
};

StressScene makeStressScene(const StressSceneParams& p);

} // namespace pb::stress
