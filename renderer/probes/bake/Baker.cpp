#include "probes/bake/Baker.h"

#include "probes/sh/ShIrradiance.h"

#include "core/Error.h"
#include "core/Luminance.h"
#include "core/ParallelFor.h"
#include "probes/StorageScale.h"
#include "probes/bake/BakeOrigin.h"
#include "probes/bake/BakePhaseClock.h"
#include "probes/bake/GeometryPass.h"
#include "probes/bake/LitSurfaces.h"
#include "probes/bake/NestingBlend.h"
#include "probes/bake/NoiseRounds.h"
#include "probes/bake/RadiancePass.h"
#include "probes/bake/RayDirections.h"
#include "raytrace/RayScene.h"
#include "probes/store/FreeSpaceTiles.h"
#include "probes/store/SparseStorage.h"

#include <algorithm>
#include <map>
#include <tuple>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>

namespace pb::probes {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Flat probe numbering over all volumes.
struct ProbeIndex {
    std::vector<std::size_t> first; // first flat index of each volume, plus the total
    explicit ProbeIndex(const std::vector<ProbeVolume>& vols) {
        first.push_back(0);
        for (const auto& v : vols)
            first.push_back(first.back() + std::size_t(v.probeCount()));
    }
    std::size_t total() const { return first.back(); }
    std::pair<int, int> locate(std::size_t flat) const {
        std::size_t v = 0;
        while (flat >= first[v + 1])
            ++v;
        return {int(v), int(flat - first[v])};
    }
};

// BakeStats::noisiestRegion: the volume with most of `above` (flat indices, ProbeIndex), and
// its aligned block of kNoisyBlockCells^3 cells with most of them.
std::optional<BakeStats::NoisyRegion> noisiestRegion(const std::vector<ProbeVolume>& vols,
                                                     const std::vector<std::size_t>& above) {
    if (above.empty()) return std::nullopt;
    const ProbeIndex index(vols);
    std::vector<std::size_t> perVolume(vols.size(), 0);
    for (std::size_t flat : above)
        ++perVolume[std::size_t(index.locate(flat).first)];
    const std::size_t v = std::size_t(
        std::max_element(perVolume.begin(), perVolume.end()) - perVolume.begin());
    std::map<std::tuple<int, int, int>, std::size_t> blocks;
    for (std::size_t flat : above) {
        const auto [vol, probe] = index.locate(flat);
        if (std::size_t(vol) != v) continue;
        const glm::ivec3 b = vols[v].probeCoords(probe) / kNoisyBlockCells;
        ++blocks[{b.x, b.y, b.z}];
    }
    const auto best = std::max_element(blocks.begin(), blocks.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;
    });
    const auto [bx, by, bz] = best->first;
    BakeStats::NoisyRegion r;
    r.volume = vols[v].name;
    r.from = glm::ivec3(bx, by, bz) * kNoisyBlockCells;
    r.to = glm::min(r.from + glm::ivec3(kNoisyBlockCells - 1), vols[v].counts - glm::ivec3(1));
    r.probes = best->second;
    r.probesInVolume = perVolume[v];
    return r;
}

QuantisationError measureQuantisation(const std::vector<float>& before, const ProbeTexture& after,
                                      QuantisationError e) {
    const int ch = after.shape.channels, used = ch == 4 ? 3 : ch; // irradiance alpha is 1
    float peak = 0.0f;
    for (float v : before)
        peak = std::max(peak, std::abs(v));
    const double floor = std::max(1e-3 * peak, 1e-12);
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < before.size(); i += std::size_t(ch))
        for (int c = 0; c < used; ++c) {
            double a = before[i + std::size_t(c)], b = after.texels[i + std::size_t(c)];
            double rel = std::abs(b - a) / std::max(std::abs(a), floor);
            e.maxRelative = std::max(e.maxRelative, rel);
            sum += rel;
            ++n;
        }
    e.meanRelative = n ? sum / double(n) : 0.0;
    return e;
}

