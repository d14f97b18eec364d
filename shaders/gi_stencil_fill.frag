// gi.multi_volume=stencil, the cheap fill pass of one volume: no lookup, no colour; a pixel
// whose surface lies in the volume's influence survives and the stencil test marks it
// 'current' (where no smaller volume took it: 'any' clear). The apply shader's test, on the
// same position (common_gi_pixel.glsl), so the full pass finds exactly these pixels.
#include "common_gi_pixel.glsl"
#include "common_ddgi.glsl"
uniform highp sampler2D u_gbuffer_depth;

void main() {
    ivec2 px = giGBufferPixel();
    float depth = texelFetch(u_gbuffer_depth, px, 0).r;
    if (depth >= 1.0) discard; // sky
    if (!ddgiInfluences(ddgiLocal(giRelPosition(px, depth)))) discard;
}
