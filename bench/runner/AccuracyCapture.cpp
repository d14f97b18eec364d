#include "AccuracyCapture.h"

#include "IrradianceScene.h"
#include "profile/GiVolumeLod.h"
#include "metrics/ImageMetrics.h"
#include "views/WorstCaseView.h"

#include <glm/gtc/constants.hpp>

#include <map>
#include <memory>

namespace pb::bench {

namespace {

image::ImageF giIrradiance(const scene::Scene& white, const AccuracyInputs& in,
                           const profile::Profile& switches) {
    render::GiOptions gi{in.probes, 0, switches};
    render::FrameRenderer r(white, in.settings, gi);
    const render::RenderView rv =
        render::makeRenderView(in.view, white.worldBounds(), in.width, in.height);
    for (int f = 0; f < std::max(1, in.frames); ++f)
        r.render(rv);
    image::ImageF e = r.readRadiance();
    for (size_t i = 0; i < e.pixels.size(); ++i)
        if (i % size_t(e.channels) < 3) e.pixels[i] *= glm::pi<float>();
    return e;
}

CoverageResult coverageOf(const AccuracyInputs& in, const std::string& volumeLod,
                          std::map<std::string, CoverageResult>& cache) {
    if (auto it = cache.find(volumeLod); it != cache.end()) return it->second;
    std::vector<bool> kept(in.probes->volumes.size(), false);
    for (int v : profile::selectVolumes(*in.probes, profile::parseVolumeLod(volumeLod)))
        kept[size_t(v)] = true;
    const views::CoverageTester tester(*in.scene, *in.probes, kept);
    const views::Coverage c = tester.measure(in.view, in.width, in.height);
    return cache[volumeLod] = {c.fraction, c.maxOverlap, c.meanOverlap};
}

} // namespace

void captureAccuracy(SessionResult& s, const std::vector<render::FrameRenderer*>& renderers,
                     const AccuracyInputs& in, AccuracyPictures* pictures) {
    const size_t n = s.variants.size();
    const scene::Scene white = irradianceOnlyScene(*in.scene);
    std::vector<image::Image8> ldr(n);
    std::vector<image::ImageF> irr(n);
    std::map<std::string, CoverageResult> coverage;
    for (size_t i = 0; i < n; ++i) {
        VariantResult& v = s.variants[i];
        if (!v.ok() || !renderers[i]) continue;
        ldr[i] = renderers[i]->readOutput();
        irr[i] = giIrradiance(white, in, v.variant.switches);
        // The frame's own allocations: the figure tune estimates for its budget.
        const render::GiMemory memory = renderers[i]->giMemory();
        v.giMemoryMiB = memory.totalMiB();
        v.giProbeMemoryMiB = double(memory.probes) / (1024.0 * 1024.0);
        if (const render::GpuProbes* gp = renderers[i]->gpuProbes())
            v.volumesKept = int(gp->volumes().size());
        v.coverage = coverageOf(in, v.variant.switches.gi.volumeLod, coverage);
    }
    const size_t ref = size_t(s.session.referenceVariant);
    if (!s.variants[ref].ok()) return; // no baseline: accuracy stays unmeasured
    for (size_t i = 0; i < n; ++i) {
        VariantResult& v = s.variants[i];
        if (!v.ok() || ldr[i].pixels.empty()) continue;
        metrics::FlipResult flip = metrics::ldrFlip(ldr[i], ldr[ref], in.pixelsPerDegree);
        v.accuracy.measured = true;
        v.accuracy.flipMean = flip.mean;
        v.accuracy.flipMax = flip.max;
        v.accuracy.psnr = metrics::psnr(ldr[i], ldr[ref]);
        v.accuracy.ssim = metrics::ssim(ldr[i], ldr[ref]);
        v.accuracy.relativeMseGi = metrics::relativeMse(irr[i], irr[ref]);
        if (pictures && i == 0) {
            pictures->flip = std::move(flip.map);
            pictures->frame = ldr[i];
            pictures->reference = ldr[ref];
        }
    }
}

} // namespace pb::bench
