#pragma once
// The GBuffer as one channel table: the FBO, the shader defines (output locations and sampler
// names) and the debug dumps are all generated from kGBufferChannels, so adding a channel is
// one line here plus its use in the shaders.
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "gl/Texture.h"

#include <array>
#include <string>
#include <vector>

namespace pb::render {

enum class ChannelEncoding { LinearColor, OctNormal, Flags };

struct GBufferChannel {
    const char* name;          // shader names: out_<name>, u_gbuffer_<name>, GBUFFER_LOC_<name>
    gl::TextureFormat format;
    ChannelEncoding encoding;  // how the debug dump decodes it
    const char* meaning;
};

inline constexpr std::array<GBufferChannel, 4> kGBufferChannels = {{
    {"albedo", gl::TextureFormat::SRGB8_A8, ChannelEncoding::LinearColor,
     "diffuse albedo, linear RGB stored sRGB-encoded"},
    {"normal", gl::TextureFormat::RG16F, ChannelEncoding::OctNormal,
     "world normal, octahedral-encoded in [-1,1]^2"},
    {"emissive", gl::TextureFormat::RGBA16F, ChannelEncoding::LinearColor,
     "emitted radiance, linear"},
    {"flags", gl::TextureFormat::R8, ChannelEncoding::Flags,
     "bit 0: dynamic object, bits 1-7: its number (DynamicObjects.h); stored as bits/255"},
}};
// Its stencil is cleared to 0 by GBufferPass and written by nothing: GiApplyPass's stencil path
// copies depth and stencil together (a plain copy) and uses that 0 as its cleared 'taken' bit.
inline constexpr gl::TextureFormat kGBufferDepthFormat = gl::TextureFormat::Depth32FStencil8;

// Flag bits written to the `flags` channel.
inline constexpr unsigned kFlagDynamic = 1u;

// GBUFFER_LOC_<name> defines for the GBuffer fill shader.
gl::Defines gbufferOutputDefines();
// First texture unit used for GBuffer channel i is firstUnit + i; depth follows the channels.
int gbufferDepthUnit(int firstUnit);

class GBuffer {
public:
    GBuffer(int width, int height);
    const gl::Texture& channel(size_t i) const { return channels_[i]; }
    const gl::Texture& depth() const { return depth_; }
    const gl::Framebuffer& framebuffer() const { return fbo_; }
    // Binds every channel (firstUnit + i) and the depth texture, and sets the u_gbuffer_* samplers.
    void bindForReading(const gl::Program& program, int firstUnit) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    std::vector<gl::Texture> channels_;
    gl::Texture depth_;
    gl::Framebuffer fbo_;
};

} // namespace pb::render
