#include "gl/Capabilities.h"

#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace pb::gl {
namespace {

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

int glInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

// Bindings the probes change, restored on scope exit so the caller's state survives.
class BindingGuard {
public:
    BindingGuard()
        : drawFbo_(glInt(GL_DRAW_FRAMEBUFFER_BINDING)),
          readFbo_(glInt(GL_READ_FRAMEBUFFER_BINDING)), texture_(glInt(GL_TEXTURE_BINDING_2D)),
          unpack_(glInt(GL_PIXEL_UNPACK_BUFFER_BINDING)) {
        // A bound unpack buffer would turn the null data pointers below into buffer offsets.
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }
    ~BindingGuard() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFbo_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFbo_));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_));
    }
    BindingGuard(const BindingGuard&) = delete;
    BindingGuard& operator=(const BindingGuard&) = delete;

private:
    GLint drawFbo_, readFbo_, texture_, unpack_;
};

struct Format {
    GLenum internal, format, type;
};

GLuint makeTexture(const Format& f) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(f.internal), 4, 4, 0, f.format, f.type,
                 nullptr);
    return tex;
}

// Whether an FBO with `color` (and optionally `depth`) attachments is complete.
bool fboComplete(const Format& color, const Format* depthStencil) {
    GLuint textures[2] = {makeTexture(color), depthStencil ? makeTexture(*depthStencil) : 0};
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures[0], 0);
    if (depthStencil)
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               textures[1], 0);
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(depthStencil ? 2 : 1, textures);
    return complete;
}

bool isSoftwareRenderer(const std::string& renderer) {
    for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

} // namespace

bool GlCaps::hasExtension(std::string_view name) const {
    return std::binary_search(extensions.begin(), extensions.end(), name);
}

GlCaps queryCaps() {
    GlCaps c;
    c.version = glString(GL_VERSION);
    c.renderer = glString(GL_RENDERER);
    c.vendor = glString(GL_VENDOR);
    c.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    // Parsed here rather than taken from glad's GLAD_GL_* flags: after one backend loaded
    // desktop GL and another GLES in the same process, the other API's flags are stale.
    c.es = c.version.rfind("OpenGL ES", 0) == 0;
    c.major = glInt(GL_MAJOR_VERSION);
    c.minor = glInt(GL_MINOR_VERSION);
    const int count = glInt(GL_NUM_EXTENSIONS);
    for (int i = 0; i < count; ++i)
        if (const GLubyte* e = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)))
            c.extensions.emplace_back(reinterpret_cast<const char*>(e));
    std::sort(c.extensions.begin(), c.extensions.end());

    {
        BindingGuard guard;
        c.renderRgba16f = fboComplete({GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT}, nullptr);
        c.renderRgba32f = fboComplete({GL_RGBA32F, GL_RGBA, GL_FLOAT}, nullptr);
        c.renderR11fG11fB10f =
            fboComplete({GL_R11F_G11F_B10F, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV}, nullptr);
        c.renderRg16f = fboComplete({GL_RG16F, GL_RG, GL_HALF_FLOAT}, nullptr);
        const Format depth{GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
        c.depth24Stencil8 = fboComplete({GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE}, &depth);
    }

    if (c.es) {
        c.bptc = c.hasExtension("GL_EXT_texture_compression_bptc");
        c.timerQuery = c.hasExtension("GL_EXT_disjoint_timer_query");
        c.khrDebug = c.versionAtLeast(3, 2) || c.hasExtension("GL_KHR_debug");
        c.floatLinearFilter = c.hasExtension("GL_OES_texture_float_linear");
    } else {
        c.bptc = c.versionAtLeast(4, 2) || c.hasExtension("GL_ARB_texture_compression_bptc");
        c.timerQuery = c.versionAtLeast(3, 3) || c.hasExtension("GL_ARB_timer_query");
        c.khrDebug = c.versionAtLeast(4, 3) || c.hasExtension("GL_KHR_debug");
        c.floatLinearFilter = true; // core since GL 3.0
    }
    c.framebufferFetch = c.hasExtension("GL_EXT_shader_framebuffer_fetch");
    c.software = isSoftwareRenderer(c.renderer);

    c.maxTextureSize = glInt(GL_MAX_TEXTURE_SIZE);
    c.maxRenderbufferSize = glInt(GL_MAX_RENDERBUFFER_SIZE);
    c.maxArrayLayers = glInt(GL_MAX_ARRAY_TEXTURE_LAYERS);
    c.maxColorAttachments = glInt(GL_MAX_COLOR_ATTACHMENTS);
    c.maxDrawBuffers = glInt(GL_MAX_DRAW_BUFFERS);
    return c;
}

