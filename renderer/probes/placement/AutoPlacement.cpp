#include "probes/placement/AutoPlacement.h"

#include "core/Error.h"
#include "probes/placement/LatticeAlignment.h"
#include "probes/store/MemoryReport.h"
#include "probes/placement/PlacementError.h"
#include "probes/bake/RayScene.h"
#include "probes/store/SparseStorage.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace pb::probes {
namespace {

std::string mib(double bytes) {
    std::ostringstream s;
    s.precision(3);
    s << bytes / (1024.0 * 1024.0) << " MiB";
    return s.str();
}

std::string budgetOption(double bytes) {
    std::ostringstream s;
    s << "--probe-budget-mib " << bytes / (1024.0 * 1024.0);
    return s.str();
}

} // namespace

bool parseAutoMode(const std::string& text, AutoMode& mode) {
    if (text == "auto")
        mode = AutoMode::Adaptive;
    else if (text == "auto-uniform")
        mode = AutoMode::Uniform;
    else
        return false;
    return true;
}

const char* autoModeName(AutoMode mode) {
    return mode == AutoMode::Adaptive ? "adaptive" : "uniform";
}

float defaultUniformSpacing(const scene::Bounds& b) {
    return fitAutoVolume(b, 0.0f, std::numeric_limits<long long>::max()).spacing;
}

