// Sun shadow map: positions are transformed by a light matrix built in double precision on the
// CPU relative to the shadow frustum's centre, so far-from-origin scenes keep their precision.
layout(location = 0) in vec3 a_position;
uniform mat4 u_lightFromLocal;
void main() { gl_Position = u_lightFromLocal * vec4(a_position, 1.0); }
