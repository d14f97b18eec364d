// Debug views probes_irradiance / probes_visibility: a small sphere around every probe of the
// bound volume (instance = probe, 432 vertices = 6 x 12 quads of a UV sphere, no buffers), at
// the probe's relocated position. Uniforms as in common_ddgi.glsl (GpuProbes::bindVolume).
uniform highp sampler2DArray u_ddgiState;
uniform vec3 u_ddgiCenter;
uniform mat3 u_ddgiToLocal;
uniform vec3 u_ddgiGridOrigin;
uniform vec3 u_ddgiGridStep;
uniform ivec3 u_ddgiCounts;
uniform ivec2 u_ddgiTileGrid;
uniform mat4 u_clipFromRel;
uniform float u_sphereRadius;
out vec3 v_localDir;
flat out ivec3 v_tile; // the probe's tile (column, row, layer), as common_ddgi.glsl's ddgiTile
flat out float v_valid;

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
    int slot = int(abs(state.w) + 0.5) - 1; // common_ddgi.glsl's ddgiTile
    ivec2 grid = u_ddgiTileGrid.x > 0 ? u_ddgiTileGrid : u_ddgiCounts.xz; // (0, 0): dense
    v_tile = ivec3(slot % grid.x, (slot / grid.x) % grid.y, slot / (grid.x * grid.y));
    v_valid = state.w;
    // Absent probes (sparse storage, w = 0) have no data: no sphere (outside the clip volume).
    gl_Position = slot < 0 ? vec4(2.0, 2.0, 2.0, 1.0) : u_clipFromRel * vec4(rel, 1.0);
}
