// Deferred direct lighting: sun (shadow-mapped), punctual lights, emissive, and the indirect
// irradiance input: the GI evaluation target where a probe volume covers the pixel
// (GI_ENABLED), blended by its weight with the hemispherical ambient, which stays the fallback
// outside every volume (and the whole input without GI); with GI_DYNAMIC_SH, dynamic-object
// pixels take their object's L1 SH instead. Output: linear radiance x u_preExposure
// (gi.guard_exposure, FrameContext.h; 1 without it): the GI inputs arrive pre-exposed and are
// brought back to scene units here, the lighting is computed in fp32 and pre-exposed once for
// the RGBA16F target (the GBuffer's emissive is stored pre-exposed). GI_GUARD_CLAMP_ON: NaN -> 0 and overflow -> 65504 before the store.
#include "common_octahedral.glsl"
in vec2 v_uv;
out vec4 out_radiance;
uniform sampler2D u_gbuffer_albedo;
uniform sampler2D u_gbuffer_normal;
uniform sampler2D u_gbuffer_emissive;
uniform sampler2D u_gbuffer_depth;
uniform sampler2DShadow u_shadowMap;      // the view map (ShadowPass.h)...
uniform sampler2DShadow u_shadowMapScene; // ...and the whole-scene map, its fallback
uniform mat4 u_relFromClip;        // inverse of the camera's clip-from-camera-relative matrix
uniform mat4 u_shadowFromRel;      // camera-relative world -> view map texture space [0,1]^3
uniform mat4 u_shadowSceneFromRel; // ... -> scene map texture space
uniform int u_sunEnabled;
uniform vec3 u_toSun;
uniform vec3 u_sunIrradiance;      // colour * intensity
uniform float u_shadowNormalOffset; // world units, half a texel of the view map (scene map: ...Scene...)
uniform float u_shadowSceneNormalOffset;
uniform float u_shadowTexel;        // one texel of the view map in texture space
uniform float u_shadowDepthTexel;   // one texel's world size in depth-texture units
uniform mat3 u_shadowNormalToMap;   // world normal -> normal in the view map's texture space
uniform float u_shadowSceneDepthTexel;
uniform vec3 u_skyRadiance;
uniform vec3 u_ambientUp;          // indirect irradiance for an upward normal...
uniform vec3 u_ambientDown;        // ...and a downward one
uniform float u_preExposure;       // the radiance target holds radiance x this (a power of 2)
#define MAX_LIGHTS 16
uniform int u_lightCount;
uniform vec4 u_lightPosType[MAX_LIGHTS];   // xyz camera-relative position, w: 0 dir, 1 point, 2 spot
uniform vec4 u_lightDirRange[MAX_LIGHTS];  // xyz direction the light travels, w: range (0 = inf)
uniform vec4 u_lightColor[MAX_LIGHTS];     // rgb colour * intensity
uniform vec4 u_lightCone[MAX_LIGHTS];      // x: cos outer, y: cos inner

const float PI = 3.14159265358979;

#ifdef GI_ENABLED
uniform highp sampler2D u_giIrradiance; // gi_ddgi_apply.frag's layout, full resolution
#ifdef GI_DYNAMIC_SH
uniform sampler2D u_gbuffer_flags;      // bit 0: dynamic, bits 1-7: object (bits / 255)
uniform highp sampler2D u_giDynamicSh;  // texel (k, object): gi_dynamic_sh_project.frag
#endif
vec3 indirectIrradiance(vec3 n, ivec2 px) {
    vec3 ambient = mix(u_ambientDown, u_ambientUp, n.y * 0.5 + 0.5);
#ifdef GI_DYNAMIC_SH
    // Dynamic objects: their L1 fit at this normal (rgb = E * fade, a = fade), never the
    // target (the apply pass skipped these pixels).
    int flags = int(texelFetch(u_gbuffer_flags, px, 0).r * 255.0 + 0.5);
    if ((flags & 1) != 0) {
        int object = flags >> 1;
        vec4 sh = texelFetch(u_giDynamicSh, ivec2(0, object), 0) +
                  texelFetch(u_giDynamicSh, ivec2(1, object), 0) * n.x +
                  texelFetch(u_giDynamicSh, ivec2(2, object), 0) * n.y +
                  texelFetch(u_giDynamicSh, ivec2(3, object), 0) * n.z;
        sh = max(sh, vec4(0.0)); // an L1 fit can dip below 0 opposite a bright side
        return sh.rgb / u_preExposure + (1.0 - min(sh.a, 1.0)) * ambient;
    }
#endif
    // Full resolution: the apply pass's target, or at half/quarter the upsample pass's output.
    vec4 gi = texelFetch(u_giIrradiance, px, 0);
#ifdef GI_TARGET_R11G11B10F
    // No alpha: the apply pass blended the ambient in; all zero = no volume drew here.
    return gi.rgb == vec3(0.0) ? ambient : gi.rgb / u_preExposure;
#else
    return gi.rgb / u_preExposure + (1.0 - gi.a) * ambient;
#endif
}
#else
vec3 indirectIrradiance(vec3 n, ivec2 px) {
    return mix(u_ambientDown, u_ambientUp, n.y * 0.5 + 0.5);
}
#endif