void checkRequest(const BakeRequest& r) {
    if (r.volumes.empty()) throw Error("bake: no probe volumes");
    if (r.scenarios.empty()) throw Error("bake: no lighting scenario");
    for (std::size_t i = 0; i < r.onlyScenarios.size(); ++i)
        if (r.onlyScenarios[i] >= r.scenarios.size() ||
            (i > 0 && r.onlyScenarios[i] <= r.onlyScenarios[i - 1]))
            throw Error("bake: the scenario split's indices must ascend within the scenarios");
    if (r.settings.raysPerProbe < 1 || r.settings.raysPerProbe > 65536)
        throw Error("--rays: must be in [1, 65536] (got " +
                    std::to_string(r.settings.raysPerProbe) + ")");
    if (r.settings.bounces < 0 || r.settings.bounces > 64)
        throw Error("--bounces: must be in [0, 64], 0 until converged (got " +
                    std::to_string(r.settings.bounces) + ")");
    if (!(r.settings.backfaceThreshold >= 0.0f && r.settings.backfaceThreshold <= 1.0f))
        throw Error("backface threshold must be in [0, 1]");
    if (!(r.settings.noiseTarget == 0.0f ||
          (r.settings.noiseTarget > 0.0f && r.settings.noiseTarget < 1.0f)))
        throw Error("--noise-target: must be in (0, 1), or 0 for no noise control (got " +
                    std::to_string(r.settings.noiseTarget) + ")");
    if (r.settings.emitterSamples < 0 || r.settings.emitterSamples > 65536)
        throw Error("--emitter-samples: must be in [0, 65536] (got " +
                    std::to_string(r.settings.emitterSamples) + ")");
    if (r.settings.litSamples < 0 || r.settings.litSamples > 65536)
        throw Error("--lit-samples: must be in [0, 65536] (got " +
                    std::to_string(r.settings.litSamples) + ")");
}

// What every stage of one bake shares: the set being filled, the flat probe numbering, the
// threads and their ray counters, the phase clock and the progress over all stages.
struct BakeRun {
    const scene::Scene& scene;
    const BakeRequest& req;
    const BakeSettings& cfg;
    const raytrace::RayScene& rs;
    const int threads;
    const BakeProgressFn& progress;
    ProbeSet set;
    std::vector<int> parents; // per volume, its parent's index or -1
    ProbeIndex index;
    std::size_t stages;         // geometry + one per scenario and pass (grows while converging)
    std::size_t doneBefore = 0; // probes of the stages already finished
    std::vector<RayCounters> counters;
    BakePhaseClock phases{}; // the tracing time is the sum of its phases
    RadianceSlab slab{};     // reused by every pass (keeps its buffers)
    NoiseRounds noise{0.0f}; // the converged bake's bookkeeping (NoiseRounds.h)
    // Per scenario, built by its first pass when the settings ask for lit-surface samples.
    std::vector<std::unique_ptr<LitSurfaces>> lit{};
    // The current pass's radiance SH per volume (9 RGB per probe, zero for probes not
    // traced): the same samples as its irradiance tiles, projected (RadianceSlab::projectSh).
    std::vector<std::vector<glm::vec3>> passSh{};
    std::vector<int> passes{};          // per baked scenario: the passes run
    std::vector<double> lastChange{};   // and the share of the light its last pass added

    void report(const std::string& stage, std::size_t done) const {
        if (progress) progress({stage, doneBefore + done, stages * index.total()});
    }
    std::pair<int, int> locate(std::size_t flat) const { return index.locate(flat); }
    // The light samples of scenario s's first pass, from the pass's stream; later passes
    // carry only the previous pass's increment (EmitterSampling::incrementOnly).
    EmitterSampling passSampling(std::size_t s, int pass, std::uint64_t stream) {
        if (pass > 1) return {.incrementOnly = true};
        if (lit.size() <= s) lit.resize(s + 1);
        if (cfg.litSamples > 0 && !lit[s])
            lit[s] = std::make_unique<LitSurfaces>(rs, req.scenarios[s], scene.lights, threads,
                                                   counters[0].shadow);
        EmitterSampling e{cfg.emitterSamples, stream ^ 0x656d6974ull, // "emit"
                          cfg.litSamples, lit[s].get()};
        e.projectSh = !req.irradianceOnly; // a trial's SH stay zero (BakeRequest)
        return e;
    }
};

ProbeSet emptySet(const scene::Scene& scene, const BakeRequest& req, int threads) {
    ProbeSet set;
    // A trial is never written nor compared with a file, and hashing the scene's geometry
    // for each of the lattice search's trials cost about 1% of a default bake.
    set.inputHash = req.irradianceOnly ? 0 : bakeInputHash(scene, req);
    set.settings = req.settings;
    set.volumes = req.volumes;
    set.scenarios = req.scenarios;
    for (const ProbeVolume& v : set.volumes) {
        set.states.emplace_back(size_t(v.probeCount()));
        set.visibility.push_back(ProbeTexture::make(visibilityShape(v.counts), threads));
    }
    return set;
}

