// Debug views: a probe's sphere. probes_irradiance: a white Lambertian lit by the probe's
// irradiance for the sphere's normal (E / pi, the scene's brightness scale); DEBUG_VISIBILITY:
// brightness = the probe's mean free distance towards the normal (normalised to its maximum,
// 1 = open), black when the probe is invalid.
#include "common_ddgi.glsl"
in vec3 v_localDir;
flat in ivec3 v_tile;
flat in float v_valid;
out vec4 out_radiance;
uniform float u_visibilityScale; // radiance of a fully open direction (0.5 after exposure)

void main() {
    vec3 d = normalize(v_localDir);
#ifdef DEBUG_VISIBILITY
    vec2 c = (vec2(v_tile.xy) * DDGI_VIS_TILE + ddgiTileLocal(d, DDGI_VIS_INTERIOR)) *
             u_ddgiVisInvSize;
    float mean = texture(u_ddgiVisibility, vec3(c, float(v_tile.z))).r;
    out_radiance = vec4(vec3(v_valid >= 0.5 ? mean * u_visibilityScale : 0.0), 1.0);
#else
    ddgiInitLoopConstants();
    out_radiance = vec4(ddgiProbeIrradiance(v_tile, ddgiIrrCoord(d)) / 3.14159265358979, 1.0);
#endif
}
