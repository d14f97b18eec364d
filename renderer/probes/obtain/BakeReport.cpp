#include "BakeReport.h"

#include "probes/AbsentProbeFill.h"
#include "probes/ProbeCounts.h"
#include "probes/store/MemoryReport.h"
#include "probes/store/SparseLayout.h"
#include "probes/store/SparseStorage.h"
#include "raytrace/StaticTriangles.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace pb::probes {
namespace {

// printf into a string: the report's figures keep the formats they were printed with.
std::string strf(const char* format, ...) {
    char buf[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buf, sizeof buf, format, args);
    va_end(args);
    return buf;
}

// A count, or null when the file cannot tell (ProbeCounts.h).
nlohmann::json countJson(const std::optional<std::size_t>& n) {
    return n ? nlohmann::json(*n) : nlohmann::json(nullptr);
}

nlohmann::json volumesJson(const ProbeSet& set, const std::vector<ProbeCounts>& counts) {
    nlohmann::json out = nlohmann::json::array();
    for (size_t v = 0; v < set.volumes.size(); ++v) {
        const ProbeVolume& vol = set.volumes[v];
        std::size_t moved = 0;
        for (const ProbeState& p : set.states[v])
            moved += p.offset != glm::vec3(0.0f) ? 1 : 0;
        out.push_back({{"name", vol.name},
                       {"parent", vol.parent},
                       {"counts", {vol.counts.x, vol.counts.y, vol.counts.z}},
                       {"center", {vol.center.x, vol.center.y, vol.center.z}},
                       {"half_extents", {vol.halfExtents.x, vol.halfExtents.y, vol.halfExtents.z}},
                       {"probes", vol.probeCount()},
                       {"stored", counts[v].stored},
                       {"absent", countJson(counts[v].absent)},
                       {"invalid", countJson(counts[v].invalid)},
                       {"relocated", moved}});
    }
    return out;
}

// "probes: N in V volume(s), ..." : stored / absent / invalid (ProbeCounts.h).
// `irradianceOnly`: how many absent probes kept their irradiance (--free-space).
// volumeProbeCounts always knows absent and invalid (the bake's count, or the states).
std::string probeCountsText(const ProbeCounts& c, std::size_t volumes,
                            std::size_t irradianceOnly) {
    std::ostringstream s;
    s << "probes: " << c.probes << " in " << volumes << " volume(s), ";
    if (c.notStored() == 0)
        s << "all stored, " << *c.invalid << " invalid (inside geometry)";
    else
        s << c.stored << " stored, " << *c.absent
          << (irradianceOnly == 0 ? " absent (not stored: no surface nearby), "
              : irradianceOnly == *c.absent
                  ? " absent (no surface nearby: irradiance only, no visibility), "
                  : " absent (no surface nearby; " + std::to_string(irradianceOnly) +
                        " of them keep their irradiance, no visibility), ")
          << *c.invalid << " invalid (inside geometry, not stored)";
    return s.str();
}

// Per scenario, the irradiance's storage scale (probes/StorageScale.h; 1 when in range).
float scenarioScale(const ProbeSet& set, std::size_t s) {
    return s < set.irradiance.size() && !set.irradiance[s].empty()
               ? set.irradiance[s].front().storageScale
               : 1.0f;
}

// The bytes the irradiance-only probes' tiles add (one scenario, in the file's format): what
// `with` (the set's memory report) counts beyond the stored tiles. 0 when there are none.
std::size_t irradianceOnlyBytes(const ProbeSet& set, const MemoryReport& with) {
    if (with.total.irradianceOnlyProbes == 0) return 0;
    std::vector<std::size_t> stored;
    for (const auto& states : set.states) stored.push_back(probes::storedCount(states));
    const MemoryReport without = memoryReport(set.volumes, set.format(), &stored);
    return with.total.stored.total() - std::min(with.total.stored.total(),
                                                without.total.stored.total());
}

// The end of the summary's "free space:" line: what the absent probes keep (--free-space).
std::string freeSpaceText(std::size_t tiles, const std::string& tileBytes, std::size_t standIns,
                          const BakeStats* st) {
    if (tiles == 0) return "absent probes are read as their nearest stored one";
    std::ostringstream s;
    s << tiles << " absent probes keep their irradiance (" << tileBytes << ", no visibility)";
    if (standIns == 0) return s.str();
    s << ": the ones whose nearest stored probe is furthest from their own light; the other "
      << standIns << " are read as it";
    if (st && st->freeSpaceCandidates > 0) {
        s.precision(3);
        s << " (largest difference left " << 100.0 * st->freeSpaceWorstLeft << "%)";
    }
    return s.str();
}

// Figures both forms of the report use.
struct Derived {
    MemoryReport mem;
    std::size_t freeSpaceBytes = 0, irradianceOnly = 0, standIns = 0;
    std::vector<ProbeCounts> counts;
    ProbeCounts total;
    double commandSeconds = 0.0, searchSeconds = 0.0;
};

Derived derive(const BakeReport& r) {
    Derived d;
    d.commandSeconds = r.times.command;
    d.searchSeconds = r.placedThisRun ? r.placement.value("lattice_search", nlohmann::json::object())
                                            .value("seconds", 0.0)
                                      : 0.0;
    d.mem = memoryReport(r.set);
    d.freeSpaceBytes = r.freeSpace * bytesPerProbe(r.set.format()).total();
    d.irradianceOnly = irradianceOnlyBytes(r.set, d.mem);
    // Absent probes lookups read their nearest stored probe for.
    for (const auto& states : r.set.states)
        for (const ProbeState& p : states)
            d.standIns += fillable(p, r.set.settings.backfaceThreshold) ? 1 : 0;
    d.counts = volumeProbeCounts(r.set, r.stats ? &r.stats->invalidPerVolume : nullptr);
    d.total = totalProbeCounts(d.counts);
    return d;
}

} // namespace