// The receiver's depth bias, in texels of the map read. Most of the bias is the casters'
// (ShadowPass.cpp, shadow_depth.vert: each caster drawn moved into its back side), so the
// receiver keeps only x: a constant half texel; y: the steepest receiver plane, in texels of
// depth per texel, that the PCF taps follow.
uniform vec2 u_shadowBias;

// Above every caster's depth and below the clear depth 1: compared with it, a tap passes only
// where nothing was drawn (the maps span the scene's diameter, so no caster comes this far).
const float kOpenDepth = 0.99999;

// The receiver in one map's texture space: normal-offset by sin(angle) x the map's offset,
// depth-biased by u_shadowBias.x of the map's texels.
vec3 shadowCoord(mat4 fromRel, float normalOffset, float depthTexel, vec3 rel, vec3 n, float sinT) {
    vec4 s = fromRel * vec4(rel + n * (normalOffset * sinT), 1.0);
    vec3 p = s.xyz / s.w;
    p.z -= depthTexel * u_shadowBias.x;
    return p;
}

// The view map's 3 x 3 bilinear PCF, as four taps: along one axis the three taps at -1, 0, +1
// texel weigh the four texels they touch 1 - f, 1, 1, f (f: the receiver's fraction past a
// texel centre), which two bilinear taps give exactly, with weights 2 - f and 1 + f.
struct Pcf4 {
    vec2 uv[2];     // the two taps' positions along x and y: [0] between texels i0 - 1 and i0, [1] i0 + 1 and i0 + 2
    vec2 weight[2]; // their weights, per axis (summing to 3)
};

Pcf4 pcf4(vec2 uv) {
    vec2 c = uv / u_shadowTexel - 0.5;
    vec2 i0 = floor(c);
    vec2 f = c - i0;
    Pcf4 k;
    k.weight[0] = 2.0 - f;
    k.weight[1] = 1.0 + f;
    k.uv[0] = (i0 - 0.5 + 1.0 / k.weight[0]) * u_shadowTexel;
    k.uv[1] = (i0 + 1.5 + f / k.weight[1]) * u_shadowTexel;
    return k;
}

// The view map's PCF where it covers the receiver (with the kernel's reach); else the
// whole-scene map's single bilinear tap (a rare fallback: surfaces the view fit's rays missed,
// dynamic objects), else lit (outside the scene's bounds).
float sunShadow(vec3 rel, vec3 n, float ndl) {
    float sinT = sqrt(max(1.0 - ndl * ndl, 0.0));
    vec3 p = shadowCoord(u_shadowFromRel, u_shadowNormalOffset, u_shadowDepthTexel, rel, n, sinT);
    float edge = 1.5 * u_shadowTexel;
    if (p.x > edge && p.x < 1.0 - edge && p.y > edge && p.y < 1.0 - edge) {
        if (p.z >= 1.0) return 1.0;
        // A tap where the receiver's plane falls away from the sun compares the plane's depth
        // there, not the centre's: a floor beside a wall's foot otherwise reads the foot one
        // tap along as deeper than itself and is lit through it. Where the plane rises towards
        // the sun the tap keeps the centre's depth: beyond a concave corner (a wall under the
        // ceiling) the plane runs outside the room, in front of the occluder. Depth per unit of
        // texture x and y, from the normal in the map's space, clamped at u_shadowBias.y texels
        // of depth per texel.
        vec3 nm = u_shadowNormalToMap * n;
        float maxSlope = u_shadowBias.y * u_shadowDepthTexel / u_shadowTexel;
        vec2 dz = clamp(-nm.xy / (abs(nm.z) > 1e-8 ? nm.z : 1e-8), -maxSlope, maxSlope);
        Pcf4 k = pcf4(p.xy);
        float lit = 0.0;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                vec2 uv = vec2(k.uv[i].x, k.uv[j].y);
                float z = p.z + max(dot(uv - p.xy, dz), 0.0);
                lit += k.weight[i].x * k.weight[j].y * texture(u_shadowMap, vec3(uv, z));
            }
        // A penumbra: some taps may reach past the outline of every caster, where the map
        // holds its clear depth and says lit whatever the receiver. A receiver on the outline
        // (a room's back corner, its wall seen edge-on by the sun) got the sun through them.
        // Average over the texels a caster was drawn into instead: the same taps compared with
        // kOpenDepth pass only at cleared texels, so they count the lit weight that came from
        // nowhere (issue 42, ShadowZeroThickness).
        if (lit > 1e-4 && lit < 9.0 - 1e-4) {
            float open = 0.0;
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i)
                    open += k.weight[i].x * k.weight[j].y *
                            texture(u_shadowMap, vec3(k.uv[i].x, k.uv[j].y, kOpenDepth));
            float covered = 9.0 - open; // > 0 unless every tap read nothing: then lit
            return covered > 1e-3 ? clamp((lit - open) / covered, 0.0, 1.0) : 1.0;
        }
        return clamp(lit / 9.0, 0.0, 1.0);
    }
    p = shadowCoord(u_shadowSceneFromRel, u_shadowSceneNormalOffset, u_shadowSceneDepthTexel, rel,
                    n, sinT);
    if (p.x <= 0.0 || p.x >= 1.0 || p.y <= 0.0 || p.y >= 1.0 || p.z >= 1.0) return 1.0;
    return texture(u_shadowMapScene, p);
}

