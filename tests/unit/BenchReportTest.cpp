// The bench's outputs from a hand-made result (no GL): JSON fields and nulls, the Markdown
// table, a self-contained HTML report, and the Pareto front.
#include "bench/report/CiLevels.h"
#include "bench/report/GiSections.h"
#include "bench/report/Spread.h"
#include "bench/report/HtmlReport.h"
#include "bench/report/MarkdownSummary.h"
#include "bench/report/ResultJson.h"
#include "bench/report/SvgCharts.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

namespace pb::test {
namespace {

using namespace pb::bench;

VariantResult variant(const Variant& v, double frameMs, double flip, double psnr) {
    VariantResult r;
    r.variant = v;
    for (int i = 0; i < 6; ++i) {
        r.frameSamples.push_back(frameMs + 0.1 * i);
        r.roundMedians.push_back(frameMs + 0.1 * i);
    }
    r.frameMs = stats::summarize(r.frameSamples);
    for (const char* pass : {"gbuffer", "gi-apply", "direct"}) {
        SectionTiming t{pass, std::vector<double>(6, frameMs / 3), {}};
        t.ms = stats::summarize(t.samples);
        r.sections.push_back(t);
    }
    r.accuracy = {true, flip, 2 * flip, psnr, 1.0 - flip, flip * flip, "", "", ""};
    r.coverage = {1.0, 1, 1.0};
    r.giMemoryMiB = 2.5;
    r.volumesKept = 1;
    return r;
}

BenchResult result() {
    profile::PlatformProfile ref, low;
    ref.name = "reference";
    low.name = "low";
    low.switches.set("gi.resolution", "half");
    BenchPlan plan = makeBenchPlan({ref, low}, ref, {true, 64, 36});
    BenchResult r;
    r.context = {{"gl_renderer", "llvmpipe"}, {"software_renderer", true}, {"date", "today"}};
    r.scene = {{"name", "cornell"}};
    r.view = {{"source", "worst-case"}, {"camera", "0,1,2,0,1,0,60"}};
    r.settings = {1, 6, 1, true, "cpu-finish", "test", 67};
    for (const Session& s : plan.sessions) {
        SessionResult sr;
        sr.session = s;
        for (const Variant& v : s.variants) {
            bool isRef = v.switches == ref.switches;
            sr.variants.push_back(
                variant(v, isRef ? 10.0 : 4.0, isRef ? 0.0 : 0.02, isRef ? INFINITY : 30.0));
        }
        for (const PlannedDelta& p : s.deltas) {
            DeltaResult d;
            d.planned = p;
            d.measured = true;
            d.ms = stats::pairedShift(sr.variants[size_t(p.off)].roundMedians,
                                      sr.variants[size_t(p.on)].roundMedians);
            d.flip = 0.02;
            sr.deltas.push_back(d);
        }
        r.sessions.push_back(sr);
    }
    return r;
}

TEST(BenchReport, JsonHasEveryProfileWithTimesAccuracyAndAblation) {
    nlohmann::json j = benchJson(result());
    EXPECT_EQ(j["schema"], "probebench.bench/1");
    ASSERT_EQ(j["profiles"].size(), 2u);
    const auto& ref = j["profiles"][0];
    EXPECT_TRUE(ref["vs_reference"].is_null()) << "the reference is not compared to itself";
    EXPECT_TRUE(ref["accuracy"]["psnr_db"].is_null()) << "+inf is written as null";
    const auto& low = j["profiles"][1];
    EXPECT_EQ(low["status"], "ok");
    EXPECT_NEAR(low["vs_reference"]["delta_ms"]["estimate"].get<double>(), -6.0, 1e-9);
    EXPECT_FALSE(low.contains("passes")) << "passes live in the variants";
    ASSERT_EQ(low["ablation"].size(), 1u);
    EXPECT_EQ(low["ablation"][0]["switch"], "gi.resolution");
    EXPECT_EQ(low["ablation"][0]["reference_value"], "full");
    EXPECT_EQ(low["ablation"][0]["profile_value"], "half");
    EXPECT_TRUE(low["ablation"][0].contains("on_reference"));
    EXPECT_EQ(low["coverage"]["fraction"], 1.0);
    for (const auto& v : j["variants"]) {
        EXPECT_EQ(v["passes"].size(), 3u);
        EXPECT_EQ(v["frame_samples_ms"].size(), 6u);
        EXPECT_TRUE(v.contains("coverage"));
    }
}

TEST(BenchReport, MarkdownAndHtmlShowEveryProfileAndNeedNoNetwork) {
    BenchResult r = result();
    std::string md = markdownSummary(r);
    EXPECT_NE(md.find("| reference | 64x36 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| low | 64x36 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| gi.resolution | full → half |"), std::string::npos) << md;
    EXPECT_NE(md.find("Software rasterizer"), std::string::npos);

    std::string html = htmlReport(r);
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("</html>"), std::string::npos);
    EXPECT_NE(html.find("aria-label=\"Pareto chart\""), std::string::npos);
    EXPECT_NE(html.find("aria-label=\"per-pass times\""), std::string::npos);
    // Nothing is fetched: the only URL is the SVG namespace; no script, no external sheet.
    std::string stripped =
        std::regex_replace(html, std::regex("xmlns=\"http://www.w3.org/2000/svg\""), "");
    EXPECT_EQ(stripped.find("http"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
}

TEST(BenchReport, ParetoFrontKeepsPointsNothingBeatsOnBothAxes) {
    std::vector<ParetoPoint> pts = {{"ref", 0, 0, 0, 0.0, true, ""},
                                    {"fast-bad", -10, -11, -9, 0.05, true, ""},
                                    {"dominated", -5, -6, -4, 0.06, true, ""},
                                    {"mid", -6, -7, -5, 0.01, true, ""},
                                    {"slow-bad", 2, 1, 3, 0.02, false, "1"}};
    std::vector<size_t> front = paretoFront(pts);
    EXPECT_EQ(front, (std::vector<size_t>{1, 3, 0}));
    std::string svg = paretoSvg(pts);
    EXPECT_NE(svg.find("<polyline"), std::string::npos);
}

TEST(BenchReport, CacheModelSectionComparesTheVariantsPerProfile) {
    BenchResult r = result();
    EXPECT_EQ(cacheModelMarkdown(r.cacheModel), ""); // not modelled: no section
    EXPECT_EQ(benchJson(r)["cache_model"], nlohmann::json::array());
    CacheModelEntry e{
        "handheld", "handheld: 16 KiB, 64 B lines, 4-way", 512, 288, "slice_first/split", {}};
    e.variants = {{"xyz/fused", 0.9950, 10.0},
                  {"xyz/split", 0.9952, 9.5},
                  {"slice_first/fused", 0.9955, 9.0},
                  {"slice_first/split", 0.9956, 8.8}};
    r.cacheModel = {e};
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("| handheld | handheld: 16 KiB, 64 B lines, 4-way | 99.50% / 10.0 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("99.56% / 8.8 * |"), std::string::npos);   // the profile's own variant
    EXPECT_NE(md.find("| -10.0% | -5.0% |"), std::string::npos); // slice_first, split vs xyz/fused
    const std::string html = htmlReport(r);
    EXPECT_NE(html.find("<table id=\"cache-model\">"), std::string::npos);
    const nlohmann::json j = benchJson(r)["cache_model"];
    ASSERT_EQ(j.size(), 1u);
    EXPECT_EQ(j[0]["profile_variant"], "slice_first/split");
    EXPECT_DOUBLE_EQ(j[0]["variants"][2]["probe_bytes_missed_per_pixel"].get<double>(), 9.0);
}

// An SH profile has one stream (costmodel: "technique/leak"): the SH column shows it, the
// DDGI variants' columns and the changes between them are n/a.
TEST(BenchReport, CacheModelSectionShowsAnShProfilesStreamInItsOwnColumn) {
    BenchResult r = result();
    CacheModelEntry ddgi{
        "reference", "pc-high: 128 KiB, 128 B lines, 16-way", 512, 288, "xyz/fused", {}};
    ddgi.variants = {{"xyz/fused", 0.9950, 10.0}};
    CacheModelEntry sh{"sh-l1", "pc-high: 128 KiB, 128 B lines, 16-way", 512, 288, "sh_l1/weight",
                       {}};
    sh.variants = {{"sh_l1/weight", 0.9900, 2.5}};
    r.cacheModel = {ddgi, sh};
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("| SH (gi.technique/gi.sh_leak) |"), std::string::npos) << md;
    EXPECT_NE(md.find("| n/a | n/a | n/a | n/a | sh_l1/weight: 99.00% / 2.5 * | n/a | n/a |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("99.50% / 10.0 * | n/a | n/a | n/a | n/a |"), std::string::npos) << md;
    EXPECT_NE(htmlReport(r).find("sh_l1/weight: 99.00% / 2.5 *"), std::string::npos);
}

} // namespace
} // namespace pb::test

namespace pb::test {
namespace {

// Every table, chart and line says the level its intervals reach (issue 25, item 1): never
// "95%" unless it is, and a warning when the rounds are too few.
BenchResult resultWithRounds(int rounds) {
    BenchResult r = result();
    r.settings.rounds = rounds;
    for (SessionResult& s : r.sessions) {
        for (VariantResult& v : s.variants) {
            v.roundMedians.resize(size_t(rounds), v.roundMedians.front());
            for (int i = 0; i < rounds; ++i)
                v.roundMedians[size_t(i)] = v.frameMs.median + 0.1 * i;
            v.frameSamples = v.roundMedians; // 1 frame per round
            v.frameMs = stats::summarize(v.frameSamples);
        }
        for (DeltaResult& d : s.deltas)
            d.ms = stats::pairedShift(s.variants[size_t(d.planned.off)].roundMedians,
                                      s.variants[size_t(d.planned.on)].roundMedians);
    }
    return r;
}

TEST(BenchCiLevel, LabelsSayTheLevelReachedNeverAnOverstated95) {
    EXPECT_EQ(ciLabel({0.75, 0.75}), "75% CI");
    EXPECT_EQ(ciLabel({0.96875}), "96.8% CI"); // rounded down
    EXPECT_EQ(ciLabel({0.94999}), "94.9% CI");
    EXPECT_EQ(ciLabel({0.75, 0.96875}), "CI ≥ 75%");
    EXPECT_EQ(ciLabel({0.0}), "no CI");
    EXPECT_EQ(roundsFor95(), 6);
    EXPECT_NEAR(deltaLevelOfRounds(3), 0.75, 1e-12);
}

TEST(BenchCiLevel, ThreeRoundsPrint75PercentAndWarnEverywhere) {
    const BenchResult r = resultWithRounds(3);
    const std::string md = markdownSummary(r);
    const std::string html = htmlReport(r);
    for (const std::string* text : {&md, &html}) {
        EXPECT_EQ(text->find("95% CI"), std::string::npos) << *text;
        EXPECT_NE(text->find("[75% CI]"), std::string::npos) << *text;
        EXPECT_NE(text->find("3 round(s) give delta intervals of 75% at most, not 95%; --rounds 6 "
                             "or more give 95%"),
                  std::string::npos)
            << *text;
    }
    EXPECT_NE(md.find("(ns) = the 75% CI contains 0"), std::string::npos) << md;
    EXPECT_NE(html.find("Δ frame ms vs reference, 75% CI"), std::string::npos); // Pareto axis
}

TEST(BenchCiLevel, OneRoundHasNoIntervalAndNoSignificance) {
    const BenchResult r = resultWithRounds(1);
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("[no CI]"), std::string::npos) << md;
    EXPECT_EQ(md.find("[-6.00, -6.00]"), std::string::npos) << "a point is not an interval:\n" << md;
    EXPECT_NE(md.find("give no interval at all"), std::string::npos) << md;
}

TEST(BenchCiLevel, EnoughRoundsSayTheirTrueLevelWithoutWarning) {
    const BenchResult r = resultWithRounds(10);
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("Δ ms vs reference [" + ciLabel(deltaCiLevels(r)) + "]"), std::string::npos)
        << md;
    EXPECT_EQ(ciLabel(deltaCiLevels(r)), "95.1% CI"); // Wilcoxon at n = 10: 95.1%, not 95%
    EXPECT_EQ(md.find("Warning"), std::string::npos) << md;
}

} // namespace
} // namespace pb::test

namespace pb::test {
namespace {

// "GI ms" counts every pass that exists for GI (issue 25, item 2), not only "gi-" names: the
// temporal upsample made handheld look cheaper than the reference.
TEST(BenchGiMs, SumsUpsampleDepthCopyStencilFillAndShProjection) {
    EXPECT_TRUE(isGiSection("upsample"));
    EXPECT_TRUE(isGiSection("gi-apply"));
    EXPECT_FALSE(isGiSection("gi-fetch-floor")); // a separate measurement
    EXPECT_FALSE(isGiSection("gbuffer"));

    VariantResult v;
    v.frameSamples = {20, 20};
    for (const auto& [name, ms] : std::vector<std::pair<std::string, double>>{
             {"gbuffer", 5}, {"gi-depth-copy", 1}, {"gi-apply", 2}, {"gi-fill", 0.5},
             {"gi-dynamic-sh", 0.25}, {"upsample", 3}, {"direct", 4}}) {
        SectionTiming t{name, std::vector<double>(2, ms), {}};
        t.ms = stats::summarize(t.samples);
        v.sections.push_back(t);
    }
    EXPECT_EQ(giPassSamples(v), (std::vector<double>{6.75, 6.75}));

    BenchResult r = result(); // gi-apply 4/3 ms in every variant
    for (VariantResult& low : r.sessions[1].variants)
        low.sections.push_back({"upsample", std::vector<double>(6, 7.7),
                                stats::summarize(std::vector<double>(6, 7.7))});
    EXPECT_NEAR(stats::summarize(giPassSamples(r.sessions[1].profile())).median, 4.0 / 3 + 7.7,
                1e-9);
    // The low row's GI ms cell: 9.03, not gi-apply's 1.33 alone.
    const std::string md = markdownSummary(r);
    const size_t row = md.find("| low | 64x36 |");
    ASSERT_NE(row, std::string::npos) << md;
    const std::string line = md.substr(row, md.find('\n', row) - row);
    EXPECT_NE(line.find("| 9.03 |"), std::string::npos) << line;
    EXPECT_NE(markdownSummary(r).find("upsample (every pass that exists for GI"),
              std::string::npos);
}

} // namespace
} // namespace pb::test

namespace pb::test {
namespace {

// Issue 17: GI over the fetch floor per evaluation as well as per texel. The floor does one
// lookup per texel; a pass that evaluates 2 lookups per texel costs half as much per lookup.
TEST(BenchFetchFloor, TheRatioPerEvaluationDividesByTheEvaluationsPerTexel) {
    BenchResult r = result(); // gi-apply 10/3 ms per frame in the reference's variants
    for (VariantResult& v : r.sessions[0].variants) {
        const std::vector<double> floor(6, 10.0 / 3 / 4); // GI / floor = 4 per texel
        v.fetchFloor = SectionTiming{"gi-fetch-floor", floor, stats::summarize(floor)};
    }
    VariantResult& ref = r.sessions[0].variants[size_t(r.sessions[0].session.referenceVariant)];
    ref.giEvaluations = 2 * 36 * 64 + 36 * 64 / 2; // 2.5 lookups per texel
    ref.giTexels = 36 * 64;
    EXPECT_NEAR(giOverFloor(ref), 4.0, 1e-12);
    EXPECT_NEAR(giOverFloorPerEvaluation(ref), 4.0 / 2.5, 1e-12);
    VariantResult uncounted = ref;
    uncounted.giEvaluations = 0;
    EXPECT_TRUE(std::isnan(giOverFloorPerEvaluation(uncounted)));
    VariantResult noFloor = ref;
    noFloor.fetchFloor.reset();
    EXPECT_TRUE(std::isnan(giOverFloorPerEvaluation(noFloor)));

    const nlohmann::json j = benchJson(r);
    int counted = 0;
    for (const auto& v : j["variants"]) {
        if (!v.contains("gi_evaluations")) {
            if (v.contains("gi_over_floor_per_evaluation")) {
                EXPECT_TRUE(v["gi_over_floor_per_evaluation"].is_null()) << v.dump();
            }
            continue;
        }
        ++counted;
        EXPECT_EQ(v["gi_evaluations"], ref.giEvaluations);
        EXPECT_NEAR(v["gi_evaluations_per_texel"].get<double>(), 2.5, 1e-12);
        EXPECT_NEAR(v["gi_over_floor"].get<double>(), 4.0, 1e-9);
        EXPECT_NEAR(v["gi_over_floor_per_evaluation"].get<double>(), 1.6, 1e-9);
    }
    EXPECT_EQ(counted, 1);

    const std::string md = markdownSummary(r);
    const size_t row = md.find("| reference | 64x36 |");
    ASSERT_NE(row, std::string::npos) << md;
    const std::string line = md.substr(row, md.find('\n', row) - row);
    EXPECT_NE(line.find("| 1.60 (4.00) |"), std::string::npos) << line;
    const std::string low = md.substr(md.find("| low | 64x36 |"));
    EXPECT_NE(low.substr(0, low.find('\n')).find("| n/a |"), std::string::npos) << low; // no floor
    const std::string html = htmlReport(r);
    EXPECT_NE(html.find("<th>GI / floor per evaluation</th>"), std::string::npos);
    EXPECT_NE(html.find("<td>1.60</td>"), std::string::npos);
}

// Percentiles and noise flags beside the medians (issue 25, item 4).
TEST(BenchSpread, PercentilesAndBimodalityFlagTheDelta) {
    std::vector<double> ramp;
    for (int i = 0; i <= 100; ++i)
        ramp.push_back(i);
    EXPECT_DOUBLE_EQ(percentile(ramp, 0.5), 50);
    EXPECT_DOUBLE_EQ(percentile(ramp, 0.9), 90);
    EXPECT_DOUBLE_EQ(percentile(ramp, 0.99), 99);

    std::vector<double> twoModes, oneMode;
    for (int i = 0; i < 20; ++i) {
        twoModes.push_back(i % 2 ? 15.0 + 0.01 * i : 5.0 + 0.01 * i);
        const int bell[10] = {-2, -1, -1, 0, 0, 0, 0, 1, 1, 2}; // one symmetric mode
        oneMode.push_back(10.0 + 0.1 * bell[i % 10]);
    }
    EXPECT_GT(bimodalityCoefficient(twoModes), kBimodalAbove);
    EXPECT_LT(bimodalityCoefficient(oneMode), kBimodalAbove);

    BenchResult r = result();
    SessionResult& low = r.sessions[1];
    low.variants[0].frameSamples = twoModes; // the profile itself (SessionResult::profile())
    const std::string md = markdownSummary(r);
    EXPECT_NE(md.find("| profile | p50 | p90 | p99 | flags |"), std::string::npos) << md;
    EXPECT_NE(md.find("bimodal: on"), std::string::npos) << md;
    EXPECT_NE(md.find("variance x"), std::string::npos) << md;
    EXPECT_NE(md.find("Median ms per pass (IQR"), std::string::npos) << md;

    const nlohmann::json j = benchJson(r);
    bool sawPercentiles = false;
    for (const auto& v : j["variants"])
        if (v.contains("frame_percentiles_ms"))
            sawPercentiles = v["frame_percentiles_ms"].contains("p99");
    EXPECT_TRUE(sawPercentiles);
    EXPECT_FALSE(j["profiles"][1]["vs_reference"]["noise_flags"].is_null())
        << j["profiles"][1]["vs_reference"].dump();
}

} // namespace
} // namespace pb::test
