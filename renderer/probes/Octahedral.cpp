#include "probes/Octahedral.h"

#include <cmath>

namespace pb::probes {
namespace {
float signNotZero(float a) {
    return a >= 0.0f ? 1.0f : -1.0f;
}
} // namespace

glm::vec3 octDecode(const glm::vec2& e) {
    glm::vec3 d(e.x, 1.0f - std::abs(e.x) - std::abs(e.y), e.y);
    if (d.y < 0.0f) {
        d.x = (1.0f - std::abs(e.y)) * signNotZero(e.x);
        d.z = (1.0f - std::abs(e.x)) * signNotZero(e.y);
    }
    return glm::normalize(d);
}

glm::vec2 octTexelCentreUv(int i, int j, int interior) {
    float n = float(interior);
    return {(2.0f * float(i) + 1.0f) / n - 1.0f, (2.0f * float(j) + 1.0f) / n - 1.0f};
}

glm::vec3 octTexelDirection(int i, int j, int interior) {
    return octDecode(octTexelCentreUv(i, j, interior));
}

void fillOctahedralBorder(float* tile, int rowPitch, int channels, int interior) {
    const int n = interior;
    auto copy = [&](int dx, int dy, int sx, int sy) {
        float* dst = tile + (size_t(dy) * rowPitch + dx) * channels;
        const float* src = tile + (size_t(sy) * rowPitch + sx) * channels;
        for (int c = 0; c < channels; ++c)
            dst[c] = src[c];
    };
    for (int x = 1; x <= n; ++x) {
        copy(x, 0, n + 1 - x, 1);
        copy(x, n + 1, n + 1 - x, n);
    }
    for (int y = 1; y <= n; ++y) {
        copy(0, y, 1, n + 1 - y);
        copy(n + 1, y, n, n + 1 - y);
    }
    copy(0, 0, n, n);
    copy(n + 1, 0, 1, n);
    copy(0, n + 1, n, 1);
    copy(n + 1, n + 1, 1, 1);
}

} // namespace pb::probes
