#pragma once
// Random points on the static surface, where irradiance errors are measured (bench_placement,
// PlacementError.h): area-weighted over the baked triangles, on the front side of a
// single-sided triangle and a random side of a double-sided one, lifted off the surface by a
// hair (1e-4 of the scene's diagonal). Points sealed inside geometry (every one of 16 rays
// over the hemisphere hits within `sealedBelow`) are skipped: nothing shades them.
// Deterministic for a given seed.
#include "raytrace/RayScene.h"
#include "raytrace/StaticTriangles.h"
#include "probes/bake/SurfaceGather.h"

#include <cstdint>
#include <vector>

namespace pb::probes {

// Up to `count` points (fewer when most candidates are sealed: 4 * count tries).
std::vector<GatherPoint> surfaceSamples(const std::vector<raytrace::WorldTriangle>& triangles,
                                        const raytrace::RayScene& rs, int count, float sealedBelow,
                                        std::uint64_t seed = 0xB0A710C5u);

} // namespace pb::probes
