#pragma once
// The base fixture for every GL test: a current context and a GL error check.
//
//   class MyPassTest : public pb::test::GlTest {};          // egl (or $PB_GL_PLATFORM)
//   TEST_F(MyPassTest, Draws) { ... GL calls ...; }          // any GL error fails the test
//
// SetUp creates the platform (egl by default, OsMesaGlTest for osmesa, GlBackendTest to run
// one test on each headless backend) and installs pb::gl::DebugOutput. TearDown fails the
// test, listing the messages, if the GL reported any error (KHR_debug or glGetError) during
// it. checkNoGlErrors("after upload") checks at a point of your choosing; a test that provokes
// an error on purpose collects it with takeGlErrors(), so TearDown does not count it.
// A backend whose library is missing (OSMesa left Mesa 25.1) skips, except under CI=true.
// Environment: PB_GL_PLATFORM=osmesa runs every GlTest on another backend.
#include "gl/Capabilities.h"
#include "gl/DebugOutput.h"
#include "platforms/Platform.h"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pb::test {

class GlTest : public ::testing::Test {
protected:
    // Which backend and options; override to change them.
    virtual platform::PlatformOptions platformOptions() const;

    void SetUp() override;
    void TearDown() override;

public: // helpers tests call (public so gtest's EXPECT_*_FAILURE statements can reach them)
    platform::Platform& platform() { return *platform_; }
    gl::DebugOutput& debugOutput() { return *debug_; }
    const gl::GlCaps& caps(); // queried on first use

    // Adds a (non-fatal) test failure listing the GL errors since the last check, then moves
    // the mark past them.
    void checkNoGlErrors(const std::string& where = "");

    // The GL errors since the last check, which then no longer fail the test.
    std::vector<gl::DebugMessage> takeGlErrors();

private:
    std::unique_ptr<platform::Platform> platform_;
    std::unique_ptr<gl::DebugOutput> debug_; // destroyed before platform_ (needs the context)
    std::optional<gl::GlCaps> caps_;
    std::uint64_t mark_ = 0;
};

// The same fixture on OSMesa's desktop GL core context.
class OsMesaGlTest : public GlTest {
protected:
    platform::PlatformOptions platformOptions() const override;
};

// Runs a TEST_P once per headless backend:
//   class MyTest : public pb::test::GlBackendTest {};
//   TEST_P(MyTest, X) { ... }
//   PB_INSTANTIATE_HEADLESS_BACKENDS(MyTest);
class GlBackendTest : public GlTest, public ::testing::WithParamInterface<std::string> {
protected:
    platform::PlatformOptions platformOptions() const override;
};

} // namespace pb::test

#define PB_INSTANTIATE_HEADLESS_BACKENDS(suite)                                                    \
    INSTANTIATE_TEST_SUITE_P(Backends, suite, ::testing::Values("egl", "osmesa"),                  \
                             [](const auto& info) { return info.param; })
