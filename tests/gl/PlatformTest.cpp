// The context backends: each headless one gives a context that really renders, reports sane
// caps, and has GL errors caught; plus device selection and error messages.
#include "gl/GlTestFixture.h"
#include "support/TestEnv.h"

#include <glad/gl.h>
#include <gtest/gtest-spi.h>

#include <array>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace pb::test {
namespace {

using Rgba = std::array<int, 4>;
constexpr int kSize = 32;
constexpr Rgba kClear = {51, 102, 153, 255};   // glClearColor(0.2, 0.4, 0.6, 1)
constexpr Rgba kTriangle = {255, 128, 0, 255}; // the fragment shader's colour

// GLSL ES 3.00 on both APIs: desktop core takes it through ARB_ES3_compatibility.
const char* kPlatformVertex = R"(#version 300 es
void main() {
    // Lower-left half of the viewport: (-1,-1), (1,-1), (-1,1).
    gl_Position = vec4(gl_VertexID == 1 ? 1.0 : -1.0, gl_VertexID == 2 ? 1.0 : -1.0, 0.0, 1.0);
}
)";
const char* kPlatformFragment = R"(#version 300 es
precision mediump float;
out vec4 color;
void main() { color = vec4(1.0, 0.5, 0.0, 1.0); }
)";

GLuint platformCompile(GLenum stage, const char* source) {
    GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        ADD_FAILURE() << "shader compile failed: " << log;
    }
    return shader;
}

// Clears an FBO (RGBA8 unless told), draws one triangle into it and reads every pixel back.
std::vector<std::uint8_t> renderTestImage(GLenum internalFormat = GL_RGBA8) {
    GLuint tex = 0, fbo = 0, vao = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), kSize, kSize, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));

    GLuint vs = platformCompile(GL_VERTEX_SHADER, kPlatformVertex),
           fs = platformCompile(GL_FRAGMENT_SHADER, kPlatformFragment);
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    EXPECT_TRUE(linked);

    glViewport(0, 0, kSize, kSize);
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glGenVertexArrays(1, &vao); // desktop core has no default vertex array
    glBindVertexArray(vao);
    glUseProgram(program);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<std::uint8_t> pixels(kSize * kSize * 4, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());

    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
    return pixels;
}

void expectPixel(const std::vector<std::uint8_t>& pixels, int x, int y, const Rgba& want) {
    const std::uint8_t* p = &pixels[static_cast<size_t>((y * kSize + x) * 4)];
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(p[c], want[static_cast<size_t>(c)], 1)
            << "pixel (" << x << "," << y << ") channel " << c;
}

void expectTestImage(const std::vector<std::uint8_t>& pixels) {
    expectPixel(pixels, 4, 4, kTriangle);              // inside the triangle
    expectPixel(pixels, kSize - 4, kSize - 4, kClear); // outside: the clear colour
}

} // namespace

class PlatformTest : public GlBackendTest {};
PB_INSTANTIATE_HEADLESS_BACKENDS(PlatformTest);

