#pragma once
// Covers the marked cells of a 3D cell grid with a few axis-aligned boxes (automatic
// placement turns each box into a child probe volume). Greedy top-down splitting: start from
// the tight box around every marked cell; repeatedly split the box whose best split saves the
// most probes, along the plane (any axis, any cell boundary) that minimises the probes of the
// two tight halves; stop at `maxBoxes` or when no split saves at least `minGain` of the box's
// probes. A box of n cells per axis holds prod(n + 1 + 2 * pad) probes (corner to corner,
// padded by `pad` cells per side), so splits happen across empty gaps, where the halves
// shrink, and never through a dense block (that would only add a probe plane).
// Deterministic: ties go to the first box, the lowest axis, the lowest plane.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace pb::probes {

struct CellBox {
    glm::ivec3 lo{0}, hi{0}; // cells [lo, hi) per axis
    glm::ivec3 size() const { return hi - lo; }
};

struct BoxMergeOptions {
    int maxBoxes = 4;
    int pad = 1;           // cells added per side after merging (counted in the cost)
    double minGain = 0.05; // a split must save this share of the box's probes
};

// `marked` has one entry per cell (index: cellIndex). Returns no box when nothing is marked. Boxes
// are tight (before padding), do not overlap, and together contain every marked cell; sorted by
// (lo.y, lo.z, lo.x).
std::vector<CellBox> mergeMarkedCells(const glm::ivec3& dims,
                                      const std::vector<std::uint8_t>& marked,
                                      const BoxMergeOptions& options = {});

inline std::size_t cellIndex(const glm::ivec3& dims, const glm::ivec3& c) {
    return (std::size_t(c.z) * std::size_t(dims.y) + std::size_t(c.y)) * std::size_t(dims.x) +
           std::size_t(c.x);
}

// Probes of a box of `cells` per axis, padded by `pad` per side.
double boxProbeCost(const glm::ivec3& cells, int pad);

} // namespace pb::probes
