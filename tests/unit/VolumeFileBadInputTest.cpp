// Volumes TOML files with out-of-range values: each is one line "vols.toml:LINE: problem"
// naming the key, never an infinite or NaN volume or sun that reaches the bake.
#include "core/Error.h"
#include "probes/store/VolumeFile.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

std::string volumeFileBadInputErrorOf(const std::string& toml) {
    try {
        parseVolumeToml(toml, "vols.toml");
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        EXPECT_EQ(msg.rfind("vols.toml:", 0), 0u) << msg;
        return msg;
    }
    return "(no error)";
}

std::string volumeFileBadInputVolume(const std::string& center,
                                     const std::string& half = "[1.0, 1.0, 1.0]") {
    return "[[volume]]\nname = \"v\"\ncenter = " + center + "\nhalf_extents = " + half +
           "\nprobes = [2, 2, 2]\n";
}

std::string withSun(const std::string& sun) {
    return volumeFileBadInputVolume("[0.0, 0.0, 0.0]") +
           "[[scenario]]\nname = \"s\"\nsun = " + sun + "\n";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

} // namespace

TEST(VolumeFileBadInput, NumbersBeyondTheFloatRange) {
    // 1e300 is a finite double: it used to become an infinite float centre or sun colour.
    EXPECT_CONTAINS(volumeFileBadInputErrorOf(volumeFileBadInputVolume("[1e300, 0.0, 0.0]")),
                    "vols.toml:3: volume 'v': key 'center': a number is too large for a float");
    EXPECT_CONTAINS(
        volumeFileBadInputErrorOf(withSun("{ direction = [0.0, 1.0, 0.0], intensity = 1.0, "
                                          "color = [1e39, 1.0, 1.0] }")),
        "key 'color': a number is too large for a float");
    EXPECT_CONTAINS(
        volumeFileBadInputErrorOf(withSun("{ direction = [0.0, 1.0, 0.0], intensity = 1e300 }")),
        "sun intensity must be a finite number >= 0");
}

TEST(VolumeFileBadInput, OutOfRangeVolumes) {
    EXPECT_CONTAINS(volumeFileBadInputErrorOf(volumeFileBadInputVolume("[1e11, 0.0, 0.0]")),
                    "center is beyond 1e10");
    EXPECT_CONTAINS(
        volumeFileBadInputErrorOf(volumeFileBadInputVolume("[0.0, 0.0, 0.0]", "[1e-9, 1.0, 1.0]")),
        "half extents must lie in [1e-6, 1e10]");
    EXPECT_CONTAINS(
        volumeFileBadInputErrorOf(volumeFileBadInputVolume("[0.0, 0.0, 0.0]", "[3e38, 1.0, 1.0]")),
        "half extents must lie in [1e-6, 1e10]");
}

TEST(VolumeFileBadInput, SunValues) {
    EXPECT_CONTAINS(
        volumeFileBadInputErrorOf(withSun("{ direction = [0.0, 1.0, 0.0], intensity = 1.0, "
                                          "color = [1.0, -0.5, 1.0] }")),
        "sun color must be >= 0");
    // A huge but finite direction is scaled before normalising instead of overflowing.
    const VolumeFile f =
        parseVolumeToml(withSun("{ direction = [3e38, 3e38, 0.0], intensity = 2.0 }"), "vols.toml");
    ASSERT_EQ(f.scenarios.size(), 1u);
    const glm::vec3 d = f.scenarios[0].sun->toSun;
    EXPECT_NEAR(d.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(d.y, std::sqrt(0.5f), 1e-6f);
    EXPECT_EQ(d.z, 0.0f);
}

TEST(VolumeFileBadInput, NamesWithLineBreaksStayOnOneLine) {
    const std::string toml = "[[volume]]\nname = \"a\\nb\"\ncenter = [0.0, 0.0, 0.0]\n"
                             "half_extents = [1.0, 1.0, 1.0]\nprobes = [0, 2, 2]\n";
    EXPECT_CONTAINS(volumeFileBadInputErrorOf(toml), "volume 'a\\nb'");
}

TEST(VolumeFileBadInput, FloatProbeCountsAreNotIntegers) {
    // toml++ 3.3 converted 51e300 to int64 without a range check (undefined behaviour).
    for (const char* count : {"51e300", "2.0", "-inf", "nan"})
        EXPECT_CONTAINS(
            volumeFileBadInputErrorOf("[[volume]]\nname = \"v\"\ncenter = [0.0, 0.0, 0.0]\n"
                                      "half_extents = [1.0, 1.0, 1.0]\nprobes = [" +
                                      std::string(count) + ", 2, 2]\n"),
            "vols.toml:5: volume 'v': key 'probes' must be an array of 3 integers");
}
