#include "raytrace/AliasTable.h"

#include <algorithm>
#include <cmath>

namespace pb::raytrace {

AliasTable::AliasTable(const std::vector<double>& weights) {
    double total = 0.0;
    for (double w : weights) {
        if (!(w >= 0.0) || !std::isfinite(w)) return;
        total += w;
    }
    if (!(total > 0.0) || !std::isfinite(total)) return;
    const std::size_t n = weights.size();
    if (n > std::size_t(UINT32_MAX)) return; // aliases are 32-bit
    probability_.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        probability_[k] = weights[k] / total;

    // Columns of height 1: each keeps its own index with its scaled probability and is topped
    // up by a column whose scaled probability is above 1.
    columns_.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        columns_[k] = {1.0f, std::uint32_t(k)};
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t k = 0; k < n; ++k) {
        scaled[k] = probability_[k] * double(n);
        (scaled[k] < 1.0 ? small : large).push_back(k);
    }
    while (!small.empty() && !large.empty()) {
        const std::size_t s = small.back(), l = large.back();
        small.pop_back();
        columns_[s] = {float(scaled[s]), std::uint32_t(l)};
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What is left has probability 1 up to rounding (its keep is already 1).
}

std::size_t AliasTable::pick(float u) const {
    const std::size_t n = columns_.size();
    const float scaled = u * float(n);
    const std::size_t k = std::min(std::size_t(scaled), n - 1);
    return scaled - float(k) >= columns_[k].keep ? columns_[k].alias : k;
}

} // namespace pb::raytrace
