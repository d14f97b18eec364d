// Platform profiles from TOML: every error names FILE:LINE and the key (unknown keys, wrong
// types, out-of-range values, bad inheritance, cycles), inheritance applies parent then child,
// every switch-table row is a profile key with no loader edit, the writer round-trips, and the
// shipped profiles load and say what the talk says.
#include "support/TestEnv.h"

#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "profile/ProfileLoader.h"
#include "profile/SwitchTable.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace pb::test {
namespace {

namespace fs = std::filesystem;

profile::ProfileSearch search(std::vector<std::string> dirs = {}) {
    profile::ProfileSearch s;
    s.dirs = std::move(dirs);
    for (const auto& c : costmodel::cachePresets())
        s.cachePresets.push_back(c.name);
    return s;
}

profile::ProfileSearch shipped() {
    return search({(sourceDir() / "profiles").string()});
}

// The settings a profile without `inherit` must give.
const char* kRoot = "[output]\nwidth = 640\nheight = 360\n[budget]\nframe_ms = 16.7\n"
                    "gi_memory_mib = 8\n[costmodel]\ncache_preset = \"pc-low\"\n";

std::string profileLoaderErrorOf(const std::string& text, const std::string& path = "dir/p.toml") {
    try {
        profile::parseProfileToml(text, path, search());
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

void write(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

TEST(ProfileLoader, RootProfileSetsEverySettingAndSwitches) {
    auto p = profile::parseProfileToml(std::string(kRoot) + "[gi]\nresolution = \"half\"\n",
                                       "dir/low.toml", search());
    EXPECT_EQ(p.name, "low");
    EXPECT_EQ(p.width, 640);
    EXPECT_EQ(p.height, 360);
    EXPECT_DOUBLE_EQ(p.frameBudgetMs, 16.7);
    EXPECT_DOUBLE_EQ(p.giMemoryBudgetMiB, 8.0);
    EXPECT_EQ(p.cachePreset, "pc-low");
    EXPECT_EQ(p.switches.gi.resolution, profile::GiResolution::Half);
    EXPECT_EQ(p.switches.get("gi.loops"), "fused"); // unset switches keep the table default
}

TEST(ProfileLoader, UnknownKeyNamesFileLineAndKey) {
    std::string e = profileLoaderErrorOf(std::string(kRoot) + "[gi]\nresolutoin = \"half\"\n");
    EXPECT_NE(e.find("dir/p.toml:10:"), std::string::npos) << e;
    EXPECT_NE(e.find("key 'gi.resolutoin': unknown key"), std::string::npos) << e;
    EXPECT_NE(e.find("gi.resolution"), std::string::npos) << "lists the known keys: " << e;

    e = profileLoaderErrorOf("colour = 3\n" + std::string(kRoot));
    EXPECT_NE(e.find("dir/p.toml:1: key 'colour': unknown key"), std::string::npos) << e;
    e = profileLoaderErrorOf(std::string(kRoot) + "[render]\nfoo = 1\n");
    EXPECT_NE(e.find("dir/p.toml:9: key 'render': unknown table"), std::string::npos) << e;
}

TEST(ProfileLoader, WrongTypesAreErrors) {
    std::string e = profileLoaderErrorOf("[output]\nwidth = \"640\"\n");
    EXPECT_NE(e.find("dir/p.toml:2: key 'output.width': expected an integer"), std::string::npos)
        << e;
    e = profileLoaderErrorOf("[output]\nwidth = 640.0\n");
    EXPECT_NE(e.find("key 'output.width': expected an integer"), std::string::npos) << e;
    e = profileLoaderErrorOf(std::string(kRoot) + "[gi]\nresolution = 2\n");
    EXPECT_NE(e.find("dir/p.toml:10: key 'gi.resolution': expected a string (one of: full, half, "
                     "quarter)"),
              std::string::npos)
        << e;
    e = profileLoaderErrorOf("description = true\n" + std::string(kRoot));
    EXPECT_NE(e.find("key 'description': expected a string"), std::string::npos) << e;
    e = profileLoaderErrorOf("[budget]\nframe_ms = \"fast\"\n");
    EXPECT_NE(e.find("key 'budget.frame_ms': expected a number"), std::string::npos) << e;
}

TEST(ProfileLoader, OutOfRangeValuesAreErrors) {
    std::string e = profileLoaderErrorOf("[output]\nwidth = 8\n");
    EXPECT_NE(e.find("dir/p.toml:2: key 'output.width': must be an integer in [16, 16384]"),
              std::string::npos)
        << e;
    e = profileLoaderErrorOf("[budget]\nframe_ms = 0\n");
    EXPECT_NE(e.find("key 'budget.frame_ms': must be a number in (0, 1000]"), std::string::npos)
        << e;
    e = profileLoaderErrorOf("[budget]\ngi_memory_mib = -1.5\n");
    EXPECT_NE(e.find("key 'budget.gi_memory_mib'"), std::string::npos) << e;
    e = profileLoaderErrorOf(std::string(kRoot) + "[gi]\nresolution = \"eighth\"\n");
    EXPECT_NE(e.find("dir/p.toml:10: key 'gi.resolution': 'eighth' is not allowed (allowed "
                     "values: full, half, quarter)"),
              std::string::npos)
        << e;
    e = profileLoaderErrorOf(std::string(kRoot) + "[gi]\nvolume_lod = \"budget_mib:-3\"\n");
    EXPECT_NE(e.find("key 'gi.volume_lod'"), std::string::npos) << e;
    e = profileLoaderErrorOf("[costmodel]\ncache_preset = \"gtx9000\"\n");
    EXPECT_NE(e.find("key 'costmodel.cache_preset': unknown cache preset 'gtx9000' (presets: "
                     "handheld"),
              std::string::npos)
        << e;
}

TEST(ProfileLoader, MissingSettingsAndSyntaxErrors) {
    std::string e = profileLoaderErrorOf("[gi]\nresolution = \"half\"\n");
    EXPECT_NE(e.find("dir/p.toml: missing key 'output.width'"), std::string::npos) << e;
    e = profileLoaderErrorOf(std::string(kRoot) + "[gi\n");
    EXPECT_NE(e.find("dir/p.toml:9: TOML syntax error"), std::string::npos) << e;
}

// core/TomlText.h screens the text before toml++ sees it (toml++ 3.3.0 reaches undefined
// behaviour on some non-ASCII outside strings); non-ASCII in strings and comments is fine.
TEST(ProfileLoader, NonAsciiOutsideStringsIsRefusedBeforeParsing) {
    EXPECT_EQ(profileLoaderErrorOf(std::string(kRoot) + "[gi]\nresolution = \"half\" \xC3\xA9\n"),
              "dir/p.toml:10: non-ASCII character outside a string or comment");
    EXPECT_EQ(
        profileLoaderErrorOf(std::string("description = \"caf\xC3\xA9\" # \xC2\xA0\n") + kRoot),
        "(no error)");
}

TEST(ProfileLoader, InheritanceAppliesTheParentThenTheChild) {
    fs::path dir = outputDir();
    write(dir / "base.toml", std::string("description = \"base\"\n") + kRoot +
                                 "[gi]\nresolution = \"half\"\nloops = \"split\"\n");
    write(dir / "child.toml", "inherit = \"base\"\n[output]\nwidth = 320\n[gi]\nloops = \"fused\"\n"
                              "probe_order = \"slice_first\"\n");
    write(dir / "grandchild.toml", "inherit = \"child.toml\"\n[budget]\nframe_ms = 33.3\n");
    auto p = profile::loadProfile((dir / "grandchild.toml").string(), search());
    EXPECT_EQ(p.name, "grandchild");
    EXPECT_EQ(p.inherits, (std::vector<std::string>{"child", "base"}));
    EXPECT_EQ(p.width, 320);                 // child
    EXPECT_EQ(p.height, 360);                // base
    EXPECT_DOUBLE_EQ(p.frameBudgetMs, 33.3); // grandchild
    EXPECT_EQ(p.switches.get("gi.resolution"), "half");
    EXPECT_EQ(p.switches.get("gi.loops"), "fused"); // the child overrides the parent
    EXPECT_EQ(p.switches.get("gi.probe_order"), "slice_first");
    EXPECT_EQ(p.description, "") << "a description belongs to its file";

    // By name from a search folder, when not next to the file.
    fs::path other = dir / "elsewhere";
    fs::create_directories(other);
    write(other / "leaf.toml", "inherit = \"child\"\n");
    auto leaf = profile::loadProfile((other / "leaf.toml").string(), search({dir.string()}));
    EXPECT_EQ(leaf.switches.get("gi.probe_order"), "slice_first");
}

TEST(ProfileLoader, InheritanceCyclesAndUnknownParentsAreErrors) {
    fs::path dir = outputDir();
    write(dir / "a.toml", "inherit = \"b\"\n");
    write(dir / "b.toml", "# b\ninherit = \"a\"\n");
    write(dir / "self.toml", "inherit = \"self\"\n");
    write(dir / "orphan.toml", "\ninherit = \"nobody\"\n");
    auto err = [&](const char* name) {
        try {
            profile::loadProfile((dir / name).string(), search({dir.string()}));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    std::string e = err("a.toml");
    EXPECT_NE(e.find("b.toml:2: key 'inherit': inheritance cycle: a -> b -> a"), std::string::npos)
        << e;
    e = err("self.toml");
    EXPECT_NE(e.find("self.toml:1: key 'inherit': inheritance cycle: self -> self"),
              std::string::npos)
        << e;
    e = err("orphan.toml");
    EXPECT_NE(e.find("orphan.toml:2: key 'inherit': no profile 'nobody' (profiles: "),
              std::string::npos)
        << e;
}

// One switch = one place: a row of the switch table is a profile key without any loader edit.
TEST(ProfileLoader, EverySwitchTableRowIsSettableInAProfile) {
    for (const profile::SwitchInfo& s : profile::switchTable()) {
        SCOPED_TRACE(s.key);
        std::string value = s.defaultValue, literal;
        if (s.kind == profile::SwitchKind::Choice) {
            value = s.choices.back() != s.defaultValue ? s.choices.back() : s.choices.front();
            literal = "\"" + value + "\"";
        } else if (s.kind == profile::SwitchKind::Number) {
            literal = std::to_string(0.5 * (s.minValue + s.maxValue));
        } else {
            literal = "\"" + value + "\"";
        }
        const auto dot = s.key.rfind('.');
        // A stream, not a chain of +: GCC 12 takes the chain's inlined copies for overflows
        // (false -Warray-bounds / -Wstringop-overflow) once this file is in a unity batch.
        std::ostringstream toml;
        toml << kRoot << "[" << s.key.substr(0, dot) << "]\n"
             << s.key.substr(dot + 1) << " = " << literal << "\n";
        const std::string text = toml.str();
        auto p = profile::parseProfileToml(text, "dir/one.toml", search());
        if (s.kind == profile::SwitchKind::Number)
            EXPECT_DOUBLE_EQ(std::stod(p.switches.get(s.key)), std::stod(literal));
        else
            EXPECT_EQ(p.switches.get(s.key), value);
    }
}

TEST(ProfileLoader, WrittenProfilesLoadBackTheSame) {
    auto ps = shipped();
    std::vector<std::string> names = profile::profileNames(ps);
    ASSERT_FALSE(names.empty());
    for (const std::string& n : names) {
        SCOPED_TRACE(n);
        profile::PlatformProfile p = profile::loadProfile(n, ps);
        std::string text = profile::profileToml(p);
        profile::PlatformProfile back = profile::parseProfileToml(text, "out/" + n + ".toml", ps);
        EXPECT_TRUE(back.sameSettings(p)) << text;
        EXPECT_EQ(back.description, p.description);
    }
    // Awkward values survive: a float with no short decimal form, quotes in text.
    auto p = profile::parseProfileToml("description = 'say \"hi\" \\ bye'\n" + std::string(kRoot),
                                       "x/q.toml", search());
    p.frameBudgetMs = 0.1 + 0.2;
    auto back = profile::parseProfileToml(profile::profileToml(p), "x/q.toml", search());
    EXPECT_EQ(back.frameBudgetMs, p.frameBudgetMs);
    EXPECT_EQ(back.description, "say \"hi\" \\ bye");
}

// The shipped profiles: the five platforms, one inheritance tree rooted at reference, and the
// talk's choices (../shared/reference/overwatch2-ddgi-talk.txt).
TEST(ShippedProfiles, LoadAndFollowTheTalk) {
    auto ps = shipped();
    std::vector<std::string> names = profile::profileNames(ps);
    for (const char* n : {"reference", "pc-high", "console-base", "handheld", "pc-low"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    EXPECT_EQ(names.front(), "reference");
    for (const std::string& n : names) {
        SCOPED_TRACE(n);
        auto p = profile::loadProfile(n, ps);
        EXPECT_FALSE(p.description.empty());
        if (n != "reference") {
            ASSERT_FALSE(p.inherits.empty());
            EXPECT_EQ(p.inherits.back(), "reference");
        }
        costmodel::cachePresetFor(p.cachePreset); // a preset the cost model knows
    }
    auto ref = profile::loadProfile("reference", ps);
    EXPECT_EQ(ref.switches.gi.resolution, profile::GiResolution::Full);
    EXPECT_EQ(ref.switches.gi.targetFormat, profile::GiTargetFormat::Rgba32f);
    EXPECT_EQ(ref.switches.gi.precision, profile::GiPrecision::Fp32);
    auto handheld = profile::loadProfile("handheld", ps);
    EXPECT_EQ(handheld.switches.gi.resolution, profile::GiResolution::Half);
    EXPECT_EQ(handheld.switches.gi.targetFormat, profile::GiTargetFormat::R11g11b10f);
    EXPECT_EQ(handheld.switches.gi.precision, profile::GiPrecision::Fp16);
    EXPECT_EQ(handheld.switches.gi.loops, profile::GiLoops::Split);
    EXPECT_EQ(handheld.switches.gi.probeOrder, profile::GiProbeOrder::SliceFirst);
    EXPECT_EQ(handheld.switches.gi.multiVolume, profile::GiMultiVolume::Stencil);
    EXPECT_EQ(handheld.switches.gi.dynamic, profile::GiDynamic::Sh);
    EXPECT_DOUBLE_EQ(handheld.frameBudgetMs, 33.3); // "a 30 fps target there"
    auto high = profile::loadProfile("pc-high", ps);
    EXPECT_EQ(high.switches.gi.resolution, profile::GiResolution::Full);
    EXPECT_LT(handheld.giMemoryBudgetMiB, high.giMemoryBudgetMiB);
}

TEST(ProfileLoader, UnknownNamesListTheProfiles) {
    try {
        profile::loadProfile("switch2", shipped());
        FAIL() << "no error";
    } catch (const Error& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("profile 'switch2': no such profile (profiles: reference, "),
                  std::string::npos)
            << m;
    }
    EXPECT_THROW(profile::loadProfile("missing/x.toml", shipped()), Error);
}

} // namespace
} // namespace pb::test
