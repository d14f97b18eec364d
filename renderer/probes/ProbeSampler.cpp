#include "probes/ProbeSampler.h"

#include "core/Error.h"
#include "probes/Octahedral.h"

#include <cmath>
#include <limits>

namespace pb::probes {

namespace {

// floor() for the texel math: an int conversion (libm's floor is a call without SSE4.1).
constexpr std::size_t kIrrTileFloats = kIrradianceTile * kIrradianceTile * 3;
constexpr std::size_t kVisTileFloats = kVisibilityTile * kVisibilityTile * 2;

inline int floorToInt(float v) {
    int i = int(v);
    return float(i) > v ? i - 1 : i;
}

// GL_LINEAR + CLAMP_TO_EDGE on one layer, CH channels read (of t.shape.channels).
template <int CH>
inline void bilinear(const ProbeTexture& t, float x, float y, int layer, float* out) {
    const int w = t.shape.width, h = t.shape.height, stride = t.shape.channels;
    const float a = x - 0.5f, b = y - 0.5f;
    int x0 = floorToInt(a), y0 = floorToInt(b);
    const float ax = a - float(x0), by = b - float(y0);
    int x1 = std::min(std::max(x0 + 1, 0), w - 1), y1 = std::min(std::max(y0 + 1, 0), h - 1);
    x0 = std::min(std::max(x0, 0), w - 1);
    y0 = std::min(std::max(y0, 0), h - 1);
    const float* base = t.texels.data() +
                        std::size_t(layer) * std::size_t(h) * std::size_t(w) * std::size_t(stride);
    const float* r0 = base + std::size_t(y0) * std::size_t(w) * std::size_t(stride);
    const float* r1 = base + std::size_t(y1) * std::size_t(w) * std::size_t(stride);
    const float* t00 = r0 + x0 * stride;
    const float* t10 = r0 + x1 * stride;
    const float* t01 = r1 + x0 * stride;
    const float* t11 = r1 + x1 * stride;
    for (int c = 0; c < CH; ++c) {
        float top = t00[c] + (t10[c] - t00[c]) * ax;
        float bottom = t01[c] + (t11[c] - t01[c]) * ax;
        out[c] = top + (bottom - top) * by;
    }
}

// GL_LINEAR inside one tile of T x T texels, CH floats each, at tile-local continuous texel
// coordinates. Valid coordinates (octahedral interior + 1) keep x0, y0 in [0, T-2]; the clamp
// only guards against NaN input.
template <int CH, int T>
inline void tileBilinear(const float* tile, float lx, float ly, float* out) {
    const TileFootprint fp = tileFootprint(lx, ly, T);
    const float ax = fp.fx, by = fp.fy;
    const float* t00 = tile + (fp.y0 * T + fp.x0) * CH;
    const float* t01 = t00 + T * CH;
    for (int c = 0; c < CH; ++c) {
        float top = t00[c] + (t00[CH + c] - t00[c]) * ax;
        float bottom = t01[c] + (t01[CH + c] - t01[c]) * ax;
        out[c] = top + (bottom - top) * by;
    }
}

// Hints the two texel rows a tileBilinear at (lx, ly) will read into the cache.
template <int CH, int T> inline void prefetchTexels(const float* tile, glm::vec2 l) {
    const TileFootprint fp = tileFootprint(l.x, l.y, T);
    const float* p = tile + (fp.y0 * T + fp.x0) * CH;
    __builtin_prefetch(p);
    __builtin_prefetch(p + T * CH);
}

// Tile-major copy of a texture array: probe after probe, `channels` of its channels.
std::vector<float> copyTiles(const ProbeVolume& v, const ProbeTexture& t, int tile, int channels) {
    std::vector<float> out(std::size_t(v.probeCount()) * std::size_t(tile * tile * channels));
    float* dst = out.data();
    for (int p = 0; p < v.probeCount(); ++p) {
        glm::ivec3 c = v.probeCoords(p);
        for (int y = 0; y < tile; ++y)
            for (int x = 0; x < tile; ++x) {
                const float* src = t.at(c.x * tile + x, c.z * tile + y, c.y);
                for (int ch = 0; ch < channels; ++ch)
                    *dst++ = src[ch];
            }
    }
    return out;
}

// The texels of a corner's two fetches, layer-relative (tile origin + footprint origin).
void recordFootprints(CornerFetch& c, glm::vec2 visCoord, glm::vec2 irrCoord) {
    const TileFootprint vis = tileFootprint(visCoord.x, visCoord.y, kVisibilityTile);
    const TileFootprint irr = tileFootprint(irrCoord.x, irrCoord.y, kIrradianceTile);
    c.visTexel = {c.probe.x * kVisibilityTile + vis.x0, c.probe.z * kVisibilityTile + vis.y0};
    c.irradianceTexel = {c.probe.x * kIrradianceTile + irr.x0,
                         c.probe.z * kIrradianceTile + irr.y0};
}

} // namespace

void bilinearFetch(const ProbeTexture& t, float x, float y, int layer, float* out) {
    switch (t.shape.channels) {
    case 1:
        bilinear<1>(t, x, y, layer, out);
        break;
    case 2:
        bilinear<2>(t, x, y, layer, out);
        break;
    case 3:
        bilinear<3>(t, x, y, layer, out);
        break;
    default:
        bilinear<4>(t, x, y, layer, out);
        break;
    }
}

glm::vec2 tileCoord(const glm::ivec3& c, const glm::vec3& dir, int interior) {
    const int tile = interior + 2;
    glm::vec2 oc = octInteriorCoord(dir, interior);
    return {float(c.x * tile + 1) + oc.x, float(c.z * tile + 1) + oc.y};
}

ProbeSampler::ProbeSampler(const ProbeSet& set, int scenario) {
    if (scenario < 0 || scenario >= int(set.irradiance.size()))
        throw Error("probe set has no scenario #" + std::to_string(scenario));
    std::vector<int> parents = validateVolumes(set.volumes, "probe set");
    std::vector<SamplerVolume> views;
    for (size_t v = 0; v < set.volumes.size(); ++v)
        views.push_back({&set.volumes[v], set.states[v].data(),
                         &set.irradiance[size_t(scenario)][v], &set.visibility[v], parents[v] < 0});
    init(views);
}

ProbeSampler::ProbeSampler(const std::vector<SamplerVolume>& volumes) {
    init(volumes);
}

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
        for (int a = 0; a < 3; ++a) {
            bool grid = v.counts[a] > 1;
            f.invCell[a] = grid ? 1.0f / f.cell[a] : 0.0f;
            f.gridOrigin[a] = grid ? -v.halfExtents[a] : 0.0f;
            f.gridStep[a] = grid ? f.cell[a] : 0.0f;
        }
        f.fadeWidth = sv.root ? kEdgeFadeCells * f.cell : glm::vec3(0.0f);
        f.minCell = v.minCellSize();
        f.invMaxDistance = 1.0f / v.maxDistance();
        f.boxVolume = v.boxVolume();
        f.irradianceTiles = copyTiles(v, *sv.irradiance, kIrradianceTile, 3);
        f.visibilityTiles = copyTiles(v, *sv.visibility, kVisibilityTile, 2);
        frames_.push_back(std::move(f));
    }
}

