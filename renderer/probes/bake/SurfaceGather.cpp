#include "probes/bake/SurfaceGather.h"

#include "core/Error.h"
#include "core/ParallelFor.h"
#include "probes/bake/RadiancePass.h"
#include "probes/bake/RayDirections.h"

#include <cmath>

namespace pb::probes {

std::vector<glm::vec3> cosineHemisphereSpiral(int rays) {
    // Point i on the unit disk at radius sqrt((i + 0.5) / n) and the golden angle: equal-area
    // strata; lifting the disk onto the hemisphere (z = sqrt(1 - r^2)) makes the density
    // proportional to cos(theta) (Malley's method).
    std::vector<glm::vec3> out(std::size_t(std::max(rays, 0)));
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < rays; ++i) {
        const double r2 = (double(i) + 0.5) / double(rays), r = std::sqrt(r2);
        const double phi = golden * double(i);
        out[std::size_t(i)] = glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)),
                                        float(std::sqrt(1.0 - r2)));
    }
    return out;
}

namespace {

// Columns: tangent, bitangent, n; the tangent turned by `twist` about n.
glm::mat3 normalFrame(const glm::vec3& n, float twist) {
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t0 = glm::normalize(glm::cross(helper, n)), b0 = glm::cross(n, t0);
    const glm::vec3 t = std::cos(twist) * t0 + std::sin(twist) * b0;
    return glm::mat3(t, glm::cross(n, t), n);
}

// The gathers' common loop: points in batches that bound the slab's memory (rays per point *
// 100 B or so per ray); `trace(slab, slot, point, thread)` shoots the point's rays into its
// slot of the batch, the indirect light is looked up, and `finish(L, point)` reads the slot's
// radiance per ray.
template <class Trace, class Finish>
void gatherInBatches(std::size_t points, int rays, int threads, const ProbeSampler* indirect,
                     Trace trace, Finish finish) {
    RadianceSlab slab;
    const std::size_t batch = std::max<std::size_t>(64, (1u << 18) / std::size_t(rays));
    for (std::size_t lo = 0; lo < points; lo += batch) {
        const std::size_t count = std::min(batch, points - lo);
        slab.reset(count, rays);
        parallelFor(count, threads, [&](std::size_t i, int t) { trace(slab, i, lo + i, t); });
        if (indirect) slab.lookUp(*indirect, threads);
        parallelFor(count, threads, [&](std::size_t i, int) { finish(slab.finish(i), lo + i); });
    }
}

} // namespace

std::vector<glm::vec3> gatherIrradiance(const raytrace::RayScene& rs, const Scenario& sc,
                                        const std::vector<scene::Light>& lights,
                                        const std::vector<GatherPoint>& points,
                                        const ProbeSampler* indirect, const GatherSettings& g) {
    if (g.rays < 1) throw Error("gather: rays must be at least 1, got " + std::to_string(g.rays));
    const std::vector<glm::vec3> dirs = cosineHemisphereSpiral(g.rays);
    const int threads = resolveThreadCount(g.threads);
    // The twist of point i comes from its own stream: the same for any batch or thread count.
    auto twist = [&](std::size_t i) {
        std::uint64_t state = g.seed ^ (0x9E3779B97F4A7C15ull * (std::uint64_t(i) + 1));
        return float(2.0 * M_PI) * uniformFloat(state);
    };
    std::vector<glm::vec3> out(points.size());
    std::vector<RayCounters> counters(static_cast<std::size_t>(threads));
    gatherInBatches(
        points.size(), g.rays, threads, indirect,
        [&](RadianceSlab& slab, std::size_t slot, std::size_t i, int t) {
            const GatherPoint& p = points[i];
            // Leave the surface by the scene's ray epsilon, as bake hits do for shadow rays.
            slab.trace(slot, rs, sc, lights, normalFrame(p.normal, twist(i)),
                       p.pos + p.normal * rs.epsilon(), dirs, indirect, counters[std::size_t(t)]);
        },
        [&](const glm::vec4* L, std::size_t i) {
            glm::dvec3 sum(0.0);
            for (int r = 0; r < g.rays; ++r)
                sum += glm::dvec3(L[r]);
            out[i] = glm::vec3(sum * (M_PI / double(g.rays)));
        });
    return out;
}

std::vector<glm::vec3> gatherIrradianceSphere(const raytrace::RayScene& rs, const Scenario& sc,
                                              const std::vector<scene::Light>& lights,
                                              const std::vector<glm::vec3>& points,
                                              const std::vector<glm::vec3>& normals,
                                              const ProbeSampler* indirect,
                                              const GatherSettings& g) {
    if (g.rays < 1) throw Error("gather: rays must be at least 1, got " + std::to_string(g.rays));
    const std::vector<glm::vec3> dirs = sphericalFibonacci(g.rays);
    const int threads = resolveThreadCount(g.threads);
    // Point i's rotation comes from its own stream: the same for any batch or thread count.
    auto rotation = [&](std::size_t i) {
        std::uint64_t state = g.seed ^ (0x9E3779B97F4A7C15ull * (std::uint64_t(i) + 1));
        return randomRotation(state);
    };
    const std::size_t nn = normals.size();
    std::vector<glm::vec3> out(points.size() * nn);
    std::vector<RayCounters> counters(static_cast<std::size_t>(threads));
    gatherInBatches(
        points.size(), g.rays, threads, indirect,
        [&](RadianceSlab& slab, std::size_t slot, std::size_t i, int t) {
            slab.trace(slot, rs, sc, lights, rotation(i), points[i], dirs, indirect,
                       counters[std::size_t(t)]);
        },
        [&](const glm::vec4* L, std::size_t i) {
            const glm::mat3 rot = rotation(i);
            for (std::size_t k = 0; k < nn; ++k) {
                glm::dvec3 sum(0.0);
                double weights = 0.0;
                for (int r = 0; r < g.rays; ++r) {
                    const double w =
                        std::max(0.0f, glm::dot(normals[k], rot * dirs[std::size_t(r)]));
                    sum += w * glm::dvec3(L[r]);
                    weights += w;
                }
                out[i * nn + k] =
                    weights > 0.0 ? glm::vec3(sum * (M_PI / weights)) : glm::vec3(0.0f);
            }
        });
    return out;
}

} // namespace pb::probes
