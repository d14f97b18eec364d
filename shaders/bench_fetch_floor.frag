// Texture-fetch floor of the GI apply pass (bench only, bench/runner/FetchFloorPass): per pixel
// of the GI target exactly the fetches of one DDGI lookup at its maximum - GBuffer depth and
// normal (texelFetch), then for 8 probes the state texel (texelFetch), one bilinear visibility
// and one bilinear irradiance sample - from the same textures, with next to no arithmetic.
// Coordinates come from the pixel (probe cell from the screen position, tile texel from the
// stored octahedral normal), so neighbouring pixels read neighbouring texels as in the real
// pass; the sum is written so no fetch can be optimised away. The real pass's time over this
// one says how far the lookup's math, branches and discards are from the fetch cost alone.
out vec4 out_floor;
uniform highp sampler2D u_gbuffer_normal;
uniform highp sampler2D u_gbuffer_depth;
uniform highp sampler2DArray u_ddgiIrradiance;
uniform highp sampler2DArray u_ddgiVisibility;
uniform highp sampler2DArray u_ddgiState;
uniform ivec3 u_ddgiCounts;
uniform vec2 u_ddgiIrrInvSize;
uniform vec2 u_ddgiVisInvSize;
uniform int u_giDivisor;       // GBuffer pixels per target texel, per axis
uniform vec2 u_targetInvSize;  // 1 / target size

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy) * u_giDivisor + (u_giDivisor - 1) / 2;
    float depth = texelFetch(u_gbuffer_depth, px, 0).r;
    vec2 oct = texelFetch(u_gbuffer_normal, px, 0).xy;
    vec2 uv = gl_FragCoord.xy * u_targetInvSize;
    ivec3 last = max(u_ddgiCounts - 2, ivec3(0));
    ivec3 base = ivec3(vec3(uv.x, uv.y, fract(depth * 64.0)) * vec3(last));
    vec2 local = clamp(oct * 0.5 + 0.5, 0.0, 1.0);
    vec2 visLocal = local * DDGI_VIS_INTERIOR + 1.0;
    vec2 irrLocal = local * DDGI_IRR_INTERIOR + 1.0;
    vec4 sum = vec4(depth);
    for (int i = 0; i < 8; ++i) {
        ivec3 q = min(base + ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), u_ddgiCounts - 1);
        sum += texelFetch(u_ddgiState, ivec3(q.x, q.z, q.y), 0);
        vec2 vis = (vec2(q.xz) * DDGI_VIS_TILE + visLocal) * u_ddgiVisInvSize;
        sum.xy += texture(u_ddgiVisibility, vec3(vis, float(q.y))).rg;
        vec2 irr = (vec2(q.xz) * DDGI_IRR_TILE + irrLocal) * u_ddgiIrrInvSize;
        sum.xyz += texture(u_ddgiIrradiance, vec3(irr, float(q.y))).rgb;
    }
    out_floor = sum * 1e-3;
}
