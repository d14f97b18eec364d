// `probebench info` as a user runs it: JSON output, each backend, and bad options.
#include "support/TestEnv.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace pb::test {
namespace {

struct RunResult {
    int exitCode = -1;
    std::string out; // stdout
    std::string err; // stderr
};

// Runs `probebench <args>` through the shell; `prefix` goes before the binary (xvfb-run).
RunResult infoRunProbebench(const std::string& args, const std::string& prefix = "") {
    const auto errFile = outputDir() / "stderr.txt";
    const std::string cmd =
        prefix + "'" + binaryPath().string() + "' " + args + " 2>'" + errFile.string() + "'";
    RunResult r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    for (size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;)
        r.out.append(buf, n);
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(errFile);
    r.err.assign(std::istreambuf_iterator<char>(err), {});
    return r;
}

bool osmesaMissing(const RunResult& r) {
    return r.exitCode != 0 && r.err.find("osmesa: cannot load") != std::string::npos;
}

} // namespace

TEST(InfoCli, JsonHasTheDriverStringsAndCapabilities) {
    const RunResult r = infoRunProbebench("info --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << "not JSON:\n" << r.out;
    for (const char* key : {"platform", "api", "version", "renderer", "vendor", "glsl_version",
                            "capabilities", "limits", "extensions"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["platform"]["name"], "egl");
    EXPECT_FALSE(j["version"].get<std::string>().empty());
    EXPECT_TRUE(j["capabilities"]["render_rgba16f"].get<bool>());
}

TEST(InfoCli, TextListsCapabilitiesAsYesNo) {
    const RunResult r = infoRunProbebench("info");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* text : {"GL_VERSION", "GL_RENDERER", "GL_VENDOR", "RGBA16F", "yes"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text << " in:\n" << r.out;
}

TEST(InfoCli, ListsTheSupportedGltfExtensions) {
    const RunResult text = infoRunProbebench("info");
    ASSERT_EQ(text.exitCode, 0) << text.err;
    for (const char* ext : {"EXT_meshopt_compression", "KHR_draco_mesh_compression",
                            "KHR_mesh_quantization", "KHR_texture_transform"})
        EXPECT_NE(text.out.find(ext), std::string::npos) << ext << " in:\n" << text.out;
    const RunResult js = infoRunProbebench("info --json");
    ASSERT_EQ(js.exitCode, 0) << js.err;
    const auto j = nlohmann::json::parse(js.out);
    ASSERT_TRUE(j.contains("gltf_extensions"));
    EXPECT_NE(j["gltf_extensions"].dump().find("KHR_draco_mesh_compression"), std::string::npos);
}

TEST(InfoCli, RunsOnOsMesa) {
    const RunResult r = infoRunProbebench("info --platform osmesa");
    if (osmesaMissing(r) && !underCi()) GTEST_SKIP() << r.err;
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("osmesa"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Core Profile"), std::string::npos) << r.out;
}

TEST(InfoCli, RejectsAnUnknownPlatform) {
    const RunResult r = infoRunProbebench("info --platform nonsense");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE((r.out + r.err).find("--platform"), std::string::npos) << r.out << r.err;
    EXPECT_NE((r.out + r.err).find("nonsense"), std::string::npos) << r.out << r.err;
}

TEST(InfoCli, NamesAMissingDevice) {
    const RunResult r = infoRunProbebench("info --device 99");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("egl: device 99"), std::string::npos) << r.err;
}

TEST(InfoCli, ListsEglDevices) {
    const RunResult r = infoRunProbebench("info --devices --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
    ASSERT_TRUE(j.is_array()) << r.out;
    for (const auto& d : j) {
        EXPECT_TRUE(d.contains("index"));
        EXPECT_TRUE(d.contains("name"));
        EXPECT_TRUE(d.contains("software"));
    }
}

TEST(InfoCli, RunsOnGlfwUnderXvfb) {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
        if (underCi()) FAIL() << "xvfb-run is missing under CI (apt install xvfb xauth)";
        GTEST_SKIP() << "xvfb-run not installed: the glfw backend needs an X server";
    }
    const RunResult r = infoRunProbebench("info --platform glfw", "xvfb-run -a ");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("glfw: GLFW"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("GL_VERSION"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Mesa"), std::string::npos) << r.out;
}

} // namespace pb::test
