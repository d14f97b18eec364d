// The stress sweep's GL-free parts (renderer/stress): variant specs, the frame comparison, the
// culprit/guard analysis on a fake renderer whose breakage is known, and the JSON shape.
#include "stress/StressSweep.h"
#include "core/Error.h"
#include "stress/StressReport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>

using namespace pb::stress;

namespace {

std::string stressSweepErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "";
}

pb::image::ImageF flat(int w, int h, float v) {
    pb::image::ImageF img;
    img.width = w;
    img.height = h;
    img.pixels.assign(std::size_t(w) * h * 4, v);
    return img;
}

// A renderer whose frames follow rules on the variant, so the analysis has a known answer:
//   fp16 with gi.guard_exposure off           -> one NaN pixel
//   probes.format=bc6h                        -> every pixel 30% too bright
//   gi.guard_clamp off and case "frame_breaks" -> every pixel Inf (whatever the switches)
class FakeRenderer : public StressRenderer {
public:
    int frames = 0;
    std::map<std::string, int> rendered; // settings key -> frames
    RenderedFrame render(const CaseData& data, const StressVariant& v) override {
        ++frames;
        ++rendered[v.settingsKey()];
        RenderedFrame f;
        f.radiance = flat(4, 2, 2.0f);
        if (v.get("gi.precision") == "fp16" && v.get("gi.guard_exposure") == "off")
            f.radiance.pixels[0] = std::numeric_limits<float>::quiet_NaN();
        if (v.storage == pb::probes::StorageFormat::Bc6h)
            for (float& p : f.radiance.pixels)
                p *= 1.3f;
        if (data.scene.name == "frame_breaks" && v.get("gi.guard_clamp") == "off")
            for (float& p : f.radiance.pixels)
                p = std::numeric_limits<float>::infinity();
        return f;
    }
};

StressCase fakeCase(const std::string& name) {
    return {"fake",
            name,
            "a fake case",
            [name] {
                CaseData d;
                d.scene.name = name;
                return d;
            },
            {}};
}

const StressRun& findRun(const SweepResult& r, const std::string& c, const std::string& v,
                         bool off) {
    for (const StressRun& run : r.runs)
        if (run.caseName == c && run.variant == v && run.guardsOff == off) return run;
    ADD_FAILURE() << "no run " << c << " " << v;
    static StressRun none;
    return none;
}

} // namespace

TEST(StressVariant, SpecsSetSwitchesAndStorage) {
    const StressVariant v = parseVariantSpec("hh:gi.precision=fp16,probes.format=bc6h");
    EXPECT_EQ(v.name, "hh");
    EXPECT_EQ(v.get("gi.precision"), "fp16");
    EXPECT_EQ(v.storage, pb::probes::StorageFormat::Bc6h);
    EXPECT_EQ(v.get("probes.format"), "bc6h");
    EXPECT_EQ(parseVariantSpec("plain").settingsKey(), StressVariant().settingsKey());
    EXPECT_EQ(v.differingKeys(StressVariant()),
              (std::vector<std::string>{"gi.precision", "probes.format"}));
}

TEST(StressVariant, BadSpecsNameTheProblem) {
    EXPECT_NE(
        stressSweepErrorOf([] { parseVariantSpec(":gi.precision=fp16"); }).find("expected NAME"),
        std::string::npos);
    EXPECT_NE(
        stressSweepErrorOf([] { parseVariantSpec("a:gi.precision"); }).find("is not key=value"),
        std::string::npos);
    EXPECT_NE(stressSweepErrorOf([] {
                  parseVariantSpec("a:gi.precison=fp16");
              }).find("unknown switch 'gi.precison'"),
              std::string::npos);
    EXPECT_NE(stressSweepErrorOf([] { parseVariantSpec("a:gi.precision=fp8"); }).find("fp32, fp16"),
              std::string::npos);
    EXPECT_NE(stressSweepErrorOf([] { parseVariantSpec("a:probes.format=bc7"); }).find("bc7"),
              std::string::npos);
}

