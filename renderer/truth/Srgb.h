#pragma once
// The sRGB transfer function (IEC 61966-2-1) as the renderer applies it, once for the truth:
// the encode of common_color.glsl's linearToSrgb (the tonemapped PNG, the GBuffer's SRGB8_A8
// albedo) and GL's decode of an 8-bit sRGB texel (base colour textures, the stored albedo).
#include <cstdint>

namespace pb::truth {

// Linear -> sRGB-encoded, the input clamped to [0, 1].
float linearToSrgb(float linear);
// An 8-bit sRGB code -> linear (a table of the 256 exact decodes).
float srgb8ToLinear(std::uint8_t code);

} // namespace pb::truth
