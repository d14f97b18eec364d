#pragma once
// A built-in scene's dense bake of one root volume over its static bounds (64 rays, 2 bounces,
// the "day" scenario), and the same set stored sparse with `freeSpace` - exactly what a sparse bake of that grid
// gives (SparseStorageTest). The mid-air tests compare lookups of the two.
#include "probes/StaticTriangles.h"
#include "probes/bake/Baker.h"
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
        probes::fitAutoVolume(probes::staticBakeBounds(b.scene), 0.0f, maxProbes).volume);
    r.scenarios = probes::resolveScenarios({"day"}, {}, b.scene);
    r.settings.raysPerProbe = 64;
    r.settings.bounces = 2;
    b.dense = probes::bakeProbes(b.scene, r);
    b.sparse = b.dense;
    probes::applySparseStorage(b.sparse, probes::staticBakeTriangles(b.scene), freeSpace);
    return b;
}

} // namespace pb::test
