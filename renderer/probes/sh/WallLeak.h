#pragma once
// The leak figure of issue 19: on the built-in scene `thin_wall` (two rooms sharing a 10 cm
// wall at x = 0, only the west room lit), the mean irradiance a GI lookup gives on the wall's
// dark (east) face over its lit (west) face, each face sampled on a regular grid with the
// face's normal (and the normal as view). The scene itself lets no light through the wall, so
// the truth of the ratio is 0 and everything above 0 is light that leaked through the probes.
#include "probes/ProbeSet.h"

#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pb::probes {

struct WallLeak {
    double litMean = 0;  // mean luminance of E on the lit face
    double darkMean = 0; // on the dark face
    double ratio = 0;    // darkMean / litMean (0 when litMean is 0)
    int points = 0;      // per face
};

// The lookup under test: irradiance at (position, normal, view).
using IrradianceLookup =
    std::function<glm::vec3(const glm::vec3& pos, const glm::vec3& normal, const glm::vec3& view)>;

// `thin_wall`'s shared wall faces, `n` x `n` points each (inset 15 cm from the edges).
WallLeak measureWallLeak(const IrradianceLookup& lookup, int n = 12);

// The probe volume the leak figure bakes `thin_wall` with: probes every 0.5 m from wall to
// wall, so a probe plane lies inside the shared wall (as a regular lattice over a building
// puts probes in thin walls).
ProbeVolume thinWallVolume();

// The leak of each technique and mode on one bake of `thin_wall` (set must be that bake):
// "ddgi", "sh_l1/none", ... "sh_l2/validity_mask", in that order.
std::vector<std::pair<std::string, WallLeak>> wallLeakPerTechnique(const ProbeSet& set);

} // namespace pb::probes
