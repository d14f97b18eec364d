// GBuffer fill. u_viewFromLocal maps local positions to camera-relative space (the eye at the
// origin, axes of the world): built in double precision on the CPU so that scenes far from
// the origin do not lose precision in float.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_relFromLocal;     // local -> camera-relative world
uniform mat3 u_normalFromLocal;  // inverse transpose of the model matrix's 3x3
uniform mat4 u_clipFromRel;      // camera-relative world -> clip
out vec3 v_normal;
out vec2 v_uv;
void main() {
    vec4 rel = u_relFromLocal * vec4(a_position, 1.0);
    v_normal = u_normalFromLocal * a_normal;
    v_uv = a_uv;
    gl_Position = u_clipFromRel * rel;
}
