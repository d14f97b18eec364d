// Exposure, filmic tonemap (the ACES fit published by K. Narkowicz, 2015) and sRGB encoding
// to an 8-bit target. The sRGB curve is applied in the shader so the output bytes do not
// depend on the driver's sRGB framebuffer handling.
#include "common_color.glsl"
in vec2 v_uv;
out vec4 out_color;
uniform sampler2D u_radiance;
uniform float u_exposure;
vec3 acesFit(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
void main() {
    vec3 hdr = texelFetch(u_radiance, ivec2(gl_FragCoord.xy), 0).rgb * u_exposure;
    // NaN/Inf never reach the 8-bit image as undefined bytes: they become black.
    if (any(isnan(hdr)) || any(isinf(hdr))) hdr = vec3(0.0);
    out_color = vec4(linearToSrgb(acesFit(max(hdr, vec3(0.0)))), 1.0);
}
