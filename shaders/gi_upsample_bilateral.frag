// gi.upsample=bilateral: each full-resolution pixel blends its four neighbouring low-resolution
// GI samples with bilinear x depth (tangent plane) x normal weights from the full-resolution
// GBuffer (common_upsample.glsl), so light does not bleed across depth steps and creases.
#include "common_octahedral.glsl"
#include "common_upsample.glsl"
out vec4 out_gi;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_gbuffer_depth, p, 0).r;
    if (depth >= 1.0) {
        out_gi = vec4(0.0); // sky: the lighting does not read GI there
        return;
    }
    vec3 n = octDecode(texelFetch(u_gbuffer_normal, p, 0).xy);
    out_gi = upsampleBilateral(p, upsampleRel(p, depth), n);
}