AutoPlacementResult placeAutoVolumes(const scene::Scene& scene, const AutoPlacementRequest& req) {
    const scene::Bounds bounds = staticBakeBounds(scene);
    const bool adaptive = req.mode == AutoMode::Adaptive;
    const char* option = adaptive ? "--volumes auto" : "--volumes auto-uniform";
    float spacing = req.adaptive.spacing;
    if (!(spacing >= 0.0f) || !std::isfinite(spacing))
        throw Error("--spacing: must be a positive number");
    if (adaptive && (req.adaptive.levels < 1 || req.adaptive.levels > 4))
        throw Error("--auto-levels: must be 1..4 (got " + std::to_string(req.adaptive.levels) +
                    ")");
    if (adaptive && req.adaptive.maxChildren < 1) throw Error("--auto-max-children: must be >= 1");
    if (!(req.budgetBytes >= 0.0) || !std::isfinite(req.budgetBytes))
        throw Error("--probe-budget-mib: must be a positive number");
    if (req.budgetBytes > 0.0) {
        ProbeVolume smallest;
        smallest.name = "smallest";
        const std::size_t need = memoryReport({smallest}, req.format).total.stored.total();
        if (double(need) > req.budgetBytes)
            throw Error(budgetOption(req.budgetBytes) + ": too small, the smallest volume (2x2x2 " +
                        "probes) needs " + formatBytes(need) + " as " + formatName(req.format));
    }
    if (bounds.empty()) fitAutoVolume(bounds, 1.0f); // throws the one-line empty-scene error

    std::unique_ptr<RayScene> rays;
    std::vector<WorldTriangle> triangles;
    bool defaultBudget = false;
    double budget = req.budgetBytes;
    if (adaptive || req.sparse) triangles = staticBakeTriangles(scene);
    // What the bake will store of these volumes, as the memory report counts it.
    auto storedBytes = [&](const std::vector<ProbeVolume>& volumes) {
        if (!req.sparse) return memoryReport(volumes, req.format).total.storedTotal();
        const std::vector<std::size_t> kept = sparseProbeCounts(volumes, triangles);
        return memoryReport(volumes, req.format, &kept).total.storedTotal();
    };
    if (adaptive) {
        rays = std::make_unique<RayScene>(scene);
        if (!(spacing > 0.0f)) {
            // Default: the memory of the default uniform grid, spent where the scene needs it,
            // starting from half the uniform spacing near surfaces.
            const float uniform = defaultUniformSpacing(bounds);
            spacing = 0.5f * uniform;
            if (!(budget > 0.0)) {
                AutoVolume fit = fitAutoVolume(bounds, uniform, req.maxProbes);
                budget = double(memoryReport({fit.volume}, req.format).total.stored.total());
                defaultBudget = true;
            }
        }
    }

    // `auto` keeps probe planes off the boundary surfaces; `auto-uniform` is the naive fit.
    const AutoLattice lattice = adaptive ? AutoLattice::HalfCellMargin : AutoLattice::FitBounds;
    int placements = 0;
    std::string capNote;
    // levels 0 = one uniform volume.
    auto place = [&](float s, int levels) {
        ++placements;
        AutoPlacementResult r;
        if (levels > 0) {
            AdaptiveOptions o = req.adaptive;
            o.spacing = s;
            o.levels = levels;
            AdaptivePlacement p = placeAdaptiveVolumes(*rays, triangles, bounds, o);
            r.volumes = std::move(p.volumes);
            r.stats = p.stats;
            r.spacing = s;
        } else {
            AutoVolume fit = fitAutoVolume(bounds, s, req.maxProbes, lattice);
            if (placements == 1) capNote = fit.note;
            r.volumes.push_back(fit.volume);
            r.spacing = fit.spacing;
        }
        r.levels = levels;
        for (const ProbeVolume& v : r.volumes)
            r.probes += v.probeCount();
        r.bytes = storedBytes(r.volumes);
        return r;
    };
    auto fits = [&](const AutoPlacementResult& r) {
        if (budget > 0.0 && double(r.bytes) > budget) return false;
        if (r.probes > req.maxProbes) return false;
        for (const ProbeVolume& v : r.volumes)
            if (!volumeProblem(v).empty()) return false;
        return true;
    };
    // How far over the limits a placement is (> 1: over).
    auto excess = [&](const AutoPlacementResult& r) {
        double e = double(r.probes) / double(req.maxProbes);
        if (budget > 0.0) e = std::max(e, double(r.bytes) / budget);
        for (const ProbeVolume& v : r.volumes)
            e = std::max(e, double(v.probeCount()) / double(kMaxProbesPerVolume));
        return e;
    };
    // Geometric bisection between a spacing that does not fit and one that does (`best`, the
    // placement at `fitting`): the finest placement that fits, to within 2%.
    auto bisect = [&](float failing, float fitting, AutoPlacementResult best, int levels) {
        for (int i = 0; i < 5 && fitting > failing * 1.02f; ++i) {
            const float mid = std::sqrt(failing * fitting);
            AutoPlacementResult m = place(mid, levels);
            if (fits(m)) {
                fitting = mid;
                best = std::move(m);
            } else {
                failing = mid;
            }
        }
        return best;
    };
    // Grow the spacing until the placement fits (probes fall with the spacing squared near
    // surfaces, cubed in open space: the square root never undershoots much), then bisect
    // towards the finest spacing that fits.
    auto coarsen = [&](const AutoPlacementResult& first, int levels) {
        float lo = first.spacing, hi = first.spacing;
        AutoPlacementResult r = first;
        const int start = placements;
        while (!fits(r)) {
            lo = hi;
            hi = lo * float(std::max(1.05, std::sqrt(excess(r))));
            AutoPlacementResult next = place(hi, levels);
            if ((next.probes >= r.probes && !fits(next) && placements - start > 8) ||
                placements - start > 60)
                throw Error(std::string(option) + ": " +
                            (budget > 0.0 ? budgetOption(budget) + " is" : "the probe limit is") +
                            " too small for this placement (it needs at least " +
                            formatBytes(next.bytes) + ", " + std::to_string(next.probes) +
                            " probes); raise it, lower --auto-levels or use auto-uniform");
            r = std::move(next);
        }
        return bisect(lo, hi, std::move(r), levels);
    };
    // Sparse storage: memory follows the surface, not the volume, so the starting spacing often
    // fits with room to spare: shrink it while it fits, then bisect (the mirror of coarsen).
    auto refine = [&](const AutoPlacementResult& first, int levels) {
        float fine = first.spacing, coarse = first.spacing;
        AutoPlacementResult best = first;
        for (int i = 0; i < 24; ++i) {
            fine = coarse / float(std::max(1.05, std::sqrt(1.0 / std::max(excess(best), 1e-6))));
            AutoPlacementResult next = place(fine, levels);
            if (!fits(next)) break;
            coarse = fine;
            best = std::move(next);
        }
        return bisect(fine, coarse, std::move(best), levels);
    };
    auto finest = [](const AutoPlacementResult& r) {
        float f = std::numeric_limits<float>::infinity();
        for (const ProbeVolume& v : r.volumes) {
            glm::vec3 c = v.cellSize();
            f = std::min(f, std::max(c.x, std::max(c.y, c.z)));
        }
        return f;
    };

    const int levels = adaptive ? req.adaptive.levels : 0;
    AutoPlacementResult first = place(spacing, levels);
    spacing = first.spacing;
    AutoPlacementResult best = first;
    if (!fits(first)) {
        best = coarsen(first, levels);
        if (adaptive) {
            // Under a budget the nested grid must be a 2^levels subdivision of the outer one,
            // which rounds the spacing in big steps; fewer levels, or one uniform volume when
            // nothing was worth nesting, may fit a finer spacing into the same memory. The
            // finest spacing that fits wins (ties: fewer bytes).
            for (int alt : {1, 0}) {
                if (alt >= levels) continue;

                AutoPlacementResult a = place(spacing, alt);
                if (!fits(a)) a = coarsen(a, alt);
                if (finest(a) < finest(best) * 0.999f ||
                    (finest(a) <= finest(best) * 1.001f && a.bytes < best.bytes))
                    best = std::move(a);
            }
        }
        std::ostringstream note;
        note << option << ": spacing " << spacing << " needs " << first.probes << " probes, "
             << mib(double(first.bytes)) << " as " << formatName(req.format) << "; coarsened to "
             << "finest spacing " << finest(best) << " (" << best.volumes.size() << " volume(s), "
             << best.probes << " probes, " << mib(double(best.bytes)) << ") to fit ";
        if (defaultBudget)
            note << "the default budget";
        else if (budget > 0.0 && double(first.bytes) > budget)
            note << budgetOption(budget);
        else
            note << "the limit of " << req.maxProbes << " probes";
        best.notes.push_back(note.str());
    } else if (req.sparse && budget > 0.0 && !(req.adaptive.spacing > 0.0f)) {
        // The finest spacing whose stored bytes fit, over the same level choices as above.
        best = refine(first, levels);
        if (adaptive)
            for (int alt : {1, 0}) {
                if (alt >= levels) continue;
                AutoPlacementResult a = place(spacing, alt);
                a = fits(a) ? refine(a, alt) : coarsen(a, alt);
                if (finest(a) < finest(best) * 0.999f ||
                    (finest(a) <= finest(best) * 1.001f && a.bytes < best.bytes))
                    best = std::move(a);
            }
        std::ostringstream note;
        note << option << ": sparse storage fits finest spacing " << finest(best) << " ("
             << best.volumes.size() << " volume(s), " << best.probes << " probes, "
             << mib(double(best.bytes)) << " stored) into the budget";
        best.notes.push_back(note.str());
    } else if (!capNote.empty()) {
        best.notes.push_back(capNote);
    }
    // Lattice choice (auto only, when the budget set the spacing): the finest spacing that
    // fits may put a wall on a probe plane, which costs more accuracy than the resolution
    // gains (LatticeAlignment.h). A spacing up to 10% coarser that also fits and keeps clearly
    // less surface on probe planes wins.
    auto onPlanes = [&](const AutoPlacementResult& r) {
        float worst = 0.0f;
        for (const ProbeVolume& v : r.volumes)
            worst = std::max(worst, surfaceOnProbePlanes(v, triangles));
        return worst;
    };
    if (adaptive && budget > 0.0 && !(req.adaptive.spacing > 0.0f)) {
        best.onProbePlanes = onPlanes(best);
        const float base = best.spacing;
        // The same tiers at coarser spacings, and, when the result is one volume (an enclosed
        // scene refines its outer volume to one fine grid), one uniform volume: its lattice
        // moves with every step, a tiered one only when the outer count changes.
        std::vector<int> tiers{best.levels};
        if (best.volumes.size() == 1 && best.levels > 0) tiers.push_back(0);
        for (int levels : tiers)
            for (int step = levels == best.levels ? 1 : 0; step <= 5; ++step) {
                AutoPlacementResult a = place(base * (1.0f + 0.02f * float(step)), levels);
                if (!fits(a)) continue;
                a.onProbePlanes = onPlanes(a);
                if (a.onProbePlanes < best.onProbePlanes - kLatticeScoreMargin) {
                    a.notes = std::move(best.notes);
                    best = std::move(a);
                }
            }
    }
    // Where the lattice sits, by measured error (LatticeShiftSearch.h). Same condition as the
    // lattice choice above: with an explicit spacing the user placed the grid.
    if (adaptive && budget > 0.0 && !(req.adaptive.spacing > 0.0f) && req.latticeSearch) {
        const auto t0 = std::chrono::steady_clock::now();
        const Scenario light = req.lighting ? *req.lighting : resolveScenarios({}, {}, scene)[0];
        PlacementErrorSettings es;
        es.threads = req.adaptive.threads;
        const float cell = finest(best);
        es.bounces = req.bounces;
        const PlacementErrorEstimate estimate(scene, *rays, light, 0.5f * cell, 0.5f * cell, es);
        const glm::vec3 finestCell = [&] {
            glm::vec3 c(std::numeric_limits<float>::infinity());
            for (const ProbeVolume& v : best.volumes)
                c = glm::min(c, v.cellSize());
            return c;
        }();
        best.latticeShift = searchLatticeShift(
            best.volumes, finestCell,
            [&](const std::vector<ProbeVolume>& v) {
                return estimate.relativeError(v, req.sparse);
            },
            [&](const std::vector<ProbeVolume>& v) {
                AutoPlacementResult r = best;
                r.volumes = v;
                r.bytes = storedBytes(v);
                return fits(r);
            });
        best.bytes = storedBytes(best.volumes);
        best.onProbePlanes = onPlanes(best);
        best.latticeSearched = true;
        best.latticeSearchSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    // The default budget coarsens every time: that is how the default is defined, not news.
    if (defaultBudget) best.notes.clear();
    best.budgetBytes = budget;
    best.defaultBudget = defaultBudget;
    best.placements = placements;
    return best;
}

} // namespace pb::probes