// Which probes the radiance passes trace. Sparse storage keeps only the surface corners and
// the free-space lattice (SparseStorage.h), and the radiance of a kept probe reads only kept
// probes: a later pass
// looks up the previous one at surface hits, i.e. at surface cells' corners. So the others'
// radiance is not traced. Except in a parent volume: its children's rings are blended
// towards it at ring positions, which need not lie on a surface. Their geometry pass still
// runs (the states stay as dense), except in a trial bake (geometryOnlyKept).
struct RadianceMask {
    std::vector<std::vector<std::uint8_t>> keep; // sparse only: per volume, per probe
    std::vector<bool> isParent;
    bool irradianceOnly = false; // left-out probes may keep their irradiance (FreeSpace)
    // A trial bake (BakeRequest::irradianceOnly) stored sparse with stand-ins drops the
    // probes sparse storage leaves out and reads only surface cells, whose corners it keeps:
    // their geometry is not traced either.
    bool geometryOnlyKept = false;

    explicit RadianceMask(const BakeRun& run)
        : isParent(run.set.volumes.size(), false),
          irradianceOnly(run.req.freeSpace != FreeSpace::StandIns) {
        if (run.req.sparse && run.req.keptProbes) {
            keep = *run.req.keptProbes;
        } else if (run.req.sparse && run.req.staticTriangles) {
            keep = sparseKeptMasks(run.set.volumes, *run.req.staticTriangles);
        } else if (run.req.sparse) {
            keep = sparseKeptMasks(run.set.volumes, raytrace::staticBakeTriangles(run.scene));
        }
        for (int p : run.parents)
            if (p >= 0) isParent[size_t(p)] = true;
        geometryOnlyKept = run.req.irradianceOnly && !keep.empty() && !irradianceOnly;
    }
    bool geometryNeeded(int v, int p) const {
        return !geometryOnlyKept || isParent[size_t(v)] || keep[size_t(v)][size_t(p)] != 0;
    }
    // With FreeSpace::Irradiance or Ranked a probe sparse storage leaves out is still traced:
    // it may keep its irradiance tile (ProbeState::irradianceOnly), and Ranked compares it
    // with its stand-in. Its irradiance is the sum of every pass, so every pass traces it.
    bool needed(const ProbeSet& set, int v, int p) const {
        if (!set.states[size_t(v)][size_t(p)].valid) return false;
        return keep.empty() || isParent[size_t(v)] || irradianceOnly ||
               keep[size_t(v)][size_t(p)] != 0;
    }
};

// 1. Geometry: per probe its state (validity, relocation) and its visibility tile.
void bakeGeometry(BakeRun& run, const RadianceMask& mask) {
    ProbeSet& set = run.set;
    // The geometry pass's rotation does not follow the seed: where probes sit (relocation) and
    // which are valid must not change when a scene is re-baked with another seed, only the
    // radiance's sampling noise may (the seed's job). kGeometrySeed keeps the rotation the
    // default seed always had.
    const int rays = run.req.geometryRays > 0 ? run.req.geometryRays : run.cfg.raysPerProbe;
    const auto dirs = passDirections(rays, geometryStream(kGeometrySeed));
    const ProbeConvolution conv(dirs);
    std::vector<GeometryScratch> scratch(static_cast<size_t>(run.threads));
    std::vector<std::vector<float>> vis(
        static_cast<size_t>(run.threads),
        std::vector<float>(kVisibilityInterior * kVisibilityInterior * 2));
    parallelFor(
        run.index.total(), run.threads,
        [&](std::size_t flat, int t) {
            auto [v, p] = run.locate(flat);
            if (!mask.geometryNeeded(v, p)) return;
            const ProbeVolume& vol = set.volumes[size_t(v)];
            glm::ivec3 c = vol.probeCoords(p);
            float* out = vis[size_t(t)].data();
            ProbeState& st = set.states[size_t(v)][size_t(p)];
            bakeProbeGeometry(run.rs, vol, c, dirs, conv, run.cfg, scratch[size_t(t)], st, out,
                              run.counters[size_t(t)].primary);
            if (!st.valid) return;
            float* tile = tileOrigin(set.visibility[size_t(v)], c, kVisibilityTile);
            const int pitch = set.visibility[size_t(v)].shape.width;
            for (int y = 0; y < kVisibilityInterior; ++y)
                for (int x = 0; x < kVisibilityInterior; ++x)
                    for (int ch = 0; ch < 2; ++ch)
                        tile[(size_t(y + 1) * pitch + size_t(x + 1)) * 2 + size_t(ch)] =
                            out[(y * kVisibilityInterior + x) * 2 + ch];
        },
        [&](std::size_t done) { run.report("geometry", done); });
    run.doneBefore += run.index.total();
    for (ProbeTexture& t : set.visibility)
        fillAllBorders(t, kVisibilityInterior);
    run.phases.mark("geometry");
}

