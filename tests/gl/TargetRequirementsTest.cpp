// What a weak GPU lacks is said in one line naming what needs it, before the GL is asked:
// a texture past the context's limits (gl/TextureLimits.h) and a GI target format the context
// cannot render to (passes/GiApplyPass.h requireRenderableTarget). `probebench shaders` lists
// such a profile as "cannot run" on that target.
#include "gl/GlTestFixture.h"

#include "core/Error.h"
#include "gl/Texture.h"
#include "gl/TextureLimits.h"
#include "passes/GiApplyPass.h"

namespace pb::test {
namespace {

gl::TextureLimits es30Minimum() {
    return {2048, 256, 256};
} // what GL ES 3.0 guarantees

TEST(TextureLimits, ArrayLayersSidesAndVolumesAgainstTheLimits) {
    gl::TextureDesc d;
    d.width = 2048;
    d.height = 1024;
    d.layers = 256;
    EXPECT_EQ(gl::textureLimitProblem(d, es30Minimum()), "");
    d.layers = 300;
    const std::string layers = gl::textureLimitProblem(d, es30Minimum());
    EXPECT_NE(layers.find("300"), std::string::npos) << layers;
    EXPECT_NE(layers.find("GL_MAX_ARRAY_TEXTURE_LAYERS"), std::string::npos) << layers;
    d.layers = 0;
    d.width = 4096;
    EXPECT_NE(gl::textureLimitProblem(d, es30Minimum()).find("GL_MAX_TEXTURE_SIZE"),
              std::string::npos);
    gl::TextureDesc v;
    v.volume = true;
    v.width = 64;
    v.height = 64;
    v.layers = 257;
    EXPECT_NE(gl::textureLimitProblem(v, es30Minimum()).find("GL_MAX_3D_TEXTURE_SIZE"),
              std::string::npos);
    v.layers = 256; // a volume's depth is not an array's layer count
    EXPECT_EQ(gl::textureLimitProblem(v, {2048, 16, 256}), "");
}

TEST(GiTargetRequirement, AFormatTheContextCannotRenderNamesTheSwitch) {
    gl::GlCaps caps;
    caps.renderer = "Test GPU";
    caps.renderRgba16f = true;
    caps.renderR11fG11fB10f = true;
    caps.renderRgba32f = false;
    profile::Profile p;
    p.set("gi.target_format", "rgba32f");
    try {
        render::requireRenderableTarget(p, caps);
        FAIL() << "accepted rgba32f without RGBA32F rendering";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("gi.target_format=rgba32f"), std::string::npos) << m;
        EXPECT_NE(m.find("Test GPU"), std::string::npos) << m;
    }
    p.set("gi.target_format", "r11g11b10f");
    EXPECT_NO_THROW(render::requireRenderableTarget(p, caps));
    caps.renderR11fG11fB10f = false;
    EXPECT_THROW(render::requireRenderableTarget(p, caps), Error);
}

class TextureLimitsGlTest : public GlTest {};

TEST_F(TextureLimitsGlTest, ATexturePastTheLimitIsAnErrorNotAGlError) {
    const gl::TextureLimits limits = gl::queryTextureLimits();
    ASSERT_GE(limits.maxArrayLayers, 256);
    gl::TextureDesc d;
    d.format = gl::TextureFormat::RGBA16F;
    d.width = 4;
    d.height = 4;
    d.layers = limits.maxArrayLayers + 1;
    try {
        gl::Texture t(d);
        FAIL() << "created " << d.layers << " layers";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("GL_MAX_ARRAY_TEXTURE_LAYERS"), std::string::npos)
            << e.what();
    }
    d.layers = 2;
    EXPECT_NO_THROW(gl::Texture{d});
    checkNoGlErrors("after the refused texture");
}

} // namespace
} // namespace pb::test
