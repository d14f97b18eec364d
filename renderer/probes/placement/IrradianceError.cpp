#include "probes/placement/IrradianceError.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pb::probes {

IrradianceErrors irradianceErrors(const std::vector<glm::vec3>& values,
                                  const std::vector<glm::vec3>& truth,
                                  const std::vector<float>& covered) {
    if (values.size() != truth.size() || (!covered.empty() && covered.size() != truth.size()))
        throw Error("irradianceErrors: " + std::to_string(values.size()) + " values, " +
                    std::to_string(truth.size()) + " truths, " + std::to_string(covered.size()) +
                    " coverage weights");
    auto counts = [&](std::size_t i) { return covered.empty() || covered[i] > 0.99f; };
    auto sum = [](const glm::vec3& v) { return double(v.r) + double(v.g) + double(v.b); };
    double mean = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < truth.size(); ++i)
        if (counts(i)) {
            mean += sum(truth[i]);
            ++n;
        }
    IrradianceErrors out;
    if (n == 0) {
        out.relative = out.nmae = NAN;
        return out;
    }
    mean /= double(n);
    const double floor = 0.1 * mean;
    double rel = 0.0, abs = 0.0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!counts(i)) continue;
        const double d = sum(glm::abs(values[i] - truth[i]));
        rel += d / std::max(sum(truth[i]), floor);
        abs += d;
    }
    out.points = n;
    out.relative = rel / double(n);
    out.nmae = abs / double(n) / mean;
    return out;
}

} // namespace pb::probes
