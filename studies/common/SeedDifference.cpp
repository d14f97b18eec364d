#include "studies/common/SeedDifference.h"

#include "core/Luminance.h"
#include "probes/ProbeSampler.h"
#include "raytrace/StaticTriangles.h"
#include "raytrace/RayScene.h"
#include "probes/bake/SurfaceSamples.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pb::studies {

using namespace pb::probes;

namespace {

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

double meanOf(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v)
        m += x / double(v.size());
    return m;
}

} // namespace

SeedDifference seedDifference(const scene::Scene& scene, const ProbeSet& a, const ProbeSet& b,
                              int count, const scene::Bounds* region) {
    const raytrace::RayScene rs(scene);
    const float diag = glm::length(rs.bounds().size());
    const std::vector<GatherPoint> points =
        surfaceSamples(raytrace::staticBakeTriangles(scene), rs, count, 0.02f * diag);
    const ProbeSampler sa(a, 0), sb(b, 0);
    std::vector<double> rel, lum;
    for (const GatherPoint& p : points) {
        if (region && (glm::any(glm::lessThan(p.pos, region->min)) ||
                       glm::any(glm::greaterThan(p.pos, region->max))))
            continue;
        const IrradianceSample ea = sa.sample(p.pos, p.normal, p.normal);
        const IrradianceSample eb = sb.sample(p.pos, p.normal, p.normal);
        if (ea.weight <= 0.0f || eb.weight <= 0.0f) continue; // no stored probe reaches it
        const double ya = luminance(ea.irradiance), yb = luminance(eb.irradiance);
        if (!(ya + yb > 1e-6)) continue;
        rel.push_back(std::fabs(ya - yb) / (0.5 * (ya + yb)));
        lum.push_back(0.5 * (ya + yb));
    }
    SeedDifference d;
    d.points = rel.size();
    if (rel.empty()) return d;
    d.mean = meanOf(rel);
    d.median = percentile(rel, 0.5);
    d.p90 = percentile(rel, 0.9);
    d.dimQuarterBelow = percentile(lum, 0.25);
    std::vector<double> dim, bright;
    for (std::size_t k = 0; k < rel.size(); ++k)
        (lum[k] < d.dimQuarterBelow ? dim : bright).push_back(rel[k]);
    d.dimMean = meanOf(dim);
    d.brightMean = meanOf(bright);
    return d;
}

} // namespace pb::studies
