// gi.upsample=bilinear: the low-resolution GI target filtered bilinearly to full resolution,
// one hardware fetch per pixel - the talk's "naive" starting point, blending across every
// edge. The sample positions (texel i at GBuffer pixel i * divisor + jitter) set the offset.
out vec4 out_gi;
uniform highp sampler2D u_giLow; // linear filtering (GiApplyPass)
uniform ivec2 u_giLowSize;
uniform int u_giDivisor;
uniform ivec2 u_giJitter;

void main() {
    vec2 f = (gl_FragCoord.xy - 0.5 - vec2(u_giJitter)) / float(u_giDivisor);
    out_gi = texture(u_giLow, (f + 0.5) / vec2(u_giLowSize));
}
