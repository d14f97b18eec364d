#pragma once
// A built-in scene's dense bake of one root volume over its static bounds (64 rays, 2 bounces,
// the "day" scenario), and the same set stored sparse with `freeSpace` - exactly what a sparse bake of that grid
// gives (SparseStorageTest). The mid-air tests compare lookups of the two.
#include "raytrace/StaticTriangles.h"
#include "probes/bake/Baker.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/SparseStorage.h"
#include "scene/SceneLoader.h"

#include <string>

namespace pb::test {

struct DenseAndSparse {
    pb::scene::Scene scene;
    probes::ProbeSet dense, sparse;
};

inline DenseAndSparse bakeDenseAndSparse(const std::string& builtin, int maxProbes,
                                         probes::FreeSpace freeSpace) {
    DenseAndSparse b{pb::scene::makeBuiltinScene(builtin), {}, {}};
    probes::BakeRequest r;
    r.volumes.push_back(
        probes::fitAutoVolume(raytrace::staticBakeBounds(b.scene), 0.0f, maxProbes).volume);
    r.scenarios = probes::resolveScenarios({"day"}, {}, b.scene);
    r.settings.raysPerProbe = 64;
    r.settings.bounces = 2;
    b.dense = probes::bakeProbes(b.scene, r);
    b.sparse = b.dense;
    probes::applySparseStorage(b.sparse, raytrace::staticBakeTriangles(b.scene), freeSpace);
    return b;
}

// The default bake's volumes (`bake --volumes auto`: adaptive placement under the default
// budget, stored sparse, FreeSpace::Ranked), baked dense, and stored as that bake stores them
// (SparseStorageTest: the same as the sparse bake). The lattice search is skipped for time: it
// shifts the lattice by under a cell and changes nothing the tiles are chosen by. `budget`
// receives the placement's budget, which the tiles fill.
inline DenseAndSparse bakeDefaultDenseAndSparse(const std::string& builtin, double& budget) {
    DenseAndSparse b{pb::scene::makeBuiltinScene(builtin), {}, {}};
    probes::AutoPlacementRequest p;
    p.sparse = true;
    p.freeSpace = probes::FreeSpace::Ranked;
    p.latticeSearch = false;
    const probes::AutoPlacementResult placed = probes::placeAutoVolumes(b.scene, p);
    budget = placed.budgetBytes;
    probes::BakeRequest r;
    r.volumes = placed.volumes;
    r.scenarios = probes::resolveScenarios({"day"}, {}, b.scene);
    r.settings.raysPerProbe = 64;
    r.settings.bounces = 2;
    b.dense = probes::bakeProbes(b.scene, r);
    b.sparse = b.dense;
    probes::applySparseStorage(b.sparse, raytrace::staticBakeTriangles(b.scene),
                               probes::FreeSpace::Ranked, budget);
    return b;
}

} // namespace pb::test
