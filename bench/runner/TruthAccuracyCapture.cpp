#include "TruthAccuracyCapture.h"

#include "core/Error.h"
#include "metrics/ImageMetrics.h"
#include "truth/PathTracer.h"

namespace pb::bench {

TruthAccuracy truthAccuracyOf(render::FrameRenderer& renderer, const image::ImageF& truthHdr,
                              const image::Image8& truthLdr, double pixelsPerDegree,
                              metrics::FlipResult* flipOut) {
    const image::Image8 ldr = renderer.readOutput();
    const image::ImageF hdr = renderer.readRadiance();
    if (ldr.width != truthHdr.width || ldr.height != truthHdr.height)
        throw Error("bench --truth: the truth is " + std::to_string(truthHdr.width) + "x" +
                    std::to_string(truthHdr.height) + ", the frame " + std::to_string(ldr.width) +
                    "x" + std::to_string(ldr.height));
    metrics::FlipResult flip = metrics::ldrFlip(ldr, truthLdr, pixelsPerDegree);
    TruthAccuracy a;
    a.measured = true;
    a.flipMean = flip.mean;
    a.flipMax = flip.max;
    a.psnr = metrics::psnr(ldr, truthLdr);
    a.relativeMse = metrics::relativeMse(hdr, truthHdr);
    if (flipOut) *flipOut = std::move(flip);
    return a;
}

void captureTruthAccuracy(SessionResult& s, const std::vector<render::FrameRenderer*>& renderers,
                          const image::ImageF& truthHdr, float exposure, double pixelsPerDegree,
                          TruthMaps* maps) {
    const image::Image8 truthLdr = truth::tonemap(truthHdr, exposure);
    if (maps) maps->truth = truthLdr;
    const size_t ref = size_t(s.session.referenceVariant);
    for (size_t i = 0; i < s.variants.size(); ++i) {
        VariantResult& v = s.variants[i];
        if (!v.ok() || !renderers[i]) continue;
        metrics::FlipResult flip;
        v.vsTruth = truthAccuracyOf(*renderers[i], truthHdr, truthLdr, pixelsPerDegree, &flip);
        if (!maps) continue;
        if (i == 0) {
            maps->profile = renderers[i]->readOutput();
            maps->profileFlip = flip.map;
        }
        if (i == ref) {
            maps->reference = renderers[i]->readOutput();
            maps->referenceFlip = std::move(flip.map);
        }
    }
}

} // namespace pb::bench
