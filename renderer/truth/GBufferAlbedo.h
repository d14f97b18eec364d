#pragma once
// The albedo a camera ray's first hit has in the rasterizer: the GBuffer stores it in an
// SRGB8_A8 target (passes/GBufferLayout.h), i.e. rounded to 8 bits after sRGB encoding. The
// rounding moves a material's albedo by up to about 0.4% (half a step of 1/255 in sRGB), the
// same way on every pixel of that material: one code value of the final 8-bit image on most
// of the frame, which LDR-FLIP at 67 pixels per degree scores about 0.03 (a +1 shift of every
// pixel of the courtyard's truth PNG). Reading the first hit's albedo through the same rounding
// keeps the GBuffer's storage out of every error measured against the truth, as the truth
// already clamps albedo to [0, 1] the way that target does. Later vertices keep the exact
// albedo: the bake's and the truth's bounces never pass through the GBuffer.
#include <glm/glm.hpp>

namespace pb::truth {

// Linear [0, 1] -> sRGB-encoded, rounded to 8 bits -> linear (the sRGB transfer function of
// IEC 61966-2-1, round to nearest).
float throughSrgb8(float linear);
glm::vec3 asGBufferStoresAlbedo(const glm::vec3& albedo);

} // namespace pb::truth