std::size_t freeSpaceProbes(const ProbeSet& set, const scene::Scene& s) {
    if (set.storedCount() == set.probeCount()) return 0;
    return freeSpaceOnlyProbes(set, raytrace::staticBakeTriangles(s));
}

// One line from the placement's JSON, so a cached placement prints as a fresh one does.
std::string placementText(const nlohmann::json& j, bool placedThisRun) {
    std::ostringstream s;
    int volumes = 0;
    for (const auto& tier : j["tiers"])
        volumes += tier["volumes"].get<int>();
    s << "placement: " << j["mode"].get<std::string>() << ", " << volumes << " volume(s)";
    for (size_t t = 0; t < j["tiers"].size(); ++t) {
        const auto& tier = j["tiers"][t];
        s << (t == 0 ? "; outer " : "; tier " + std::to_string(t) + " ")
          << tier["volumes"].get<int>() << " x spacing " << tier["spacing"].get<double>() << " ("
          << tier["probes"].get<long long>() << " probes)";
    }
    const double budget = j["budget_bytes"].get<double>();
    s << "; " << formatBytes(j["bytes"].get<std::size_t>()) << " as "
      << j["format"].get<std::string>() << (j["storage"] == "sparse" ? " stored sparse" : "");
    if (j["default_budget"].get<bool>())
        s << " (default budget: the default uniform grid's " << formatBytes(std::size_t(budget))
          << ")";
    else if (budget > 0.0)
        s << " (budget " << formatBytes(std::size_t(budget)) << ")";
    if (j.contains("corner_rays"))
        s << "; " << j["corner_rays"].get<long long>() << " corner rays, "
          << j["placements"].get<int>() << " placement(s)";
    if (j.contains("lattice_search")) {
        const auto& l = j["lattice_search"];
        s.precision(3);
        s << "; lattice search: shift (" << l["shift_cells"][0].get<double>() << ", "
          << l["shift_cells"][1].get<double>() << ", " << l["shift_cells"][2].get<double>()
          << ") cells, estimated error " << l["estimated_error_before"].get<double>() << " -> "
          << l["estimated_error_after"].get<double>() << ", " << l["trials"].get<int>()
          << " trial bakes in " << l["seconds"].get<double>() << " s";
    }
    if (!placedThisRun) s << " (when baked; not placed again: the placement cache matches)";
    return s.str();
}

