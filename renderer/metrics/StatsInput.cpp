#include "metrics/StatsInput.h"

#include "core/Error.h"

#include <cmath>
#include <string>

namespace pb::stats::detail {

void requireSample(const char* function, const char* name, const std::vector<double>& v) {
    if (v.empty()) throw Error(std::string(function) + ": sample " + name + " is empty");
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw Error(std::string(function) + ": sample " + name + " has a non-finite value at " +
                        std::to_string(i));
}

void requireConfidence(const char* function, double confidence) {
    if (!(confidence > 0 && confidence < 1))
        throw Error(std::string(function) + ": confidence must be in (0,1), got " +
                    std::to_string(confidence));
}

double normalCdf(double z) {
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

double normalQuantile(double p) {
    // Bisection on the CDF: slow by the standards of a numerics library, but exact to double
    // precision and called a handful of times per analysis.
    double lo = -40, hi = 40;
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
        const double mid = 0.5 * (lo + hi);
        (normalCdf(mid) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace pb::stats::detail
