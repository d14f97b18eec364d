#include "passes/ShadowViewFit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb::render {

namespace {
// 48 x 27 rays: about one per 27 x 27 pixels at 1280 x 720. A surface the grid misses is
// at most that far from one it hits on screen; the margin below covers the usual case.
constexpr int kRaysX = 48, kRaysY = 27;
// Widening of the hits' footprint: this share of its size on each side...
constexpr double kMarginShare = 0.08;
// ...and the snapping lattice: the square's side is a whole number of 1/64ths of the scene's.
constexpr double kSnapSteps = 64.0;
} // namespace

std::optional<LightSquare> fitShadowToView(const scene::RayGrid& grid, const RenderView& view,
                                           const glm::dmat4& lightFromWorld,
                                           const LightSquare& sceneSquare) {
    if (grid.empty() || !(sceneSquare.size > 0.0)) return std::nullopt;
    const glm::vec3 eye(view.eye);
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    bool any = false;
    for (int j = 0; j < kRaysY; ++j)
        for (int i = 0; i < kRaysX; ++i) {
            // Through the far plane of pixel-grid point (i, j): the renderer's own unprojection.
            const glm::vec4 clip((i + 0.5f) / kRaysX * 2.0f - 1.0f, (j + 0.5f) / kRaysY * 2.0f - 1.0f,
                                 1.0f, 1.0f);
            const glm::vec4 rel = view.relFromClip * clip;
            glm::vec3 dir = glm::vec3(rel) / rel.w;
            const float len = glm::length(dir);
            if (!(len > 0.0f)) continue;
            dir /= len;
            const scene::RayHit hit = grid.cast(eye, dir, view.farPlane);
            if (!std::isfinite(hit.distance)) continue;
            const glm::dvec3 p = view.eye + glm::dvec3(dir) * double(hit.distance);
            const glm::dvec2 l(lightFromWorld * glm::dvec4(p, 1.0));
            lo = glm::min(lo, l);
            hi = glm::max(hi, l);
            any = true;
        }
    if (!any) return std::nullopt;

    const double step = sceneSquare.size / kSnapSteps;
    const glm::dvec2 extent = hi - lo;
    double size = std::max(extent.x, extent.y) * (1.0 + 2.0 * kMarginShare);
    // One step more than the footprint needs: snapping the corner down may cost up to one.
    size = std::clamp(std::ceil(size / step) * step + step, step, sceneSquare.size);
    // Centred on the footprint, its corner on the lattice, and inside the scene's square.
    const glm::dvec2 centre = 0.5 * (lo + hi);
    glm::dvec2 min = glm::floor((centre - 0.5 * size) / step) * step;
    const glm::dvec2 sceneMax = sceneSquare.min + sceneSquare.size;
    min = glm::clamp(min, sceneSquare.min, sceneMax - size);
    return LightSquare{min, size};
}

} // namespace pb::render
