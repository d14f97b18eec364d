#pragma once
// The gate's deterministic measurements of one profile (bench/gate/README.md): each
// profile's renderer runs a fixed sequence of frames - warm-up, one counted by GlCallCounter,
// one with the GI pass counting its evaluated pixels, one plain - so every figure below is
// the same run after run:
//   gl.<pass>.*         GL calls of the real frame per pass (GlCallCounter.h)
//   memory.*            probe data and GI target on the GPU (GpuProbes, GiApplyPass)
//   model.*, cache.*    the cost model (renderer/costmodel) of the same view with the pass's
//                       culling: pixels, fetches, bytes, and the profile's cache preset
//   glPixels            the GL pass's own evaluated pixels per volume (agreement check)
//   glInvocations       the apply shader's invocations per volume (atomic counter; empty
//                       where the context has none): what the device shaded
//   accuracy            FLIP / PSNR / relative MSE of the GI against the reference, as
//                       `probebench bench` measures it (runner/AccuracyCapture.h)
#include "bench/gate/GateRecord.h"
#include "frame/FrameRenderer.h"
#include "probes/ProbeSet.h"
#include "profile/PlatformProfile.h"
#include "scene/Scene.h"
#include "views/WorstCaseView.h"

#include <map>
#include <memory>
#include <string>

namespace pb::gate {

struct GateInputs {
    const scene::Scene* scene = nullptr;
    const probes::ProbeSet* probes = nullptr;
    scene::View view;
    render::FrameSettings settings;
    int width = 0, height = 0;
    int warmup = 2;
};

// One profile's renderer and where it is in the fixed frame sequence.
class GateRenderer {
public:
    GateRenderer(const GateInputs& in, const profile::PlatformProfile& p);
    render::FrameRenderer& renderer() { return *renderer_; }
    const render::RenderView& view() const { return view_; }
    const profile::PlatformProfile& profile() const { return profile_; }
    void frame(render::FrameTimer* timer = nullptr); // one frame, counted

private:
    profile::PlatformProfile profile_;
    std::unique_ptr<render::FrameRenderer> renderer_;
    render::RenderView view_;
};

// CPU ray scenes for the cost model, one per gi.volume_lod (building one builds a BVH).
class ModelScenes {
public:
    explicit ModelScenes(const GateInputs& in) : in_(in) {}
    const views::CoverageTester& forVolumeLod(const std::string& volumeLod);

private:
    const GateInputs& in_;
    std::map<std::string, std::unique_ptr<views::CoverageTester>> testers_;
};

// The counting frames (after warm-up) and the cost model: counters and glPixels of `out`.
void measureCounters(GateRenderer& r, const GateInputs& in, ModelScenes& scenes,
                     ProfileRecord& out);
// Accuracy of `profile`'s last frame against `reference`'s (both after measureCounters).
AccuracyValues measureAccuracy(GateRenderer& profile, GateRenderer& reference,
                               const GateInputs& in);

} // namespace pb::gate
