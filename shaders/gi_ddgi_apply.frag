// GI apply (DDGI, or the SH volume under gi.technique=sh_l1|sh_l2: common_sh.glsl, the same
// target, draws and discard): per pixel of the GI evaluation target, the irradiance of the probe volume
// being drawn at the GBuffer surface (common_ddgi.glsl). One draw per volume; a pixel outside
// the volume's influence is discarded, so the smallest volume containing it wins (the CPU
// sampler's rule): gi.multi_volume=naive draws largest first and overwrites, =stencil draws
// smallest first and lets the stencil keep later volumes off taken pixels (GiApplyPass.cpp).
// Target: rgb = E * fade, a = weight; formats without alpha (GI_TARGET_R11G11B10F) get the
// ambient blended in here instead (see lighting_direct.frag).
// Variants: GI_RESOLUTION_* (the target is 1, 1/2 or 1/4 of the GBuffer per axis),
// GI_INFLUENCE_BY_RASTER (stencil, eye inside the box: the back faces' depth test decides the
// influence, as for the raster mark gi_stencil_mark_raster.frag, so both agree on every pixel),
// GI_DYNAMIC_SH (dynamic-object pixels are lit by their SH in the lighting: skipped here),
// GI_DYNAMIC_UNFADED (gi.dynamic=per_pixel in a scene with dynamic objects: their pixels keep
// the probes behind their surface, which is no baked surface: ProbeSampler.h kBehindRampCells),
// GI_COUNT_PIXELS (diagnostics: location 1 marks every pixel this draw evaluated),
// GI_COUNT_INVOCATIONS (diagnostics, GLSL ES 3.10: an atomic counter counts every invocation;
// GI_COUNT_EARLY_TESTS keeps the depth/stencil tests before the shader, as without the counter:
// common_gi_invocations.glsl).
// Guards: GI_GUARD_EXPOSURE_ON (the output is pre-exposed: common_ddgi.glsl), GI_GUARD_CLAMP_ON
// (NaN -> 0, overflow -> the target format's largest value, negatives -> 0 before the store).
#include "common_octahedral.glsl"
#include "common_gi_pixel.glsl"
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
#include "common_gi_invocations.glsl"
layout(location = 0) out vec4 out_gi;
#ifdef GI_COUNT_PIXELS
layout(location = 1) out vec4 out_evaluated;
#endif
uniform highp sampler2D u_gbuffer_normal;
uniform highp sampler2D u_gbuffer_depth;
#ifdef GI_DYNAMIC_SH
#define GI_READS_FLAGS
#endif
#ifdef GI_DYNAMIC_UNFADED
#define GI_READS_FLAGS
#endif
#ifdef GI_READS_FLAGS
uniform highp sampler2D u_gbuffer_flags;
#endif
uniform vec3 u_ambientUp;  // GI_TARGET_R11G11B10F only
uniform vec3 u_ambientDown;

#ifdef GI_GUARD_CLAMP_ON
#ifdef GI_TARGET_R11G11B10F
const vec4 GI_TARGET_MAX = vec4(65024.0, 65024.0, 64512.0, 1.0); // 6/6/5 mantissa bits
#else
#ifdef GI_TARGET_RGBA16F
const vec4 GI_TARGET_MAX = vec4(65504.0);
#else
const vec4 GI_TARGET_MAX = vec4(3.0e38);
#endif
#endif
// Comparisons are false for NaN, so NaN takes the 0 branch; +Inf takes the max.
vec4 giStorable(vec4 v) {
    return min(mix(vec4(0.0), v, greaterThanEqual(v, vec4(0.0))), GI_TARGET_MAX);
}
#endif
#ifdef GI_DEBUG_DROP_MANTISSA_BIT
// Test-only (passes/GiDebugInjection.h): one mantissa bit less than the target keeps
// (R11F_G11F_B10F 6/6/5, RGBA16F 10, RGBA32F 23), truncated so its rounding cannot restore it.
highp vec3 giDropMantissaBit(highp vec3 v) {
#ifdef GI_TARGET_R11G11B10F
    uvec3 keep = uvec3(5u, 5u, 4u);
#else
#ifdef GI_TARGET_RGBA16F
    uvec3 keep = uvec3(9u);
#else
    uvec3 keep = uvec3(22u);
#endif
#endif
    uvec3 mask = ~((uvec3(1u) << (uvec3(23u) - keep)) - uvec3(1u));
    return uintBitsToFloat(floatBitsToUint(v) & mask);
}
#endif

void main() {
    GI_COUNT_INVOCATION();
    ivec2 px = giGBufferPixel();
    float depth = texelFetch(u_gbuffer_depth, px, 0).r;
#ifndef GI_INFLUENCE_BY_RASTER
    if (depth >= 1.0) discard; // sky (the raster's depth test GEQUAL already rejects it)
#endif
#ifdef GI_READS_FLAGS
    // A dynamic object's pixel: bit 0 of the flags (stored as bits / 255).
    bool dynamicPixel = (int(texelFetch(u_gbuffer_flags, px, 0).r * 255.0 + 0.5) & 1) != 0;
#ifdef GI_DYNAMIC_SH
    if (dynamicPixel) discard; // early out: the lighting gives dynamic objects their SH
#else
    // GI_DYNAMIC_UNFADED: looked up as a mid-air point, without the behind-surface fade.
    if (dynamicPixel) ddgiBehindFadeScale = 0.0;
#endif
#endif
    vec3 rel = giRelPosition(px, depth);
    vec3 local = ddgiLocal(rel); // once: the influence test and the lookup share it
#ifndef GI_INFLUENCE_BY_RASTER
    if (!ddgiInfluences(local)) discard;
#endif
    vec3 n = octDecode(texelFetch(u_gbuffer_normal, px, 0).xy);
    // The eye is the origin of camera-relative space: the view direction is -rel.
#ifdef GI_TECHNIQUE_SH
    vec4 gi = shSample(rel, n, -rel); // gi.technique=sh_l1|sh_l2: common_sh.glsl
#else
    vec4 gi = ddgiSample(local, n, -rel);
#endif
#ifdef GI_DEBUG_EXTRA_FETCHES
    // Test-only (passes/GiDebugInjection.h): fetches that cannot change the result (irradiance
    // >= 0) but that the compiler cannot drop.
    vec3 extra = vec3(0.0);
    for (int i = 0; i < GI_DEBUG_EXTRA_FETCHES; ++i)
        extra += texture(u_ddgiIrradiance, vec3((vec2(px) + float(i)) * u_ddgiIrrInvSize, 0.0)).rgb;
    gi.rgb = max(gi.rgb, -abs(extra));
#endif
#ifdef GI_TARGET_R11G11B10F
    vec3 ambient = mix(u_ambientDown, u_ambientUp, n.y * 0.5 + 0.5);
    // Blue never 0 where a volume drew: the lighting reads all-zero as "not covered".
    out_gi = vec4(max(gi.rgb + (1.0 - gi.a) * ambient, vec3(0.0, 0.0, 6.103515625e-05)), 1.0);
#else
    out_gi = gi;
#endif
#ifdef GI_DEBUG_DROP_MANTISSA_BIT
    out_gi.rgb = giDropMantissaBit(out_gi.rgb);
#endif
#ifdef GI_GUARD_CLAMP_ON
    out_gi = giStorable(out_gi);
#endif
#ifdef GI_COUNT_PIXELS
    out_evaluated = vec4(1.0);
#endif
}
