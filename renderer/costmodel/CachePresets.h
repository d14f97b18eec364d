#pragma once
// The texture-cache sizes of the four target profiles, in ONE place (the profiles' TOML files
// name a preset; the coordinator wires them). Each preset is one GPU's per-core L1 / texture
// cache as far as public documents say; what they do not say (line size, associativity of
// the texture path) is marked as an assumption in `source`.
#include "costmodel/TextureCache.h"

#include <string>
#include <vector>

namespace pb::costmodel {

// handheld, console-base, pc-low, pc-high (small to large).
const std::vector<CacheConfig>& cachePresets();
// The preset of a profile name ("handheld", "pc-high", ...). Throws pb::Error listing the
// known names otherwise.
CacheConfig cachePresetFor(const std::string& profileName);

} // namespace pb::costmodel
