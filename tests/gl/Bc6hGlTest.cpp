// The CPU BC6H decoder (renderer/probes/bc6h/Bc6hDecoder.cpp) against the GL implementation's:
// blocks are uploaded with glCompressedTexImage2D(GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT),
// every texel is copied by texelFetch into an RGBA32F target and read back as float. BC6H
// decoding is bit-exact by specification and a half float converts to float exactly, so the
// two must agree bit for bit. Covers what the encoder writes and random blocks of every mode
// (including the decoder-only two-region modes and the reserved codes).
#include "gl/GlTestFixture.h"

#include "probes/bc6h/Bc6h.h"

#include <glad/gl.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace pb::test {
namespace {

using probes::Bc6hQuality;

const char* kVertex = R"(#version 300 es
void main() {
    // One triangle covering the viewport.
    gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
)";
const char* kFragment = R"(#version 300 es
precision highp float;
uniform highp sampler2D tex;
out vec4 color;
void main() { color = vec4(texelFetch(tex, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
)";

GLuint compile(GLenum stage, const char* source) {
    const GLuint shader = glCreateShader(stage);
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

// The GL's decode of `blocks` (width x height texels) as RGB floats, row-major.
std::vector<float> gpuDecode(const std::vector<std::uint8_t>& blocks, int width, int height) {
    GLuint tex = 0, target = 0, fbo = 0, vao = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT, width, height,
                           0, static_cast<GLsizei>(blocks.size()), blocks.data());

    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));

    const GLuint vs = compile(GL_VERTEX_SHADER, kVertex);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragment);
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    EXPECT_TRUE(linked);

    glGenVertexArrays(1, &vao); // desktop core draws nothing without one
    glBindVertexArray(vao);
    glUseProgram(program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glUniform1i(glGetUniformLocation(program, "tex"), 0);
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<float> rgba(static_cast<std::size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());

    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteVertexArrays(1, &vao);
    glDeleteProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &target);
    glDeleteTextures(1, &tex);

    std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
    for (std::size_t t = 0; t < rgb.size() / 3; ++t)
        for (int c = 0; c < 3; ++c)
            rgb[t * 3 + c] = rgba[t * 4 + c];
    return rgb;
}

std::uint32_t bitsOf(float v) {
    std::uint32_t u = 0;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

// Compares bit for bit; lists the first few differences with their block and its first byte
// (the mode code lives in its low bits).
void expectSameDecode(const std::vector<std::uint8_t>& blocks, int width, int height) {
    const std::vector<float> cpu = probes::decodeBc6hUf16(blocks.data(), width, height);
    const std::vector<float> gpu = gpuDecode(blocks, width, height);
    ASSERT_EQ(cpu.size(), gpu.size());
    std::size_t mismatches = 0;
    std::ostringstream first;
    for (std::size_t i = 0; i < cpu.size(); ++i) {
        if (bitsOf(cpu[i]) == bitsOf(gpu[i])) continue;
        if (++mismatches <= 8) {
            const int t = static_cast<int>(i / 3), x = t % width, y = t / width;
            const int block = (y / 4) * (width / 4) + x / 4;
            first << "  texel (" << x << "," << y << ") channel " << i % 3 << ": cpu " << cpu[i]
                  << " gpu " << gpu[i] << " (block " << block << ", byte0 0x" << std::hex
                  << int(blocks[block * 16]) << std::dec << ")\n";
        }
    }
    EXPECT_EQ(mismatches, 0u) << "of " << cpu.size() << " channel values differ:\n" << first.str();
}

class Bc6hGlTest : public GlBackendTest {
protected:
    void SetUp() override {
        GlBackendTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        if (!caps().bptc) GTEST_SKIP() << "no BPTC texture support on " << caps().renderer;
        if (!caps().renderRgba32f) GTEST_SKIP() << "RGBA32F not renderable";
    }
};

// What the bake uploads: encoder output for HDR data with gradients, hard edges, noise,
// zeros and clamped values.
TEST_P(Bc6hGlTest, EncoderOutputDecodesIdenticallyOnGpu) {
    const int w = 64, h = 64;
    std::mt19937 rng(42);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> src(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float* p = &src[(static_cast<std::size_t>(y) * w + x) * 3];
            const int region = (y / 16) * 4 + x / 16;
            if (region % 4 == 0) { // smooth HDR gradient
                p[0] = std::pow(10.0f, -3.0f + 7.0f * x / w);
                p[1] = 0.2f + y / 16.0f;
                p[2] = 1.0f + 0.5f * std::sin(x * 0.3f);
            } else if (region % 4 == 1) { // hard edge, like a depth discontinuity
                const float d = (x + y) % 7 < 3 ? 0.5f : 20.0f;
                p[0] = d;
                p[1] = d * d;
                p[2] = 0.0f;
            } else if (region % 4 == 2) { // noise over 7 decades
                for (int c = 0; c < 3; ++c)
                    p[c] = std::pow(10.0f, -3.0f + 7.0f * u(rng));
            } else { // zeros, maxima and values the encoder clamps
                const float special[] = {0.0f, -1.0f, 65504.0f, 1e9f, 1e-7f, 6e-5f};
                for (int c = 0; c < 3; ++c)
                    p[c] = special[(x + 2 * y + c) % 6];
            }
        }
    }
    for (Bc6hQuality q : {Bc6hQuality::Fast, Bc6hQuality::Normal, Bc6hQuality::High}) {
        SCOPED_TRACE("quality " + std::to_string(static_cast<int>(q)));
        expectSameDecode(probes::encodeBc6hUf16(src.data(), w, h, 3, q), w, h);
    }
}

// Random bits under each of the 14 mode codes and the 4 reserved ones: checks every bit
// layout, partition, anchor, delta and unquantisation path of the decoder, not only those
// the encoder happens to choose.
TEST_P(Bc6hGlTest, RandomBlocksOfEveryModeDecodeIdenticallyOnGpu) {
    const int codes[] = {0, 1, 2, 6, 10, 14, 18, 22, 26, 30, 3, 7, 11, 15, 19, 23, 27, 31};
    const int blocksPerCode = 32;
    const int blocksX = 16;
    const int count = static_cast<int>(std::size(codes)) * blocksPerCode; // 576 = 16 x 36
    std::mt19937 rng(2024);
    std::vector<std::uint8_t> blocks(static_cast<std::size_t>(count) * 16);
    for (int b = 0; b < count; ++b) {
        for (int i = 0; i < 16; ++i)
            blocks[b * 16 + i] = static_cast<std::uint8_t>(rng());
        const int code = codes[b / blocksPerCode];
        const int bits = code < 2 ? 2 : 5;
        blocks[b * 16] = static_cast<std::uint8_t>((blocks[b * 16] & ~((1 << bits) - 1)) | code);
    }
    expectSameDecode(blocks, blocksX * 4, count / blocksX * 4);
}

PB_INSTANTIATE_HEADLESS_BACKENDS(Bc6hGlTest);

} // namespace
} // namespace pb::test
