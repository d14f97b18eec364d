#include "FewerBouncePasses.h"

#include "probes/bake/Baker.h"
#include "probes/bake/RebuiltRequest.h"

#include <chrono>

namespace pb::bench {

FewerBouncePasses bakeOneFewerBouncePass(const scene::Scene& s, const probes::ProbeSet& set,
                                         int knownPasses,
                                         const std::function<void(const std::string&)>& progress) {
    FewerBouncePasses out;
    const auto t0 = std::chrono::steady_clock::now();
    std::string why;
    std::optional<probes::BakeRequest> r = probes::rebuiltBakeRequest(s, set, &why);
    if (!r) {
        out.why = why;
        return out;
    }
    out.passes = set.settings.bounces > 0 ? set.settings.bounces : knownPasses;
    if (out.passes <= 0) { // converged: count the passes of the first scenario, as rendered
        if (progress) progress("baking the probes' first scenario again to count its bounce passes");
        probes::BakeRequest count = *r;
        count.onlyScenarios = {0};
        probes::BakeStats stats;
        probes::bakeProbes(s, count, &stats);
        out.passes = stats.passes.empty() ? 0 : stats.passes.front();
    }
    if (out.passes < 2) {
        out.why = "the probes ran " + std::to_string(out.passes) +
                  " bounce pass(es): there is no fewer to compare";
        return out;
    }
    r->settings.bounces = out.passes - 1;
    if (progress)
        progress("baking the probes with one bounce pass fewer (" + std::to_string(out.passes - 1) +
                 " of " + std::to_string(out.passes) + ")");
    out.set = probes::bakeProbes(s, *r);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

nlohmann::json fewerBouncePassesJson(const FewerBouncePasses& f) {
    return {{"passes", f.passes == 0 ? nlohmann::json(nullptr) : nlohmann::json(f.passes)},
            {"baked_passes", f.set ? nlohmann::json(f.passes - 1) : nlohmann::json(nullptr)},
            {"seconds", f.set ? nlohmann::json(f.seconds) : nlohmann::json(nullptr)},
            {"why_not", f.set ? nlohmann::json(nullptr) : nlohmann::json(f.why)}};
}

} // namespace pb::bench
