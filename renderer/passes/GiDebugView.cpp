#include "passes/GiDebugView.h"

#include "core/Error.h"

namespace pb::render {

namespace {
struct Entry {
    GiDebugView view;
    const char* name;
};
constexpr Entry kViews[] = {
    {GiDebugView::GiOnly, "gi_only"},
    {GiDebugView::ProbesIrradiance, "probes_irradiance"},
    {GiDebugView::ProbesVisibility, "probes_visibility"},
    {GiDebugView::VolumeCoverage, "volume_coverage"},
};
} // namespace

const std::vector<std::string>& giDebugViewNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const Entry& e : kViews)
            n.push_back(e.name);
        return n;
    }();
    return names;
}

const char* giDebugViewName(GiDebugView v) {
    for (const Entry& e : kViews)
        if (e.view == v) return e.name;
    return "";
}

GiDebugView parseGiDebugView(const std::string& name) {
    for (const Entry& e : kViews)
        if (name == e.name) return e.view;
    std::string list;
    for (const std::string& n : giDebugViewNames())
        list += (list.empty() ? "" : ", ") + n;
    throw Error("--debug '" + name + "': unknown debug view (views: " + list + ")");
}

} // namespace pb::render