// The converged bake (BakeSettings::noiseTarget): the slab's probes still above the target get
// more rounds, each a fresh ray rotation and fresh emitter samples, averaged into their tile
// (cur) until they are below it or have had kMaxNoiseRounds.
void traceMoreRounds(BakeRun& run, const Scenario& sc, size_t s, int pass,
                     const ProbeSampler* previous, std::vector<ProbeTexture>& cur,
                     std::vector<std::vector<float>>& irr, std::size_t first, std::size_t count) {
    const BakeSettings& cfg = run.cfg;
    const int rays = passRays(cfg.raysPerProbe, pass);
    for (int round = 1; round < kMaxNoiseRounds; ++round) {
        const std::vector<std::size_t> todo = run.noise.aboveTarget(count);
        if (todo.empty()) return;
        const std::uint64_t stream = roundStream(cfg.seed, int(s), pass, round);
        const auto dirs = passDirections(rays, stream);
        const ProbeConvolution conv(dirs, ProbeConvolution::Parts::IrradianceOnly);
        const EmitterSampling nee = run.passSampling(s, pass, stream);
        run.slab.reset(todo.size(), rays);
        parallelFor(todo.size(), run.threads, [&](std::size_t j, int t) {
            auto [v, p] = run.locate(first + todo[j]);
            const ProbeVolume& vol = run.set.volumes[size_t(v)];
            const ProbeState& st = run.set.states[size_t(v)][size_t(p)];
            glm::ivec3 c = vol.probeCoords(p);
            run.slab.trace(j, run.rs, sc, run.scene.lights, vol.localToWorldRotation(),
                           vol.toWorld(vol.gridLocal(c) + st.offset), dirs, previous,
                           run.counters[size_t(t)], nee, first + todo[j]);
        });
        run.noise.extraRays += std::uint64_t(todo.size()) * std::uint64_t(rays);
        run.phases.mark("trace");
        if (previous) {
            run.slab.lookUp(*previous, run.threads);
            run.phases.mark("lookup");
        }
        parallelFor(todo.size(), run.threads, [&](std::size_t j, int t) {
            auto [v, p] = run.locate(first + todo[j]);
            glm::ivec3 c = run.set.volumes[size_t(v)].probeCoords(p);
            float* tile = tileOrigin(cur[size_t(v)], c, kIrradianceTile);
            const int pitch = cur[size_t(v)].shape.width;
            float* out = irr[size_t(t)].data();
            run.slab.convolve(j, conv, out);
            const int k = run.noise.addRound(todo[j], out);
            glm::vec3 sh[kShL2Coefficients];
            run.slab.projectSh(j, conv, sh);
            glm::vec3* mean = &run.passSh[size_t(v)][size_t(p) * kShL2Coefficients];
            for (int q = 0; q < kShL2Coefficients; ++q)
                mean[q] += (sh[q] - mean[q]) / float(k); // the running mean, as the texels
            for (int y = 0; y < kIrradianceInterior; ++y)
                for (int x = 0; x < kIrradianceInterior; ++x)
                    for (int ch = 0; ch < 3; ++ch) {
                        float& texel =
                            tile[(size_t(y + 1) * pitch + size_t(x + 1)) * 4 + size_t(ch)];
                        // The running mean over the probe's k rounds.
                        texel += (out[(y * kIrradianceInterior + x) * 3 + ch] - texel) / float(k);
                    }
            run.noise.setMean(todo[j], tile, pitch);
        });
        run.phases.mark("convolve");
    }
}

