// gi.multi_volume=stencil: the GI target's own depth buffer (its size, not the GBuffer's)
// receives the depth of the GBuffer pixel each texel stands for, so the volume boxes are
// depth-tested against exactly the surfaces the apply shader evaluates.
#include "common_gi_pixel.glsl"
uniform highp sampler2D u_gbuffer_depth;

void main() {
    gl_FragDepth = texelFetch(u_gbuffer_depth, giGBufferPixel(), 0).r;
}
