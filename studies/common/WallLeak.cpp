#include "studies/common/WallLeak.h"

#include "probes/ProbeSampler.h"
#include "probes/sh/ShSampler.h"

namespace pb::studies {

using namespace pb::probes;

namespace {
constexpr float kWallHalf = 0.05f; // BuiltinThinWall.cpp: the shared wall spans x in +-0.05
constexpr float kInset = 0.15f;

double luminance(const glm::vec3& e) {
    return 0.2126 * double(e.x) + 0.7152 * double(e.y) + 0.0722 * double(e.z);
}
} // namespace

WallLeak measureWallLeak(const IrradianceLookup& lookup, int n) {
    WallLeak r;
    r.points = n * n;
    for (int side = 0; side < 2; ++side) {
        const float sign = side == 0 ? -1.0f : 1.0f; // west (lit) face, then east (dark)
        const glm::vec3 normal(sign, 0.0f, 0.0f);
        double sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const float y = kInset + (2.0f - 2 * kInset) * (float(i) + 0.5f) / float(n);
                const float z = -1.0f + kInset + (2.0f - 2 * kInset) * (float(j) + 0.5f) / float(n);
                sum += luminance(lookup({sign * kWallHalf, y, z}, normal, normal));
            }
        (side == 0 ? r.litMean : r.darkMean) = sum / double(r.points);
    }
    r.ratio = r.litMean > 0 ? r.darkMean / r.litMean : 0.0;
    return r;
}

ProbeVolume thinWallVolume() {
    ProbeVolume v;
    v.name = "thin_wall";
    v.center = {0.0f, 1.0f, 0.0f};
    v.halfExtents = {2.0f, 1.0f, 1.0f};
    v.counts = {9, 5, 5}; // 0.5 m: the plane x = 0 lies in the shared wall
    return v;
}

std::vector<std::pair<std::string, WallLeak>> wallLeakPerTechnique(const ProbeSet& set) {
    std::vector<std::pair<std::string, WallLeak>> out;
    const ProbeSampler ddgi(set, 0);
    out.emplace_back(
        "ddgi", measureWallLeak([&](const glm::vec3& p, const glm::vec3& n, const glm::vec3& v) {
            return ddgi.sample(p, n, v).irradiance;
        }));
    const ShSampler sh(set, 0, "thin_wall bake");
    const std::pair<const char*, ShLeak> modes[] = {{"none", ShLeak::None},
                                                    {"weight", ShLeak::Weight},
                                                    {"validity_mask", ShLeak::ValidityMask}};
    for (int coefficients : {kShL1Coefficients, kShL2Coefficients})
        for (const auto& [name, leak] : modes) {
            ShSampleOptions o;
            o.coefficients = coefficients;
            o.leak = leak;
            out.emplace_back(
                std::string(coefficients == kShL1Coefficients ? "sh_l1/" : "sh_l2/") + name,
                measureWallLeak([&](const glm::vec3& p, const glm::vec3& n, const glm::vec3& v) {
                    return sh.sample(p, n, v, o).irradiance;
                }));
        }
    return out;
}

} // namespace pb::studies
