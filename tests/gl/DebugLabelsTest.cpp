// What a GL capture (RenderDoc, Nsight, apitrace) shows of a frame (issue 25, item 10): every
// FrameTimer section is a debug group of the same name, timer or not, balanced and nested as
// the sections are; the main textures, framebuffers and programs carry labels. Read back
// through KHR_debug itself: the push-group messages and glGetObjectLabel.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"
#include "support/TestEnv.h"

#include "frame/FrameRenderer.h"
#include "gl/DebugLabels.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "passes/FrameContext.h"

#include <string>
#include <vector>

namespace pb::test {
namespace {

GLint groupDepth() {
    GLint depth = -1;
    glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
    return depth;
}

// Records each section as "+name" / "-name" with the debug group depth at its begin.
class DepthTimer : public render::FrameTimer {
public:
    std::vector<std::string> events;
    std::vector<GLint> depthAtBegin;
    void begin(const char* s) override {
        events.push_back(std::string("+") + s);
        depthAtBegin.push_back(groupDepth());
    }
    void end(const char* s) override { events.push_back(std::string("-") + s); }
};

// The debug-group pushes and pops the GL reported since `mark`, as "+name" / "-name".
std::vector<std::string> groupMessages(gl::DebugOutput& out, std::uint64_t mark) {
    std::vector<std::string> events;
    for (const gl::DebugMessage& m : out.messagesSince(mark))
        if (m.type == GL_DEBUG_TYPE_PUSH_GROUP)
            events.push_back("+" + m.text);
        else if (m.type == GL_DEBUG_TYPE_POP_GROUP)
            events.push_back("-" + m.text);
    return events;
}

class DebugLabelsTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (!debugOutput().callbackInstalled()) {
            if (underCi()) FAIL() << "no KHR_debug callback on this context";
            GTEST_SKIP() << "no KHR_debug callback on this context";
        }
    }
};

TEST_F(DebugLabelsTest, EverySectionIsADebugGroupOfTheSameName) {
    const scene::Scene& s = giTestScene();
    render::GiOptions gi;
    gi.probes = &giTestProbes(probes::StorageFormat::Rgba16f);
    gi.profile.gi.multiVolume = profile::GiMultiVolume::Stencil; // nested gi-fill sections
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    const render::RenderView view =
        render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 64, 36);
    ASSERT_EQ(groupDepth(), 1) << "only the default group before the frame";

    DepthTimer timer;
    std::uint64_t mark = debugOutput().mark();
    r.render(view, &timer);
    // The groups the GL saw are the sections, in the same order and nesting.
    EXPECT_EQ(groupMessages(debugOutput(), mark), timer.events);
    bool nested = false;
    for (const std::string& e : timer.events)
        nested = nested || e == "+gi-fill";
    EXPECT_TRUE(nested) << "the stencil fill's sections nest inside gi-apply";
    // Each section begins inside its own group: depth 1 (default) + its nesting level.
    int level = 0;
    for (std::size_t i = 0, b = 0; i < timer.events.size(); ++i) {
        if (timer.events[i][0] == '+') {
            ++level;
            EXPECT_EQ(timer.depthAtBegin[b++], 1 + level) << timer.events[i];
        } else {
            --level;
        }
    }
    EXPECT_EQ(groupDepth(), 1) << "every group popped";

    // Without a timer (render, the window, a capture of either) the groups are the same.
    mark = debugOutput().mark();
    r.render(view);
    EXPECT_EQ(groupMessages(debugOutput(), mark), timer.events);
}

TEST_F(DebugLabelsTest, MainObjectsCarryLabels) {
    const render::FrameTargets targets(16, 16);
    EXPECT_EQ(gl::objectLabel(GL_TEXTURE, targets.radiance.id()), "radiance");
    EXPECT_EQ(gl::objectLabel(GL_TEXTURE, targets.output.id()), "output");
    EXPECT_EQ(gl::objectLabel(GL_FRAMEBUFFER, targets.radianceFbo.id()), "radiance");
    EXPECT_EQ(gl::objectLabel(GL_FRAMEBUFFER, targets.gbuffer.framebuffer().id()), "gbuffer");

    const gl::Program program("fullscreen.vert", "composite_tonemap.frag", {});
    GLint id = 0;
    program.use();
    glGetIntegerv(GL_CURRENT_PROGRAM, &id);
    glUseProgram(0);
    const std::string label = gl::objectLabel(GL_PROGRAM, GLuint(id));
    EXPECT_EQ(label.rfind("fullscreen.vert+composite_tonemap.frag", 0), 0u) << label;

    const scene::Scene& s = giTestScene();
    render::GiOptions gi;
    gi.probes = &giTestProbes(probes::StorageFormat::Rgba16f);
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 32, 18));
    ASSERT_NE(r.gpuProbes(), nullptr);
    const render::GpuProbeVolume& v = r.gpuProbes()->volumes().front();
    const std::string irradiance =
        gl::objectLabel(GL_TEXTURE, v.textures[render::kDdgiIrradiance].id());
    EXPECT_NE(irradiance.find("irradiance"), std::string::npos) << irradiance;
    EXPECT_NE(irradiance.find(gi.probes->volumes.front().name), std::string::npos) << irradiance;

    // A label longer than GL_MAX_LABEL_LENGTH is cut, not a GL error (TearDown checks).
    gl::labelObject(GL_TEXTURE, targets.output.id(), std::string(1000, 'x'));
    EXPECT_EQ(gl::objectLabel(GL_TEXTURE, targets.output.id()).size(), 255u);
}

} // namespace
} // namespace pb::test
