// gi.upsample=temporal: a full-resolution GI history, reprojected with the camera matrices
// alone (no motion vectors: valid for static surfaces), refreshed by this frame's jittered
// low-resolution samples. Per pixel:
//  - the pixel this frame's jittered sample was evaluated at, a dynamic pixel (GBuffer flag),
//    or no usable history (first frame, cut): this frame's bilateral reconstruction;
//  - otherwise the previous frame's history at the reprojected position (four taps, each
//    rejected when the surface it stored is not this pixel's surface), blended with the
//    bilateral reconstruction by alpha = max(disocclusion, depth difference, luma difference,
//    distance moved) - the talk's weights; the thresholds are documented in renderer/README.md.
// Outputs the new history: GI (read by the lighting) and its surface (RGBA16F): the pixel's
// distance from the eye (-1 = nothing to reproject: sky, dynamic), the history's confidence -
// the share of it that comes from exact samples (1 at this frame's sample, 0 for a
// reconstruction, blended like the GI) - and the octahedral normal.
#include "common_octahedral.glsl"
#include "common_upsample.glsl"
layout(location = 0) out vec4 out_gi;
layout(location = 1) out vec4 out_distance;
uniform highp sampler2D u_historyGi;
uniform highp sampler2D u_historyDistance;
uniform int u_historyValid;
uniform mat4 u_prevClipFromRel; // previous clip <- this frame's camera-relative (double-composed)
uniform mat4 u_prevRelFromClip; // previous camera-relative <- previous clip
uniform vec3 u_eyeOffset;       // eye - previous eye: rel + offset is relative to the previous eye
uniform int u_stillCamera;      // the same camera as last frame (decided in double on the CPU)

// Temporal weights (renderer/README.md, "gi.upsample").
// Plane distances below 0.5% of the distance are the stored fp16 distance's rounding (5e-4)
// and the matrices' (1e-6), not another surface: they do not count as a depth difference.
const float TEMPORAL_DEPTH_FLOOR = 0.005;
// Luma: the history at this frame's fresh sample against the sample itself. Up to 5% apart is
// agreement (fp16, the view-dependent bias); alpha reaches 1 at 30%.
const float TEMPORAL_LUMA_TOLERANCE = 0.05;
const float TEMPORAL_LUMA_FULL = 0.30;
const float TEMPORAL_MOTION_PIXELS = 16.0; // alpha from motion = pixels moved / 16...
const float TEMPORAL_MOTION_MAX = 0.5;     // ...at most 0.5

float luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

vec2 size() { return 1.0 / u_gbufferInvSize; }

// Window position in the previous frame of a camera-relative position (w <= 0: behind).
vec3 previousWindow(vec3 rel) {
    vec4 clip = u_prevClipFromRel * vec4(rel, 1.0);
    return vec3((clip.xy / max(clip.w, 1e-20) * 0.5 + 0.5) * size(), clip.w);
}

bool onPreviousScreen(vec3 w) {
    return w.z > 0.0 && all(greaterThanEqual(w.xy, vec2(0.0))) && all(lessThanEqual(w.xy, size()));
}

// History texel q against the surface at relPrev (relative to the previous eye) with normal n:
// x = relative distance of the stored surface from that tangent plane (> 1e29 when it stored
// none), y = the stored confidence, z = the normal agreement weight (the bilateral one).
vec3 historyTap(ivec2 q, vec3 relPrev, vec3 n) {
    vec4 stored = texelFetch(u_historyDistance, q, 0);
    if (stored.x < 0.0) return vec3(1e30, 0.0, 0.0);
    vec2 ndc = (vec2(q) + 0.5) * u_gbufferInvSize * 2.0 - 1.0;
    vec4 farH = u_prevRelFromClip * vec4(ndc, 1.0, 1.0);
    vec3 tap = normalize(farH.xyz / farH.w) * stored.x;
    float plane = abs(dot(n, tap - relPrev)) / max(length(relPrev), 1e-6);
    return vec3(plane, stored.y, upsampleNormalWeight(n, octDecode(stored.zw)));
}

