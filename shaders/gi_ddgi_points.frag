// The DDGI lookup at arbitrary points (tests, accuracy tools): texel (x, y) reads its world
// position, normal and view direction from three RGBA32F textures and writes what the apply
// pass would compute there (common_ddgi.glsl, the same code). One draw per volume, like the
// apply pass: points outside the drawn volume's influence keep what an earlier draw wrote.
#include "common_ddgi.glsl"
#ifdef GI_TECHNIQUE_SH_L1
#define GI_TECHNIQUE_SH
#endif
#ifdef GI_TECHNIQUE_SH_L2
#define GI_TECHNIQUE_SH
#endif
#ifdef GI_TECHNIQUE_SH
#include "common_sh.glsl"
#endif
out vec4 out_gi;
uniform highp sampler2D u_pointPosition;
uniform highp sampler2D u_pointNormal;
uniform highp sampler2D u_pointView;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 pos = texelFetch(u_pointPosition, px, 0).xyz;
    vec3 local = ddgiLocal(pos);
    if (!ddgiInfluences(local)) discard;
#ifdef GI_TECHNIQUE_SH
    out_gi = shSample(pos, texelFetch(u_pointNormal, px, 0).xyz,
                      texelFetch(u_pointView, px, 0).xyz);
#else
    out_gi = ddgiSample(local, texelFetch(u_pointNormal, px, 0).xyz,
                        texelFetch(u_pointView, px, 0).xyz);
#endif
}
