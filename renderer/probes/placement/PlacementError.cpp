#include "probes/placement/PlacementError.h"

#include "core/Error.h"
#include "probes/placement/AutoVolume.h"
#include "probes/bake/Baker.h"
#include "probes/placement/IrradianceError.h"
#include "probes/ProbeSampler.h"
#include "raytrace/StaticTriangles.h"
#include "probes/bake/SurfaceSamples.h"

namespace pb::probes {

namespace {
// Trial bakes are estimates compared with each other: one round of rays (no noise target), and
// a few emitter samples so that an emitter-lit scene is not ranked on chance hits. 32, as many as
// a trial's rays: at 64 their shadow rays were a third of a trial's radiance passes (the
// garden), and the shifts chosen on the nine scenes measured are the same; at 16 the built-in
// Cornell box's changed (studies/results/2026-12-04-bake-setup-costs.md).
void trialNoise(BakeSettings& s) {
    s.noiseTarget = 0.0f;
    s.emitterSamples = 32;
    s.litSamples = 0; // the placement's error is scored against a gather of rays alone
}
} // namespace

PlacementErrorEstimate::PlacementErrorEstimate(const scene::Scene& scene, const raytrace::RayScene& rs,
                                               const Scenario& scenario, float sealedBelow,
                                               float truthSpacing,
                                               const PlacementErrorSettings& settings)
    : scene_(scene), rays_(rs), scenario_(scenario), settings_(settings),
      triangles_(raytrace::staticBakeTriangles(scene)) {
    points_ = surfaceSamples(triangles_, rs, settings.points, sealedBelow, settings.seed);
    if (points_.empty())
        throw Error("placement error estimate: the scene has no open static surface");
    if (settings.bounces < 1) throw Error("placement error estimate: bounces must be at least 1");
    GatherSettings g;
    g.rays = settings.gatherRays;
    g.threads = settings.threads;
    if (settings.bounces == 1) {
        truth_ = gatherIrradiance(rs, scenario, scene.lights, points_, nullptr, g);
        return;
    }
    BakeRequest req;
    req.volumes = {fitAutoVolume(raytrace::staticBakeBounds(scene), truthSpacing, kAutoMaxProbes,
                                 AutoLattice::HalfCellMargin)
                       .volume};
    req.scenarios = {scenario};
    req.settings.raysPerProbe = settings.probeRays;
    req.settings.bounces = settings.bounces - 1;
    req.settings.format = StorageFormat::Rgba32f;
    trialNoise(req.settings);
    req.threads = settings.threads;
    req.rayScene = &rs;
    req.staticTriangles = &triangles_;
    req.sparse = true; // see the header: the gather reads surface cells
    req.irradianceOnly = true;
    const ProbeSet earlier = bakeProbes(scene, req);
    const ProbeSampler sampler(earlier, 0);
    truth_ = gatherIrradiance(rs, scenario, scene.lights, points_, &sampler, g);
}

double PlacementErrorEstimate::relativeError(const std::vector<ProbeVolume>& volumes,
                                             bool sparse, int threads,
                                             const std::vector<std::vector<std::uint8_t>>* kept) const {
    BakeRequest req;
    req.volumes = volumes;
    req.scenarios = {scenario_};
    req.settings.raysPerProbe = settings_.probeRays;
    req.settings.bounces = settings_.bounces;
    // rgba32f: no encoding pass (rgba16f's cost more than the trial's tracing), and the lattice,
    // not the storage format, is what the estimate compares.
    req.settings.format = StorageFormat::Rgba32f;
    trialNoise(req.settings);
    req.threads = threads < 0 ? settings_.threads : threads;
    req.sparse = sparse;
    req.rayScene = &rays_;
    req.staticTriangles = &triangles_;
    req.keptProbes = sparse ? kept : nullptr;
    req.irradianceOnly = true; // the sampler below reads nothing else
    const ProbeSet set = bakeProbes(scene_, req);
    const ProbeSampler sampler(set, 0);
    std::vector<SampleQuery> queries;
    queries.reserve(points_.size());
    for (const GatherPoint& p : points_)
        queries.push_back({p.pos, p.normal, p.normal});
    std::vector<IrradianceSample> samples(queries.size());
    // Without the behind-surface fade: the search's choices, hence the bakes, stay as they
    // were before it (SampleOptions::behindFade).
    SampleOptions asBefore;
    asBefore.behindFade = false;
    sampler.sampleBatch(queries.data(), queries.size(), samples.data(), asBefore);
    std::vector<glm::vec3> values(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i)
        values[i] = samples[i].irradiance;
    return irradianceErrors(values, truth_).relative;
}

} // namespace pb::probes
