// `bench --truth` in the bench's outputs, from a hand-made result (no GL): accuracy_vs_truth on
// every variant, profile (with its reference) and ablation row; null without a truth; the
// Markdown table and the HTML section only when there is a truth.
#include "bench/report/Format.h"
#include "bench/report/HtmlReport.h"
#include "bench/report/MarkdownSummary.h"
#include "bench/report/ResultJson.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

using namespace pb::bench;

BenchResult benchTruthReportResult(bool withTruth) {
    profile::PlatformProfile ref, low;
    ref.name = "reference";
    low.name = "low";
    low.switches.set("gi.resolution", "half");
    BenchPlan plan = makeBenchPlan({ref, low}, ref, {true, 64, 36});
    BenchResult r;
    r.context = {{"gl_renderer", "llvmpipe"}, {"date", "today"}};
    r.scene = {{"name", "cornell"}};
    r.view = {{"source", "worst-case"}, {"camera", "0,1,2,0,1,0,60"}};
    r.settings = {1, 2, 1, true, "cpu-finish", "test", 67};
    if (withTruth) r.truth = {{"spp", 256}, {"heatmap_scale", 0.3}};
    for (const Session& s : plan.sessions) {
        SessionResult sr;
        sr.session = s;
        for (size_t i = 0; i < s.variants.size(); ++i) {
            VariantResult v;
            v.variant = s.variants[i];
            v.frameSamples = {1.0, 1.1};
            v.roundMedians = {1.0, 1.1};
            v.frameMs = stats::summarize(v.frameSamples);
            // The reference is not at 0 against the truth: that is the point.
            if (withTruth) v.vsTruth = {true, 0.1 + 0.01 * double(i), 0.5, 25.0, 0.02 + 0.001 * double(i)};
            sr.variants.push_back(v);
        }
        for (const PlannedDelta& p : s.deltas) {
            DeltaResult d;
            d.planned = p;
            d.measured = true;
            d.ms = stats::pairedShift(sr.variants[size_t(p.off)].roundMedians,
                                      sr.variants[size_t(p.on)].roundMedians);
            sr.deltas.push_back(d);
        }
        r.sessions.push_back(sr);
    }
    return r;
}

} // namespace

TEST(BenchTruthReport, EveryVariantProfileAndAblationRowHasAccuracyVsTruth) {
    const BenchResult r = benchTruthReportResult(true);
    const nlohmann::json j = benchJson(r);
    EXPECT_EQ(j["truth"]["spp"], 256);
    for (const auto& v : j["variants"]) {
        ASSERT_TRUE(v["accuracy_vs_truth"].is_object()) << v["id"];
        EXPECT_GT(v["accuracy_vs_truth"]["flip_mean"].get<double>(), 0.0);
        EXPECT_EQ(v["accuracy_vs_truth"]["psnr_db"], 25.0);
        EXPECT_TRUE(v["accuracy_vs_truth"].contains("relative_mse"));
    }
    bool sawAblation = false;
    for (const auto& p : j["profiles"]) {
        ASSERT_TRUE(p["accuracy_vs_truth"].is_object());
        ASSERT_TRUE(p["reference_accuracy_vs_truth"].is_object());
        EXPECT_GT(p["reference_accuracy_vs_truth"]["flip_mean"].get<double>(), 0.0);
        for (const auto& a : p["ablation"]) {
            sawAblation = true;
            EXPECT_TRUE(a["in_profile"]["accuracy_vs_truth"]["on"].is_object());
            EXPECT_TRUE(a["in_profile"]["accuracy_vs_truth"]["off"].is_object());
            EXPECT_TRUE(a["on_reference"]["accuracy_vs_truth"]["on"].is_object());
        }
    }
    EXPECT_TRUE(sawAblation);
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("Against the path-traced truth (256 spp"), std::string::npos) << md;
    const std::string html = htmlReport(r);
    EXPECT_NE(html.find("Against the ground truth"), std::string::npos);
    EXPECT_NE(html.find("<td class=\"l\">reference</td>"), std::string::npos);
}

