// Debug views probes_irradiance / probes_visibility: a small sphere around every probe of the
// bound volume (instance = probe, 432 vertices = 6 x 12 quads of a UV sphere, no buffers), at
// the probe's relocated position. Uniforms as in common_ddgi.glsl (GpuProbes::bindVolume).
uniform highp sampler2DArray u_ddgiState;
uniform vec3 u_ddgiCenter;
uniform mat3 u_ddgiToLocal;
uniform vec3 u_ddgiGridOrigin;
uniform vec3 u_ddgiGridStep;
uniform ivec3 u_ddgiCounts;
uniform mat4 u_clipFromRel;
uniform float u_sphereRadius;
out vec3 v_localDir;
flat out ivec3 v_tile; // the probe's tile (column, row, layer) from its w (ddgiTile)
flat out float v_valid;
#include "common_ddgi_tile.glsl"

const int kSegments = 12, kRings = 6;
const float PI = 3.14159265358979;

void main() {
    int probe = gl_InstanceID; // i + counts.x * (k + counts.z * j), the state texel order
    ivec3 q = ivec3(probe % u_ddgiCounts.x, probe / (u_ddgiCounts.x * u_ddgiCounts.z),
                    (probe / u_ddgiCounts.x) % u_ddgiCounts.z);
    vec4 state = texelFetch(u_ddgiState, ivec3(q.x, q.z, q.y), 0);
    int quad = gl_VertexID / 6, corner = gl_VertexID % 6;
    int ring = quad / kSegments + ((corner == 1 || corner == 2 || corner == 4) ? 1 : 0);
    int seg = quad % kSegments + ((corner == 2 || corner == 4 || corner == 5) ? 1 : 0);
    float theta = PI * float(ring) / float(kRings);
    float phi = 2.0 * PI * float(seg) / float(kSegments);
    vec3 dir = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
    vec3 local = u_ddgiGridOrigin + vec3(q) * u_ddgiGridStep + state.xyz + dir * u_sphereRadius;
    vec3 rel = u_ddgiCenter + transpose(u_ddgiToLocal) * local;
    v_localDir = dir;
    // Every volume's w holds its tile's code (GpuProbes), dense or sparse; invalid probes too.
    ddgiInitTileFields();
    v_tile = ddgiTile(abs(state.w));
    v_valid = state.w;
    // Absent probes (sparse storage, w = 0) have no data: no sphere (outside the clip volume).
    gl_Position = state.w == 0.0 ? vec4(2.0, 2.0, 2.0, 1.0) : u_clipFromRel * vec4(rel, 1.0);
}
