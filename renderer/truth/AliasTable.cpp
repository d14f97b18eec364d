#include "truth/AliasTable.h"

#include <algorithm>

namespace pb::truth {

AliasTable::AliasTable(const std::vector<double>& weights) {
    double total = 0.0;
    for (double w : weights)
        total += w > 0.0 ? w : 0.0;
    if (!(total > 0.0)) return;
    const std::size_t n = weights.size();
    prob_.assign(n, 1.0f);
    alias_.resize(n);
    pdf_.resize(n);
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        double w = weights[i] > 0.0 ? weights[i] : 0.0;
        pdf_[i] = float(w / total);
        scaled[i] = w / total * double(n);
        alias_[i] = i;
        (scaled[i] < 1.0 ? small : large).push_back(i);
    }
    while (!small.empty() && !large.empty()) {
        std::size_t s = small.back(), l = large.back();
        small.pop_back();
        large.pop_back();
        prob_[s] = float(scaled[s]);
        alias_[s] = l;
        scaled[l] = (scaled[l] + scaled[s]) - 1.0;
        (scaled[l] < 1.0 ? small : large).push_back(l);
    }
    // Left-overs are 1 up to rounding.
    for (std::size_t i : small)
        prob_[i] = 1.0f;
    for (std::size_t i : large)
        prob_[i] = 1.0f;
}

std::size_t AliasTable::sample(float u) const {
    const std::size_t n = prob_.size();
    float x = u * float(n);
    std::size_t i = std::min(n - 1, std::size_t(x));
    float frac = x - float(i);
    return frac < prob_[i] ? i : alias_[i];
}

} // namespace pb::truth
