// Probe volumes: TOML parsing and its errors (file:line: key), nesting rules, auto fitting,
// scenario resolution.
#include "probes/store/VolumeFile.h"
#include "core/Error.h"
#include "probes/placement/AutoVolume.h"
#include "probes/ProbeVolume.h"
#include "probes/Scenario.h"

#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

std::string volumeFileErrorOf(const std::string& toml) {
    try {
        parseVolumeToml(toml, "vols.toml");
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "(no error)";
}

const char* kGood = R"(
[[volume]]
name = "world"
center = [0.0, 5.0, 0.0]
half_extents = [20.0, 5.0, 10.0]
probes = [9, 3, 5]

[[volume]]
name = "room"
center = [2.0, 2.0, 1.0]
half_extents = [3.0, 2.0, 2.0]
rotation = [0.0, 90.0, 0.0]
probes = [4, 3, 4]
parent = "world"
edge_blend = 0.5

[[scenario]]
name = "dusk"
sun = { direction = [-1.0, 0.2, 0.0], intensity = 1.5, color = [1.0, 0.5, 0.3] }
sky = [0.1, 0.05, 0.02]

[[scenario]]
name = "blackout"
sun = "off"
)";

} // namespace

TEST(VolumeFile, ParsesVolumesAndScenarios) {
    VolumeFile f = parseVolumeToml(kGood, "vols.toml");
    ASSERT_EQ(f.volumes.size(), 2u);
    EXPECT_EQ(f.volumes[0].name, "world");
    EXPECT_EQ(f.volumes[0].counts, glm::ivec3(9, 3, 5));
    EXPECT_EQ(f.volumes[0].probeCount(), 135);
    EXPECT_EQ(f.volumes[1].parent, "world");
    EXPECT_FLOAT_EQ(f.volumes[1].edgeBlend, 0.5f);
    // rotation = [0, 90, 0]: local +X turns to world -Z (yaw about +Y, right-handed).
    glm::vec3 x = f.volumes[1].rotation * glm::vec3(1, 0, 0);
    EXPECT_NEAR(x.x, 0.0f, 1e-6f);
    EXPECT_NEAR(x.z, -1.0f, 1e-6f);
    ASSERT_EQ(f.scenarios.size(), 2u);
    ASSERT_TRUE(f.scenarios[0].sun.has_value());
    EXPECT_NEAR(glm::length(f.scenarios[0].sun->toSun), 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(f.scenarios[0].sun->intensity, 1.5f);
    EXPECT_FALSE(f.scenarios[1].sun->enabled);
    EXPECT_FALSE(f.scenarios[1].sky.has_value());
}

TEST(VolumeFile, GridPositionsRunCornerToCorner) {
    ProbeVolume v;
    v.halfExtents = {2, 1, 3};
    v.counts = {3, 1, 4};
    EXPECT_EQ(v.gridLocal({0, 0, 0}), glm::vec3(-2, 0, -3)); // count 1 on y: centre
    EXPECT_EQ(v.gridLocal({2, 0, 3}), glm::vec3(2, 0, 3));
    EXPECT_EQ(v.cellSize(), glm::vec3(2, 2, 2));
    for (int i = 0; i < v.probeCount(); ++i)
        EXPECT_EQ(v.probeIndex(v.probeCoords(i)), i);
}

TEST(VolumeFile, MalformedTomlNamesFileAndLine) {
    std::string e = volumeFileErrorOf("[[volume]]\nname = \"a\"\ncenter = [0, 0,\n");
    EXPECT_NE(e.find("vols.toml:"), std::string::npos) << e;
    EXPECT_NE(e.find("TOML syntax error"), std::string::npos) << e;
}

TEST(VolumeFile, UnknownKeyNamesLineAndKey) {
    std::string e =
        volumeFileErrorOf("[[volume]]\nname = \"a\"\ncenter = [0,0,0]\nhalf_extents = [1,1,1]\n"
                          "probes = [2,2,2]\nprobs = 3\n");
    EXPECT_NE(e.find("vols.toml:6:"), std::string::npos) << e;
    EXPECT_NE(e.find("'probs'"), std::string::npos) << e;
    EXPECT_NE(volumeFileErrorOf("volumes = 1\n").find("vols.toml:1: unknown key 'volumes'"),
              std::string::npos);
}

TEST(VolumeFile, ZeroProbesIsAnError) {
    std::string e =
        volumeFileErrorOf("[[volume]]\nname = \"a\"\ncenter = [0,0,0]\nhalf_extents = [1,1,1]\n"
                          "probes = [0, 4, 4]\n");
    EXPECT_NE(e.find("vols.toml:5:"), std::string::npos) << e;
    EXPECT_NE(e.find("'probes'"), std::string::npos) << e;
    EXPECT_NE(
        volumeFileErrorOf("[[volume]]\nname = \"a\"\ncenter = [0,0,0]\nhalf_extents = [1,1,1]\n"
                          "probes = [2.5, 4, 4]\n")
            .find("integers"),
        std::string::npos);
    EXPECT_NE(
        volumeFileErrorOf("[[volume]]\nname = \"a\"\ncenter = [0,0,0]\nhalf_extents = [1,0,1]\n"
                          "probes = [2, 4, 4]\n")
            .find("vols.toml:4:"),
        std::string::npos);
}

TEST(VolumeFile, MissingKeyAndEmptyFile) {
    std::string e =
        volumeFileErrorOf("\n[[volume]]\nname = \"a\"\ncenter = [0,0,0]\nprobes = [2,2,2]\n");
    EXPECT_NE(e.find("vols.toml:2:"), std::string::npos) << e;
    EXPECT_NE(e.find("missing key 'half_extents'"), std::string::npos) << e;
    EXPECT_NE(volumeFileErrorOf("").find("no [[volume]]"), std::string::npos);
}

TEST(VolumeFile, ChildOutsideParentIsAnError) {
    std::string toml = R"([[volume]]
name = "world"
center = [0, 0, 0]
half_extents = [5, 5, 5]
probes = [3, 3, 3]
[[volume]]
name = "room"
center = [4, 0, 0]
half_extents = [2, 1, 1]
probes = [2, 2, 2]
parent = "world"
)";
    std::string e = volumeFileErrorOf(toml);
    EXPECT_NE(e.find("vols.toml:11:"), std::string::npos) << e;
    EXPECT_NE(e.find("not inside its parent 'world'"), std::string::npos) << e;
    std::string unknown =
        volumeFileErrorOf(toml.substr(0, toml.find("parent")) + "parent = \"wrld\"\n");
    EXPECT_NE(unknown.find("unknown volume 'wrld'"), std::string::npos) << unknown;
}

