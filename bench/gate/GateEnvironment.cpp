#include "GateEnvironment.h"

#include <cstdio>

namespace pb::gate {

namespace {

std::string percent(double fraction) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g%%", 100 * fraction);
    return buf;
}

} // namespace

bool dependsOnBake(const std::string& group, const std::string& field) {
    const std::string key = field.empty() ? group : group + "." + field;
    return key.rfind("model.fetches.", 0) == 0 || key == "model.probe_bytes_read" ||
           (key.rfind("cache.", 0) == 0 && key.rfind("cache.preset.", 0) != 0);
}

double compareEnvironment(const GateRecord& baseline, const GateRecord& now, GateOutcome& out) {
    const GateEnvironment& b = baseline.environment;
    const GateEnvironment& n = now.environment;
    const bool sameBake = baseline.probes == now.probes;
    const bool hasBaseline = !baseline.probes.empty(); // not a new suite's --update
    double bakeTolerance = 0;
    if (hasBaseline && b.embreeIsa.empty()) {
        if (!sameBake)
            out.notes.push_back("environment: the baseline does not record the Embree ISA of "
                                "its bake (an older file): the probe data and every counter "
                                "are compared exactly; `--update` records it");
    } else if (hasBaseline && b.embreeIsa != n.embreeIsa) {
        bakeTolerance = now.suite.isaCounterTolerance;
        out.notes.push_back("environment: probes baked with Embree " + n.embreeIsa +
                            ", the baseline's with " + b.embreeIsa +
                            " (PB_EMBREE_ISA?): the probe data may differ in the last bits, so "
                            "probe fetches, bytes and the cache model are compared within " +
                            percent(bakeTolerance) + " and the probe data row does not fail");
    }
    std::string baseGl = b.glRenderer;
    if (baseGl.empty() && baseline.recorded.contains("gl_renderer") &&
        baseline.recorded.at("gl_renderer").is_string())
        baseGl = baseline.recorded.at("gl_renderer").get<std::string>();
    if (hasBaseline && !baseGl.empty() && baseGl != n.glRenderer)
        out.notes.push_back("environment: GL '" + n.glRenderer + "', the baseline's '" + baseGl +
                            "': GL call counts stay exact; the GL pass's pixels and the accuracy "
                            "are compared within their tolerances, as always");

    GateRow row{"", "probes", "probe data", baseline.probes, now.probes, RowStatus::Ok, ""};
    if (!sameBake && bakeTolerance > 0) {
        row.status = RowStatus::Skipped;
        row.note = "another Embree ISA (see the notes): not compared bit for bit";
    } else if (!sameBake) {
        row.status = RowStatus::Changed;
        row.note = "the bake differs: counters and accuracy below follow from it";
    }
    out.rows.push_back(row);
    return bakeTolerance;
}

} // namespace pb::gate