// How far the history disagrees with this frame's fresh sample nearest p - the one place where
// the truth is known this frame -, times that history's confidence: a history that is still a
// reconstruction is expected to differ and says nothing about staleness. 0 when that sample has
// no history to compare with.
float freshSampleLumaDifference(ivec2 p) {
    vec2 f = vec2(p - u_giJitter) / float(u_giDivisor);
    ivec2 i = clamp(ivec2(floor(f + 0.5)), ivec2(0), u_giLowSize - 1);
    ivec2 s = i * u_giDivisor + u_giJitter;
    float ds = texelFetch(u_gbuffer_depth, s, 0).r;
    if (ds >= 1.0 || upsampleIsDynamic(s)) return 0.0;
    vec3 relS = upsampleRel(s, ds);
    vec3 w = previousWindow(relS);
    if (!onPreviousScreen(w)) return 0.0;
    ivec2 q = u_stillCamera != 0 ? s : clamp(ivec2(floor(w.xy)), ivec2(0), ivec2(size()) - 1);
    vec3 nS = octDecode(texelFetch(u_gbuffer_normal, s, 0).xy);
    vec3 tap = historyTap(q, relS + u_eyeOffset, nS);
    if (tap.x > UPSAMPLE_PLANE_TOLERANCE || tap.z < 0.5) return 0.0;
    float fresh = luma(texelFetch(u_giLow, i, 0).rgb);
    float old = luma(texelFetch(u_historyGi, q, 0).rgb);
    return tap.y * abs(fresh - old) / max(max(fresh, old), 1e-4);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_gbuffer_depth, p, 0).r;
    if (depth >= 1.0) {
        out_gi = vec4(0.0);
        out_distance = vec4(-1.0, 0.0, 0.0, 0.0);
        return;
    }
    vec3 rel = upsampleRel(p, depth);
    vec3 n = octDecode(texelFetch(u_gbuffer_normal, p, 0).xy);
    vec4 spatial = upsampleBilateral(p, rel, n);
    bool dynamic = upsampleIsDynamic(p);
    bool exact = upsampleIsExactSample(p);
    out_distance = vec4(dynamic ? -1.0 : length(rel), exact ? 1.0 : 0.0,
                        texelFetch(u_gbuffer_normal, p, 0).xy);
    out_gi = spatial;
    if (dynamic || u_historyValid == 0 || exact) return;

    vec3 w = previousWindow(rel);
    if (!onPreviousScreen(w)) return;
    // A still camera reprojects onto the pixel itself; the float round trip through the
    // inverse projection would miss it by up to a few hundredths of a pixel far away, and that
    // bilinear blur, compounded every frame, would bleed neighbours into a converged history.
    float moved = u_stillCamera != 0 ? 0.0 : length(w.xy - (vec2(p) + 0.5));
    vec2 h = u_stillCamera != 0 ? vec2(p) : w.xy - 0.5;
    ivec2 h0 = ivec2(floor(h));
    vec2 t = h - vec2(h0);
    vec3 relPrev = rel + u_eyeOffset;
    vec4 history = vec4(0.0);
    float accepted = 0.0, depthError = 0.0, confidence = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        float wb = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
        if (wb <= 0.0) continue;
        ivec2 q = clamp(h0 + o, ivec2(0), ivec2(size()) - 1);
        vec3 tap = historyTap(q, relPrev, n);
        float plane = tap.x;
        if (plane > UPSAMPLE_PLANE_TOLERANCE) continue;
        float w = wb * tap.z; // another orientation is another surface, as in the bilateral
        history += w * texelFetch(u_historyGi, q, 0);
        accepted += w;
        confidence += w * tap.y;
        depthError += w * clamp((plane - TEMPORAL_DEPTH_FLOOR) /
                                    (UPSAMPLE_PLANE_TOLERANCE - TEMPORAL_DEPTH_FLOOR),
                                0.0, 1.0);
    }
    if (accepted < 1e-3) return; // disoccluded: nothing of this surface in the history
    history /= accepted;
    confidence /= accepted;

    float alphaDisocclusion = 1.0 - accepted;
    float alphaDepth = depthError / accepted;
    float alphaLuma = clamp((freshSampleLumaDifference(p) - TEMPORAL_LUMA_TOLERANCE) /
                                (TEMPORAL_LUMA_FULL - TEMPORAL_LUMA_TOLERANCE),
                            0.0, 1.0);
    float alphaMotion = min(moved / TEMPORAL_MOTION_PIXELS, TEMPORAL_MOTION_MAX);
    float alpha = max(max(alphaDisocclusion, alphaDepth), max(alphaLuma, alphaMotion));
    out_gi = mix(history, spatial, alpha);
    out_distance.y = confidence * (1.0 - alpha);
}
