// The profile switches (renderer/profile): one table drives defaults, --set parsing, errors,
// the JSON description and the shader defines.
#include "profile/Profile.h"
#include "core/Error.h"
#include "profile/SwitchTable.h"
#include "profile/VolumeLod.h"

#include <functional>
#include <gtest/gtest.h>
#include <set>

using namespace pb::profile;

namespace {
std::string profileErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(Profile, DefaultsComeFromTheTable) {
    Profile p;
    for (const SwitchInfo& s : switchTable())
        EXPECT_EQ(p.get(s.key), s.defaultValue) << s.key;
    EXPECT_EQ(p.gi.technique, GiTechnique::Ddgi);
    EXPECT_EQ(p.gi.resolution, GiResolution::Full);
    EXPECT_EQ(p.gi.precision, GiPrecision::Fp32);
    EXPECT_EQ(p.gi.loops, GiLoops::Fused);
    EXPECT_EQ(p.gi.probeOrder, GiProbeOrder::Xyz);
    EXPECT_EQ(p.gi.multiVolume, GiMultiVolume::Naive);
    EXPECT_EQ(p.gi.volumeLod, "all");
    EXPECT_TRUE(p.changedSwitches().empty());
}

TEST(Profile, TableRowsAreComplete) {
    std::set<std::string> keys, defines;
    for (const SwitchInfo& s : switchTable()) {
        EXPECT_TRUE(keys.insert(s.key).second) << "duplicate key " << s.key;
        EXPECT_FALSE(s.doc.empty()) << s.key;
        EXPECT_EQ(switchValueProblem(s, s.defaultValue), "") << s.key << " default not allowed";
        if (s.kind == SwitchKind::Choice) {
            EXPECT_GE(s.choices.size(), 1u) << s.key;
        }
        if (s.defineStyle != DefineStyle::HostOnly) {
            EXPECT_TRUE(defines.insert(s.define).second) << "define reused by " << s.key;
        }
    }
    for (const char* k :
         {"gi.technique", "gi.resolution", "gi.target_format", "gi.precision", "gi.loops",
          "gi.probe_order", "gi.multi_volume", "gi.dynamic", "gi.volume_lod"})
        EXPECT_TRUE(keys.count(k)) << k;
}

TEST(Profile, EveryChoiceRoundTrips) {
    for (const SwitchInfo& s : switchTable())
        for (const std::string& v : s.choices) {
            Profile p;
            p.applyOverride(s.key + "=" + v);
            EXPECT_EQ(p.get(s.key), v);
            EXPECT_EQ(p.valuesJson()[s.key], v);
        }
    Profile p;
    p.applyOverride("gi.resolution=quarter");
    p.applyOverride("gi.target_format=r11g11b10f");
    EXPECT_EQ(p.gi.resolution, GiResolution::Quarter);
    EXPECT_EQ(p.gi.targetFormat, GiTargetFormat::R11g11b10f);
    EXPECT_EQ(resolutionDivisor(p.gi.resolution), 4);
    EXPECT_EQ(p.changedSwitches(),
              (std::vector<std::string>{"gi.resolution=quarter", "gi.target_format=r11g11b10f"}));
    EXPECT_FALSE(p == Profile());
}

TEST(Profile, BadValueNamesTheKeyAndListsAllowedValues) {
    Profile p;
    std::string e = profileErrorOf([&] { p.applyOverride("gi.resolution=eighth"); });
    EXPECT_NE(e.find("gi.resolution=eighth"), std::string::npos) << e;
    EXPECT_NE(e.find("full, half, quarter"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
    EXPECT_EQ(p.gi.resolution, GiResolution::Full) << "a rejected value changes nothing";
}

TEST(Profile, UnknownKeyListsTheSwitches) {
    Profile p;
    std::string e = profileErrorOf([&] { p.applyOverride("gi.resolutoin=half"); });
    EXPECT_NE(e.find("unknown switch 'gi.resolutoin'"), std::string::npos) << e;
    EXPECT_NE(e.find("gi.resolution"), std::string::npos) << e;
    EXPECT_NE(profileErrorOf([&] { p.applyOverride("gi.loops"); }).find("expected key=value"),
              std::string::npos);
    EXPECT_NE(profileErrorOf([&] { p.applyOverride("=x"); }).find("expected key=value"),
              std::string::npos);
    EXPECT_NE(profileErrorOf([&] { p.set("nope", "1"); }).find("unknown switch"),
              std::string::npos);
}

TEST(Profile, ShaderDefinesFollowTheTable) {
    Profile p;
    auto d = shaderDefines(p);
    EXPECT_TRUE(d.count("GI_LOOPS_FUSED"));
    EXPECT_TRUE(d.count("GI_ORDER_XYZ"));
    EXPECT_TRUE(d.count("GI_RESOLUTION_FULL"));
    EXPECT_TRUE(d.count("GI_TARGET_RGBA16F"));
    EXPECT_TRUE(d.count("GI_PRECISION_FP32"));
    p.applyOverride("gi.loops=split");
    p.applyOverride("gi.probe_order=slice_first");
    d = shaderDefines(p);
    EXPECT_TRUE(d.count("GI_LOOPS_SPLIT"));
    EXPECT_FALSE(d.count("GI_LOOPS_FUSED"));
    EXPECT_TRUE(d.count("GI_ORDER_SLICE_FIRST"));
    for (const auto& [name, value] : d)
        EXPECT_EQ(name.find("VOLUME_LOD"), std::string::npos);
}

TEST(Profile, DescribeListsEverySwitch) {
    Profile p;
    p.applyOverride("gi.loops=split");
    nlohmann::json j = describeSwitches(p);
    ASSERT_EQ(j.size(), switchTable().size());
    for (const auto& row : j) {
        EXPECT_TRUE(row.contains("key") && row.contains("default") && row.contains("doc") &&
                    row.contains("define") && row.contains("value"));
        if (row["key"] == "gi.loops") {
            EXPECT_EQ(row["value"], "split");
            EXPECT_EQ(row["default"], "fused");
            EXPECT_EQ(row["values"], nlohmann::json({"fused", "split"}));
            EXPECT_EQ(row["define"], "GI_LOOPS_<VALUE>");
        }
    }
    std::string text = describeSwitchesText(p);
    EXPECT_NE(text.find("gi.loops = split  (default fused)"), std::string::npos) << text;
}

TEST(Profile, VolumeLodForms) {
    EXPECT_EQ(parseVolumeLod("all").mode, VolumeLod::Mode::All);
    VolumeLod omit = parseVolumeLod("omit:a,b");
    EXPECT_EQ(omit.mode, VolumeLod::Mode::Omit);
    EXPECT_EQ(omit.names, (std::vector<std::string>{"a", "b"}));
    EXPECT_DOUBLE_EQ(parseVolumeLod("min_spacing:0.5").value, 0.5);
    EXPECT_EQ(parseVolumeLod("budget_mib:8").mode, VolumeLod::Mode::BudgetMiB);
    for (const char* bad : {"", "none", "omit:", "min_spacing:-1", "budget_mib:x", "foo:1"})
        EXPECT_THROW(parseVolumeLod(bad), pb::Error) << bad;
    Profile p;
    p.applyOverride("gi.volume_lod=omit:inner");
    EXPECT_EQ(p.gi.volumeLod, "omit:inner");
    std::string e = profileErrorOf([&] { p.applyOverride("gi.volume_lod=half"); });
    EXPECT_NE(e.find("gi.volume_lod=half"), std::string::npos) << e;
    EXPECT_NE(e.find("omit:NAME"), std::string::npos) << e;
}
