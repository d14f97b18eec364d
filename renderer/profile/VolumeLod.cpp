#include "profile/VolumeLod.h"

#include "core/Error.h"

#include <cmath>
#include <sstream>

namespace pb::profile {

namespace {
const char* kForms = "expected all, omit:NAME[,NAME...], min_spacing:METRES, budget_mib:MIB or "
                     "rank_budget_mib:MIB";

double positiveNumber(const std::string& text, const std::string& whole) {
    std::istringstream in(text);
    double v = 0;
    if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v) || v <= 0)
        throw Error("'" + whole + "': '" + text + "' is not a positive number");
    return v;
}
} // namespace

VolumeLod parseVolumeLod(const std::string& text) {
    VolumeLod lod;
    if (text == "all") return lod;
    auto colon = text.find(':');
    if (colon == std::string::npos) throw Error("'" + text + "': " + kForms);
    std::string mode = text.substr(0, colon), arg = text.substr(colon + 1);
    if (mode == "omit") {
        lod.mode = VolumeLod::Mode::Omit;
        std::istringstream in(arg);
        std::string name;
        while (std::getline(in, name, ','))
            if (!name.empty()) lod.names.push_back(name);
        if (lod.names.empty()) throw Error("'" + text + "': omit: needs at least one volume name");
    } else if (mode == "min_spacing") {
        lod.mode = VolumeLod::Mode::MinSpacing;
        lod.value = positiveNumber(arg, text);
    } else if (mode == "budget_mib") {
        lod.mode = VolumeLod::Mode::BudgetMiB;
        lod.value = positiveNumber(arg, text);
    } else if (mode == "rank_budget_mib") {
        lod.mode = VolumeLod::Mode::RankBudgetMiB;
        lod.value = positiveNumber(arg, text);
    } else {
        throw Error("'" + text + "': " + kForms);
    }
    return lod;
}

} // namespace pb::profile
