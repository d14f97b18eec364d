#pragma once
// Where the update engine's fresh samples come from: the bake's own code (Baker.h) run on the
// changed world. `count` low-ray, single-round bakes (seeds 1..count after the file's seed,
// --rays-per-update rays per probe and pass, no noise rounds, RGBA32F so nothing is
// quantised) are traced once; a probe's k-th update takes its texels from bake k mod count.
// Each sample is thus an independent estimate of the new irradiance with the bake's full
// shading (direct light, emitter and lit-surface sampling, all bounce passes) - a real DDGI
// update gets the further bounces over later frames from its previous probes instead.
// The cost per update: its primary rays (rays per update x bounce passes; the shadow rays of
// direct light and light samples come on top) and the radiance passes' measured process CPU
// time divided by the probes they traced (this machine). The sample bakes trace the geometry
// pass with the file's ray count (BakeRequest::geometryRays) so that every probe sits where
// the file's bake put it; that pass is not charged.
//
// The converged reference is the full bake of the changed world with the file's own settings
// but kReferenceRayFactor times its rays per round (the geometry pass keeps the file's, so
// the probes sit where they did), cached under its input hash (readCachedProbeFile) so
// repeated runs trace it once. Why more rays: rooms with the sun off is lit by the sky through
// one window, and the file's 256 rays leave 5.7% mean probe noise even after 16 rounds
// (studies/results/2026-11-25-respond.md) - a reference that noisy would hide a 5% settle.
#include "probes/bake/Baker.h"
#include "respond/ProbeUpdate.h"

#include <functional>
#include <string>

namespace pb::respond {

// The probe file's bake, for `world`: its volumes and settings, one scenario (the world's),
// dense storage.
probes::BakeRequest bakeRequestFor(const World& world, const probes::ProbeSet& original);

// Whether the world's bake inputs differ (an event with no effect leaves them equal).
bool bakeInputsDiffer(const World& a, const World& b, const probes::ProbeSet& original);

constexpr int kReferenceRayFactor = 4;

class SampleBakes {
public:
    SampleBakes(const World& world, const probes::ProbeSet& original, int raysPerUpdate, int count,
                const std::function<void(const std::string&)>& progress = {});
    // rgb: kIrradianceInterior^2 RGB triples of the probe's interior texels.
    void sample(const ProbeRef& p, int sampleNo, float* rgb) const;
    double raysPerUpdate() const { return raysPerUpdate_; }   // primary rays
    double cpuMsPerUpdate() const { return cpuMsPerUpdate_; } // this machine
    int count() const { return int(bakes_.size()); }

private:
    std::vector<probes::ProbeSet> bakes_;
    double raysPerUpdate_ = 0, cpuMsPerUpdate_ = 0;
};

// The full re-bake of `world`, read from `cacheDir` when an earlier run stored it (an empty
// cacheDir: no cache). `note` says whether it was baked or read.
probes::ProbeSet convergedBake(const World& world, const probes::ProbeSet& original,
                               const std::string& cacheDir, std::string* note = nullptr);

} // namespace pb::respond
