#include "probes/placement/AutoPlacement.h"

#include "core/Error.h"
#include "core/ParallelFor.h"
#include "probes/bake/BakeHash.h"
#include "probes/placement/LatticeAlignment.h"
#include "probes/store/MemoryReport.h"
#include "probes/placement/PlacementError.h"
#include "raytrace/RayScene.h"
#include "probes/store/FreeSpaceTiles.h"
#include "probes/store/SparseStorage.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
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

// One auto placement as named steps: check the request, read the scene's geometry and the
// default budget, place at the starting spacing, then fit the limits (coarsen) or fill a
// sparse budget (refine), try fewer tiers, choose the lattice and search its shift. Every
// candidate placement goes through place() so `placements` counts the work done.
class AutoPlacer {
public:
    AutoPlacer(const scene::Scene& scene, const AutoPlacementRequest& req)
        : scene_(scene), req_(req), bounds_(raytrace::staticBakeBounds(scene)),
          adaptive_(req.mode == AutoMode::Adaptive),
          option_(adaptive_ ? "--volumes auto" : "--volumes auto-uniform"),
          // `auto` keeps probe planes off the boundary surfaces; `auto-uniform` is the naive fit.
          lattice_(adaptive_ ? AutoLattice::HalfCellMargin : AutoLattice::FitBounds),
          spacing_(req.adaptive.spacing), budget_(req.budgetBytes) {}

    AutoPlacementResult run() {
        checkRequest();
        prepare();
        const int levels = adaptive_ ? req_.adaptive.levels : 0;
        const AutoPlacementResult first = place(spacing_, levels);
        spacing_ = first.spacing;
        AutoPlacementResult best = first;
        if (!fits(first))
            best = fitLimits(first, levels);
        else if (req_.sparse && budget_ > 0.0 && !(req_.adaptive.spacing > 0.0f))
            best = fillSparseBudget(first, levels);
        else if (!capNote_.empty())
            best.notes.push_back(capNote_);
        if (req_.sparse && req_.freeSpace == FreeSpace::Ranked && budgetSetsSpacing())
            reserveFreeSpaceTiles(first, levels, best);
        if (budgetSetsSpacing()) chooseLattice(best);
        if (budgetSetsSpacing() && req_.latticeSearch) searchShift(best);
        // The default budget coarsens every time: that is how the default is defined, not news.
        if (defaultBudget_) best.notes.clear();
        best.budgetBytes = budget_;
        best.defaultBudget = defaultBudget_;
        best.placements = placements_;
        return best;
    }

private:
    void checkRequest() const {
        if (!(spacing_ >= 0.0f) || !std::isfinite(spacing_))
            throw Error("--spacing: must be a positive number");
        if (adaptive_ && (req_.adaptive.levels < 1 || req_.adaptive.levels > 4))
            throw Error("--auto-levels: must be 1..4 (got " + std::to_string(req_.adaptive.levels) +
                        ")");
        if (adaptive_ && req_.adaptive.maxChildren < 1)
            throw Error("--auto-max-children: must be >= 1");
        if (!(req_.budgetBytes >= 0.0) || !std::isfinite(req_.budgetBytes))
            throw Error("--probe-budget-mib: must be a positive number");
        if (req_.budgetBytes > 0.0) {
            ProbeVolume smallest;
            smallest.name = "smallest";
            const std::size_t need = memoryReport({smallest}, req_.format).total.stored.total();
            if (double(need) > req_.budgetBytes)
                throw Error(budgetOption(req_.budgetBytes) +
                            ": too small, the smallest volume (2x2x2 " + "probes) needs " +
                            formatBytes(need) + " as " + formatName(req_.format));
        }
        if (bounds_.empty()) fitAutoVolume(bounds_, 1.0f); // throws the one-line empty-scene error
    }

    // The triangles (adaptive tiers and sparse counts need them), the ray scene, and for
    // `auto` without a spacing the default start and budget.
    void prepare() {
        if (adaptive_ || req_.sparse) triangles_ = raytrace::staticBakeTriangles(scene_);
        if (!adaptive_) return;
        rays_ = std::make_unique<raytrace::RayScene>(scene_);
        if (spacing_ > 0.0f) return;
        // Default: the memory of the default uniform grid, spent where the scene needs it,
        // starting from half the uniform spacing near surfaces.
        const float uniform = defaultUniformSpacing(bounds_);
        spacing_ = 0.5f * uniform;
        if (!(budget_ > 0.0)) {
            AutoVolume fit = fitAutoVolume(bounds_, uniform, req_.maxProbes);
            budget_ = double(memoryReport({fit.volume}, req_.format).total.stored.total());
            defaultBudget_ = true;
        }
    }