nlohmann::json bakeReportJson(const BakeReport& r) {
    const Derived d = derive(r);
    const MemoryReport& mem = d.mem;
    const std::size_t freeSpaceBytes = d.freeSpaceBytes, irradianceOnly = d.irradianceOnly,
                      standIns = d.standIns;
    const std::vector<ProbeCounts>& counts = d.counts;
    const ProbeCounts& total = d.total;
    const double commandSeconds = d.commandSeconds, searchSeconds = d.searchSeconds;
    nlohmann::json j{{"file", r.file},
                     {"placement", r.placement},
                     {"placed_this_run", r.placedThisRun},
                     {"up_to_date", r.upToDate},
                     {"input_hash", r.set.inputHash},
                     {"format", formatName(r.set.format())},
                     {"rays_per_probe", r.set.settings.raysPerProbe},
                     {"bounces", r.set.settings.bounces},
                     {"seed", r.set.settings.seed},
                     {"probes", total.probes},
                     {"stored_probes", total.stored},
                     {"absent_probes", countJson(total.absent)},
                     {"invalid_probes", countJson(total.invalid)},
                     {"volumes", volumesJson(r.set, counts)},
                     {"memory", memoryReportJson(mem)}};
    if (r.set.storedCount() < r.set.probeCount())
        j["free_space"] = {{"lattice_probes", r.freeSpace},
                           {"lattice_bytes", freeSpaceBytes},
                           {"lattice_step", kFreeSpaceLatticeStep},
                           {"irradiance_only_probes", mem.total.irradianceOnlyProbes},
                           {"irradiance_only_bytes", irradianceOnly},
                           {"stand_in_probes", standIns}};
    if (r.stats && r.stats->freeSpaceCandidates > 0) {
        j["free_space"]["tile_candidates"] = r.stats->freeSpaceCandidates;
        j["free_space"]["worst_stand_in_difference"] = r.stats->freeSpaceWorstLeft;
    }
    nlohmann::json sc = nlohmann::json::array();
    nlohmann::json scales = nlohmann::json::object();
    for (std::size_t i = 0; i < r.set.scenarios.size(); ++i) {
        sc.push_back(r.set.scenarios[i].name);
        scales[r.set.scenarios[i].name] = scenarioScale(r.set, i);
    }
    j["scenarios"] = sc;
    j["storage_scales"] = scales;
    if (r.stats) {
        double rays = double(r.stats->primaryRays + r.stats->shadowRays);
        j["relocated_probes"] = r.stats->relocatedProbes;
        j["rays"] = r.stats->primaryRays;
        j["shadow_rays"] = r.stats->shadowRays;
        j["seconds"] = r.stats->seconds;
        j["command_seconds"] = commandSeconds;
        j["load_seconds"] = r.times.load;
        j["placement_seconds"] = r.times.placement;
        j["lattice_search_seconds"] = searchSeconds;
        j["write_seconds"] = r.times.write;
        j["bvh_seconds"] = r.stats->buildSeconds;
        j["trace_seconds"] = r.stats->traceSeconds;
        j["encode_seconds"] = r.stats->quantiseSeconds;
        j["rays_per_second"] = r.stats->seconds > 0 ? rays / r.stats->seconds : 0.0;
        j["threads"] = r.stats->threads;
        j["triangles"] = r.stats->triangles;
        j["noise"] = {{"target", r.set.settings.noiseTarget},
                      {"emitter_samples", r.set.settings.emitterSamples},
                      {"lit_samples", r.set.settings.litSamples},
                      {"mean_relative_se", r.stats->noiseMean},
                      {"p95_relative_se", r.stats->noiseP95},
                      {"probe_passes", r.stats->tracedProbePasses},
                      {"probe_passes_with_more_rounds", r.stats->noisyProbePasses},
                      {"probes", r.stats->tracedProbes},
                      {"probes_above_target", r.stats->probesAboveTarget},
                      {"extra_round_rays", r.stats->extraRoundRays},
                      {"above_target_region", nullptr}};
        if (const auto& g = r.stats->noisiestRegion)
            j["noise"]["above_target_region"] = {{"volume", g->volume},
                                                 {"cells_from", {g->from.x, g->from.y, g->from.z}},
                                                 {"cells_to", {g->to.x, g->to.y, g->to.z}},
                                                 {"probes", g->probes},
                                                 {"probes_in_volume", g->probesInVolume}};
        nlohmann::json passes = nlohmann::json::array();
        for (std::size_t i = 0; i < r.stats->passes.size() && i < r.set.scenarios.size(); ++i)
            passes.push_back({{"scenario", r.set.scenarios[i].name},
                              {"passes", r.stats->passes[i]},
                              {"last_pass_share", r.stats->lastChange[i]}});
        j["bounce_passes"] = passes;
        nlohmann::json q = nlohmann::json::array();
        for (const auto& e : r.stats->quantisation)
            q.push_back({{"volume", e.volume},
                         {"texture", e.texture},
                         {"max_relative_error", e.maxRelative},
                         {"mean_relative_error", e.meanRelative}});
        j["quantisation"] = q;
    }
    return j;
}

