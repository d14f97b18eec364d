#include "probes/ProbeSampler.h"

#include "probes/Octahedral.h"

#include <cmath>
#include <limits>

namespace pb::probes {

void bilinearFetch(const ProbeTexture& t, float x, float y, int layer, float* out) {
    const int w = t.shape.width, h = t.shape.height, ch = t.shape.channels;
    float a = x - 0.5f, b = y - 0.5f;
    float fa = std::floor(a), fb = std::floor(b);
    float ax = a - fa, by = b - fb;
    int x0 = int(fa), y0 = int(fb);
    int x1 = std::min(std::max(x0 + 1, 0), w - 1), y1 = std::min(std::max(y0 + 1, 0), h - 1);
    x0 = std::min(std::max(x0, 0), w - 1);
    y0 = std::min(std::max(y0, 0), h - 1);
    const float* t00 = t.at(x0, y0, layer);
    const float* t10 = t.at(x1, y0, layer);
    const float* t01 = t.at(x0, y1, layer);
    const float* t11 = t.at(x1, y1, layer);
    for (int c = 0; c < ch; ++c) {
        float top = t00[c] + (t10[c] - t00[c]) * ax;
        float bottom = t01[c] + (t11[c] - t01[c]) * ax;
        out[c] = top + (bottom - top) * by;
    }
}

glm::vec2 tileCoord(const glm::ivec3& c, const glm::vec3& dir, int interior) {
    const int tile = interior + 2;
    glm::vec2 oc = octInteriorCoord(dir, interior);
    return {float(c.x * tile + 1) + oc.x, float(c.z * tile + 1) + oc.y};
}

ProbeSampler::ProbeSampler(const ProbeSet& set, int scenario) {
    std::vector<int> parents = validateVolumes(set.volumes, "probe set");
    std::vector<SamplerVolume> views;
    for (size_t v = 0; v < set.volumes.size(); ++v)
        views.push_back({&set.volumes[v], set.states[v].data(),
                         &set.irradiance[size_t(scenario)][v], &set.visibility[v],
                         parents[v] < 0});
    init(views);
}

ProbeSampler::ProbeSampler(const std::vector<SamplerVolume>& volumes) { init(volumes); }

void ProbeSampler::init(const std::vector<SamplerVolume>& volumes) {
    for (const SamplerVolume& sv : volumes) {
        const ProbeVolume& v = *sv.volume;
        Frame f;
        f.src = sv;
        f.toLocal = glm::transpose(v.localToWorldRotation());
        f.center = v.center;
        f.half = v.halfExtents;
        f.cell = v.cellSize();
        f.counts = v.counts;
        for (int a = 0; a < 3; ++a) f.invCell[a] = v.counts[a] > 1 ? 1.0f / f.cell[a] : 0.0f;
        f.fadeWidth = sv.root ? kEdgeFadeCells * f.cell : glm::vec3(0.0f);
        f.minCell = v.minCellSize();
        f.invMaxDistance = 1.0f / v.maxDistance();
        f.boxVolume = v.boxVolume();
        frames_.push_back(f);
    }
}

bool ProbeSampler::influences(const Frame& f, const glm::vec3& p) const {
    for (int a = 0; a < 3; ++a)
        if (!(std::abs(p[a]) <= f.half[a] + f.fadeWidth[a])) return false;
    return true;
}

int ProbeSampler::selectVolume(const glm::vec3& pos) const {
    int best = -1;
    float bestVolume = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < frames_.size(); ++i) {
        const Frame& f = frames_[i];
        if (f.boxVolume < bestVolume && influences(f, f.toLocal * (pos - f.center))) {
            best = int(i);
            bestVolume = f.boxVolume;
        }
    }
    return best;
}

IrradianceSample ProbeSampler::sample(const glm::vec3& pos, const glm::vec3& normal,
                                      const glm::vec3& view, SampleOptions opt) const {
    int v = selectVolume(pos);
    if (v < 0) return {};
    return sampleVolume(v, pos, normal, view, opt);
}

namespace {
bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    float len = glm::length(v);
    return len > 0.0f && std::isfinite(len) ? v / len : fallback;
}
} // namespace

