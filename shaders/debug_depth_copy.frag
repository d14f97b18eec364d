// Copies the GBuffer depth into a float colour target as view distance, for --dump-gbuffer
// (GLES cannot read depth with glReadPixels).
in vec2 v_uv;
out vec4 out_value;
uniform sampler2D u_depth;
uniform mat4 u_relFromClip;
void main() {
    float d = texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r;
    vec4 rel = u_relFromClip * vec4(v_uv * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
    float dist = d >= 1.0 ? 0.0 : length(rel.xyz / rel.w);
    out_value = vec4(dist, d, 0.0, 1.0);
}
