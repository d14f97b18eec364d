#include "ShaderTargetsSection.h"

#include "Html.h"
#include "bench/shaders/ShaderTables.h"

#include <sstream>

namespace pb::bench {
namespace {

std::string cell(const std::string& text, const char* cls = "") {
    return std::string("<td class=\"") + cls + "\">" + htmlEscape(text) + "</td>";
}

// Spills and fills in red: the figure a weak GPU pays for most.
std::string spillCell(const shaders::StageStatistics* s) {
    const std::string text = shaders::spillsFills(s);
    const bool spills = s && (s->spills() > 0 || s->field("local", 0) > 0);
    return cell(text, spills ? "bad" : "");
}

void passTable(std::ostringstream& h, const shaders::TargetStatistics& t) {
    h << "<table class=\"shader-passes\"><tr><th class=\"l\">profile</th><th class=\"l\">pass</th>"
         "<th class=\"l\">fragment program</th><th>inst</th><th>cycles</th><th class=\"l\">bound"
         "</th><th class=\"l\">registers</th><th>threads / waves</th><th>spills:fills</th>"
         "<th>loops</th></tr>\n";
    for (const shaders::PassRow& r : shaders::passRows(t)) {
        const shaders::StageStatistics* f = r.fragment;
        h << "<tr>" << cell(r.profile, "l") << cell(r.pass, "l") << cell(r.program->fragment, "l")
          << cell(shaders::figure(f->instructions(), false))
          << cell(shaders::figure(f->cycles(), true))
          << cell(f->boundUnit().empty() ? "-" : f->boundUnit(), "l")
          << cell(shaders::registers(f), "l") << cell(shaders::figure(f->occupancy(), false))
          << spillCell(f) << cell(shaders::figure(f->field("loops"), false)) << "</tr>\n";
    }
    h << "</table>\n";
}

void switchTable(std::ostringstream& h, const shaders::ShaderStatisticsRun& run,
                 const shaders::TargetStatistics& t) {
    const std::vector<shaders::SwitchRow> rows = shaders::switchRows(run, t);
    if (rows.empty()) return;
    h << "<table class=\"shader-switches\"><tr><th class=\"l\">where</th><th class=\"l\">switch"
         "</th><th class=\"l\">off → on</th><th class=\"l\">pass</th><th>Δ inst</th>"
         "<th>Δ cycles</th><th class=\"l\">registers off → on</th><th>spills:fills off</th>"
         "<th>on</th></tr>\n";
    for (const shaders::SwitchRow& r : rows) {
        const shaders::SwitchPair& p = *r.pair;
        h << "<tr>" << cell(p.kind == "on_reference" ? "on reference" : "in " + p.profile, "l")
          << cell(p.switchKey, "l") << cell(p.offValue + " → " + p.onValue, "l");
        if (r.pass.empty()) {
            h << "<td class=\"l ns\" colspan=\"6\">changes no program</td></tr>\n";
            continue;
        }
        const shaders::StageStatistics *a = r.offFragment, *b = r.onFragment;
        h << cell(r.pass, "l")
          << cell(a && b ? shaders::change(a->instructions(), b->instructions(), false)
                         : (a ? "removed" : "added"))
          << cell(a && b ? shaders::change(a->cycles(), b->cycles(), true) : "-")
          << cell(shaders::registers(a) + " → " + shaders::registers(b), "l") << spillCell(a)
          << spillCell(b) << "</tr>\n";
    }
    h << "</table>\n";
}

} // namespace

std::string shaderTargetsHtml(const BenchResult& r) {
    const shaders::ShaderStatisticsRun& run = r.shaderTargets;
    if (run.targets.empty()) return {};
    std::ostringstream h;
    h << "<h2 id=\"shader-targets\">The weak GPUs' compilers</h2>\n<p class=\"note\">Every "
         "profile's programs compiled by Mesa "
      << htmlEscape(run.mesaVersion)
      << "'s own drivers for these GPUs (drm-shim, no hardware): each compiler's static "
         "estimates for one fragment, deterministic for this Mesa version and comparable within "
         "one driver; not timings. A pass's figure is its heaviest fragment program; a loop's "
         "body is counted once. Spills in red.</p>\n";
    for (const shaders::TargetStatistics& t : run.targets) {
        h << "<h3>" << htmlEscape(t.target) << ": " << htmlEscape(t.device) << " ("
          << htmlEscape(t.driver) << ")</h3>\n";
        if (!t.error.empty()) {
            h << "<p class=\"note bad\">Not run: " << htmlEscape(t.error) << "</p>\n";
            continue;
        }
        h << "<p class=\"note\">" << htmlEscape(t.glVersion) << "; " << htmlEscape(t.glRenderer)
          << (t.note.empty() ? "" : ". " + htmlEscape(t.note)) << ".</p>\n";
        for (const shaders::VariantStatistics& v : t.variants)
            if (!v.notRun.empty())
                h << "<p class=\"note bad\">Cannot run " << htmlEscape(v.id) << ": "
                  << htmlEscape(v.notRun) << "</p>\n";
        passTable(h, t);
        switchTable(h, run, t);
    }
    return h.str();
}

std::string shaderTargetsMarkdown(const BenchResult& r) {
    if (r.shaderTargets.targets.empty()) return {};
    std::string md = "\n"; // appended, not "\n" + ...: GCC 12 warns -Wrestrict on that
    md += shaders::shaderMarkdown(r.shaderTargets, 3);
    return md;
}

} // namespace pb::bench