// "bounces: 9 pass(es) (converged: the last added 0.80% of the light)", per scenario
// when they differ.
std::string bouncesText(const BakeReport& r) {
    const BakeStats& st = *r.stats;
    const bool converge = r.set.settings.bounces == 0;
    std::string o = "bounces:";
    for (std::size_t i = 0; i < st.passes.size() && i < r.set.scenarios.size(); ++i) {
        if (i > 0) o += ";";
        if (st.passes.size() > 1) o += " " + r.set.scenarios[i].name;
        o += strf(" %d pass(es)", st.passes[i]);
        if (st.passes[i] > 1)
            o += strf(" (%s: the last added %.2f%% of the light)",
                      converge ? (st.lastChange[i] < kConvergedChange ? "converged"
                                                                       : "stopped at the pass cap")
                               : "as asked",
                      100.0 * st.lastChange[i]);
    }
    return o + "\n";
}

std::string noiseTargetWarning(const BakeReport& r) {
    if (!r.stats || r.stats->probesAboveTarget == 0 || r.set.settings.noiseTarget <= 0) return {};
    const BakeStats& st = *r.stats;
    std::string o = strf("%zu of %zu probes (%.1f%%) stayed above the noise target %.3g%% after "
                         "%d rounds a pass",
                         st.probesAboveTarget, st.tracedProbes,
                         st.tracedProbes ? 100.0 * double(st.probesAboveTarget) / double(st.tracedProbes) : 0.0,
                         100.0 * r.set.settings.noiseTarget, kMaxNoiseRounds);
    if (const auto& g = st.noisiestRegion)
        o += strf("; most in volume '%s' (%zu of them; cells x %d..%d, y %d..%d, z %d..%d hold %zu)",
                  g->volume.c_str(), g->probesInVolume, g->from.x, g->to.x, g->from.y, g->to.y,
                  g->from.z, g->to.z, g->probes);
    return o + strf("; p95 %.3g%%: more --rays lower it", 100.0 * st.noiseP95);
}