TEST(VolumeFile, DuplicateNamesAndCyclesAreErrors) {
    std::string one = "[[volume]]\nname = \"a\"\ncenter = [0,0,0]\nhalf_extents = [1,1,1]\n"
                      "probes = [2,2,2]\n";
    EXPECT_NE(volumeFileErrorOf(one + one).find("duplicate volume name 'a'"), std::string::npos);
    std::vector<ProbeVolume> loop(2);
    loop[0].name = "a";
    loop[0].parent = "b";
    loop[1].name = "b";
    loop[1].parent = "a";
    EXPECT_THROW(validateVolumes(loop, "x"), pb::Error);
}

TEST(VolumeFile, MissingFileIsAClearError) {
    try {
        loadVolumeFile("/nonexistent/vols.toml");
        FAIL();
    } catch (const pb::Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/vols.toml"), std::string::npos);
    }
}

TEST(VolumeAuto, FitsTheBoundsAtTheSpacing) {
    pb::scene::Bounds b;
    b.extend(glm::vec3(10, 0, -5));
    b.extend(glm::vec3(30, 6, 5));
    AutoVolume a = fitAutoVolume(b, 1.0f);
    EXPECT_TRUE(a.note.empty());
    glm::vec3 cell = a.volume.cellSize();
    for (int k = 0; k < 3; ++k)
        EXPECT_LE(cell[k], 1.0f + 1e-5f);
    for (glm::vec3 c : {b.min, b.max})
        EXPECT_TRUE(a.volume.contains(c));
    EXPECT_EQ(volumeProblem(a.volume), "");
}