IrradianceSample ProbeSampler::sampleVolume(int vi, const glm::vec3& pos, const glm::vec3& normal,
                                            const glm::vec3& view, SampleOptions opt) const {
    IrradianceSample out;
    if (vi < 0 || vi >= int(frames_.size())) return out;
    const Frame& f = frames_[size_t(vi)];
    if (!finite3(pos) || !finite3(normal) || !finite3(view)) return out;
    out.volume = vi;

    // 1. Everything in the volume's local frame (rotation keeps lengths and dot products).
    const glm::vec3 p = f.toLocal * (pos - f.center);
    const glm::vec3 n = safeNormalize(f.toLocal * normal, glm::vec3(0, 1, 0));
    const glm::vec3 vdir = safeNormalize(f.toLocal * view, n);

    // 2. Edge fade (roots only): 1 inside the box, linear to 0 across the fade width.
    float fade = 1.0f;
    for (int a = 0; a < 3; ++a) {
        float outside = std::abs(p[a]) - f.half[a];
        if (outside > 0.0f)
            fade *= f.fadeWidth[a] > 0.0f
                        ? std::min(std::max(1.0f - outside / f.fadeWidth[a], 0.0f), 1.0f)
                        : 0.0f;
    }
    if (!opt.edgeFade) fade = fade > 0.0f ? 1.0f : 0.0f;
    if (fade <= 0.0f) return out;

    // 3. Surface bias, base probe (unbiased point) and trilinear fractions (biased point).
    const glm::vec3 biased =
        p + (kBiasNormalWeight * n + kBiasViewWeight * vdir) * (kBiasScale * f.minCell);
    glm::ivec3 base;
    glm::vec3 alpha;
    for (int a = 0; a < 3; ++a) {
        if (f.counts[a] <= 1) {
            base[a] = 0;
            alpha[a] = 0.0f;
            continue;
        }
        float g = std::floor((p[a] + f.half[a]) * f.invCell[a]);
        base[a] = int(std::min(std::max(g, 0.0f), float(f.counts[a] - 2)));
        float gb = (biased[a] + f.half[a]) * f.invCell[a] - float(base[a]);
        alpha[a] = std::min(std::max(gb, 0.0f), 1.0f);
    }

    // 4. The 8 surrounding probes.
    const ProbeVolume& vol = *f.src.volume;
    const glm::vec2 irrCoordInTile = octInteriorCoord(n, kIrradianceInterior);
    glm::vec3 sumE(0.0f);
    float sumW = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        glm::ivec3 off(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        glm::ivec3 c = base + off;
        if (c.x >= f.counts.x || c.y >= f.counts.y || c.z >= f.counts.z) continue;
        const int index = vol.probeIndex(c);
        const ProbeState& st = f.src.states[index];
        if (!st.valid) continue;
        const glm::vec3 probe = vol.gridLocal(c) + st.offset;

        // 4a. Wrap shading: probes behind the surface count less (never zero).
        glm::vec3 dirToProbe = safeNormalize(probe - p, n);
        float t = (glm::dot(dirToProbe, n) + 1.0f) * 0.5f;
        float w = t * t + kWrapBias;

        // 4b. Chebyshev visibility from the probe towards the biased point.
        glm::vec3 toPoint = biased - probe;
        float dist = glm::length(toPoint);
        glm::vec3 dir = dist > 0.0f ? toPoint / dist : n;
        glm::vec2 vc = tileCoord(c, dir, kVisibilityInterior);
        float vis[2];
        bilinearFetch(*f.src.visibility, vc.x, vc.y, c.y, vis);
        float mean = vis[0], meanSq = vis[1];
        float d01 = dist * f.invMaxDistance;
        if (d01 > mean) {
            float variance = std::max(meanSq - mean * mean, kVarianceFloor);
            float dd = d01 - mean;
            float cheb = variance / (variance + dd * dd);
            w *= std::max(cheb * cheb * cheb, kChebyshevFloor);
        }

        // 4c. Crush tiny weights (keeps a faint leak from dominating once normalised).
        if (w < kCrushThreshold) w *= (w * w) / (kCrushThreshold * kCrushThreshold);

        // 4d. Trilinear.
        float tri = (off.x ? alpha.x : 1.0f - alpha.x) * (off.y ? alpha.y : 1.0f - alpha.y) *
                    (off.z ? alpha.z : 1.0f - alpha.z);
        w *= std::max(tri, kMinTrilinear);

        // 4e. Irradiance of this probe in the normal's direction.
        float irr[4];
        bilinearFetch(*f.src.irradiance, float(c.x * kIrradianceTile + 1) + irrCoordInTile.x,
                      float(c.z * kIrradianceTile + 1) + irrCoordInTile.y, c.y, irr);
        sumE += w * glm::vec3(irr[0], irr[1], irr[2]);
        sumW += w;
        ++out.probes;
    }

    // 5. Normalise, then apply the fade.
    if (!(sumW > 0.0f)) {
        out.probes = 0;
        return out;
    }
    out.irradiance = sumE / sumW * fade;
    out.weight = fade;
    return out;
}

} // namespace pb::probes