    // Ranked free space: the bake's tiles fill what the placement leaves of the budget. When the
    // placement that fills it leaves them under kFreeSpaceTileShare, `auto` is placed again
    // into the rest (`auto-uniform`, the comparison baseline, stays as it is placed). 5% fewer
    // bytes should cost about 2.5% of spacing where surfaces set the memory (bytes ~
    // 1/spacing^2); a placement more than kMaxReserveCoarsening coarser is the placement's own
    // steps (tiers of 2^levels, the lattice choice), whose price on the surfaces exceeds what
    // the tiles return in the air (studies/results/2026-11-29-ranked-free-space.md): then the
    // first placement stays and the tiles get what it leaves.
    void reserveFreeSpaceTiles(const AutoPlacementResult& first, int levels,
                               AutoPlacementResult& best) {
        if (double(best.bytes) <= reservedBudget()) return;
        reserved_ = true;
        AutoPlacementResult r = fits(first) ? fillSparseBudget(first, levels)
                                            : fitLimits(first, levels);
        if (finest(r) <= finest(best) * (1.0f + kMaxReserveCoarsening))
            best = std::move(r);
        else
            reserved_ = false;
    }
    static constexpr float kMaxReserveCoarsening = 0.05f;

    // What the volumes may store of the budget: all of it, or, once the free-space tiles'
    // share is reserved (reserveFreeSpaceTiles), the rest (FreeSpaceTiles.h).
    double reservedBudget() const { return budget_ * (1.0 - kFreeSpaceTileShare); }
    double placeBudget() const { return reserved_ ? reservedBudget() : budget_; }

    // The budget, not the user, set the spacing: only then are the lattice steps ours to choose.
    bool budgetSetsSpacing() const {
        return adaptive_ && budget_ > 0.0 && !(req_.adaptive.spacing > 0.0f);
    }

    // What the bake will store of these volumes, as the memory report counts it. Sparse counts
    // mark every triangle's cells (about 5 ms a call on the apartment's 178k triangles), and the
    // placement asks again for placements it has seen (the bisection's ends, the lattice
    // search's fit checks and its result): 71 calls for 51 placements there. So each answer is
    // kept, by the volumes' hash as the bake's input hash takes them (always asked from the
    // placing thread).
    std::size_t storedBytes(const std::vector<ProbeVolume>& volumes) const {
        if (!req_.sparse) return memoryReport(volumes, req_.format).total.storedTotal();
        return seen(volumes).bytes;
    }

    // What sparse storage keeps of these volumes and what that stores, marked once per
    // placement. The lattice search hands the masks on to its trial bakes
    // (BakeRequest::keptProbes), which would mark the same cells again.
    struct SparseSeen {
        std::vector<std::vector<std::uint8_t>> kept; // sparseKeptProbes per volume
        std::size_t bytes = 0;
    };
    static std::uint64_t volumesHash(const std::vector<ProbeVolume>& volumes) {
        Hasher h;
        for (const ProbeVolume& v : volumes)
            hashVolume(h, v);
        return h.value();
    }
    // seen()'s answer if it was asked before, else nothing; never writes.
    const SparseSeen* seenBefore(const std::vector<ProbeVolume>& volumes) const {
        const auto it = sparseSeen_.find(volumesHash(volumes));
        return it == sparseSeen_.end() ? nullptr : &it->second;
    }
    const SparseSeen& seen(const std::vector<ProbeVolume>& volumes) const {
        const std::uint64_t h = volumesHash(volumes);
        if (auto it = sparseSeen_.find(h); it != sparseSeen_.end()) return it->second;
        SparseSeen s;
        s.kept = sparseKeptMasks(volumes, triangles_);
        s.bytes = sparseStoredBytes(volumes, s.kept);
        return sparseSeen_.emplace(h, std::move(s)).first->second;
    }

    std::size_t sparseStoredBytes(const std::vector<ProbeVolume>& volumes,
                                  const std::vector<std::vector<std::uint8_t>>& masks) const {
        // With free-space irradiance every probe left out keeps an irradiance tile unless it
        // bakes inside geometry, which is not known yet: all count (an upper bound).
        const std::vector<std::size_t> kept = keptCounts(masks);
        std::vector<std::size_t> rest;
        for (std::size_t v = 0; v < volumes.size(); ++v)
            rest.push_back(req_.freeSpace == FreeSpace::Irradiance
                               ? std::size_t(volumes[v].probeCount()) - kept[v]
                               : 0);
        return memoryReport(volumes, req_.format, &kept, &rest).total.storedTotal();
    }