TEST_P(PlatformTest, ContextAndCapsAreSane) {
    const gl::GlCaps& c = caps();
    EXPECT_EQ(platform().name(), GetParam());
    EXPECT_FALSE(platform().description().empty());
    EXPECT_FALSE(c.version.empty());
    EXPECT_FALSE(c.renderer.empty());
    EXPECT_FALSE(c.glslVersion.empty());
    EXPECT_EQ(c.es, platform().api() == platform::GlApi::GLES);
    EXPECT_GE(c.major, 3);
    EXPECT_TRUE(c.renderRgba16f) << "half-float render targets are required";
    EXPECT_TRUE(c.khrDebug);
    EXPECT_GE(c.maxTextureSize, 2048);
    EXPECT_GE(c.maxArrayLayers, 256);
    EXPECT_FALSE(c.extensions.empty());
    const nlohmann::json j = gl::toJson(c);
    for (const char* key :
         {"version", "renderer", "vendor", "glsl_version", "capabilities", "limits", "extensions"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_NE(gl::toText(c).find("RGBA16F colour-renderable"), std::string::npos);
}

TEST_P(PlatformTest, ClearsAndDrawsIntoAnFbo) {
    expectTestImage(renderTestImage());
}

// ES always sRGB-encodes writes to an sRGB attachment; desktop core only with
// GL_FRAMEBUFFER_SRGB, which the osmesa backend enables (platforms/EsSemantics.h).
TEST_P(PlatformTest, EncodesWritesToSrgbTargetsAsOnEs) {
    const auto pixels = renderTestImage(GL_SRGB8_ALPHA8);
    expectPixel(pixels, 4, 4, {255, 188, 0, 255}); // 0.5 linear is 188 in sRGB
}

TEST_P(PlatformTest, DebugOutputCatchesABadCall) {
    EXPECT_TRUE(debugOutput().callbackInstalled());
    glEnable(0xBAD); // not a capability: GL_INVALID_ENUM
    const auto errors = takeGlErrors();
    ASSERT_FALSE(errors.empty());
    EXPECT_FALSE(errors[0].fromGetError) << "expected the KHR_debug callback to report it";
    EXPECT_NE(gl::DebugOutput::format(errors).find("GL_INVALID_ENUM"), std::string::npos)
        << gl::DebugOutput::format(errors);
}

TEST_P(PlatformTest, PollingCatchesABadCallWithoutTheCallback) {
    gl::DebugOutput polling(gl::DebugOutput::Mode::PollingOnly);
    const std::uint64_t mark = polling.mark();
    glDisable(0xBAD); // not a capability: GL_INVALID_ENUM
    const auto errors = polling.errorsSince(mark);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_TRUE(errors[0].fromGetError);
    EXPECT_EQ(errors[0].id, GLuint(GL_INVALID_ENUM));
    takeGlErrors(); // the fixture's callback saw it too
}

TEST_P(PlatformTest, FixtureFailsTheTestOnAGlError) {
    static GlTest* self; // EXPECT_NONFATAL_FAILURE cannot capture `this`
    self = this;
    glEnable(0xBAD);
    EXPECT_NONFATAL_FAILURE(self->checkNoGlErrors("after the bad call"), "GL_INVALID_ENUM");
}

TEST_P(PlatformTest, CapsQueryLeavesBindingsAlone) {
    GLuint tex = 0, fbo = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl::queryCaps();
    GLint boundTex = 0, boundDraw = 0, boundRead = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &boundTex);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &boundDraw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &boundRead);
    EXPECT_EQ(GLuint(boundTex), tex);
    EXPECT_EQ(GLuint(boundDraw), fbo);
    EXPECT_EQ(GLuint(boundRead), fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
}

TEST(PlatformFactory, RejectsAnUnknownName) {
    platform::PlatformOptions o;
    o.name = "nonsense";
    try {
        platform::createPlatform(o);
        FAIL() << "expected a PlatformError";
    } catch (const platform::PlatformError& e) {
        EXPECT_NE(std::string(e.what()).find("'nonsense'"), std::string::npos) << e.what();
    }
}

TEST(PlatformFactory, NamesEveryBackend) {
    EXPECT_EQ(platform::platformNames(), (std::vector<std::string>{"egl", "osmesa", "glfw"}));
}

TEST(EglPlatform, ListsDevices) {
    const auto devices = platform::listEglDevices();
    if (devices.empty()) GTEST_SKIP() << "libEGL has no EGL_EXT_device_enumeration";
    for (size_t i = 0; i < devices.size(); ++i) {
        EXPECT_EQ(devices[i].index, int(i));
        EXPECT_FALSE(devices[i].name.empty());
    }
}

TEST(EglPlatform, OpensTheDeviceAskedFor) {
    const auto devices = platform::listEglDevices();
    if (devices.empty()) GTEST_SKIP() << "libEGL has no EGL_EXT_device_enumeration";
    // The software device is the one every Mesa machine can open.
    int index = devices.back().index;
    for (const auto& d : devices)
        if (d.software) index = d.index;
    platform::PlatformOptions o;
    o.device = index;
    const auto p = platform::createPlatform(o);
    EXPECT_NE(p->description().find("device " + std::to_string(index)), std::string::npos)
        << p->description();
    EXPECT_FALSE(gl::queryCaps().version.empty());
}

TEST(EglPlatform, NamesAMissingDevice) {
    platform::PlatformOptions o;
    o.device = 99;
    try {
        platform::createPlatform(o);
        FAIL() << "expected a PlatformError";
    } catch (const platform::PlatformError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("egl: ", 0), 0u) << what;
        EXPECT_NE(what.find("99"), std::string::npos) << what;
    }
}