// Issue 43 item 3: each profile's error against the truth split into the reference's own and
// what its switches add, in the JSON, the Markdown table and the HTML report.
TEST(BenchTruthReport, EachProfilesErrorIsSplitIntoTheReferencesAndTheSwitches) {
    const BenchResult r = benchTruthReportResult(true);
    const nlohmann::json j = benchJson(r);
    ASSERT_FALSE(j["profiles"].empty());
    int withSwitches = 0;
    for (const auto& p : j["profiles"]) {
        const nlohmann::json& split = p["truth_error_split"];
        ASSERT_TRUE(split.is_object()) << p.dump();
        const double profileFlip = p["accuracy_vs_truth"]["flip_mean"];
        const double refFlip = p["reference_accuracy_vs_truth"]["flip_mean"];
        const double profileMse = p["accuracy_vs_truth"]["relative_mse"];
        const double refMse = p["reference_accuracy_vs_truth"]["relative_mse"];
        EXPECT_DOUBLE_EQ(split["reference_flip"].get<double>(), refFlip);
        EXPECT_DOUBLE_EQ(split["switches_flip"].get<double>(), profileFlip - refFlip);
        EXPECT_DOUBLE_EQ(split["reference_relative_mse"].get<double>(), refMse);
        EXPECT_DOUBLE_EQ(split["switches_relative_mse"].get<double>(), profileMse - refMse);
        if (profileFlip == refFlip) continue; // the reference's own session: nothing added
        ++withSwitches;
        const std::string md = markdownSummary(r);
        EXPECT_NE(md.find("switches add: FLIP"), std::string::npos) << md;
        EXPECT_NE(md.find(signedFixed(profileFlip - refFlip, 4)), std::string::npos) << md;
        EXPECT_NE(htmlReport(r).find("its switches add FLIP " + signedFixed(profileFlip - refFlip, 4)),
                  std::string::npos);
    }
    EXPECT_EQ(withSwitches, 1) << "the low profile's switches add to the reference's error";
}

// Issue 43 item 3's last column: the reference with probes of one bounce pass fewer, shown in
// the JSON, the Markdown table (with the pass counts) and the HTML; or why it is missing.
TEST(BenchTruthReport, TheReferenceWithOneBouncePassFewerSitsBesideTheSplit) {
    BenchResult r = benchTruthReportResult(true);
    r.truth["fewer_bounce_passes"] = {{"passes", 9}, {"baked_passes", 8}, {"seconds", 1.0}, {"why_not", nullptr}};
    for (SessionResult& s : r.sessions) {
        s.referenceFewerPassesVsTruth = {true, 0.2, 0.6, 20.0, 0.05};
        s.directLightVsTruth = {true, 0.03, 0.4, 30.0, 0.002};
    }
    const nlohmann::json j = benchJson(r);
    for (const auto& p : j["profiles"]) {
        EXPECT_DOUBLE_EQ(p["truth_error_split"]["direct_light_flip"].get<double>(), 0.03);
        EXPECT_DOUBLE_EQ(p["truth_error_split"]["direct_light_relative_mse"].get<double>(), 0.002);
        EXPECT_DOUBLE_EQ(p["truth_error_split"]["reference_one_pass_fewer_flip"].get<double>(), 0.2);
        EXPECT_DOUBLE_EQ(p["truth_error_split"]["reference_one_pass_fewer_relative_mse"].get<double>(), 0.05);
    }
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("reference, one bounce pass fewer (8 of 9 passes): FLIP"), std::string::npos) << md;
    EXPECT_NE(md.find("| 0.2000 | 5.00e-02 |"), std::string::npos) << md;
    // The direct-light floor once per size, in both reports.
    const std::string floor = "The direct light alone (the frame without GI of the sun and punctual "
                              "lights, sky and emission off) is FLIP 0.0300, rel. MSE 2.00e-03";
    EXPECT_NE(md.find("At 64x36: " + floor), std::string::npos) << md;
    EXPECT_EQ(md.find(floor), md.rfind(floor)) << "one line per size, not per profile\n" << md;
    EXPECT_NE(htmlReport(r).find(floor), std::string::npos);
    EXPECT_NE(htmlReport(r).find("With one bounce pass fewer (8 of 9 passes) the reference is at FLIP 0.2000"),
              std::string::npos);

    // Not baked (e.g. a single-pass bake): the columns say n/a and the note says why.
    BenchResult none = benchTruthReportResult(true);
    none.truth["fewer_bounce_passes"] = {{"passes", 1}, {"baked_passes", nullptr}, {"seconds", nullptr},
                                         {"why_not", "the probes ran 1 bounce pass(es)"}};
    const nlohmann::json jn = benchJson(none);
    for (const auto& p : jn["profiles"])
        EXPECT_TRUE(p["truth_error_split"]["reference_one_pass_fewer_flip"].is_null());
    const std::string mdn = markdownSummary(none);
    EXPECT_NE(mdn.find("| n/a | n/a |\n"), std::string::npos) << mdn;
    EXPECT_NE(mdn.find("not measured here: the probes ran 1 bounce pass(es)"), std::string::npos) << mdn;
}

TEST(BenchTruthReport, WithoutATruthTheKeysAreNullAndNoSectionIsShown) {
    const BenchResult r = benchTruthReportResult(false);
    const nlohmann::json j = benchJson(r);
    EXPECT_TRUE(j["truth"].is_null());
    for (const auto& v : j["variants"])
        EXPECT_TRUE(v["accuracy_vs_truth"].is_null());
    for (const auto& p : j["profiles"])
        EXPECT_TRUE(p["truth_error_split"].is_null());
    EXPECT_EQ(markdownSummary(r).find("path-traced truth"), std::string::npos);
    EXPECT_EQ(htmlReport(r).find("Against the ground truth"), std::string::npos);
}

} // namespace pb::test
