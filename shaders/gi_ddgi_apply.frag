// GI apply (DDGI): per pixel of the GI evaluation target, the irradiance of the probe volume
// being drawn at the GBuffer surface (common_ddgi.glsl). One draw per volume, largest first;
// a pixel outside the volume's influence is discarded so the smallest volume containing it
// wins (the CPU sampler's rule). Target: rgb = E * fade, a = weight; formats without alpha
// (GI_TARGET_R11G11B10F) get the ambient blended in here instead (see lighting_direct.frag).
// Variants: GI_RESOLUTION_* (the target is 1, 1/2 or 1/4 of the GBuffer per axis).
#include "common_octahedral.glsl"
#include "common_ddgi.glsl"
out vec4 out_gi;
uniform highp sampler2D u_gbuffer_normal;
uniform highp sampler2D u_gbuffer_depth;
uniform mat4 u_relFromClip;
uniform vec2 u_gbufferInvSize;
uniform int u_giDivisor;   // GBuffer pixels per target texel, per axis
uniform ivec2 u_giJitter;  // the GBuffer pixel of the texel's footprint sampled this frame
uniform vec3 u_ambientUp;  // GI_TARGET_R11G11B10F only
uniform vec3 u_ambientDown;

void main() {
    // The GBuffer pixel this frame samples in the texel's footprint: (divisor - 1) / 2 (nearest
    // the centre) unless gi.upsample=temporal jitters it (GiUpsamplePass, common_upsample.glsl).
    ivec2 px = ivec2(gl_FragCoord.xy) * u_giDivisor + u_giJitter;
    float depth = texelFetch(u_gbuffer_depth, px, 0).r;
    if (depth >= 1.0) discard; // sky
    vec2 uv = (vec2(px) + 0.5) * u_gbufferInvSize;
    vec4 relH = u_relFromClip * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec3 rel = relH.xyz / relH.w;
    if (!ddgiInfluences(ddgiLocal(rel))) discard;
    vec3 n = octDecode(texelFetch(u_gbuffer_normal, px, 0).xy);
    // The eye is the origin of camera-relative space: the view direction is -rel.
    vec4 gi = ddgiSample(rel, n, -rel);
#ifdef GI_TARGET_R11G11B10F
    vec3 ambient = mix(u_ambientDown, u_ambientUp, n.y * 0.5 + 0.5);
    // Blue never 0 where a volume drew: the lighting reads all-zero as "not covered".
    out_gi = vec4(max(gi.rgb + (1.0 - gi.a) * ambient, vec3(0.0, 0.0, 6.103515625e-05)), 1.0);
#else
    out_gi = gi;
#endif
}