    // levels 0 = one uniform volume.
    AutoPlacementResult place(float s, int levels) {
        ++placements_;
        if (req_.progress) req_.progress("placement", placements_, 0);
        AutoPlacementResult r;
        if (levels > 0) {
            AdaptiveOptions o = req_.adaptive;
            o.spacing = s;
            o.levels = levels;
            AdaptivePlacement p = placeAdaptiveVolumes(*rays_, triangles_, bounds_, o);
            r.volumes = std::move(p.volumes);
            r.stats = p.stats;
            r.spacing = s;
        } else {
            AutoVolume fit = fitAutoVolume(bounds_, s, req_.maxProbes, lattice_);
            if (placements_ == 1) capNote_ = fit.note;
            r.volumes.push_back(fit.volume);
            r.spacing = fit.spacing;
        }
        r.levels = levels;
        for (const ProbeVolume& v : r.volumes)
            r.probes += v.probeCount();
        r.bytes = storedBytes(r.volumes);
        return r;
    }

    bool fits(const AutoPlacementResult& r) const {
        if (budget_ > 0.0 && double(r.bytes) > placeBudget()) return false;
        if (r.probes > req_.maxProbes) return false;
        for (const ProbeVolume& v : r.volumes)
            if (!volumeProblem(v).empty()) return false;
        return true;
    }

    // How far over the limits a placement is (> 1: over).
    double excess(const AutoPlacementResult& r) const {
        double e = double(r.probes) / double(req_.maxProbes);
        if (budget_ > 0.0) e = std::max(e, double(r.bytes) / placeBudget());
        for (const ProbeVolume& v : r.volumes)
            e = std::max(e, double(v.probeCount()) / double(kMaxProbesPerVolume));
        return e;
    }

    // Geometric bisection between a spacing that does not fit and one that does (`best`, the
    // placement at `fitting`): the finest placement that fits, to within 2%.
    AutoPlacementResult bisect(float failing, float fitting, AutoPlacementResult best, int levels) {
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
    }

    // Grow the spacing until the placement fits (probes fall with the spacing squared near
    // surfaces, cubed in open space: the square root never undershoots much), then bisect
    // towards the finest spacing that fits.
    AutoPlacementResult coarsen(const AutoPlacementResult& first, int levels) {
        float lo = first.spacing, hi = first.spacing;
        AutoPlacementResult r = first;
        const int start = placements_;
        while (!fits(r)) {
            lo = hi;
            hi = lo * float(std::max(1.05, std::sqrt(excess(r))));
            AutoPlacementResult next = place(hi, levels);
            if ((next.probes >= r.probes && !fits(next) && placements_ - start > 8) ||
                placements_ - start > 60)
                throw Error(std::string(option_) + ": " +
                            (budget_ > 0.0 ? budgetOption(budget_) + " is" : "the probe limit is") +
                            " too small for this placement (it needs at least " +
                            formatBytes(next.bytes) + ", " + std::to_string(next.probes) +
                            " probes); raise it, lower --auto-levels or use auto-uniform");
            r = std::move(next);
        }
        return bisect(lo, hi, std::move(r), levels);
    }

    // Sparse storage: memory follows the surface, not the volume, so the starting spacing often
    // fits with room to spare: shrink it while it fits, then bisect (the mirror of coarsen).
    AutoPlacementResult refine(const AutoPlacementResult& first, int levels) {
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
    }

    static float finest(const AutoPlacementResult& r) {
        float f = std::numeric_limits<float>::infinity();
        for (const ProbeVolume& v : r.volumes) {
            glm::vec3 c = v.cellSize();
            f = std::min(f, std::max(c.x, std::max(c.y, c.z)));
        }
        return f;
    }

    // Under a budget the nested grid must be a 2^levels subdivision of the outer one, which
    // rounds the spacing in big steps; fewer levels, or one uniform volume when nothing was
    // worth nesting, may fit a finer spacing into the same memory. The finest spacing that
    // fits wins (ties: fewer bytes). `refineFitting`: a tier that fits at the start spacing
    // is refined into the budget (sparse), else kept.
    void tryFewerLevels(AutoPlacementResult& best, int levels, bool refineFitting) {
        if (!adaptive_) return;
        for (int alt : {1, 0}) {
            if (alt >= levels) continue;
            AutoPlacementResult a = place(spacing_, alt);
            if (!fits(a))
                a = coarsen(a, alt);
            else if (refineFitting)
                a = refine(a, alt);
            if (finest(a) < finest(best) * 0.999f ||
                (finest(a) <= finest(best) * 1.001f && a.bytes < best.bytes))
                best = std::move(a);
        }
    }

    // The start does not fit: coarsen every tier choice to the limits and say why.
    AutoPlacementResult fitLimits(const AutoPlacementResult& first, int levels) {
        AutoPlacementResult best = coarsen(first, levels);
        tryFewerLevels(best, levels, false);
        std::ostringstream note;
        note << option_ << ": spacing " << spacing_ << " needs " << first.probes << " probes, "
             << mib(double(first.bytes)) << " as " << formatName(req_.format) << "; coarsened to "
             << "finest spacing " << finest(best) << " (" << best.volumes.size() << " volume(s), "
             << best.probes << " probes, " << mib(double(best.bytes)) << ") to fit ";
        if (defaultBudget_)
            note << "the default budget";
        else if (budget_ > 0.0 && double(first.bytes) > placeBudget())
            note << budgetOption(budget_);
        else
            note << "the limit of " << req_.maxProbes << " probes";
        best.notes.push_back(note.str());
        return best;
    }