TEST(VolumeAuto, HalfCellMarginKeepsProbePlanesOffTheBounds) {
    // A flat axis too (the thin floor of a level), and the finer tiers of adaptive placement
    // (the lattice split 2 and 4 times per axis): no plane of the finest split on a face.
    for (int subdivisions : {0, 1, 2})
        for (glm::vec3 hi : {glm::vec3(30, 6, 5), glm::vec3(30, -5, 5)}) {
            pb::scene::Bounds b;
            b.extend(glm::vec3(10, -5, -5));
            b.extend(hi);
            const float spacing = 1.0f * float(1 << subdivisions);
            const AutoVolume a = fitAutoVolume(b, spacing, kAutoMaxProbes,
                                               AutoLattice::HalfCellMargin, subdivisions);
            EXPECT_EQ(volumeProblem(a.volume), "");
            for (glm::vec3 c : {b.min, b.max})
                EXPECT_TRUE(a.volume.contains(c));
            const glm::vec3 cell = a.volume.cellSize();
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(cell[k], spacing + 1e-5f);
                const int planes = (a.volume.counts[k] - 1) * (1 << subdivisions) + 1;
                const float fine = cell[k] / float(1 << subdivisions);
                for (int i = 0; i < planes; ++i) {
                    const float x = a.volume.center[k] - a.volume.halfExtents[k] + float(i) * fine;
                    EXPECT_GE(std::abs(x - b.min[k]), 0.45f * fine) << k << " plane " << i;
                    EXPECT_GE(std::abs(x - b.max[k]), 0.45f * fine) << k << " plane " << i;
                }
            }
            if (subdivisions == 0) { // one plane per axis more than the naive fit
                const AutoVolume f = fitAutoVolume(b, spacing);
                for (int k = 0; k < 3; ++k)
                    EXPECT_EQ(a.volume.counts[k], b.size()[k] > 0.0f ? f.volume.counts[k] + 1 : 2);
            }
        }
}

TEST(VolumeAuto, CapsTheProbeCountWithAMessage) {
    pb::scene::Bounds b;
    b.extend(glm::vec3(0));
    b.extend(glm::vec3(100, 20, 100));
    AutoVolume a = fitAutoVolume(b, 0.05f, 10000);
    EXPECT_LE(a.volume.probeCount(), 10000);
    EXPECT_GT(a.spacing, 0.05f);
    EXPECT_NE(a.note.find("spacing 0.05 would need"), std::string::npos) << a.note;
    AutoVolume d = fitAutoVolume(b, 0.0f); // default spacing: about 4096 probes
    EXPECT_GT(d.volume.probeCount(), 2000);
    EXPECT_LT(d.volume.probeCount(), 9000);
}

TEST(VolumeAuto, FlatOrEmptyScenes) {
    pb::scene::Bounds flat;
    flat.extend(glm::vec3(-10, 0, -10));
    flat.extend(glm::vec3(10, 0, 10));
    AutoVolume a = fitAutoVolume(flat, 2.0f);
    EXPECT_GE(a.volume.halfExtents.y * 2.0f, 2.0f - 1e-4f); // widened to one spacing
    EXPECT_EQ(volumeProblem(a.volume), "");
    AutoVolume d = fitAutoVolume(flat, 0.0f); // default spacing still aims at ~4096 probes
    EXPECT_LT(d.volume.probeCount(), 9000);
    EXPECT_EQ(d.volume.counts.y, 2);
    EXPECT_THROW(fitAutoVolume(pb::scene::Bounds{}, 1.0f), pb::Error);
}

TEST(VolumeScenario, PresetsAndFileScenarios) {
    pb::scene::Scene s;
    s.sun.intensity = 7.0f;
    auto day = resolveScenarios({}, {}, s);
    ASSERT_EQ(day.size(), 1u);
    EXPECT_EQ(day[0].name, "day");
    EXPECT_FLOAT_EQ(day[0].sun.intensity, 7.0f);
    auto both = resolveScenarios({"day", "night"}, {}, s);
    EXPECT_FALSE(both[1].sun.enabled);
    VolumeFile f = parseVolumeToml(kGood, "vols.toml");
    auto dusk = resolveScenarios({"dusk"}, f.scenarios, s);
    EXPECT_FLOAT_EQ(dusk[0].sun.intensity, 1.5f);
    try {
        resolveScenarios({"noon"}, f.scenarios, s);
        FAIL();
    } catch (const pb::Error& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("'noon'"), std::string::npos);
        EXPECT_NE(m.find("dusk"), std::string::npos);
        EXPECT_NE(m.find("night"), std::string::npos);
    }
    EXPECT_THROW(resolveScenarios({"day", "day"}, {}, s), pb::Error);
}