// 2. Radiance of one scenario's bounce `pass`: the first (prev empty) the light reflected
// once, a later one the increment `prev` (the previous pass's) looked up at its hits and
// reflected once more. The irradiance textures of every volume, nested rings blended.
std::vector<ProbeTexture> bakeRadiancePass(BakeRun& run, const RadianceMask& mask, size_t s,
                                           int pass, const std::vector<ProbeTexture>& prev) {
    ProbeSet& set = run.set;
    const BakeSettings& cfg = run.cfg;
    const Scenario& sc = run.req.scenarios[s];
    std::vector<ProbeTexture> cur;
    run.passSh.clear();
    for (const ProbeVolume& v : set.volumes) {
        cur.push_back(ProbeTexture::make(irradianceShape(v.counts), run.threads));
        run.passSh.emplace_back(std::size_t(v.probeCount()) * kShL2Coefficients, glm::vec3(0.0f));
    }
    std::vector<SamplerVolume> prevViews, curViews;
    std::vector<ProbeTexture*> targets;
    for (size_t v = 0; v < set.volumes.size(); ++v) {
        if (!prev.empty())
            prevViews.push_back({&set.volumes[v], set.states[v].data(), &prev[v],
                                 &set.visibility[v], run.parents[v] < 0});
        curViews.push_back({&set.volumes[v], set.states[v].data(), &cur[v], &set.visibility[v],
                            run.parents[v] < 0});
        targets.push_back(&cur[v]);
    }
    const ProbeSampler prevSampler(prevViews);
    const ProbeSampler* previous = prev.empty() ? nullptr : &prevSampler;
    const int rays = passRays(cfg.raysPerProbe, pass);
    const auto dirs = passDirections(rays, radianceStream(cfg.seed, int(s), pass));
    const ProbeConvolution conv(dirs, ProbeConvolution::Parts::IrradianceOnly);
    // Light samples draw from their own streams, each probe by its index.
    const EmitterSampling nee = run.passSampling(s, pass, radianceStream(cfg.seed, int(s), pass));
    std::vector<std::vector<float>> irr(
        size_t(run.threads), std::vector<float>(kIrradianceInterior * kIrradianceInterior * 3));
    const std::string stage =
        sc.name + " pass " + std::to_string(pass) +
        (cfg.bounces > 0 ? "/" + std::to_string(cfg.bounces) : " (until converged)");
    // Slabs of probes (RadiancePass.h): about 2^18 rays each, so the indirect lookups
    // of a slab share cells without holding a whole pass's hits in memory.
    const std::size_t slabProbes =
        run.req.slabProbes > 0
            ? std::size_t(run.req.slabProbes)
            : std::max<std::size_t>(1, (std::size_t(1) << 18) / std::size_t(rays));
    run.phases.mark("setup");
    // Convolves probe `first + i` of the slab into its irradiance tile.
    auto writeTile = [&](std::size_t first, std::size_t i, int t) {
        auto [v, p] = run.locate(first + i);
        const ProbeVolume& vol = set.volumes[size_t(v)];
        glm::ivec3 c = vol.probeCoords(p);
        float* tile = tileOrigin(cur[size_t(v)], c, kIrradianceTile);
        const int pitch = cur[size_t(v)].shape.width;
        for (int y = 0; y < kIrradianceTile; ++y)
            for (int x = 0; x < kIrradianceTile; ++x)
                tile[(size_t(y) * pitch + size_t(x)) * 4 + 3] = 1.0f;
        if (!mask.needed(set, v, p)) return;
        float* out = irr[size_t(t)].data();
        run.slab.convolve(i, conv, out);
        if (!run.req.irradianceOnly) {
            run.slab.projectSh(i, conv, &run.passSh[size_t(v)][size_t(p) * kShL2Coefficients]);
            run.noise.firstRound(i, run.slab, conv, out);
        }
        for (int y = 0; y < kIrradianceInterior; ++y)
            for (int x = 0; x < kIrradianceInterior; ++x)
                for (int ch = 0; ch < 3; ++ch)
                    tile[(size_t(y + 1) * pitch + size_t(x + 1)) * 4 + size_t(ch)] =
                        out[(y * kIrradianceInterior + x) * 3 + ch];
    };
    const std::size_t total = run.index.total();
    for (std::size_t first = 0; first < total; first += slabProbes) {
        const std::size_t count = std::min(slabProbes, total - first);
        run.slab.reset(count, rays);
        run.noise.startSlab(first, count);
        // Without a previous pass a probe's radiance is final once traced: it is
        // convolved right away, while its rays are still in the cache.
        parallelFor(
            count, run.threads,
            [&](std::size_t i, int t) {
                auto [v, p] = run.locate(first + i);
                const ProbeVolume& vol = set.volumes[size_t(v)];
                const ProbeState& st = set.states[size_t(v)][size_t(p)];
                if (mask.needed(set, v, p)) {
                    glm::ivec3 c = vol.probeCoords(p);
                    run.slab.trace(i, run.rs, sc, run.scene.lights, vol.localToWorldRotation(),
                                   vol.toWorld(vol.gridLocal(c) + st.offset), dirs, previous,
                                   run.counters[size_t(t)], nee, first + i);
                }
                if (!previous) writeTile(first, i, t);
            },
            [&, first](std::size_t done) {
                if (!previous) run.report(stage, first + done);
            });
        run.phases.mark("trace");
        if (previous) {
            run.slab.lookUp(*previous, run.threads);
            run.phases.mark("lookup");
            parallelFor(
                count, run.threads, [&](std::size_t i, int t) { writeTile(first, i, t); },
                [&, first](std::size_t done) { run.report(stage, first + done); });
            run.phases.mark("convolve");
        }
        if (run.noise.active()) traceMoreRounds(run, sc, s, pass, previous, cur, irr, first, count);
        run.noise.finishSlab(count);
    }
    run.doneBefore += total;
    for (ProbeTexture& t : cur)
        fillAllBorders(t, kIrradianceInterior);
    blendNestedRings(set.volumes, run.parents, curViews, targets);
    run.phases.mark("convolve");
    return cur;
}