std::string bakeReportText(const BakeReport& r) {
    const Derived d = derive(r);
    const MemoryReport& mem = d.mem;
    const std::size_t freeSpaceBytes = d.freeSpaceBytes, irradianceOnly = d.irradianceOnly,
                      standIns = d.standIns;
    const ProbeCounts& total = d.total;
    const double commandSeconds = d.commandSeconds, searchSeconds = d.searchSeconds;
    std::ostringstream o;
    if (r.upToDate) o << r.file << ": up to date (input hash matches; --force re-bakes)\n";
    o << probeCountsText(total, r.set.volumes.size(), mem.total.irradianceOnlyProbes);
    if (r.stats) o << ", " << r.stats->relocatedProbes << " relocated";
    o << "\n";
    if (r.stats) {
        double rays = double(r.stats->primaryRays + r.stats->shadowRays);
        o << strf("rays: %llu (%d per probe per pass) + %llu shadow rays, %d thread(s), %zu "
                    "triangles\n",
                    (unsigned long long)r.stats->primaryRays, r.set.settings.raysPerProbe,
                    (unsigned long long)r.stats->shadowRays, r.stats->threads, r.stats->triangles);
        o << bouncesText(r);
        o << strf("noise: mean %.2f%%, p95 %.2f%% relative standard error of a probe's "
                    "irradiance (all bounces)",
                    100 * r.stats->noiseMean, 100 * r.stats->noiseP95);
        if (r.set.settings.noiseTarget > 0)
            o << strf(" (target %.3g%%: %zu of %zu probe passes took more rounds, +%llu rays; "
                        "%zu of %zu probes stayed above after %d rounds a pass)",
                        100 * r.set.settings.noiseTarget, r.stats->noisyProbePasses,
                        r.stats->tracedProbePasses, (unsigned long long)r.stats->extraRoundRays,
                        r.stats->probesAboveTarget, r.stats->tracedProbes, probes::kMaxNoiseRounds);
        o << strf("\n");
        o << strf("time: %.2f s in all: scene %.2f s, placement %.2f s", commandSeconds,
                    r.times.load, r.times.placement);
        if (searchSeconds > 0) o << strf(" (lattice search %.2f s)", searchSeconds);
        o << strf(", bake %.2f s (BVH %.2f s, tracing %.2f s, %s encoding %.2f s), write "
                    "%.2f s; %.2f M rays/s in the bake\n",
                    r.stats->seconds, r.stats->buildSeconds, r.stats->traceSeconds, formatName(r.set.format()),
                    r.stats->quantiseSeconds, r.times.write,
                    r.stats->seconds > 0 ? rays / r.stats->seconds * 1e-6 : 0.0);
        double worst = 0.0;
        for (const auto& e : r.stats->quantisation)
            worst = std::max(worst, e.maxRelative);
        if (r.set.format() == StorageFormat::Bc6h)
            for (const auto& e : r.stats->quantisation)
                o << strf("bc6h error %-12s %-20s max %.4f mean %.5f (relative)\n",
                            e.volume.c_str(), e.texture.c_str(), e.maxRelative, e.meanRelative);
        else
            o << strf("%s quantisation: max relative error %.2g\n", formatName(r.set.format()),
                        worst);
    }
    for (std::size_t i = 0; i < r.set.scenarios.size(); ++i)
        if (scenarioScale(r.set, i) != 1.0f)
            o << strf("scenario %s: irradiance stored x2^%d (outside %s's comfortable range)\n",
                        r.set.scenarios[i].name.c_str(), std::ilogb(scenarioScale(r.set, i)),
                        formatName(r.set.format()));
    o << "memory (one scenario resident): " << formatBytes(mem.total.uncompressed.total())
              << " uncompressed, " << formatBytes(mem.total.bc6h.total()) << " bc6h; file holds "
              << r.set.scenarios.size() << " scenario(s) as " << formatName(r.set.format()) << "\n";
    if (r.set.storedCount() < r.set.probeCount())
        o << "sparse storage: " << r.set.storedCount() << " of " << r.set.probeCount()
                  << " grid probes stored, " << formatBytes(mem.total.storedTotal()) << " as "
                  << formatName(r.set.format()) << " with the indirection\n"
                  << "free space: " << r.freeSpace << " of the stored probes ("
                  << formatBytes(freeSpaceBytes) << ") are kept only as the free-space lattice "
                  << "(every " << kFreeSpaceLatticeStep << "nd probe per axis); "
                  << freeSpaceText(mem.total.irradianceOnlyProbes, formatBytes(irradianceOnly),
                                   standIns, r.stats)
                  << "\n";
    else
        o << "sparse-storage candidates: " << mem.total.sparse.far
                  << " probe(s) far from every surface, " << mem.total.sparse.invalid
                  << " inside geometry (stored; sparse storage drops what no surface reads)\n";
    if (!r.upToDate) o << "wrote " << r.file << "\n";
    return o.str();
}

} // namespace pb::probes
