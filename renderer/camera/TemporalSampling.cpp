#include "camera/TemporalSampling.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <stdexcept>
#include <utility>

namespace pb::camera {

namespace {
// Rank of (x, y) in the n x n ordered-dither matrix (n a power of two): the recursive Bayer
// construction, two bits of rank per level.
int bayerRank(int x, int y, int n) {
    int rank = 0;
    for (int bit = n >> 1; bit > 0; bit >>= 1) {
        const int bx = (x & bit) ? 1 : 0, by = (y & bit) ? 1 : 0;
        // 2x2 base pattern [[0, 2], [3, 1]] (row = y)
        const int base = by == 0 ? (bx == 0 ? 0 : 2) : (bx == 0 ? 3 : 1);
        rank = rank * 4 + base;
    }
    // The first level decided the top bits but must be the finest pattern: reverse the digits
    // so neighbouring ranks land in different quadrants.
    int reversed = 0;
    for (int levels = 0, r = rank; (1 << levels) < n; ++levels, r >>= 2)
        reversed = reversed * 4 + (r & 3);
    return reversed;
}
} // namespace

int jitterPeriod(int divisor) {
    return divisor * divisor;
}

glm::ivec2 giJitter(int divisor, std::uint64_t index) {
    if (divisor < 1 || divisor > 16 || (divisor & (divisor - 1)) != 0)
        throw std::invalid_argument("giJitter: divisor must be a power of two <= 16");
    if (divisor == 1) return glm::ivec2(0);
    const int want = int(index % std::uint64_t(jitterPeriod(divisor)));
    const int centre = (divisor - 1) / 2;
    for (int y = 0; y < divisor; ++y)
        for (int x = 0; x < divisor; ++x)
            if (bayerRank(x, y, divisor) == want)
                return glm::ivec2((x + centre) % divisor, (y + centre) % divisor);
    return glm::ivec2(centre); // unreachable: the ranks are a permutation
}

bool isCameraCut(const CameraState& prev, const CameraState& cur, const CameraCutRule& rule) {
    if (prev.width != cur.width || prev.height != cur.height) return true;
    if (std::abs(double(prev.fovYDegrees) - double(cur.fovYDegrees)) > rule.maxFovChangeDegrees)
        return true;
    const double cosTurn = glm::dot(glm::normalize(prev.forward), glm::normalize(cur.forward));
    const double turn = std::acos(std::clamp(cosTurn, -1.0, 1.0)) * 180.0 / glm::pi<double>();
    if (turn > rule.maxTurnDegrees) return true;
    const double extent = std::max(double(prev.farPlane), double(cur.farPlane));
    return glm::length(cur.eye - prev.eye) > rule.maxMoveFraction * extent;
}

} // namespace pb::camera
