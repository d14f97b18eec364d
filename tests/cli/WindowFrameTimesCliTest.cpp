// The window mode prints its frame-time percentiles when it closes, as glmark2 does (issue 25,
// item 10): under Xvfb, `render --platform glfw --frames N` shows N frames and reports N - 1
// frame-to-frame times (the first frame compiles shaders). The figures are only checked for
// being ordered and positive: timings are never pass/fail.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace pb::test;

TEST(WindowFrameTimesCli, TheWindowPrintsFrameTimePercentilesAtExit) {
    if (runCommand({"sh", "-c", "command -v xvfb-run"}).exitCode != 0) {
        if (underCi()) FAIL() << "xvfb-run missing under CI (test.sh installs xvfb)";
        GTEST_SKIP() << "xvfb-run not installed";
    }
    const CommandResult r =
        runCommand({"xvfb-run", "-a", binaryPath().string(), "render", "--platform", "glfw",
                    "--scene", "cornell", "--width", "64", "--height", "36", "--frames", "6"});
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::size_t at = r.output.find("window: ");
    ASSERT_NE(at, std::string::npos) << r.output;
    int frames = 0;
    double p50 = 0, p90 = 0, p99 = 0;
    ASSERT_EQ(std::sscanf(r.output.c_str() + at,
                          "window: %d frames, frame time p50 %lf ms, p90 %lf ms, p99 %lf ms",
                          &frames, &p50, &p90, &p99),
              4)
        << r.output;
    EXPECT_EQ(frames, 5) << "6 frames shown, the first not counted";
    EXPECT_GT(p50, 0.0);
    EXPECT_LE(p50, p90);
    EXPECT_LE(p90, p99);
}
