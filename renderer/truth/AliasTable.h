#pragma once
// Walker's alias method (Vose's construction): draws index i with probability w_i / sum(w) in
// O(1) from one uniform number. The path tracer picks emissive triangles by power with it.
#include <cstddef>
#include <vector>

namespace pb::truth {

class AliasTable {
public:
    AliasTable() = default;
    // Weights must be finite and >= 0; an all-zero or empty list gives an empty table.
    explicit AliasTable(const std::vector<double>& weights);
    bool empty() const { return prob_.empty(); }
    std::size_t size() const { return prob_.size(); }
    // u in [0, 1).
    std::size_t sample(float u) const;
    // The probability of drawing i.
    float pdf(std::size_t i) const { return pdf_[i]; }

private:
    std::vector<float> prob_;
    std::vector<std::size_t> alias_;
    std::vector<float> pdf_;
};

} // namespace pb::truth