TEST(OsMesaPlatform, RejectsADeviceIndex) {
    platform::PlatformOptions o;
    o.name = "osmesa";
    o.device = 0;
    EXPECT_THROW(platform::createPlatform(o), platform::PlatformError);
}

TEST(GlfwPlatform, WithoutADisplayPointsToXvfbRun) {
    // Restores the environment for any test that runs after this one in the same process.
    struct SavedEnv {
        std::string name;
        std::optional<std::string> value;
        explicit SavedEnv(const char* n) : name(n) {
            if (const char* v = std::getenv(n)) value = v;
            unsetenv(n);
        }
        ~SavedEnv() {
            if (value) setenv(name.c_str(), value->c_str(), 1);
        }
    } display("DISPLAY"), wayland("WAYLAND_DISPLAY");
    platform::PlatformOptions o;
    o.name = "glfw";
    try {
        platform::createPlatform(o);
        FAIL() << "expected a PlatformUnavailable";
    } catch (const platform::PlatformUnavailable& e) {
        EXPECT_NE(std::string(e.what()).find("xvfb-run -a"), std::string::npos) << e.what();
    }
}

// Runs only where there is a display (e.g. `xvfb-run -a ctest -R Glfw`); InfoCli covers glfw
// under xvfb-run in every ctest run.
TEST(GlfwPlatform, OpensAWindowWhenADisplayExists) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (run under xvfb-run -a)";
    platform::PlatformOptions o;
    o.name = "glfw";
    o.width = 320;
    o.height = 200;
    const auto p = platform::createPlatform(o);
    EXPECT_TRUE(p->isWindowed());
    int w = 0, h = 0;
    p->framebufferSize(w, h);
    EXPECT_EQ(w, 320);
    EXPECT_EQ(h, 200);
    platform::InputState input;
    p->pollEvents(input);
    EXPECT_FALSE(input.quit);
    EXPECT_EQ(input.mouseDx, 0.0);
    expectTestImage(renderTestImage());
    p->swapBuffers();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Can EGL and OSMesa contexts exist one after the other in one process? (platforms/README.md)
TEST(PlatformSequence, EglThenOsMesaThenEglAllRender) {
    for (const char* name : {"egl", "osmesa", "egl"}) {
        SCOPED_TRACE(name);
        platform::PlatformOptions o;
        o.name = name;
        std::unique_ptr<platform::Platform> p;
        try {
            p = platform::createPlatform(o);
        } catch (const platform::PlatformUnavailable& e) {
            if (underCi()) FAIL() << e.what();
            GTEST_SKIP() << e.what();
        }
        gl::DebugOutput debug;
        expectTestImage(renderTestImage());
        EXPECT_EQ(debug.errorCountSince(0), 0u) << gl::DebugOutput::format(debug.errorsSince(0));
    }
}

// Both alive at once: makeCurrent switches the thread between them (and reloads glad).
TEST(PlatformSequence, EglAndOsMesaAliveTogetherSwitchWithMakeCurrent) {
    platform::PlatformOptions eglOptions, osmesaOptions;
    osmesaOptions.name = "osmesa";
    auto egl = platform::createPlatform(eglOptions);
    std::unique_ptr<platform::Platform> osmesa;
    try {
        osmesa = platform::createPlatform(osmesaOptions);
    } catch (const platform::PlatformUnavailable& e) {
        if (underCi()) FAIL() << e.what();
        GTEST_SKIP() << e.what();
    }
    auto isEs = [] { return gl::queryCaps().es; };
    EXPECT_FALSE(isEs());
    egl->makeCurrent();
    EXPECT_TRUE(isEs());
    expectTestImage(renderTestImage());
    osmesa->makeCurrent();
    EXPECT_FALSE(isEs());
    expectTestImage(renderTestImage());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    osmesa.reset();
    egl->makeCurrent();
    EXPECT_TRUE(isEs());
    expectTestImage(renderTestImage());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

} // namespace pb::test
