#include "BenchResult.h"

namespace pb::bench {

const SectionTiming* VariantResult::section(const std::string& name) const {
    for (const SectionTiming& s : sections)
        if (s.name == name) return &s;
    return nullptr;
}

const DeltaResult* SessionResult::vsReference() const {
    for (const DeltaResult& d : deltas)
        if (d.planned.kind == DeltaKind::VsReference) return &d;
    return nullptr;
}

void pairDeltas(SessionResult& s) {
    for (const PlannedDelta& p : s.session.deltas) {
        DeltaResult d;
        d.planned = p;
        const VariantResult &off = s.variants[size_t(p.off)], &on = s.variants[size_t(p.on)];
        if (off.ok() && on.ok() && !off.roundMedians.empty() &&
            off.roundMedians.size() == on.roundMedians.size()) {
            d.measured = true;
            d.ms = stats::pairedShift(off.roundMedians, on.roundMedians);
            if (off.accuracy.measured && on.accuracy.measured) {
                d.flip = on.accuracy.flipMean - off.accuracy.flipMean;
                d.psnr = on.accuracy.psnr - off.accuracy.psnr; // NaN/inf when one is identical
                d.ssim = on.accuracy.ssim - off.accuracy.ssim;
                d.relativeMseGi = on.accuracy.relativeMseGi - off.accuracy.relativeMseGi;
            }
        }
        s.deltas.push_back(d);
    }
}

TruthErrorSplit sessionTruthSplit(const SessionResult& s) {
    return splitTruthError(s.profile().vsTruth, s.reference().vsTruth, s.referenceFewerPassesVsTruth,
                           s.directLightVsTruth);
}

} // namespace pb::bench
