#pragma once
// Picks an index in proportion to its weight in constant time (Vose's alias method): the
// bake's light tables (EmitterTable.h, LitSurfaces.h) choose what to sample with it.
// Deterministic: the same weights give the same table.
#include "core/HugePages.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pb::raytrace {

class AliasTable {
public:
    AliasTable() = default;
    // Weights must be finite and >= 0 with a positive sum, at most 2^32 of them; otherwise the
    // table is empty.
    explicit AliasTable(const std::vector<double>& weights);

    bool empty() const { return probability_.empty(); }
    // weight(k) / sum of weights.
    double probability(std::size_t k) const { return probability_[k]; }
    // The index for a uniform u in [0, 1).
    std::size_t pick(float u) const;
    // Hints that pick(u) comes soon (its column is read at random from a large table).
    void prefetch(float u) const { __builtin_prefetch(&columns_[column(u)]); }

private:
    std::size_t column(float u) const {
        const std::size_t n = columns_.size();
        return std::min(std::size_t(u * float(n)), n - 1);
    }

    // One column: the chance of keeping its own index, else its alias. Both in one 8-byte
    // entry, so a pick reads one cache line; on huge pages (HugePages.h), since a large table
    // is read at random (the lit-surface table of a big scene has millions of columns).
    struct Column {
        float keep;
        std::uint32_t alias;
    };
    std::vector<double> probability_;
    HugePageVector<Column> columns_;
};

} // namespace pb::raytrace