TEST(StressVariant, GuardsAreTheGuardRowsOfTheTable) {
    const std::vector<std::string> guards = guardKeys();
    EXPECT_NE(std::find(guards.begin(), guards.end(), "gi.guard_exposure"), guards.end());
    EXPECT_NE(std::find(guards.begin(), guards.end(), "gi.guard_clamp"), guards.end());
    const StressVariant off = withoutGuards(parseVariantSpec("x"));
    const StressVariant ref = referenceVariant();
    for (const std::string& g : guards) {
        EXPECT_EQ(off.get(g), "off") << g;
        EXPECT_EQ(ref.get(g), "on") << g;
    }
    EXPECT_EQ(ref.get("gi.precision"), "fp32");
    EXPECT_EQ(ref.get("gi.target_format"), "rgba32f");
    EXPECT_EQ(ref.get("gi.resolution"), "full");
    EXPECT_EQ(ref.storage, pb::probes::StorageFormat::Rgba32f);
}

TEST(StressMetrics, CountsNonFiniteAndMeasuresRelativeError) {
    pb::image::ImageF ref = flat(2, 2, 1.0f), test = flat(2, 2, 1.0f);
    test.at(0, 0, 1) = std::numeric_limits<float>::infinity();
    test.at(1, 0, 0) = 1.5f; // 50% off in one channel
    test.at(0, 1, 2) = 0.9f; // 10% off
    const Measurement m = compareRadiance(test, ref);
    EXPECT_EQ(m.pixels, 4);
    EXPECT_EQ(m.nonfinitePixels, 1);
    EXPECT_NEAR(m.maxRel, 0.5, 1e-6);
    EXPECT_NEAR(m.meanRel, (0.5 + 0.1 + 0.0) / 3.0, 1e-6);
    EXPECT_NEAR(m.medianRel, 0.1, 1e-6);
    EXPECT_EQ(symptom(m, {}), "nan/inf");
    // A black pixel of a bright frame is measured against 1e-3 of the frame's largest value.
    ref.at(1, 1, 0) = 0.0f;
    test.at(1, 1, 0) = 0.002f;
    EXPECT_NEAR(compareRadiance(test, ref).maxRel, 2.0, 1e-5);
    EXPECT_THROW(compareRadiance(flat(2, 1, 1.0f), ref), pb::Error);
}

TEST(StressSweep, NamesTheSwitchThatBreaksAndTheGuardThatFixes) {
    SweepOptions o;
    o.variants = {parseVariantSpec("fp16:gi.precision=fp16"),
                  parseVariantSpec("bc6h:probes.format=bc6h")};
    FakeRenderer fake;
    const SweepResult r = runSweep({fakeCase("room")}, o, fake);
    ASSERT_EQ(r.runs.size(), 4u);

    const StressRun& fp16 = findRun(r, "room", "fp16", false);
    EXPECT_EQ(fp16.symptom, "ok"); // the guards as given (on) keep it finite
    const StressRun& fp16off = findRun(r, "room", "fp16", true);
    EXPECT_EQ(fp16off.symptom, "nan/inf");
    EXPECT_EQ(fp16off.m.nonfinitePixels, 1);
    EXPECT_EQ(fp16off.culprits, std::vector<std::string>{"gi.precision=fp16"});
    EXPECT_EQ(fp16off.fixedBy, std::vector<std::string>{"gi.guard_exposure=on"});
    EXPECT_EQ(fp16off.finiteWith, std::vector<std::string>{"gi.guard_exposure=on"});

    for (bool off : {false, true}) {
        const StressRun& bc6h = findRun(r, "room", "bc6h", off);
        EXPECT_EQ(bc6h.symptom, "wrong");
        EXPECT_NEAR(bc6h.m.medianRel, 0.3, 1e-5);
        EXPECT_EQ(bc6h.culprits, std::vector<std::string>{"probes.format=bc6h"});
        EXPECT_TRUE(bc6h.fixedBy.empty()) << "no guard changes the storage";
    }
    // Identical settings are rendered once (the runs, the analysis and the reference share).
    EXPECT_EQ(fake.frames, r.cases[0].frames);
    for (const auto& [key, n] : fake.rendered)
        EXPECT_EQ(n, 1) << key;
}

