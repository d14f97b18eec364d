#pragma once
// What the GI apply shader (gi_ddgi_apply.frag) reads for dynamic objects' pixels, decided once
// for the pass that compiles it (GiApplyPass) and the cost model that counts its fetches
// (costmodel/CostModel.cpp).
#include "profile/Profile.h"

namespace pb::profile {

// GI_DYNAMIC_UNFADED: gi.dynamic=per_pixel DDGI in a scene with dynamic objects; their pixels
// skip the behind-surface fade (probes/ProbeSampler.h midAirLookup()). The SH technique has no
// fade; scenes without dynamic objects keep the shader as it was.
inline bool dynamicPixelsUnfaded(const Profile& p, bool sceneHasDynamicObjects) {
    return sceneHasDynamicObjects && p.gi.dynamic == GiDynamic::PerPixel &&
           p.gi.technique == GiTechnique::Ddgi;
}

// The apply fetches the GBuffer flags of every non-sky fragment, before the influence test:
// for gi.dynamic=sh's early-out, or for the unfaded lookup above.
inline bool applyReadsFlags(const Profile& p, bool sceneHasDynamicObjects) {
    return p.gi.dynamic == GiDynamic::Sh || dynamicPixelsUnfaded(p, sceneHasDynamicObjects);
}

} // namespace pb::profile
