// gi.multi_volume=stencil, the cheap mark draw of one volume, after its apply: no lookup, no
// colour; a pixel whose surface lies in the volume's influence survives and the stencil marks
// it 'taken', so no larger volume shades it again. The apply shader's test, on the same
// position (common_gi_pixel.glsl), so it marks exactly the pixels the apply could shade.
#include "common_gi_pixel.glsl"
#include "common_ddgi.glsl"
// GI_COUNT_INVOCATIONS here never comes with GI_COUNT_EARLY_TESTS: the mark writes stencil.
#include "common_gi_invocations.glsl"
uniform highp sampler2D u_gbuffer_depth;

void main() {
    GI_COUNT_INVOCATION();
    ivec2 px = giGBufferPixel();
    float depth = texelFetch(u_gbuffer_depth, px, 0).r;
    if (depth >= 1.0) discard; // sky
    if (!ddgiInfluences(ddgiLocal(giRelPosition(px, depth)))) discard;
}
