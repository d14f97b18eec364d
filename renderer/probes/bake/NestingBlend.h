#pragma once
// Nested volumes: after each bounce pass, every child's outermost probe ring (probes with an
// index 0 or count-1 on some axis) is blended towards its parent's irradiance at the same
// places, so the lighting has no seam where the smaller volume takes over:
//     texel = mix(texel, E_parent, child.edgeBlend)
// E_parent = the CPU sampler on the parent volume alone at the (relocated) probe position,
// normal = view = the texel's direction, no edge fade and no surface bias (a probe is no
// surface). Where the parent has nothing (weight 0: all its probes there invalid) the child's
// own value stays. Invalid child probes are left alone, and so are relocated ones: their face
// of the box lies in or against a wall, where there is no seam to hide and the parent's
// coarser probes straddle the wall (issue 24). Parents are blended before their children, so a
// chain of nesting cascades.
#include "probes/ProbeSampler.h"

#include <vector>

namespace pb::probes {

// Whether blendNestedRings blends probe `c` of `vol` (with a parent: `hasParent`): an outer
// ring probe of a child with edgeBlend > 0, valid and not relocated.
bool blendsRing(const ProbeVolume& vol, bool hasParent, const glm::ivec3& c, const ProbeState& s);

// `views` point at the current pass's textures; `targets` are the same irradiance textures,
// writable (one per volume); parents[i] = -1 for roots.
void blendNestedRings(const std::vector<ProbeVolume>& volumes, const std::vector<int>& parents,
                      const std::vector<SamplerVolume>& views, std::vector<ProbeTexture*>& targets);

} // namespace pb::probes
