// Probe files with a valid checksum but impossible contents (written by something else, or
// crafted): each is one line "probes.pbp: problem", never NaN or wild offsets in the sampler.
#include "core/Error.h"
#include "probes/store/ProbeFile.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>

using namespace pb::probes;

namespace {

// One 2x1x2 volume, one scenario, textures filled with 0.5: no bake needed.
ProbeSet tinySet() {
    ProbeSet set;
    ProbeVolume v;
    v.name = "v";
    v.counts = {2, 1, 2};
    set.volumes = {v};
    set.states = {std::vector<ProbeState>(4)};
    Scenario s;
    s.name = "day";
    set.scenarios = {s};
    ProbeTexture vis = ProbeTexture::make(visibilityShape(v.counts));
    ProbeTexture irr = ProbeTexture::make(irradianceShape(v.counts));
    for (ProbeTexture* t : {&vis, &irr}) {
        std::fill(t->texels.begin(), t->texels.end(), 0.5f);
        quantise(*t, set.settings.format);
    }
    set.visibility = {vis};
    set.irradiance = {{irr}};
    return set;
}

std::string probeFileBadInputErrorOf(const ProbeSet& set) {
    try {
        parseProbeSet(serializeProbeSet(set), "probes.pbp");
    } catch (const pb::Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        EXPECT_EQ(msg.rfind("probes.pbp: ", 0), 0u) << msg;
        return msg;
    }
    return "(no error)";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

const float kNan = std::numeric_limits<float>::quiet_NaN();

} // namespace

TEST(ProbeFileBadInput, TheTinySetItselfLoads) {
    EXPECT_EQ(probeFileBadInputErrorOf(tinySet()), "(no error)");
}

TEST(ProbeFileBadInput, ImpossibleBakeSettings) {
    ProbeSet a = tinySet();
    a.settings.raysPerProbe = 0;
    EXPECT_CONTAINS(probeFileBadInputErrorOf(a), "corrupt bake settings (rays 0");
    ProbeSet b = tinySet();
    b.settings.backfaceThreshold = kNan;
    EXPECT_CONTAINS(probeFileBadInputErrorOf(b), "corrupt bake settings");
}

TEST(ProbeFileBadInput, ScenariosMustBeFiniteAndUnique) {
    ProbeSet a = tinySet();
    a.scenarios[0].sun.intensity = std::numeric_limits<float>::infinity();
    EXPECT_CONTAINS(probeFileBadInputErrorOf(a), "corrupt scenario 'day'");
    ProbeSet b = tinySet();
    b.scenarios[0].sky.radiance.y = -1.0f;
    EXPECT_CONTAINS(probeFileBadInputErrorOf(b), "corrupt scenario 'day'");
    ProbeSet c = tinySet();
    c.scenarios.push_back(c.scenarios[0]);
    c.irradiance.push_back(c.irradiance[0]);
    EXPECT_CONTAINS(probeFileBadInputErrorOf(c), "scenario 'day' appears twice");
}

TEST(ProbeFileBadInput, ProbeStatesWithinACell) {
    ProbeSet a = tinySet();
    a.states[0][2].offset.x = 5.0f; // the cell is 2 units wide
    EXPECT_CONTAINS(probeFileBadInputErrorOf(a), "corrupt probe state in volume 'v'");
    ProbeSet b = tinySet();
    b.states[0][1].backfaceRatio = kNan;
    EXPECT_CONTAINS(probeFileBadInputErrorOf(b), "corrupt probe state");
}

TEST(ProbeFileBadInput, TexelsMustBeFiniteAndNonNegative) {
    for (StorageFormat f : {StorageFormat::Rgba32f, StorageFormat::Rgba16f}) {
        for (float bad : {kNan, -1.0f, std::numeric_limits<float>::infinity()}) {
            ProbeSet s = tinySet();
            s.settings.format = f;
            ProbeTexture& irr = s.irradiance[0][0];
            std::fill(irr.texels.begin(), irr.texels.end(), 0.5f);
            quantise(irr, f);
            quantise(s.visibility[0], f);
            // Written past quantise (which clamps): what a foreign writer could store.
            if (f == StorageFormat::Rgba32f) {
                std::memcpy(irr.stored.data() + 20, &bad, 4);
            } else {
                const std::uint16_t half = std::isnan(bad) ? 0x7E00 : bad < 0 ? 0xBC00 : 0x7C00;
                std::memcpy(irr.stored.data() + 10, &half, 2);
            }
            EXPECT_CONTAINS(probeFileBadInputErrorOf(s), "corrupt irradiance data")
                << formatName(f) << " " << bad;
        }
    }
}

// Version 2's per-scenario storage scale: a power of two within 2^-64..2^64, nothing else.
TEST(ProbeFileBadInput, StorageScaleMustBeAPowerOfTwo) {
    for (float bad :
         {kNan, std::numeric_limits<float>::infinity(), 0.0f, -2.0f, 3.0f, std::ldexp(1.0f, 100)}) {
        ProbeSet s = tinySet();
        s.irradiance[0][0].storageScale = bad;
        EXPECT_CONTAINS(probeFileBadInputErrorOf(s), "corrupt storage scale of scenario 'day'")
            << bad;
    }
    ProbeSet ok = tinySet();
    ok.irradiance[0][0].storageScale = 0.25f;
    EXPECT_EQ(probeFileBadInputErrorOf(ok), "(no error)");
}

TEST(ProbeFileBadInput, TheFreeSpaceRecordNamesAKnownChoiceAndAFiniteBudget) {
    ProbeSet a = tinySet();
    a.freeSpace = FreeSpace(7);
    EXPECT_CONTAINS(probeFileBadInputErrorOf(a), "corrupt free-space record (choice 7)");
    for (double budget : {-1.0, double(kNan), std::numeric_limits<double>::infinity()}) {
        ProbeSet b = tinySet();
        b.freeSpace = FreeSpace::Ranked;
        b.freeSpaceBudgetBytes = budget;
        EXPECT_CONTAINS(probeFileBadInputErrorOf(b),
                        "corrupt free-space record (budget not a finite size)");
    }
    ProbeSet c = tinySet();
    c.freeSpace = FreeSpace::Ranked;
    c.freeSpaceBudgetBytes = 123456.0;
    const ProbeSet back = parseProbeSet(serializeProbeSet(c), "probes.pbp");
    EXPECT_EQ(back.freeSpace, FreeSpace::Ranked);
    EXPECT_EQ(back.freeSpaceBudgetBytes, 123456.0);
}