std::vector<GlFeature> GlCaps::features() const {
    return {
        {"render_rgba16f", "RGBA16F colour-renderable", renderRgba16f},
        {"render_rgba32f", "RGBA32F colour-renderable", renderRgba32f},
        {"render_r11f_g11f_b10f", "R11F_G11F_B10F colour-renderable", renderR11fG11fB10f},
        {"render_rg16f", "RG16F colour-renderable", renderRg16f},
        {"depth24_stencil8", "DEPTH24_STENCIL8 FBO complete", depth24Stencil8},
        {"bptc", "BPTC (BC6H/BC7) textures", bptc},
        {"timer_query", "timer queries", timerQuery},
        {"khr_debug", "KHR_debug", khrDebug},
        {"framebuffer_fetch", "EXT_shader_framebuffer_fetch", framebufferFetch},
        {"float_linear_filter", "linear filtering of 32-bit floats", floatLinearFilter},
        {"software_renderer", "software renderer", software},
    };
}

std::vector<GlLimit> GlCaps::limits() const {
    return {
        {"max_texture_size", "max texture size", maxTextureSize},
        {"max_renderbuffer_size", "max renderbuffer size", maxRenderbufferSize},
        {"max_array_texture_layers", "max array texture layers", maxArrayLayers},
        {"max_color_attachments", "max colour attachments", maxColorAttachments},
        {"max_draw_buffers", "max draw buffers", maxDrawBuffers},
    };
}

nlohmann::json toJson(const GlCaps& c) {
    nlohmann::json j;
    j["api"] = c.es ? "gles" : "gl-core";
    j["version"] = c.version;
    j["renderer"] = c.renderer;
    j["vendor"] = c.vendor;
    j["glsl_version"] = c.glslVersion;
    j["major"] = c.major;
    j["minor"] = c.minor;
    nlohmann::json features = nlohmann::json::object();
    for (const GlFeature& f : c.features())
        features[f.key] = f.value;
    j["capabilities"] = features;
    nlohmann::json limits = nlohmann::json::object();
    for (const GlLimit& l : c.limits())
        limits[l.key] = l.value;
    j["limits"] = limits;
    j["extensions"] = c.extensions;
    return j;
}

std::string toText(const GlCaps& c) {
    std::ostringstream out;
    char line[160];
    auto row = [&](const std::string& label, const std::string& value, int indent) {
        std::snprintf(line, sizeof line, "%*s%-*s %s\n", indent, "", 36 - indent, label.c_str(),
                      value.c_str());
        out << line;
    };
    row("API", c.apiName() + " " + std::to_string(c.major) + "." + std::to_string(c.minor), 0);
    row("GL_VERSION", c.version, 0);
    row("GL_RENDERER", c.renderer, 0);
    row("GL_VENDOR", c.vendor, 0);
    row("GL_SHADING_LANGUAGE_VERSION", c.glslVersion, 0);
    out << "capabilities:\n";
    for (const GlFeature& f : c.features())
        row(f.label, f.value ? "yes" : "no", 2);
    out << "limits:\n";
    for (const GlLimit& l : c.limits())
        row(l.label, std::to_string(l.value), 2);
    row("extensions", std::to_string(c.extensions.size()), 0);
    return out.str();
}

} // namespace pb::gl
