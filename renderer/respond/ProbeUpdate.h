#pragma once
// The incremental update engine (issue 20): after a change, the probes it affects are marked,
// ordered by priority, and each frame a budget of them takes one freshly traced sample each,
// blended into the stored irradiance texels under a schedule (BlendSchedule.h). GL-free: the
// caller uploads the tiles of the probes a step updated (passes/ProbeTileUpload.h).
//
// Marking: a global change (sun, sky, a directional light) marks every valid probe at
// distance 0; a local one marks the valid probes within `radius` of any of its points, at
// their distance to the nearest. A change that leaves the bake's inputs as they were (a light
// scaled by 1) marks nothing: the caller passes `effective = false`.
// Order: ascending distance (nearest first; ties by volume, then probe index). Marked probes
// stay marked for the rest of the run (an update is never "done" under hysteresis); each step
// takes the next `budget` of them in that order, wrapping around, so with a budget below the
// marked count every probe is updated once per ceil(marked / budget) frames.
#include "probes/ProbeSet.h"
#include "respond/BlendSchedule.h"
#include "respond/ResponseEvent.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace pb::respond {

struct ProbeRef {
    int volume = 0, probe = 0;
    bool operator==(const ProbeRef&) const = default;
};

// Fills `rgb` (kIrradianceInterior^2 RGB triples, row-major) with a new irradiance sample of
// the probe; `sample` counts the probe's samples since the run began (0-based).
using SampleFn = std::function<void(const ProbeRef& probe, int sample, float* rgb)>;

// World position of a probe (relocation included).
glm::vec3 probeWorldPosition(const probes::ProbeSet& set, const ProbeRef& p);

class ProbeUpdater {
public:
    // Updates set.irradiance[scenario] in place (its `texels`; `stored` is left stale).
    ProbeUpdater(probes::ProbeSet& set, int scenario, Schedule schedule,
                 const ScheduleParams& params = {});

    // Marks the probes `change` affects (see above); returns how many were newly marked or
    // re-prioritised.
    std::size_t mark(const Change& change, float radius, bool effective = true);
    std::size_t markedCount() const { return order_.size(); }

    // One frame: updates up to `budget` marked probes (0: all of them) and returns them.
    std::vector<ProbeRef> step(int budget, const SampleFn& sample);

private:
    struct Marked {
        ProbeRef ref;
        float distance = 0;
    };
    void updateProbe(const ProbeRef& p, const SampleFn& sample);
    probes::ProbeSet& set_;
    int scenario_;
    Schedule schedule_;
    ScheduleParams params_;
    std::vector<Marked> order_;                   // priority order
    std::size_t next_ = 0;                        // where the next step starts in order_
    std::vector<std::vector<int>> hastenedIndex_; // [volume][probe] next sample index
    std::vector<std::vector<int>> samplesTaken_;  // [volume][probe]
};

} // namespace pb::respond
