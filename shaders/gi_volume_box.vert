// A probe volume's influence box as 12 triangles (draw 36 vertices, no buffers): the unit
// cube's corner c has x = bit 0, y = bit 1, z = bit 2; every face is counter-clockwise seen
// from outside. u_clipFromBox (passes/GiVolumeRaster) places it on the GI target.
uniform mat4 u_clipFromBox;
const int kCorners[36] = int[36](4, 6, 2, 4, 2, 0, 1, 3, 7, 1, 7, 5, 1, 5, 4, 1, 4, 0,
                                 2, 6, 7, 2, 7, 3, 2, 3, 1, 2, 1, 0, 4, 5, 7, 4, 7, 6);
void main() {
    int c = kCorners[gl_VertexID];
    vec3 p = vec3((c & 1) != 0 ? 1.0 : -1.0, (c & 2) != 0 ? 1.0 : -1.0, (c & 4) != 0 ? 1.0 : -1.0);
    gl_Position = u_clipFromBox * vec4(p, 1.0);
}
