#pragma once
// Picks an index in proportion to its weight in constant time (Vose's alias method): the
// bake's light tables (EmitterTable.h, LitSurfaces.h) choose what to sample with it.
// Deterministic: the same weights give the same table.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace pb::probes {

class AliasTable {
public:
    AliasTable() = default;
    // Weights must be finite and >= 0 with a positive sum; otherwise the table is empty.
    explicit AliasTable(const std::vector<double>& weights);

    bool empty() const { return probability_.empty(); }
    // weight(k) / sum of weights.
    double probability(std::size_t k) const { return probability_[k]; }
    // The index for a uniform u in [0, 1).
    std::size_t pick(float u) const;
    // Hints that pick(u) comes soon (its column is read at random from a large table).
    void prefetch(float u) const {
        const std::size_t k = column(u);
        __builtin_prefetch(&keep_[k]);
        __builtin_prefetch(&alias_[k]);
    }

private:
    std::size_t column(float u) const {
        const std::size_t n = keep_.size();
        return std::min(std::size_t(u * float(n)), n - 1);
    }

    std::vector<double> probability_;
    std::vector<float> keep_; // chance of keeping the column's own index
    std::vector<std::size_t> alias_;
};

} // namespace pb::probes
