#pragma once
// What the current GL context can do, for the features the testbed depends on. Render-target
// formats are proven by building a small FBO, not read from extension strings, because drivers
// advertise formats they cannot render to (and vice versa on desktop GL, where no string says
// it). Everything else comes from the version and the extension list.
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace pb::gl {

struct GlFeature {
    const char* key;   // JSON key, e.g. "render_rgba16f"
    const char* label; // human text, e.g. "RGBA16F colour-renderable"
    bool value;
};

struct GlLimit {
    const char* key;
    const char* label;
    int value;
};

struct GlCaps {
    bool es = false; // OpenGL ES, else desktop core
    std::string version, renderer, vendor, glslVersion;
    int major = 0, minor = 0;
    std::vector<std::string> extensions; // sorted

    // Colour-renderable: a 4x4 texture of the format makes a complete FBO.
    bool renderRgba16f = false, renderRgba32f = false, renderR11fG11fB10f = false;
    bool renderRg16f = false;
    bool depth24Stencil8 = false;   // RGBA8 + DEPTH24_STENCIL8 texture FBO is complete
    bool bptc = false;              // BC6H/BC7 textures
    bool timerQuery = false;        // GL_TIME_ELAPSED queries
    bool khrDebug = false;          // debug message callback
    bool framebufferFetch = false;  // EXT_shader_framebuffer_fetch
    bool floatLinearFilter = false; // linear filtering of 32-bit float textures
    bool software = false;          // llvmpipe / softpipe / SwiftShader: timings are CPU timings

    int maxTextureSize = 0, maxRenderbufferSize = 0, maxArrayLayers = 0;
    int maxColorAttachments = 0, maxDrawBuffers = 0;

    bool hasExtension(std::string_view name) const;
    bool versionAtLeast(int maj, int min) const {
        return major > maj || (major == maj && minor >= min);
    }
    std::string apiName() const { return es ? "OpenGL ES" : "OpenGL core"; }

    // One table for every output (JSON, text, `probebench info`): add a feature here only.
    std::vector<GlFeature> features() const;
    std::vector<GlLimit> limits() const;
};

// Queries the current context. Creates and deletes a few small textures and FBOs, and leaves
// every binding it touches as it found it.
GlCaps queryCaps();

nlohmann::json toJson(const GlCaps& caps);
std::string toText(const GlCaps& caps); // multi-line, aligned, yes/no per feature

} // namespace pb::gl