bool ProbeSampler::influencesPoint(int volume, const glm::vec3& pos) const {
    if (volume < 0 || volume >= int(frames_.size())) return false;
    const Frame& f = frames_[size_t(volume)];
    return influences(f, f.toLocal * (pos - f.center));
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
                                            const glm::vec3& view, SampleOptions opt,
                                            SampleTrace* trace) const {
    IrradianceSample out;
    if (trace) *trace = SampleTrace{};
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
        // Clamp in float first: a far-away point must not overflow the int conversion.
        float g =
            std::min(std::max((p[a] + f.half[a]) * f.invCell[a], 0.0f), float(f.counts[a] - 2));
        base[a] = floorToInt(g);
        float gb = (biased[a] + f.half[a]) * f.invCell[a] - float(base[a]);
        alpha[a] = std::min(std::max(gb, 0.0f), 1.0f);
    }

    // 4. The 8 surrounding probes. First their positions and texel addresses, prefetching the
    //    tiles (the loads are the cost of a lookup), then the weights in corner order.
    const ProbeVolume& vol = *f.src.volume;
    const glm::vec2 irrCoord = octInteriorCoord(n, kIrradianceInterior) + 1.0f;
    struct Corner {
        glm::ivec3 off;
        glm::vec3 probe, toPoint;
        float dist;
        glm::vec2 visCoord;
        const float *visTile, *irrTile;
    };
    Corner corners[8];
    int used = 0;
    for (int corner = 0; corner < 8; ++corner) {
        Corner& k = corners[used];
        k.off = glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::ivec3 c = base + k.off;
        if (c.x >= f.counts.x || c.y >= f.counts.y || c.z >= f.counts.z) continue;
        const int index = vol.probeIndex(c);
        const ProbeState& st = f.src.states[index];
        if (trace) {
            trace->corners[corner].probe = c;
            trace->corners[corner].inGrid = true;
            trace->corners[corner].valid = st.valid;
        }
        if (!st.valid) continue;
        k.probe = f.gridOrigin + glm::vec3(c) * f.gridStep + st.offset;
        k.toPoint = biased - k.probe;
        k.dist = glm::length(k.toPoint);
        const glm::vec3 dir = k.dist > 0.0f ? k.toPoint / k.dist : n;
        k.visCoord = octInteriorCoord(dir, kVisibilityInterior) + 1.0f;
        k.visTile = f.visibilityTiles.data() + std::size_t(index) * kVisTileFloats;
        k.irrTile = f.irradianceTiles.data() + std::size_t(index) * kIrrTileFloats;
        prefetchTexels<2, kVisibilityTile>(k.visTile, k.visCoord);
        prefetchTexels<3, kIrradianceTile>(k.irrTile, irrCoord);
        if (trace) recordFootprints(trace->corners[corner], k.visCoord, irrCoord);
        ++used;
    }
    if (trace) trace->probesRead = true;
    glm::vec3 sumE(0.0f);
    float sumW = 0.0f;
    for (int i = 0; i < used; ++i) {
        const Corner& k = corners[i];

        // 4a. Wrap shading: probes behind the surface count less (never zero).
        glm::vec3 dirToProbe = safeNormalize(k.probe - p, n);
        float t = (glm::dot(dirToProbe, n) + 1.0f) * 0.5f;
        float w = t * t + kWrapBias;

        // 4b. Chebyshev visibility from the probe towards the biased point.
        float vis[2];
        tileBilinear<2, kVisibilityTile>(k.visTile, k.visCoord.x, k.visCoord.y, vis);
        float mean = vis[0], meanSq = vis[1];
        float d01 = k.dist * f.invMaxDistance;
        if (d01 > mean) {
            float variance = std::max(meanSq - mean * mean, kVarianceFloor);
            float dd = d01 - mean;
            float cheb = variance / (variance + dd * dd);
            w *= std::max(cheb * cheb * cheb, kChebyshevFloor);
        }

        // 4c. Crush tiny weights (keeps a faint leak from dominating once normalised).
        if (w < kCrushThreshold) w *= (w * w) / (kCrushThreshold * kCrushThreshold);

        // 4d. Trilinear.
        float tri = (k.off.x ? alpha.x : 1.0f - alpha.x) * (k.off.y ? alpha.y : 1.0f - alpha.y) *
                    (k.off.z ? alpha.z : 1.0f - alpha.z);
        w *= std::max(tri, kMinTrilinear);

        // 4e. Irradiance of this probe in the normal's direction.
        float irr[3];
        tileBilinear<3, kIrradianceTile>(k.irrTile, irrCoord.x, irrCoord.y, irr);
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