    // Sparse storage under a budget: the finest spacing whose stored bytes fit, over the same
    // tier choices as fitLimits.
    AutoPlacementResult fillSparseBudget(const AutoPlacementResult& first, int levels) {
        AutoPlacementResult best = refine(first, levels);
        tryFewerLevels(best, levels, true);
        std::ostringstream note;
        note << option_ << ": sparse storage fits finest spacing " << finest(best) << " ("
             << best.volumes.size() << " volume(s), " << best.probes << " probes, "
             << mib(double(best.bytes)) << " stored) into the budget";
        best.notes.push_back(note.str());
        return best;
    }

    float onPlanes(const AutoPlacementResult& r) const {
        float worst = 0.0f;
        for (const ProbeVolume& v : r.volumes)
            worst = std::max(worst, surfaceOnProbePlanes(v, triangles_));
        return worst;
    }

    // Lattice choice: the finest spacing that fits may put a wall on a probe plane, which
    // costs more accuracy than the resolution gains (LatticeAlignment.h). A spacing up to 10%
    // coarser that also fits and keeps clearly less surface on probe planes wins.
    void chooseLattice(AutoPlacementResult& best) {
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
    // lattice choice: with an explicit spacing the user placed the grid.
    void searchShift(AutoPlacementResult& best) {
        const auto t0 = std::chrono::steady_clock::now();
        const Scenario light = req_.lighting ? *req_.lighting : resolveScenarios({}, {}, scene_)[0];
        PlacementErrorSettings es;
        es.threads = req_.adaptive.threads;
        const float cell = finest(best);
        // A converging bake's trials run a fixed count (ProbeSet.h kConvergedTrialBounces).
        es.bounces = req_.bounces > 0 ? req_.bounces : kConvergedTrialBounces;
        const PlacementErrorEstimate estimate(scene_, *rays_, light, 0.5f * cell, 0.5f * cell, es);
        glm::vec3 finestCell(std::numeric_limits<float>::infinity());
        for (const ProbeVolume& v : best.volumes)
            finestCell = glm::min(finestCell, v.cellSize());
        // The unshifted estimate + at most kLatticeTrialsPerAxis trials per axis.
        const int most = 1 + 3 * kLatticeTrialsPerAxis;
        // A stage's trials run side by side, one per core: one trial bake keeps 2 cores only
        // about 70% busy (its serial steps: allocation, sparse masks, sampler set-up), while
        // separate trials keep every core busy (LatticeShiftSearch.h). Same result either way.
        const int cores = resolveThreadCount(req_.adaptive.threads);
        std::mutex progressLock;
        int estimates = 0;
        best.latticeShift = searchLatticeShift(
            best.volumes, finestCell,
            [&](const std::vector<ProbeVolume>& v, int threads) {
                // Runs on several threads at once: only looks up what fits() marked (every
                // shifted candidate, on the placing thread, before the trials start).
                const SparseSeen* marked = req_.sparse ? seenBefore(v) : nullptr;
                const double e = estimate.relativeError(v, req_.sparse, threads,
                                                        marked ? &marked->kept : nullptr);
                const std::lock_guard<std::mutex> lock(progressLock);
                if (req_.progress) req_.progress("lattice search", ++estimates, most);
                return e;
            },
            [&](const std::vector<ProbeVolume>& v) {
                AutoPlacementResult r = best;
                r.volumes = v;
                r.bytes = storedBytes(v);
                return fits(r);
            },
            cores);
        best.bytes = storedBytes(best.volumes);
        best.onProbePlanes = onPlanes(best);
        best.latticeSearched = true;
        best.latticeSearchSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }

    const scene::Scene& scene_;
    const AutoPlacementRequest& req_;
    const scene::Bounds bounds_;
    const bool adaptive_;
    const char* const option_;
    const AutoLattice lattice_;
    float spacing_; // the start spacing; after the first placement, the one it used
    double budget_; // the request's, or the default one (defaultBudget_)
    bool reserved_ = false; // the free-space tiles' share is kept out of the placement's budget
    bool defaultBudget_ = false;
    std::vector<raytrace::WorldTriangle> triangles_;
    mutable std::map<std::uint64_t, SparseSeen> sparseSeen_; // seen()'s answers, by volume hash
    std::unique_ptr<raytrace::RayScene> rays_;
    int placements_ = 0;
    std::string capNote_; // the first uniform fit's note (its spacing was capped)
};

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
    return AutoPlacer(scene, req).run();
}

} // namespace pb::probes