// The SH probes of every scenario, from the passes' ray projections (BakeRun::passSh, summed),
// except the nested rings' blended probes: their irradiance was blended towards the parent
// after the rays (NestingBlend.h), so they take the map projection of their final tile.
// Rounded to half floats (the GPU's RGBA16F).
void finishSh(BakeRun& run) {
    ProbeSet& set = run.set;
    for (std::size_t s = 0; s < set.sh.size(); ++s)
        for (std::size_t v = 0; v < set.volumes.size(); ++v) {
            const ProbeVolume& vol = set.volumes[v];
            std::vector<glm::vec3>& sh = set.sh[s][v];
            parallelFor(std::size_t(vol.probeCount()), run.threads, [&](std::size_t p, int) {
                const glm::ivec3 c = vol.probeCoords(int(p));
                if (blendsRing(vol, run.parents[v] >= 0, c, set.states[v][p])) {
                    const ShCoefficients m = projectIrradianceTile(c, set.irradiance[s][v]);
                    std::copy(m.begin(), m.end(),
                              sh.begin() + std::ptrdiff_t(p * kShL2Coefficients));
                }
                for (int k = 0; k < kShL2Coefficients; ++k)
                    sh[p * kShL2Coefficients + std::size_t(k)] =
                        toHalfPrecision(sh[p * kShL2Coefficients + std::size_t(k)]);
            });
        }
}

