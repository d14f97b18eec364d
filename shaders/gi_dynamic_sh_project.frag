// gi.dynamic=sh, the fit: texel (k, o) = coefficient k of the basis (1, n.x, n.y, n.z) of
// dynamic object o, the least-squares fit of its kDirections lookups (passes/DynamicShPass).
// rgb = E * fade, a = fade, like the lookups; the lighting evaluates c0 + c1 n.x + ...
out vec4 out_coefficient;
uniform highp sampler2D u_shLookups; // directions x objects: ddgiSample per direction
uniform highp sampler2D u_shWeights; // directions x 1: the fit's weight per direction, per k
uniform int u_shDirections;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < u_shDirections; ++i)
        sum += texelFetch(u_shWeights, ivec2(i, 0), 0)[t.x] * texelFetch(u_shLookups, ivec2(i, t.y), 0);
    out_coefficient = sum;
}
