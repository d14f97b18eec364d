// The GBuffer pixel a GI target texel stands for, and that pixel's surface position: shared
// by the GI apply pass and the stencil passes of gi.multi_volume=stencil, so all of them
// judge a pixel's volume from bit-identical positions.
uniform mat4 u_relFromClip;  // inverse of the camera's clip-from-camera-relative matrix
uniform vec2 u_gbufferInvSize;
uniform int u_giDivisor;     // GBuffer pixels per target texel, per axis (gi.resolution)
uniform ivec2 u_giJitter;    // the GBuffer pixel of the texel's footprint sampled this frame

// The GBuffer pixel this frame samples in the texel's footprint: (divisor - 1) / 2 (nearest the
// centre, top-left of the middle four) unless gi.upsample=temporal jitters it (GiUpsamplePass,
// common_upsample.glsl); kept inside the GBuffer: a frame narrower than the divisor (1x1 at
// quarter) has no middle pixel, and a fetch outside would read depth 0 - a point on the near
// plane (probebench stress).
ivec2 giGBufferPixel() {
    ivec2 last = ivec2(floor(1.0 / u_gbufferInvSize + 0.5)) - 1;
    return min(ivec2(gl_FragCoord.xy) * u_giDivisor + u_giJitter, last);
}

// Camera-relative surface position of GBuffer pixel px at depth-buffer value `depth`.
vec3 giRelPosition(ivec2 px, float depth) {
    vec2 uv = (vec2(px) + 0.5) * u_gbufferInvSize;
    vec4 relH = u_relFromClip * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    return relH.xyz / relH.w;
}
