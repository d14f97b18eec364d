#include "gl/GlTestFixture.h"
#include "support/TestEnv.h"

#include <cstdlib>

namespace pb::test {

platform::PlatformOptions GlTest::platformOptions() const {
    platform::PlatformOptions o;
    if (const char* name = std::getenv("PB_GL_PLATFORM"); name && *name) o.name = name;
    return o;
}

void GlTest::SetUp() {
    try {
        platform_ = platform::createPlatform(platformOptions());
    } catch (const platform::PlatformUnavailable& e) {
        if (underCi()) FAIL() << "GL platform unavailable under CI: " << e.what();
        GTEST_SKIP() << e.what();
    } catch (const platform::PlatformError& e) {
        FAIL() << "cannot create the GL platform: " << e.what();
    }
    debug_ = std::make_unique<gl::DebugOutput>();
    mark_ = 0; // errors the context had before the test started count too
}

void GlTest::TearDown() {
    if (debug_) checkNoGlErrors("at the end of the test");
    debug_.reset();
    platform_.reset();
}

const gl::GlCaps& GlTest::caps() {
    if (!caps_) caps_ = gl::queryCaps();
    return *caps_;
}

void GlTest::checkNoGlErrors(const std::string& where) {
    const std::vector<gl::DebugMessage> errors = takeGlErrors();
    if (!errors.empty())
        ADD_FAILURE() << errors.size() << " GL error(s)" << (where.empty() ? "" : " ") << where
                      << " on " << platform_->name() << ":\n"
                      << gl::DebugOutput::format(errors);
}

std::vector<gl::DebugMessage> GlTest::takeGlErrors() {
    std::vector<gl::DebugMessage> errors = debug_->errorsSince(mark_);
    mark_ = debug_->mark();
    return errors;
}

platform::PlatformOptions OsMesaGlTest::platformOptions() const {
    platform::PlatformOptions o;
    o.name = "osmesa";
    return o;
}

platform::PlatformOptions GlBackendTest::platformOptions() const {
    platform::PlatformOptions o;
    o.name = GetParam();
    return o;
}

} // namespace pb::test
