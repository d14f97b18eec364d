#pragma once
// How much of a scene's surface lies on a probe plane of a volume's lattice (auto placement
// prefers lattices where little does). A wall on a probe plane puts a row of probes inside or
// just behind it: they leak through it or are relocated unevenly, and the bench measures the
// irradiance error of such lattices at 2-3x that of a lattice shifted by part of a cell
// (studies/findings/probe-placement.md "Probe placement").
#include "probes/ProbeVolume.h"
#include "raytrace/StaticTriangles.h"

#include <vector>

namespace pb::probes {

// Auto placement takes a coarser lattice only when it has at least this much less surface on
// its probe planes (a smaller difference is not worth the resolution).
constexpr float kLatticeScoreMargin = 0.01f;

// Within this fraction of a cell of a probe plane, a surface parallel to it counts as on it.
constexpr float kOnPlaneCells = 0.15f;

// The area-weighted share (0..1) of the triangles that are near-perpendicular to one of the
// volume's axes and lie within kOnPlaneCells of one of its probe planes along that axis
// (weighted down linearly with the distance). Only triangles inside the volume count.
float surfaceOnProbePlanes(const ProbeVolume& volume, const std::vector<raytrace::WorldTriangle>& triangles);

} // namespace pb::probes
