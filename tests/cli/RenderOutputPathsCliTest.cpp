// `render` writes each output as its name says, where it says, or fails writing nothing (issue
// 25, item 8): a missing folder needs --mkdir, the extension is the format, and the window mode
// refuses the outputs it would not write.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace pb::test;

namespace {

CommandResult renderTo(std::vector<std::string> outputs) {
    std::vector<std::string> args{"render", "--scene", "cornell", "--width", "16", "--height", "12"};
    args.insert(args.end(), outputs.begin(), outputs.end());
    return runProbebench(args);
}

void renderOutputPathsExpectOneLineError(const CommandResult& r, const std::string& text) {
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_EQ(r.output.rfind("probebench: error: ", 0), 0u) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
    EXPECT_NE(r.output.find(text), std::string::npos) << r.output;
}

} // namespace

TEST(RenderOutputPathsCli, MissingFolderIsAnErrorUnlessMkdir) {
    const fs::path dir = outputDir();
    const fs::path out = dir / "no" / "such" / "x.png";
    renderOutputPathsExpectOneLineError(renderTo({"--out", out.string()}),
                                        "does not exist (--mkdir creates it)");
    EXPECT_FALSE(fs::exists(dir / "no")) << "created the folders anyway";
    renderOutputPathsExpectOneLineError(renderTo({"--out", (dir / "x.png").string(), "--out-hdr",
                                                  (dir / "nope" / "x.pfm").string()}),
                                        "--out-hdr");
    EXPECT_FALSE(fs::exists(dir / "x.png")) << "wrote --out before refusing --out-hdr";

    const CommandResult made = renderTo({"--out", out.string(), "--mkdir"});
    EXPECT_EQ(made.exitCode, 0) << made.output;
    EXPECT_TRUE(fs::is_regular_file(out));
}

TEST(RenderOutputPathsCli, ExtensionMustBeTheFormatWritten) {
    const fs::path dir = outputDir();
    renderOutputPathsExpectOneLineError(
        renderTo({"--out", (dir / "x.jpg").string()}),
        "writes an 8-bit sRGB PNG, so the name must end in .png (not .jpg)");
    renderOutputPathsExpectOneLineError(
        renderTo({"--out", (dir / "x.png").string(), "--out-hdr", (dir / "x.exr").string()}),
        "must end in .pfm");
    EXPECT_TRUE(fs::is_empty(dir)) << "wrote something before refusing";
    const CommandResult upper = renderTo({"--out", (dir / "X.PNG").string()});
    EXPECT_EQ(upper.exitCode, 0) << upper.output;
}

TEST(RenderOutputPathsCli, WindowAndPathModesRefuseOutputsTheyWouldNotWrite) {
    // Checked before any window opens: no display needed.
    const fs::path dir = outputDir();
    renderOutputPathsExpectOneLineError(
        renderTo({"--platform", "glfw", "--out-hdr", (dir / "x.pfm").string()}),
        "--out-hdr: the window mode writes nothing at exit");
    renderOutputPathsExpectOneLineError(
        renderTo({"--platform", "glfw", "--dump-gbuffer", (dir / "gb").string()}),
        "--dump-gbuffer: the window mode writes nothing at exit");
    renderOutputPathsExpectOneLineError(
        renderTo({"--path", "static", "--frames", "1", "--out-dir", (dir / "walk").string(),
                  "--out-hdr", (dir / "x.pfm").string()}),
        "--out-hdr: not written in --path mode");
    EXPECT_TRUE(fs::is_empty(dir));
}
