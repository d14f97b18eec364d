#pragma once
// Desktop GL core contexts (osmesa, glfw) run the same GLSL ES 3.00 shaders and the same
// renderer as the ES path, so they switch on the state that ES 3 has fixed:
//  - GL_FRAMEBUFFER_SRGB: ES always sRGB-encodes writes to an SRGB8_ALPHA8 attachment; desktop
//    GL only when enabled. Off, an sRGB GBuffer channel reads back darker (gamma applied once).
//  - GL_TEXTURE_CUBE_MAP_SEAMLESS: ES 3 cube maps always filter across faces.
//  - GL_PRIMITIVE_RESTART_FIXED_INDEX: ES 3 always restarts at the all-ones index.
// Set once at context creation; it is context state, not something a pass changes.
namespace pb::platform {

void enableEsSemantics();

} // namespace pb::platform
