#pragma once
// Differences between drivers and between GL ES and desktop GL that the renderer must work
// around, as named booleans set once from the context's strings. Code asks for a quirk by
// name; there are no scattered `if (renderer == ...)` checks.
namespace pb::gl {

struct DriverQuirks {
    // Desktop contexts run with GL_FRAMEBUFFER_SRGB on (platforms/EsSemantics: sRGB
    // attachments then encode as on ES). Mesa's GLFW windows are sRGB-capable, so the final
    // blit of our already-encoded RGBA8 image to the window would be encoded twice: it must
    // turn the switch off around the blit. (GL_FRAMEBUFFER_SRGB is not an ES enum.)
    bool windowBlitNeedsSrgbOff = false;
    // llvmpipe: timer queries measure command submission, not execution, unless the timed
    // work is bracketed by glFlush (DESIGN.md).
    bool timerQueriesNeedFlush = false;
    // A software rasterizer (llvmpipe, softpipe, swrast): timings are of the CPU, not a GPU.
    bool softwareRenderer = false;
    // Timer queries do not measure the timed work's execution: llvmpipe's measure command
    // submission unless flush-bracketed (above), and on any software rasterizer the work runs
    // on the CPU threads the clock already sees. The bench then times with the CPU clock
    // around glFinish per pass (bench/runner/SectionTimer) instead of queries.
    bool timerQueriesUntrustworthy = false;
};

// Reads GL_VERSION / GL_RENDERER of the current context.
DriverQuirks detectDriverQuirks();

} // namespace pb::gl
