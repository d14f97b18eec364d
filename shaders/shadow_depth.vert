// Sun shadow map: positions are transformed by a light matrix built in double precision on the
// CPU relative to the shadow frustum's centre, so far-from-origin scenes keep their precision.
//
// Each caster is drawn moved into its back side (ShadowPass.cpp, kLitSideBias and
// kUnlitSideBias): a vertex whose shading normal faces the sun (and every vertex of a
// double-sided material) is pushed away from the sun, one facing away is pulled towards it, by
// x texels of depth plus y per unit of tan(angle to the sun), tan capped at z. Per vertex, not
// per fragment: no fragment work, and early depth testing stays (the handheld's shadow pass is
// bound by its fragments' writes).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_lightFromLocal;
uniform mat3 u_normalFromLocal; // inverse transpose of the model matrix's 3x3
uniform vec3 u_toSun;           // world, unit
uniform int u_doubleSided;
uniform float u_depthTexel;     // one map texel in clip depth units (z in -1..1)
uniform vec3 u_litSideBias;     // x: constant texels, y: texels per unit of tan, z: max tan
uniform vec3 u_unlitSideBias;   // the same for the side facing away from the sun

float slopeBias(vec3 bias, float cosT) {
    float tanT = min(sqrt(max(1.0 - cosT * cosT, 0.0)) / max(cosT, 1e-6), bias.z);
    return u_depthTexel * (bias.x + bias.y * tanT);
}

void main() {
    gl_Position = u_lightFromLocal * vec4(a_position, 1.0);
    vec3 n = normalize(u_normalFromLocal * a_normal);
    float ndl = dot(n, u_toSun);
    if (u_doubleSided != 0) ndl = abs(ndl);
    // Orthographic: w is 1, so clip z moves by exactly this; + is away from the sun. A face
    // exactly edge-on to the sun is neither lit nor in front of anything it could cover.
    if (ndl > 0.0)
        gl_Position.z += slopeBias(u_litSideBias, ndl);
    else if (ndl < 0.0)
        gl_Position.z -= slopeBias(u_unlitSideBias, -ndl);
}
