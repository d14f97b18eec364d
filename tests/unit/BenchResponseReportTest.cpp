// `bench --respond` in the bench's outputs, from a hand-made result (no GL): the JSON's
// response key only with a response, and the Markdown/HTML table putting each profile's frame
// time beside its settle frames ("never" for null, a "not run" row for a profile that did not).
#include "bench/report/HtmlReport.h"
#include "bench/report/MarkdownSummary.h"
#include "bench/report/ResultJson.h"

#include <gtest/gtest.h>

namespace pb::test {
namespace {

using namespace pb::bench;

BenchResult benchResponseReportResult(bool withResponse) {
    profile::PlatformProfile ref, low;
    ref.name = "reference";
    low.name = "low";
    low.switches.set("gi.resolution", "half");
    BenchPlan plan = makeBenchPlan({ref, low}, ref, {false, 64, 36});
    BenchResult r;
    r.context = {{"gl_renderer", "llvmpipe"}, {"date", "today"}};
    r.scene = {{"name", "rooms"}};
    r.view = {{"source", "worst-case"}, {"camera", "0,1,2,0,1,0,60"}};
    r.settings = {1, 2, 1, false, "cpu-finish", "test", 67};
    for (const Session& s : plan.sessions) {
        SessionResult sr;
        sr.session = s;
        for (const Variant& variant : s.variants) {
            VariantResult v;
            v.variant = variant;
            v.frameSamples = s.profile.name == "low" ? std::vector<double>{2.0, 2.5}
                                                     : std::vector<double>{1.0, 1.1};
            v.roundMedians = v.frameSamples;
            v.frameMs = stats::summarize(v.frameSamples);
            sr.variants.push_back(v);
        }
        r.sessions.push_back(sr);
    }
    if (withResponse)
        r.response = {{"events", {"sun:off@10"}},
                      {"frames", 40},
                      {"width", 160},
                      {"height", 90},
                      {"profiles",
                       {{{"profile", "reference"},
                         {"rays_per_frame_budget", 0},
                         {"upload_bytes_per_frame_budget", 0},
                         {"schedules",
                          {{{"schedule", "hastened"},
                            {"t95_frames", 3},
                            {"t99_frames", nullptr},
                            {"rays_per_frame", 512.0},
                            {"upload_bytes_per_frame", 1024.0}}}}},
                        {{"profile", "low"}, {"not_run", "no GL for it"}}}}};
    return r;
}

} // namespace

TEST(BenchResponseReport, WithoutRespondNothingChanges) {
    const BenchResult r = benchResponseReportResult(false);
    EXPECT_FALSE(benchJson(r).contains("response"));
    EXPECT_EQ(markdownSummary(r).find("response t95"), std::string::npos);
    EXPECT_EQ(htmlReport(r).find("id=\"response\""), std::string::npos);
}

TEST(BenchResponseReport, EachProfilesSettleFramesSitBesideItsFrameTime) {
    const BenchResult r = benchResponseReportResult(true);
    EXPECT_EQ(benchJson(r)["response"], r.response);
    const std::string md = markdownSummary(r);
    const std::string refMs = std::to_string(r.sessions[0].profile().frameMs.median).substr(0, 4);
    EXPECT_NE(
        md.find("| reference | " + refMs + " | no limit | hastened | 3 | never | 512 | 1024 |"),
        std::string::npos)
        << md;
    EXPECT_NE(md.find("| low | n/a | - | not run: no GL for it |"), std::string::npos) << md;
    // Right after the profiles table, before the per-pass table.
    EXPECT_LT(md.find("response t95 (frames)"), md.find("Median ms per pass"));
    const std::string html = htmlReport(r);
    EXPECT_NE(html.find("id=\"response\""), std::string::npos);
    EXPECT_NE(html.find("<td class=\"\">never</td>"), std::string::npos) << html;
    EXPECT_NE(html.find("not run: no GL for it"), std::string::npos);
    EXPECT_NE(html.find("sun:off@10"), std::string::npos);
}

} // namespace pb::test
