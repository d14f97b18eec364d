// Diagnostics (GiApplyPass::setCountPixels): how many times the device ran this fragment shader,
// counted by an atomic counter (GLSL ES 3.10, binding 0, the range the pass binds per draw).
// GI_COUNT_INVOCATION() is the first statement of main, so discarded invocations count too.
//
// The counter is a side effect, and a shader with side effects gets its depth/stencil tests
// after it unless it asks for early tests (GLES 3.1 spec, 13.8.1 / GLSL ES 3.10, 4.4.1.3): on
// llvmpipe the counter alone would turn an early-tested draw into a late-tested one, and count
// fragments the production shader never runs. GI_COUNT_EARLY_TESTS adds
// layout(early_fragment_tests), which reproduces the production shader's early tests only for a
// draw that writes neither depth nor stencil (the apply); a draw that writes stencil after a
// discard (the stencil mark) is late-tested in production and must not get it
// (renderer/README.md "Invocation counter").
#ifdef GI_COUNT_INVOCATIONS
#ifdef GI_COUNT_EARLY_TESTS
layout(early_fragment_tests) in;
#endif
layout(binding = 0, offset = 0) uniform atomic_uint u_giInvocations;
#define GI_COUNT_INVOCATION() atomicCounterIncrement(u_giInvocations)
#else
#define GI_COUNT_INVOCATION()
#endif
