#include "TruthAccuracyCapture.h"

#include "core/Error.h"
#include "metrics/ImageMetrics.h"
#include "truth/PathTracer.h"

namespace pb::bench {

void captureTruthAccuracy(SessionResult& s, const std::vector<render::FrameRenderer*>& renderers,
                          const image::ImageF& truthHdr, float exposure, double pixelsPerDegree,
                          TruthMaps* maps) {
    const image::Image8 truthLdr = truth::tonemap(truthHdr, exposure);
    if (maps) maps->truth = truthLdr;
    const size_t ref = size_t(s.session.referenceVariant);
    for (size_t i = 0; i < s.variants.size(); ++i) {
        VariantResult& v = s.variants[i];
        if (!v.ok() || !renderers[i]) continue;
        const image::Image8 ldr = renderers[i]->readOutput();
        const image::ImageF hdr = renderers[i]->readRadiance();
        if (ldr.width != truthHdr.width || ldr.height != truthHdr.height)
            throw Error("bench --truth: the truth is " + std::to_string(truthHdr.width) + "x" +
                        std::to_string(truthHdr.height) + ", the frame " + std::to_string(ldr.width) +
                        "x" + std::to_string(ldr.height));
        metrics::FlipResult flip = metrics::ldrFlip(ldr, truthLdr, pixelsPerDegree);
        v.vsTruth.measured = true;
        v.vsTruth.flipMean = flip.mean;
        v.vsTruth.flipMax = flip.max;
        v.vsTruth.psnr = metrics::psnr(ldr, truthLdr);
        v.vsTruth.relativeMse = metrics::relativeMse(hdr, truthHdr);
        if (!maps) continue;
        if (i == 0) {
            maps->profile = ldr;
            maps->profileFlip = flip.map;
        }
        if (i == ref) {
            maps->reference = ldr;
            maps->referenceFlip = std::move(flip.map);
        }
    }
}

} // namespace pb::bench
