#pragma once
// The extremes the stress sweep visits (issue 8), each a small scene built in code with a
// small in-memory bake (StressScene.h; seconds on 2 cores for the whole list). GL-free: the
// GL side renders what a case builds.
//
//   light=X        every light and emissive x X, exposure / X (1e-6 .. 1e6)
//   hot_spot=X     one emissive of radiance X at exposure 1 (no exposure can cover it)
//   spacing=X      the room scaled so the probe spacing is about X metres (1 cm .. 1 km)
//   offset=X       the room at (X, X, X), baked there; the truth is the room at the origin
//   offset_moved=X the origin bake moved to (X, X, X): the frame's precision alone
//   thin_wall=X    a partition X metres thick (< 1% of the spacing) splits the room
//   grid=AxBxC     a volume of 1x1x1 or 2x1x1 probes
//   rays=1         one ray per probe (texels from the nearest ray)
//   resolution=WxH 1x1 .. the largest renderbuffer (at most 4096x4096)
//   bad_normals    a mesh whose normals are zero or NaN
//   variance_zero  visibility with meanSq = mean^2 everywhere (Chebyshev variance 0)
//   fold_edges     irradiance that jumps across every octahedral fold; the room's normals lie
//                  exactly on the folds (axis directions: the diamond's edges and corners)
//   all_invalid    every probe of the volume invalid
#include "probes/ProbeSet.h"
#include "scene/Scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pb::stress {

struct CaseData {
    scene::Scene scene;
    probes::ProbeSet probes; // rgba32f: exactly what was baked (or built)
    scene::View view;
    int width = 64, height = 48;
    float exposure = 1.0f;
    std::uint64_t id = 0; // unique per build: what renderers key their caches on
};

struct StressCase {
    std::string group;    // "light"
    std::string name;     // "light=1e+06": unique, what --cases selects
    std::string stresses; // one line for the table's legend
    std::function<CaseData()> build;
    // Set when the truth is another scene (offset: the same room at the origin); the
    // reference variant renders it instead of this case.
    std::function<CaseData()> buildTruth;
};

struct CaseOptions {
    int maxResolution = 4096; // the largest case: min(this, the driver's renderbuffer limit)
    int width = 64, height = 48;
    int rays = 64; // per probe, every bake but rays=1
};

std::vector<StressCase> stressCases(const CaseOptions& o = {});

// Only the cases whose name or group is in `names` (all when empty). Throws pb::Error naming
// an unknown one and listing the groups.
std::vector<StressCase> selectCases(const std::vector<StressCase>& all,
                                    const std::vector<std::string>& names);

// The probe set stored in `format`, quantised from an rgba32f set's float texels as the bake
// would have stored them.
probes::ProbeSet inStorageFormat(const probes::ProbeSet& rgba32f, probes::StorageFormat format);

} // namespace pb::stress
