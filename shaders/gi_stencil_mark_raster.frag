// gi.multi_volume=stencil, the mark of a volume whose box contains the eye: drawn with the box's
// back faces and depth GEQUAL, the rasteriser alone selects the pixels whose surface lies in
// the box (GiApplyPass.cpp), so the shader has nothing to decide. Without a discard the driver
// can run the depth/stencil test and the stencil write before it (llvmpipe does), unlike
// gi_stencil_fill.frag, which is late-tested on every fragment of its draw.
// GI_COUNT_INVOCATIONS may come with GI_COUNT_EARLY_TESTS here: nothing is discarded.
#include "common_gi_invocations.glsl"

void main() {
    GI_COUNT_INVOCATION();
}
