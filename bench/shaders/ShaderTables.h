#pragma once
// The rows every view of the shader statistics shows (Markdown here, the bench's HTML report
// in bench/report/ShaderTargetsHtml): per profile and pass the pass's cost figure, and per
// single-switch pair what the switch changes in each pass. A pass's figure is its heaviest
// fragment program (most instructions): the GI apply shader in gi-apply, whatever else the pass
// also builds (stencil marks, depth copies).
#include "ShaderStatistics.h"

#include <string>
#include <vector>

namespace pb::shaders {

struct PassRow {
    std::string profile, variant, pass;
    const ProgramStatistics* program = nullptr;
    const StageStatistics* fragment = nullptr;
};

struct SwitchRow {
    const SwitchPair* pair = nullptr;
    std::string pass;
    const ProgramStatistics *off = nullptr, *on = nullptr; // null: the pass has no program there
    const StageStatistics *offFragment = nullptr, *onFragment = nullptr;
};

// The profile and reference variants' passes, in plan order.
std::vector<PassRow> passRows(const TargetStatistics& t);

// For each pair, every pass whose heaviest fragment program the switch changes; a pair that
// changes no program gives one row with an empty pass. Pairs a target could not run are left
// out.
std::vector<SwitchRow> switchRows(const ShaderStatisticsRun& run, const TargetStatistics& t);

// "1233", "34.80", "-" for an absent figure; signed for a change ("+12", "-0.50").
std::string figure(double value, bool fractional);
std::string change(double off, double on, bool fractional);
// "6:43", nouveau's local memory "64 B local" (its spill space), or "-".
std::string spillsFills(const StageStatistics* s);
// "12 full / 3 half", "27 temps", "15 gpr" or "-".
std::string registers(const StageStatistics* s);

// The whole run as Markdown: a section per target (what it is, its GL strings, what it could
// not run), its pass table and its switch table. `level`: the heading level of the title
// (1 standalone, 2 inside the bench's summary; targets one deeper).
std::string shaderMarkdown(const ShaderStatisticsRun& run, int level = 1);

} // namespace pb::shaders
