#include "passes/GBufferLayout.h"

#include "gl/Program.h"

namespace pb::render {

gl::Defines gbufferOutputDefines() {
    gl::Defines d;
    for (size_t i = 0; i < kGBufferChannels.size(); ++i)
        d[std::string("GBUFFER_LOC_") + kGBufferChannels[i].name] = std::to_string(i);
    return d;
}

int gbufferDepthUnit(int firstUnit) { return firstUnit + int(kGBufferChannels.size()); }

namespace {
std::vector<gl::Texture> makeChannels(int w, int h) {
    std::vector<gl::Texture> v;
    for (const auto& c : kGBufferChannels)
        v.push_back(gl::nearestTexture(c.format, w, h));
    return v;
}

std::vector<const gl::Texture*> pointers(const std::vector<gl::Texture>& v) {
    std::vector<const gl::Texture*> p;
    for (const auto& t : v) p.push_back(&t);
    return p;
}
} // namespace

GBuffer::GBuffer(int width, int height)
    : width_(width), height_(height), channels_(makeChannels(width, height)),
      depth_(gl::nearestTexture(kGBufferDepthFormat, width, height)),
      fbo_("gbuffer", pointers(channels_), &depth_) {
    for (size_t i = 0; i < channels_.size(); ++i)
        channels_[i].label(std::string("gbuffer ") + kGBufferChannels[i].name);
    depth_.label("gbuffer depth");
}

void GBuffer::bindForReading(const gl::Program& program, int firstUnit) const {
    for (size_t i = 0; i < channels_.size(); ++i) {
        channels_[i].bind(firstUnit + int(i));
        program.set(std::string("u_gbuffer_") + kGBufferChannels[i].name, firstUnit + int(i));
    }
    depth_.bind(gbufferDepthUnit(firstUnit));
    program.set("u_gbuffer_depth", gbufferDepthUnit(firstUnit));
}

} // namespace pb::render
