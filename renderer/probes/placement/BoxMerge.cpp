#include "probes/placement/BoxMerge.h"

#include <algorithm>
#include <limits>

namespace pb::probes {
namespace {

struct Tight {
    glm::ivec3 lo{std::numeric_limits<int>::max()}, hi{std::numeric_limits<int>::min()};
    bool empty() const { return lo.x >= hi.x; }
    void add(const glm::ivec3& c) {
        lo = glm::min(lo, c);
        hi = glm::max(hi, c + 1);
    }
    void add(const Tight& t) {
        if (t.empty()) return;
        lo = glm::min(lo, t.lo);
        hi = glm::max(hi, t.hi);
    }
};

struct Split {
    double gain = 0.0;
    std::vector<CellBox> parts; // 2 or 3 tight boxes
};

double cost(const CellBox& b, int pad) {
    return boxProbeCost(b.size(), pad);
}

// Best split of `box` (tight) by one plane, or by two parallel planes (the middle part may
// shrink where one plane cannot gain: a floor under an open court between two wings).
// gain = probes saved (may be <= 0: no split).
Split bestSplit(const CellBox& box, const glm::ivec3& dims, const std::vector<std::uint8_t>& marked,
                int pad) {
    Split best;
    best.gain = -std::numeric_limits<double>::infinity();
    const glm::ivec3 n = box.size();
    // Tight box of the marked cells of each slab, per axis.
    std::vector<Tight> slabs[3] = {std::vector<Tight>(size_t(n.x)), std::vector<Tight>(size_t(n.y)),
                                   std::vector<Tight>(size_t(n.z))};
    for (int z = box.lo.z; z < box.hi.z; ++z)
        for (int y = box.lo.y; y < box.hi.y; ++y)
            for (int x = box.lo.x; x < box.hi.x; ++x) {
                glm::ivec3 c(x, y, z);
                if (!marked[cellIndex(dims, c)]) continue;
                for (int a = 0; a < 3; ++a)
                    slabs[a][size_t(c[a] - box.lo[a])].add(c);
            }
    const double whole = cost(box, pad);
    auto partCost = [&](const Tight& t) { return t.empty() ? 0.0 : cost({t.lo, t.hi}, pad); };
    for (int a = 0; a < 3; ++a) {
        const int m = n[a];
        if (m < 2) continue;
        const auto& sl = slabs[a];
        std::vector<Tight> prefix(size_t(m) + 1), suffix(size_t(m) + 1);
        for (int s = 0; s < m; ++s) {
            prefix[size_t(s) + 1] = prefix[size_t(s)];
            prefix[size_t(s) + 1].add(sl[size_t(s)]);
        }
        for (int s = m - 1; s >= 0; --s) {
            suffix[size_t(s)] = suffix[size_t(s) + 1];
            suffix[size_t(s)].add(sl[size_t(s)]);
        }
        // prefix[p] = slabs [0, p), suffix[q] = slabs [q, m).
        for (int p = 1; p < m; ++p) {
            const Tight &l = prefix[size_t(p)], &r = suffix[size_t(p)];
            if (l.empty() || r.empty()) continue;
            double gain = whole - partCost(l) - partCost(r);
            if (gain > best.gain) best = {gain, {{l.lo, l.hi}, {r.lo, r.hi}}};
        }
        for (int p = 1; p < m - 1; ++p) {
            const Tight& l = prefix[size_t(p)];
            if (l.empty()) continue;
            Tight mid;
            for (int q = p + 1; q < m; ++q) {
                mid.add(sl[size_t(q) - 1]);
                const Tight& r = suffix[size_t(q)];
                if (mid.empty() || r.empty()) continue;
                // Two boxes' worth of splitting: only taken when it beats the best 2-way split
                // by a margin (below), so the count of boxes grows only for a real gain.
                double gain = whole - partCost(l) - partCost(mid) - partCost(r);
                if (gain > best.gain * 1.25 && gain > 0.0)
                    best = {gain, {{l.lo, l.hi}, {mid.lo, mid.hi}, {r.lo, r.hi}}};
            }
        }
    }
    return best;
}

} // namespace

double boxProbeCost(const glm::ivec3& cells, int pad) {
    double p = 1.0;
    for (int a = 0; a < 3; ++a)
        p *= double(cells[a] + 1 + 2 * pad);
    return p;
}

std::vector<CellBox> mergeMarkedCells(const glm::ivec3& dims,
                                      const std::vector<std::uint8_t>& marked,
                                      const BoxMergeOptions& o) {
    Tight all;
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x)
                if (marked[cellIndex(dims, {x, y, z})]) all.add(glm::ivec3(x, y, z));
    std::vector<CellBox> boxes;
    if (all.empty()) return boxes;
    boxes.push_back({all.lo, all.hi});
    std::vector<Split> splits{bestSplit(boxes[0], dims, marked, o.pad)};
    while (int(boxes.size()) < std::max(o.maxBoxes, 1)) {
        int pick = -1;
        for (size_t i = 0; i < boxes.size(); ++i) {
            if (!(splits[i].gain > o.minGain * cost(boxes[i], o.pad))) continue;
            if (int(boxes.size() + splits[i].parts.size()) - 1 > o.maxBoxes) continue;
            if (pick < 0 || splits[i].gain > splits[size_t(pick)].gain) pick = int(i);
        }
        if (pick < 0) break;
        Split s = splits[size_t(pick)];
        boxes[size_t(pick)] = s.parts[0];
        splits[size_t(pick)] = bestSplit(s.parts[0], dims, marked, o.pad);
        for (size_t k = 1; k < s.parts.size(); ++k) {
            boxes.push_back(s.parts[k]);
            splits.push_back(bestSplit(s.parts[k], dims, marked, o.pad));
        }
    }
    std::sort(boxes.begin(), boxes.end(), [](const CellBox& a, const CellBox& b) {
        if (a.lo.y != b.lo.y) return a.lo.y < b.lo.y;
        if (a.lo.z != b.lo.z) return a.lo.z < b.lo.z;
        return a.lo.x < b.lo.x;
    });
    return boxes;
}

} // namespace pb::probes
