// The bench's timing seam: FrameRenderer opens one section per pass, in pass order, each
// closed before the next opens, and sections a pass opens inside its own are nested in it.
#include "gl/GiTestProbes.h"
#include "gl/GlTestFixture.h"

#include "frame/FrameRenderer.h"

#include <algorithm>
#include <string>
#include <vector>

namespace pb::test {
namespace {

// Records begin/end events as "+name" / "-name".
class RecordingTimer : public render::FrameTimer {
public:
    std::vector<std::string> events;
    void begin(const char* s) override { events.push_back(std::string("+") + s); }
    void end(const char* s) override { events.push_back(std::string("-") + s); }
};

using FrameTimerTest = GlTest;

TEST_F(FrameTimerTest, EveryPassIsOneBalancedSectionInPassOrder) {
    const scene::Scene& s = giTestScene();
    render::GiOptions gi;
    gi.probes = &giTestProbes(probes::StorageFormat::Rgba16f);
    render::FrameRenderer r(s, render::defaultFrameSettings(s), gi);
    RecordingTimer timer;
    r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 64, 36), &timer);

    // Top-level sections are exactly the passes, in order; inner ones are balanced.
    std::vector<std::string> topLevel, open;
    for (const auto& e : timer.events) {
        if (e[0] == '+') {
            if (open.empty()) topLevel.push_back(e.substr(1));
            open.push_back(e.substr(1));
        } else {
            ASSERT_FALSE(open.empty()) << "end without begin: " << e;
            EXPECT_EQ(open.back(), e.substr(1)) << "sections overlap";
            open.pop_back();
        }
    }
    EXPECT_TRUE(open.empty());
    std::vector<std::string> passes;
    for (const auto& p : r.passes())
        passes.push_back(p->name());
    EXPECT_EQ(topLevel, passes);
    EXPECT_NE(std::find(passes.begin(), passes.end(), "gi-apply"), passes.end());

    // Without a timer the same frame renders (the seam is optional).
    r.render(render::makeRenderView(*s.findView("sunlit_room"), s.worldBounds(), 64, 36));
}

} // namespace
} // namespace pb::test
