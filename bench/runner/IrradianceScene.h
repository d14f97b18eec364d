#pragma once
// The scene the bench renders to read the linear GI irradiance of a frame: every material
// white (alpha kept, so masked cut-outs stay cut out), no emission, no sun, no punctual
// lights, a black sky. The lighting then outputs emissive + albedo/pi * (indirect + direct)
// = indirect/pi exactly: radiance * pi is the indirect irradiance the lighting applied - the
// GI target after upsampling, blended with the ambient fallback by its weight - with every
// switch's effect in it and nothing else. The probes are baked from the real scene and the
// frame settings (ambient) stay the real scene's, so the GI input is unchanged.
#include "scene/Scene.h"

namespace pb::bench {

scene::Scene irradianceOnlyScene(const scene::Scene& s);

} // namespace pb::bench