// The indices of req.scenarios this bake bakes: all, or the scenario split's part.
std::vector<std::size_t> bakedScenarios(const BakeRequest& req) {
    if (!req.onlyScenarios.empty()) return req.onlyScenarios;
    std::vector<std::size_t> all(req.scenarios.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    return all;
}

// Adds an increment pass into the running total (RGB of every texel; the tiles' alpha stays
// 1) and its SH into the total SH; returns the share of the light it added: per traced probe
// the increment's mean luminance over the total's (interior texels), averaged over the probes,
// so a dark room lit through a doorway counts as much as the bright one. A total under
// kNoiseFloorShare of the probes' mean counts as that floor (a probe next to nothing).
double addIncrement(const BakeRun& run, const RadianceMask& mask, std::vector<ProbeTexture>& total,
                    const std::vector<ProbeTexture>& inc, std::vector<std::vector<glm::vec3>>& sh,
                    const std::vector<std::vector<glm::vec3>>& incSh) {
    std::vector<std::pair<double, double>> probes; // (increment, total) mean luminance
    for (std::size_t v = 0; v < total.size(); ++v) {
        auto& t = total[v].texels;
        const auto& d = inc[v].texels;
        for (std::size_t i = 0; i < t.size(); i += 4)
            for (std::size_t ch = 0; ch < 3; ++ch)
                t[i + ch] += d[i + ch];
        for (std::size_t k = 0; k < sh[v].size(); ++k)
            sh[v][k] += incSh[v][k];
        const ProbeVolume& vol = run.set.volumes[v];
        const int pitch = total[v].shape.width;
        for (int p = 0; p < vol.probeCount(); ++p) {
            if (!mask.needed(run.set, int(v), p)) continue;
            const glm::ivec3 c = vol.probeCoords(p);
            const float* a = tileOrigin(total[v], c, kIrradianceTile);
            const float* b = tileOrigin(inc[v], c, kIrradianceTile);
            double all = 0.0, added = 0.0;
            for (int y = 1; y <= kIrradianceInterior; ++y)
                for (int x = 1; x <= kIrradianceInterior; ++x) {
                    const std::size_t at = (std::size_t(y) * std::size_t(pitch) + std::size_t(x)) * 4;
                    all += luminance(glm::vec3(a[at], a[at + 1], a[at + 2]));
                    added += luminance(glm::vec3(b[at], b[at + 1], b[at + 2]));
                }
            probes.emplace_back(added, all);
        }
    }
    if (probes.empty()) return 0.0;
    double mean = 0.0;
    for (const auto& p : probes)
        mean += p.second / double(probes.size());
    const double floor = double(kNoiseFloorShare) * mean;
    if (!(floor > 0.0)) return 0.0; // no light at all
    double change = 0.0; // signed: the increments' noise averages out, their light does not
    for (const auto& p : probes)
        change += p.first / std::max(p.second, floor) / double(probes.size());
    return std::fabs(change);
}

// 2. Radiance, per scenario: the first pass, then increments until the settings' pass count
// or convergence (Baker.h); the sum is the scenario's irradiance. `s` is the scenario's index
// in the whole request (its seed stream), also under a scenario split.
void bakeRadiance(BakeRun& run, const RadianceMask& mask) {
    std::vector<Scenario> baked;
    const int fixed = run.cfg.bounces, cap = fixed > 0 ? fixed : kMaxBouncePasses;
    for (size_t s : bakedScenarios(run.req)) {
        run.noise.startScenario(run.index.total());
        std::vector<ProbeTexture> total = bakeRadiancePass(run, mask, s, 1, {});
        std::vector<std::vector<glm::vec3>> sh = std::move(run.passSh);
        run.noise.setFloorFromCarried();
        // The previous pass's increment; empty while that is the first pass, whose increment is
        // `total` itself (a copy of it cost a single-threaded pass over fresh pages).
        std::vector<ProbeTexture> last;
        int passes = 1;
        double change = 1.0;
        while (passes < cap && (fixed > 0 || passes < 2 || change >= kConvergedChange)) {
            if (fixed == 0 && passes >= 2) ++run.stages; // one more than planned
            std::vector<ProbeTexture> inc =
                bakeRadiancePass(run, mask, s, passes + 1, last.empty() ? total : last);
            change = addIncrement(run, mask, total, inc, sh, run.passSh);
            last = std::move(inc);
            ++passes;
        }
        run.noise.finishScenario();
        run.passes.push_back(passes);
        run.lastChange.push_back(change);
        run.set.irradiance.push_back(std::move(total));
        run.set.sh.push_back(std::move(sh));
        baked.push_back(run.req.scenarios[s]);
    }
    run.set.scenarios = std::move(baked);
}

// 3. Storage format: every texture quantised to the format, with its error per texture
// (`storedBytes` false: RGBA32F keeps its texels alone, without the file's bytes).
std::vector<QuantisationError> quantiseSet(ProbeSet& set, StorageFormat format, int threads,
                                          bool storedBytes) {
    std::vector<ProbeTexture*> all;
    std::vector<QuantisationError> errors;
    for (size_t v = 0; v < set.visibility.size(); ++v) {
        all.push_back(&set.visibility[v]);
        errors.push_back({set.volumes[v].name, "visibility"});
    }
    for (size_t s = 0; s < set.irradiance.size(); ++s) {
        assignStorageScale(set.irradiance[s], format); // 1 unless out of range
        for (size_t v = 0; v < set.irradiance[s].size(); ++v) {
            all.push_back(&set.irradiance[s][v]);
            errors.push_back({set.volumes[v].name, "irradiance " + set.scenarios[s].name});
        }
    }
    parallelFor(all.size(), threads, [&](std::size_t i, int) {
        if (format == StorageFormat::Rgba32f) { // stores the floats as they are: no error
            if (storedBytes)
                quantise(*all[i], format);
            else
                sanitise(*all[i]); // the texels alone (BakeRequest::irradianceOnly)
            return;
        }
        std::vector<float> before(all[i]->texels.begin(), all[i]->texels.end());
        quantise(*all[i], format);
        errors[i] = measureQuantisation(before, *all[i], errors[i]);
    });
    return errors;
}

std::vector<std::size_t> invalidPerVolume(const ProbeSet& set) {
    std::vector<std::size_t> invalid;
    for (const auto& vs : set.states)
        invalid.push_back(std::size_t(
            std::count_if(vs.begin(), vs.end(), [](const ProbeState& p) { return !p.valid; })));
    return invalid;
}

// The counts of the finished set; the caller adds the times.
BakeStats countStats(const BakeRun& run, std::vector<std::size_t> bakedInvalidPerVolume) {
    BakeStats st;
    st.probes = run.set.probeCount();
    st.invalidProbes =
        std::accumulate(bakedInvalidPerVolume.begin(), bakedInvalidPerVolume.end(), std::size_t(0));
    st.invalidPerVolume = std::move(bakedInvalidPerVolume);
    st.storedProbes = run.set.storedCount();
    for (const auto& vs : run.set.states)
        for (const ProbeState& p : vs)
            st.relocatedProbes += p.offset != glm::vec3(0.0f);
    for (const RayCounters& c : run.counters) {
        st.primaryRays += c.primary;
        st.shadowRays += c.shadow;
    }
    st.triangles = run.rs.triangleCount();
    st.threads = run.threads;
    return st;
}

} // namespace

