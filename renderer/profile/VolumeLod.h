#pragma once
// gi.volume_lod: which probe volumes a platform leaves out. An omitted volume costs nothing:
// it is neither uploaded nor drawn. Text forms:
//   all                      keep every volume (default)
//   omit:NAME[,NAME...]      leave out these volumes (and the volumes nested in them)
//   min_spacing:METRES       leave out volumes whose smallest probe spacing is below this
//   budget_mib:MIB           keep volumes, largest spacing first, while the GPU bytes of one
//                            scenario fit the budget; a root that does not fit is an error
//   rank_budget_mib:MIB      drop the volumes of least accuracy per byte (with the volumes
//                            nested in them) until the rest fits; needs the probe file's ranks
//                            (`probebench volumes --rank --write-ranks`)
#include <string>
#include <vector>

namespace pb::profile {

struct VolumeLod {
    enum class Mode { All, Omit, MinSpacing, BudgetMiB, RankBudgetMiB };
    Mode mode = Mode::All;
    std::vector<std::string> names; // Omit
    double value = 0.0;             // MinSpacing (metres), BudgetMiB / RankBudgetMiB (MiB)
};

// Throws pb::Error (one line, without the key) when the text is malformed.
VolumeLod parseVolumeLod(const std::string& text);

} // namespace pb::profile
