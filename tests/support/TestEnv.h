#pragma once
// Paths and skip rules shared by every test suite.
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace pb::test {

inline std::filesystem::path scenesDir() { return PB_SCENES_DIR; }
inline std::filesystem::path sourceDir() { return PB_SOURCE_DIR; }
inline std::filesystem::path binaryPath() { return PB_BINARY; }
inline std::filesystem::path goldenDir() { return PB_GOLDEN_DIR; }
inline std::filesystem::path testDataDir() { return PB_TEST_DATA_DIR; }

// A fresh folder under build/test-output named after the running test.
std::filesystem::path outputDir();

inline bool underCi() {
    const char* ci = std::getenv("CI");
    return ci && std::string(ci) == "true";
}

} // namespace pb::test

// Tests that need ../shared/scenes skip with a message when it is missing, except under
// CI=true, where a missing folder is a failure (CI always has shared/ beside the clone).
#define PB_REQUIRE_SHARED_SCENES()                                                             \
    do {                                                                                       \
        if (!std::filesystem::is_directory(::pb::test::scenesDir())) {                         \
            if (::pb::test::underCi())                                                         \
                FAIL() << "shared scenes folder missing under CI: " << ::pb::test::scenesDir(); \
            GTEST_SKIP() << "shared scenes folder not found: " << ::pb::test::scenesDir()      \
                         << " (configure with -DPB_SCENES_DIR=...)";                           \
        }                                                                                      \
    } while (0)
