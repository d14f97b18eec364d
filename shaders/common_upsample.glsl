// Shared by the gi_upsample_* shaders (renderer/passes/GiUpsamplePass): where the
// low-resolution GI samples sit in the full-resolution GBuffer, and the bilateral
// reconstruction from them. Needs common_octahedral.glsl included first.
//
// Low-resolution texel i was evaluated at GBuffer pixel i * u_giDivisor + u_giJitter
// (gi_ddgi_apply.frag), so full-resolution pixel p lies at the continuous texel coordinate
// (p - jitter) / divisor: p's four neighbouring samples and their bilinear weights follow.
uniform highp sampler2D u_giLow; // the apply pass's target (texelFetch only)
uniform ivec2 u_giLowSize;
uniform int u_giDivisor;
uniform ivec2 u_giJitter;
uniform highp sampler2D u_gbuffer_normal;
uniform highp sampler2D u_gbuffer_depth;
uniform highp sampler2D u_gbuffer_flags;
uniform mat4 u_relFromClip;
uniform vec2 u_gbufferInvSize;

// Bilateral thresholds (documented in renderer/README.md, "gi.upsample"):
// a sample whose surface lies farther than this fraction of the pixel's distance from the
// eye off the pixel's tangent plane is another surface: weight 0, never blended. Slopes of the
// same plane pass at any angle; a step between parallel surfaces is rejected above 5%.
const float UPSAMPLE_PLANE_TOLERANCE = 0.05;

vec3 upsampleRel(ivec2 px, float depth) {
    vec2 uv = (vec2(px) + 0.5) * u_gbufferInvSize;
    vec4 relH = u_relFromClip * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    return relH.xyz / relH.w;
}

// Normal agreement weight: cos^8 (1 for equal normals, 0.5 at 23.5 degrees, 0.06 at 45).
float upsampleNormalWeight(vec3 a, vec3 b) {
    float c = max(dot(a, b), 0.0);
    float c2 = c * c;
    float c4 = c2 * c2;
    return c4 * c4;
}

// Bit 0 of the GBuffer flags (stored as bits / 255): a dynamic object's pixel.
bool upsampleIsDynamic(ivec2 px) {
    return (int(texelFetch(u_gbuffer_flags, px, 0).r * 255.0 + 0.5) & 1) != 0;
}

// True when this frame's low-resolution sample was evaluated exactly at pixel p.
bool upsampleIsExactSample(ivec2 p) {
    ivec2 d = p - u_giJitter;
    ivec2 i = d / u_giDivisor;
    return all(greaterThanEqual(d, ivec2(0))) && d == i * u_giDivisor &&
           all(lessThan(i, u_giLowSize));
}

// Depth- and normal-aware upsample of pixel p (camera-relative position relP, normal nP):
// the four neighbouring samples weighted bilinearly x plane test x normal weight, renormalized.
// Samples on the sky carry nothing and are skipped, and so are samples of a dynamic object for
// a static pixel and the other way round (with gi.dynamic=sh the apply pass leaves dynamic
// samples empty). When every sample is rejected the one nearest p's plane is taken alone
// (nearest-depth fallback: still no blend across a step).
vec4 upsampleBilateral(ivec2 p, vec3 relP, vec3 nP) {
    bool dynamicP = upsampleIsDynamic(p);
    vec2 f = vec2(p - u_giJitter) / float(u_giDivisor);
    ivec2 i0 = ivec2(floor(f));
    vec2 t = f - vec2(i0);
    float distP = max(length(relP), 1e-6);
    vec4 sum = vec4(0.0);
    float wsum = 0.0;
    float bestPlane = 1e30;
    vec4 best = vec4(0.0);
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        float wb = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
        ivec2 i = clamp(i0 + o, ivec2(0), u_giLowSize - 1);
        ivec2 s = i * u_giDivisor + u_giJitter;
        float ds = texelFetch(u_gbuffer_depth, s, 0).r;
        if (ds >= 1.0 || upsampleIsDynamic(s) != dynamicP) continue;
        float plane = abs(dot(nP, upsampleRel(s, ds) - relP)) / distP;
        vec4 v = texelFetch(u_giLow, i, 0);
        if (plane < bestPlane) {
            bestPlane = plane;
            best = v;
        }
        if (plane > UPSAMPLE_PLANE_TOLERANCE) continue;
        vec3 nS = octDecode(texelFetch(u_gbuffer_normal, s, 0).xy);
        float w = wb * (1.0 - plane / UPSAMPLE_PLANE_TOLERANCE) * upsampleNormalWeight(nP, nS);
        sum += w * v;
        wsum += w;
    }
    return wsum > 1e-6 ? sum / wsum : best;
}