ProbeSet bakeProbes(const scene::Scene& scene, const BakeRequest& req, BakeStats* statsOut,
                    const BakeProgressFn& progress) {
    checkRequest(req);
    // Far from the origin: bake in a moved frame (BakeOrigin.h), then this returns origin 0.
    if (const glm::dvec3 origin = bakeOrigin(scene, req.volumes); origin != glm::dvec3(0.0))
        return bakeProbesAround(origin, scene, req, statsOut, progress);
    const auto t0 = Clock::now();
    std::vector<int> parents = validateVolumes(req.volumes, "volumes");
    const int threads = resolveThreadCount(req.threads);
    std::optional<raytrace::RayScene> own;
    if (!req.rayScene || req.recordRays) own.emplace(scene);
    const raytrace::RayScene& rs = own ? *own : *req.rayScene;
    const double buildSeconds = since(t0);
    if (req.recordRays) own->startRecording();

    BakeRun run{.scene = scene,
                .req = req,
                .cfg = req.settings,
                .rs = rs,
                .threads = threads,
                .progress = progress,
                .set = emptySet(scene, req, threads),
                .parents = std::move(parents),
                .index = ProbeIndex(req.volumes),
                // A converging bake plans two passes per scenario and adds the rest as it goes.
                .stages = 1 + bakedScenarios(req).size() *
                                  size_t(req.settings.bounces > 0 ? req.settings.bounces : 2),
                .counters = std::vector<RayCounters>(static_cast<size_t>(threads))};
    run.noise = NoiseRounds(req.settings.noiseTarget);
    const RadianceMask mask(run);
    bakeGeometry(run, mask);
    bakeRadiance(run, mask);
    // The SH technique's probes: every pass's ray samples projected and summed (probes/sh/ShIrradiance.h).
    if (!run.req.irradianceOnly) finishSh(run);
    const std::vector<BakePhase> phaseTimes = run.phases.take();
    if (req.recordRays) *req.recordRays = own->stopRecording();

    const auto tq = Clock::now();
    std::vector<QuantisationError> errors = quantiseSet(run.set, req.settings.format, threads,
                                                           !req.irradianceOnly);
    // Invalid as baked, before sparse storage marks its absent probes invalid too.
    std::vector<std::size_t> bakedInvalid = invalidPerVolume(run.set);
    // Left-out valid probes keep nothing, or irradiance and SH (all of them, or the ones
    // whose stand-in is furthest off).
    FreeSpaceTileChoice tiles;
    if (req.sparse && req.freeSpace == FreeSpace::Ranked && !req.onlyScenarios.empty()) {
        // A split bake's part: the choice ranks every scenario's light, so bake-merge makes it
        // (ProbeFileParts.h); the part keeps every tile.
        storeOnly(run.set, mask.keep, FreeSpace::Irradiance);
    } else if (req.sparse && req.freeSpace == FreeSpace::Ranked) {
        tiles = chooseFreeSpaceTiles(run.set, mask.keep, req.freeSpaceBudgetBytes);
        storeOnly(run.set, mask.keep, tiles.tiles);
    } else if (req.sparse) {
        storeOnly(run.set, mask.keep, req.freeSpace);
    }
    if (req.sparse) { // as the input hash has them
        run.set.freeSpace = req.freeSpace;
        run.set.freeSpaceBudgetBytes =
            req.freeSpace == FreeSpace::Ranked ? std::max(req.freeSpaceBudgetBytes, 0.0) : 0.0;
    }

    if (statsOut) {
        BakeStats st = countStats(run, std::move(bakedInvalid));
        st.buildSeconds = buildSeconds;
        for (const BakePhase& p : phaseTimes) {
            st.traceSeconds += p.wallSeconds;
            st.traceCpuSeconds += p.cpuSeconds;
        }
        st.phases = phaseTimes;
        st.quantiseSeconds = since(tq);
        st.seconds = since(t0);
        st.quantisation = std::move(errors);
        run.noise.summarise(st);
        st.noisiestRegion = noisiestRegion(run.set.volumes, run.noise.aboveTargetProbes());
        st.passes = run.passes;
        st.lastChange = run.lastChange;
        st.freeSpaceCandidates = tiles.candidates;
        st.freeSpaceTiles = tiles.chosen;
        st.freeSpaceWorstLeft = tiles.worstLeft;
        *statsOut = st;
    }
    return std::move(run.set);
}

} // namespace pb::probes
