#pragma once
// Puts this machine's measurements beside the device model's predictions: per variant its
// median frame and per pass its section's median, per switch the paired shift - matched by
// profile, variant id and the delta's two sides. GL-free.
#include "BenchResult.h"

#include <vector>

namespace pb::bench {

void attachMeasured(std::vector<DevicePrediction>& predictions,
                    const std::vector<SessionResult>& sessions);

} // namespace pb::bench
