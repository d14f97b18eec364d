#include "PredictionMeasured.h"

namespace pb::bench {

void attachMeasured(std::vector<DevicePrediction>& predictions,
                    const std::vector<SessionResult>& sessions) {
    for (DevicePrediction& d : predictions)
        for (PredictedSession& ps : d.sessions) {
            const SessionResult* s = nullptr;
            for (const SessionResult& r : sessions)
                if (r.session.profile.name == ps.profile) s = &r;
            if (!s) continue;
            for (PredictedVariant& pv : ps.variants)
                for (const VariantResult& vr : s->variants) {
                    if (vr.variant.id != pv.id || !vr.ok()) continue;
                    pv.measuredMs = vr.frameMs.median;
                    for (PredictedPass& pp : pv.passes)
                        if (const SectionTiming* t = vr.section(pp.pass)) pp.measuredMs = t->ms.median;
                }
            for (PredictedDelta& pd : ps.deltas)
                for (const DeltaResult& dr : s->deltas) {
                    const auto& vs = s->session.variants;
                    if (deltaKindName(dr.planned.kind) != pd.kind || !dr.measured) continue;
                    if (vs.at(size_t(dr.planned.off)).id == pd.offVariant &&
                        vs.at(size_t(dr.planned.on)).id == pd.onVariant)
                        pd.measuredMs = dr.ms.estimate;
                }
        }
}

} // namespace pb::bench
