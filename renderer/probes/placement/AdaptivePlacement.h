#pragma once
// Adaptive probe placement (`--volumes auto`), after Enlighten's volume lighting
// (../shared/reference/enlighten-volume-lighting.txt, after Tatarchuk 2005):
//
//   1. The outer volume covers the static bounds at a coarse spacing (the uniform fit of
//      AutoVolume.h at finest spacing * 2^levels). Its cells are the octree's level 0.
//   2. A cell is "near a surface" when the static geometry passes through it (a voxel bitmap
//      of the triangles, sampled ~2 points per finest cell length) OR the harmonic-mean
//      distance to surfaces from one of its 8 corners is below nearFactor * its edge: from
//      every corner `cornerRays` rays go out in all directions, HM = N / sum(1 / d_i), a miss
//      adds 0. HM weights near hits strongly: a corner h above an infinite floor has HM = 4h,
//      the centre of a corridor of width w has HM ~ w, so "HM < cell" refines a cell until it
//      is about as small as the free space around it.
//   3. Near-surface cells are split into 8 (level l+1) and tested again, only those children
//      (Enlighten records which children are close to surfaces), down to `levels`.
//   4. Tier t >= 1 = the near cells of level t, merged per parent volume into at most
//      `maxChildren` axis-aligned boxes (BoxMerge.h), padded by `pad` cells so each child's
//      outermost probe ring (blended towards the parent, NestingBlend.h) lies outside the
//      cells that needed refinement, clipped to the parent. A child volume puts probes on the
//      corners of its cells: spacing = outer spacing / 2^t, aligned with the outer grid. A box
//      that fills its whole parent refines the parent instead (no duplicate volume): an
//      enclosed scene, where every cell is near a wall, ends as one uniform fine grid.
// Everything is deterministic (fixed ray directions, per-item results, sorted cell lists):
// the same scene and options give the same volumes for any thread count.
#include "probes/placement/AutoVolume.h"
#include "probes/ProbeVolume.h"
#include "raytrace/RayScene.h"
#include "raytrace/StaticTriangles.h"

#include <vector>

namespace pb::probes {

struct AdaptiveOptions {
    float spacing = 0.0f; // finest spacing (the deepest tier); must be > 0 here
    int levels = 2;       // tiers below the outer volume (1..4)
    int cornerRays = 32;
    float nearFactor = 1.0f;
    int maxChildren = 4; // child boxes per parent volume
    int pad = 1;         // cells of padding around each child box
    int threads = 0;     // 0 = all cores; never changes the result
    // The outer volume's lattice (AutoVolume.h): `--volumes auto` keeps probe planes off the
    // scene's boundary surfaces.
    AutoLattice lattice = AutoLattice::HalfCellMargin;
};

struct AdaptiveStats {
    std::vector<long long> cellsTested, cellsNear; // per octree level 0..levels
    long long corners = 0, rays = 0;
    float outerSpacing = 0.0f, finestSpacing = 0.0f; // largest cell edge of level 0 / levels
};

struct AdaptivePlacement {
    std::vector<ProbeVolume> volumes; // the outer volume first, parents before children
    AdaptiveStats stats;
};

// Throws pb::Error for empty bounds or options out of range.
AdaptivePlacement placeAdaptiveVolumes(const raytrace::RayScene& rays,
                                       const std::vector<raytrace::WorldTriangle>& triangles,
                                       const scene::Bounds& staticBounds,
                                       const AdaptiveOptions& options);

} // namespace pb::probes