TEST(StressSweep, BlamesNoSwitchWhenTheReferenceBreaksToo) {
    SweepOptions o;
    o.variants = {parseVariantSpec("defaults")};
    o.guards = RunGuards::Off;
    FakeRenderer fake;
    const SweepResult r = runSweep({fakeCase("frame_breaks")}, o, fake);
    ASSERT_EQ(r.runs.size(), 1u);
    EXPECT_EQ(r.runs[0].symptom, "nan/inf");
    EXPECT_EQ(r.runs[0].culprits,
              std::vector<std::string>{"(no switch: the reference breaks too)"});
    EXPECT_EQ(r.runs[0].fixedBy, std::vector<std::string>{"gi.guard_clamp=on"});
}

TEST(StressSweep, AFailedFrameIsAnErrorRunNotACrash) {
    class Throwing : public StressRenderer {
    public:
        RenderedFrame render(const CaseData&, const StressVariant& v) override {
            if (v.name != "reference") throw pb::Error("no BPTC here");
            RenderedFrame f;
            f.radiance = flat(2, 2, 1.0f);
            return f;
        }
    } renderer;
    SweepOptions o;
    o.variants = {parseVariantSpec("bc6h:probes.format=bc6h")};
    o.guards = RunGuards::AsGiven;
    const SweepResult r = runSweep({fakeCase("room")}, o, renderer);
    ASSERT_EQ(r.runs.size(), 1u);
    EXPECT_EQ(r.runs[0].symptom, "error");
    EXPECT_EQ(r.runs[0].m.error, "no BPTC here");
    EXPECT_TRUE(r.runs[0].culprits.empty());
}

TEST(StressReport, JsonHasEveryFieldTheReadmeLists) {
    SweepOptions o;
    o.variants = {parseVariantSpec("fp16:gi.precision=fp16")};
    FakeRenderer fake;
    const SweepResult r = runSweep({fakeCase("room")}, o, fake);
    const nlohmann::json j = sweepJson(r);
    EXPECT_EQ(j["command"], "stress");
    EXPECT_EQ(j["reference"]["settings"]["gi.guard_exposure"], "on");
    EXPECT_EQ(j["reference"]["settings"]["probes.format"], "rgba32f");
    ASSERT_EQ(j["variants"].size(), 1u);
    EXPECT_EQ(j["variants"][0]["name"], "fp16");
    ASSERT_EQ(j["cases"].size(), 1u);
    for (const char* k : {"name", "group", "stresses", "width", "height", "truth", "frames",
                          "reference_nonfinite_pixels", "reference_error"})
        EXPECT_TRUE(j["cases"][0].contains(k)) << k;
    ASSERT_EQ(j["runs"].size(), 2u);
    for (const auto& run : j["runs"])
        for (const char* k :
             {"case", "variant", "guards", "symptom", "nonfinite_pixels", "nonfinite_gi_texels",
              "max_rel", "mean_rel", "median_rel", "error", "culprits", "fixed_by", "finite_with"})
            EXPECT_TRUE(run.contains(k)) << k;
    EXPECT_EQ(j["runs"][1]["guards"], "off");
    EXPECT_EQ(j["runs"][1]["fixed_by"][0], "gi.guard_exposure=on");
    EXPECT_EQ(j["summary"]["broken"], 1);
    EXPECT_EQ(j["summary"]["broken_with_guards"], 0);
    EXPECT_EQ(j["summary"]["nonfinite_with_guards"], 0);
    const std::string text = sweepText(r);
    EXPECT_NE(text.find("fp16/off"), std::string::npos) << text;
    EXPECT_NE(text.find("fixed by gi.guard_exposure=on"), std::string::npos) << text;
}

TEST(StressCases, NamesAreUniqueAndSelectable) {
    const std::vector<StressCase> all = stressCases();
    std::set<std::string> names;
    for (const StressCase& c : all)
        EXPECT_TRUE(names.insert(c.name).second) << c.name;
    for (const char* group :
         {"light", "spacing", "offset", "thin_wall", "grid", "rays", "resolution", "bad_normals",
          "variance_zero", "fold_edges", "all_invalid"})
        EXPECT_FALSE(selectCases(all, {group}).empty()) << group;
    EXPECT_EQ(selectCases(all, {"light=1e+06"}).size(), 1u);
    EXPECT_NE(
        stressSweepErrorOf([&] { selectCases(all, {"lihgt"}); }).find("no case or group 'lihgt'"),
        std::string::npos);
}
