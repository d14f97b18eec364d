#include "PredictionCounters.h"

#include <cmath>

namespace pb::gate {

ShaderTargetRecord predictionRecord(const bench::DevicePrediction& p) {
    ShaderTargetRecord t{"model:" + p.device, {}};
    auto ns = [](double ms) { return std::int64_t(std::llround(ms * 1e6)); };
    for (const bench::PredictedSession& s : p.sessions) {
        if (s.variants.empty() || !s.variants[0].error.empty()) continue;
        const bench::PredictedVariant& v = s.variants[0];
        for (const bench::PredictedPass& pass : v.passes) {
            Counters c{{"predicted_ns", ns(pass.ms)}};
            const nlohmann::json& d = pass.detail;
            if (d.is_object() && d.contains("predicted_unit_ms"))
                for (const char* unit : {"alu", "texture", "memory", "rop"})
                    c.emplace_back(std::string(unit) + "_ns",
                                   ns(d["predicted_unit_ms"].value(unit, 0.0)));
            t.passes.push_back({s.profile, pass.pass, c});
        }
        t.passes.push_back({s.profile, "frame", {{"predicted_ns", ns(v.ms)}}});
    }
    return t;
}

} // namespace pb::gate