vec3 punctualIrradiance(vec3 rel, vec3 n) {
    vec3 e = vec3(0.0);
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= u_lightCount) break;
        vec3 l;
        float atten = 1.0;
        if (u_lightPosType[i].w == 0.0) {
            l = -u_lightDirRange[i].xyz;
        } else {
            vec3 d = u_lightPosType[i].xyz - rel;
            float dist2 = max(dot(d, d), 1e-8);
            l = d * inversesqrt(dist2);
            atten = 1.0 / dist2;
            float range = u_lightDirRange[i].w;
            if (range > 0.0) {
                float r = sqrt(dist2) / range;
                atten *= clamp(1.0 - r * r * r * r, 0.0, 1.0);
            }
            if (u_lightPosType[i].w == 2.0) {
                float cd = dot(-l, u_lightDirRange[i].xyz);
                atten *= smoothstep(u_lightCone[i].x, u_lightCone[i].y, cd);
            }
        }
        e += u_lightColor[i].rgb * atten * max(dot(n, l), 0.0);
    }
    return e;
}

// What the RGBA16F target is given: with GI_GUARD_CLAMP_ON, NaN -> 0 (comparisons with NaN are
// false), negatives -> 0, overflow and +Inf -> 65504.
vec3 storable(vec3 radiance) {
#ifdef GI_GUARD_CLAMP_ON
    return min(mix(vec3(0.0), radiance, greaterThanEqual(radiance, vec3(0.0))), vec3(65504.0));
#else
    return radiance;
#endif
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_gbuffer_depth, px, 0).r;
    if (depth >= 1.0) {
        out_radiance = vec4(storable(u_skyRadiance * u_preExposure), 1.0);
        return;
    }
    vec4 clip = vec4(v_uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vec4 relH = u_relFromClip * clip;
    vec3 rel = relH.xyz / relH.w;
    vec3 albedo = texelFetch(u_gbuffer_albedo, px, 0).rgb;
    vec3 n = octDecode(texelFetch(u_gbuffer_normal, px, 0).xy);
    vec3 emissive = texelFetch(u_gbuffer_emissive, px, 0).rgb;

#ifdef DEBUG_INDIRECT_ONLY
    out_radiance = vec4(storable(albedo / PI * indirectIrradiance(n, px) * u_preExposure), 1.0);
    return;
#endif
    vec3 irradiance = indirectIrradiance(n, px) + punctualIrradiance(rel, n);
    if (u_sunEnabled != 0) {
        float ndl = max(dot(n, u_toSun), 0.0);
        if (ndl > 0.0) irradiance += u_sunIrradiance * ndl * sunShadow(rel, n, ndl);
    }
    // Lambert: outgoing radiance = albedo / pi * irradiance.
    vec3 radiance = emissive + albedo / PI * irradiance * u_preExposure; // emissive: pre-exposed
    out_radiance = vec4(storable(radiance), 1.0);
}
