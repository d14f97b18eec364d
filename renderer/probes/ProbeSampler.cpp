#include "probes/ProbeSampler.h"

#include "core/Error.h"
#include "core/FloatLanes.h"
#include "core/FloorToInt.h"
#include "probes/AbsentProbeFill.h"
#include "probes/Octahedral.h"
#include "core/ParallelFor.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace pb::probes {

// The lookup's two halves exist twice, for the baseline x86-64 and for AVX2 (chosen once by the
// loader, ifunc). The same IEEE operations in the same order either way - AVX2 without FMA,
// and the file is built with -ffp-contract=off - so both give the same bits; the AVX2 one runs
// the 8 corners in one vector. Other architectures build the one version.
// (Inlining both halves into a cloned sampleBatch, to save the two calls through the ifunc a
// lookup, made the lookups slower: studies/results/2026-12-04-bake-own-work-4.md.)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PB_SAMPLER_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PB_SAMPLER_CLONES
#endif

namespace {

constexpr std::size_t kIrrTileFloats = kIrradianceTile * kIrradianceTile * 3;
constexpr std::size_t kVisTileFloats = kVisibilityTile * kVisibilityTile * 2;

// GCC/Clang vector types: lane-wise IEEE operations, as scalar code (Float4 and load4:
// core/FloatLanes.h).
typedef float Float8 __attribute__((vector_size(32)));
typedef int Int8 __attribute__((vector_size(32)));
inline Float4 splat(float x) {
    return Float4{x, x, x, x};
}
// load4 of an irradiance texel's RGB reads one float past it: the tile arrays keep that much
// padding after the last tile.
constexpr std::size_t kTilePadding = 4;
// sampleBatch prepares a query this many queries before it finishes it.
constexpr std::size_t kAhead = 4;

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

// Tile-major copy of a texture array: probe after probe, `channels` of its channels. A tile
// row is contiguous in the source layer, so it is copied row by row. The bake builds a
// sampler per pass between its parallel loops (the visibility alone is 16 MiB for 32x8x32):
// large volumes are copied on all cores, into memory that was not zeroed first.
HugePageVector<float> copyTiles(const ProbeVolume& v, const ProbeTexture& t, int tile,
                                int channels, const std::vector<int>& source) {
    const std::size_t tileFloats = std::size_t(tile * tile * channels);
    HugePageVector<float> out(std::size_t(v.probeCount()) * tileFloats + kTilePadding);
    std::fill(out.end() - kTilePadding, out.end(), 0.0f);
    const std::size_t stride = std::size_t(t.shape.channels);
    const int threads = v.probeCount() >= 4096 ? resolveThreadCount(0) : 1;
    parallelFor(std::size_t(v.probeCount()), threads, [&](std::size_t p, int) {
        // A filled probe's tile is a copy of its source's (AbsentProbeFill.h).
        const int from = source.empty() || source[p] < 0 ? int(p) : source[p];
        const glm::ivec3 c = v.probeCoords(from);
        float* dst = out.data() + p * tileFloats;
        for (int y = 0; y < tile; ++y) {
            const float* src =
                t.texels.data() +
                ((std::size_t(c.y) * std::size_t(t.shape.height) + std::size_t(c.z * tile + y)) *
                     std::size_t(t.shape.width) +
                 std::size_t(c.x * tile)) *
                    stride;
            if (std::size_t(channels) == stride) {
                std::copy(src, src + std::size_t(tile) * stride, dst);
                dst += std::size_t(tile) * stride;
                continue;
            }
            for (int x = 0; x < tile; ++x, src += stride)
                for (int ch = 0; ch < channels; ++ch)
                    *dst++ = src[ch];
        }
    });
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

// glm's mat3 * vec3 (the same operations in the same order), always inlined: into the volume's
// frame, for every lookup and locality key (as glm's call, the lookup's clones passed each vector
// through memory).
[[gnu::always_inline]] inline glm::vec3 rotate(const glm::mat3& m, const glm::vec3& v) {
    return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z,
            m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
            m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
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
                         &set.irradiance[size_t(scenario)][v], &set.visibility[v], parents[v] < 0,
                         set.settings.backfaceThreshold});
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
        if (!std::isnan(sv.fillThreshold)) {
            const std::vector<ProbeState> states(sv.states, sv.states + v.probeCount());
            f.fillSource = fillSources(v, states, sv.fillThreshold);
            if (!f.fillSource.empty()) f.lookupStates = lookupStates(v, states, f.fillSource);
        }
        f.irradianceTiles = copyTiles(v, *sv.irradiance, kIrradianceTile, 3, f.fillSource);
        f.visibilityTiles = copyTiles(v, *sv.visibility, kVisibilityTile, 2, f.fillSource);
        f.firstKey = std::uint32_t(keyCount_);
        keyCount_ += std::size_t(v.probeCount());
        frames_.push_back(std::move(f));
        Frame& added = frames_.back();
        if (!added.lookupStates.empty()) added.src.states = added.lookupStates.data();
    }
}

bool ProbeSampler::influencesPoint(int volume, const glm::vec3& pos) const {
    if (volume < 0 || volume >= int(frames_.size())) return false;
    const Frame& f = frames_[size_t(volume)];
    return influences(f, rotate(f.toLocal, pos - f.center));
}

bool ProbeSampler::influences(const Frame& f, const glm::vec3& p) const {
    for (int a = 0; a < 3; ++a)
        if (!(std::abs(p[a]) <= f.half[a] + f.fadeWidth[a])) return false;
    return true;
}

int ProbeSampler::selectVolume(const glm::vec3& pos) const {
    glm::vec3 local;
    return selectVolume(pos, local);
}

// Inline: the bake's locality keys call it once a shaded hit.
inline int ProbeSampler::selectVolume(const glm::vec3& pos, glm::vec3& local) const {
    int best = -1;
    float bestVolume = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < frames_.size(); ++i) {
        const Frame& f = frames_[i];
        if (!(f.boxVolume < bestVolume)) continue;
        const glm::vec3 p = rotate(f.toLocal, pos - f.center);
        if (influences(f, p)) {
            best = int(i);
            bestVolume = f.boxVolume;
            local = p;
        }
    }
    return best;
}

std::uint32_t ProbeSampler::localityKey(const glm::vec3& pos) const {
    std::uint32_t key;
    localityKeys(&pos, 1, &key);
    return key;
}

void ProbeSampler::localityKeys(const glm::vec3* positions, std::size_t count,
                                std::uint32_t* out) const {
    for (std::size_t i = 0; i < count; ++i) {
        glm::vec3 p;
        const int v = selectVolume(positions[i], p);
        if (v < 0) {
            out[i] = 0;
            continue;
        }
        const Frame& f = frames_[size_t(v)];
        glm::ivec3 base(0);
        for (int a = 0; a < 3; ++a) // the base probe of sampleVolume's step 3 (int(): as there)
            if (f.counts[a] > 1)
                base[a] = int(std::min(std::max((p[a] + f.half[a]) * f.invCell[a], 0.0f),
                                       float(f.counts[a] - 2)));
        out[i] = f.firstKey + std::uint32_t(f.src.volume->probeIndex(base));
    }
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
// glm's length and division, spelled out (the same operations in the same order) and always
// inlined: the lookup's clones called them, passing every vector through memory.
[[gnu::always_inline]] inline glm::vec3 safeNormalize(const glm::vec3& v,
                                                      const glm::vec3& fallback) {
    const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0.0f && std::isfinite(len) ? glm::vec3(v.x / len, v.y / len, v.z / len)
                                            : fallback;
}

} // namespace

// The 8 corners are kept as arrays (x fastest, corner = x + 2y + 4z) so the per-corner
// arithmetic runs as SIMD loops: the same IEEE operations per corner as a scalar loop, hence
// the same bits. Corners outside the grid or on an invalid probe are computed on a clamped
// probe and then ignored (`live` = 0).
//
// The part that depends only on the grid cell (volume and base probe, step 3 of
// sampleVolume): every lookup in the cell reads it.
struct ProbeSampler::Cell {
    int volume = -1;
    glm::ivec3 base{0};
    alignas(32) float px[8], py[8], pz[8]; // probe position (local)
    alignas(32) int visMask[8];            // ownVis as 0 / 1 in the weights' lane width
    int cx[8], cy[8], cz[8];               // the probe computed on (clamped when outside)
    const float* visTile[8];
    const float* irrTile[8];
    bool inside[8]; // in the grid
    bool valid[8];  // the probe's state (of the clamped probe when outside)
    bool live[8];   // inside and valid: the corner counts
    bool filled[8]; // live and a stand-in for an absent probe
    bool ownVis[8]; // the corner has a visibility tile (not ProbeState::irradianceOnly)
};

// The last cells built, so that a run of lookups in one cell builds it once. A batch keeps
// kAhead lookups in flight, each pointing at its cell: kAhead + 1 slots keep every one of
// them alive while the next cell is built.
class ProbeSampler::CellCache {
public:
    const Cell& get(const ProbeSampler& sampler, const Frame& f, int volume,
                    const glm::ivec3& base) {
        if (last_ >= 0) {
            const Cell& c = cells_[last_];
            // Component by component: glm's == was a call from the clones.
            if (c.volume == volume && c.base.x == base.x && c.base.y == base.y &&
                c.base.z == base.z)
                return c;
        }
        last_ = (last_ + 1) % kSlots;
        sampler.buildCell(f, volume, base, cells_[std::size_t(last_)]);
        return cells_[std::size_t(last_)];
    }

private:
    static constexpr int kSlots = int(kAhead) + 1;
    Cell cells_[kSlots];
    int last_ = -1;
};

struct ProbeSampler::Lookup {
    IrradianceSample out; // final when `done`
    bool done = true;
    const Frame* frame = nullptr;
    const Cell* cell = nullptr;
    glm::vec3 p, n, alpha;
    glm::vec2 irrCoord;
    float fade = 0.0f;
    // The behind-surface fade (kBehindRampCells): 1 / width (world units) and floor; 0 and 0
    // turn it off (the factor is then exactly 1).
    float behindInvWidth = 0.0f, behindFloor = 0.0f;
    alignas(16) float dist[8];             // |biased - probe|
    alignas(16) float vx[8], vy[8];        // visibility tile coordinates
    // tileFootprint of each corner's visibility fetch (x0, y0 as a float offset in its tile)
    // and of the irradiance fetch (the same texel coordinate in every corner's tile).
    alignas(16) float visFx[8], visFy[8];
    alignas(16) int visOffset[8];
    TileFootprint irrFoot;
};

IrradianceSample ProbeSampler::sampleVolume(int vi, const glm::vec3& pos, const glm::vec3& normal,
                                            const glm::vec3& view, SampleOptions opt,
                                            SampleTrace* trace) const {
    Lookup k;
    CellCache cells;
    prepare(vi, pos, normal, view, opt, k, cells, trace);
    return finish(k);
}

int ProbeSampler::volumeOfKey(std::uint32_t key) const {
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        const Frame& f = frames_[i];
        if (key >= f.firstKey && key - f.firstKey < std::uint32_t(f.src.volume->probeCount()))
            return int(i);
    }
    return -1;
}

void ProbeSampler::sampleBatch(const SampleQuery* q, std::size_t count, IrradianceSample* out,
                               SampleOptions opt, const std::uint32_t* keys) const {
    // Query i is prepared (addresses computed, tiles prefetched) kAhead queries before it is
    // finished, so its cache misses overlap the arithmetic of the queries in between.
    Lookup ring[kAhead];
    CellCache cells;
    for (std::size_t i = 0; i < count + kAhead; ++i) {
        Lookup& slot = ring[i % kAhead];
        if (i >= kAhead) out[i - kAhead] = finish(slot);
        if (i < count) {
            const int volume = keys ? volumeOfKey(keys[i]) : selectVolume(q[i].pos);
            prepare(volume, q[i].pos, q[i].normal, q[i].view, opt, slot, cells);
        }
    }
}

PB_SAMPLER_CLONES void ProbeSampler::buildCell(const Frame& f, int volume, const glm::ivec3& base,
                                               Cell& c) const {
    c.volume = volume;
    c.base = base;
    const ProbeVolume& vol = *f.src.volume;
    // The corners as 8-lane vectors built straight from registers and the state loads: 8
    // scalar stores read back as one vector would stall on store forwarding. Per lane the
    // same operations as the scalar expression gridOrigin + vec3(c) * gridStep + offset.
    const Int8 cx0 = base.x + Int8{0, 1, 0, 1, 0, 1, 0, 1};
    const Int8 cy0 = base.y + Int8{0, 0, 1, 1, 0, 0, 1, 1};
    const Int8 cz0 = base.z + Int8{0, 0, 0, 0, 1, 1, 1, 1};
    const Int8 inside = (cx0 < f.counts.x) & (cy0 < f.counts.y) & (cz0 < f.counts.z);
    const Int8 cx = inside ? cx0 : Int8{} + base.x; // outside: a real probe to compute on
    const Int8 cy = inside ? cy0 : Int8{} + base.y;
    const Int8 cz = inside ? cz0 : Int8{} + base.z;
    const Int8 index = (cy * vol.counts.z + cz) * vol.counts.x + cx; // ProbeVolume::probeIndex
    const ProbeState* st = f.src.states;
    const Float8 ox = {st[index[0]].offset.x, st[index[1]].offset.x, st[index[2]].offset.x,
                       st[index[3]].offset.x, st[index[4]].offset.x, st[index[5]].offset.x,
                       st[index[6]].offset.x, st[index[7]].offset.x};
    const Float8 oy = {st[index[0]].offset.y, st[index[1]].offset.y, st[index[2]].offset.y,
                       st[index[3]].offset.y, st[index[4]].offset.y, st[index[5]].offset.y,
                       st[index[6]].offset.y, st[index[7]].offset.y};
    const Float8 oz = {st[index[0]].offset.z, st[index[1]].offset.z, st[index[2]].offset.z,
                       st[index[3]].offset.z, st[index[4]].offset.z, st[index[5]].offset.z,
                       st[index[6]].offset.z, st[index[7]].offset.z};
    const Float8 px = (f.gridOrigin.x + __builtin_convertvector(cx, Float8) * f.gridStep.x) + ox;
    const Float8 py = (f.gridOrigin.y + __builtin_convertvector(cy, Float8) * f.gridStep.y) + oy;
    const Float8 pz = (f.gridOrigin.z + __builtin_convertvector(cz, Float8) * f.gridStep.z) + oz;
    std::memcpy(c.px, &px, sizeof(c.px));
    std::memcpy(c.py, &py, sizeof(c.py));
    std::memcpy(c.pz, &pz, sizeof(c.pz));
    for (int corner = 0; corner < 8; ++corner) {
        const ProbeState& state = st[index[corner]];
        c.cx[corner] = cx[corner];
        c.cy[corner] = cy[corner];
        c.cz[corner] = cz[corner];
        c.inside[corner] = inside[corner] != 0;
        c.valid[corner] = state.valid;
        c.live[corner] = c.inside[corner] && state.valid;
        c.ownVis[corner] = !state.irradianceOnly;
        c.visMask[corner] = c.ownVis[corner] ? 1 : 0;
        c.filled[corner] = c.live[corner] && !f.fillSource.empty() &&
                           f.fillSource[std::size_t(index[corner])] != index[corner];
        c.visTile[corner] = f.visibilityTiles.data() + std::size_t(index[corner]) * kVisTileFloats;
        c.irrTile[corner] = f.irradianceTiles.data() + std::size_t(index[corner]) * kIrrTileFloats;
    }
}

PB_SAMPLER_CLONES void ProbeSampler::prepare(int vi, const glm::vec3& pos, const glm::vec3& normal,
                                             const glm::vec3& view, SampleOptions opt, Lookup& k,
                                             CellCache& cells, SampleTrace* trace) const {
    k.out = {};
    k.done = true;
    if (trace) *trace = SampleTrace{};
    if (vi < 0 || vi >= int(frames_.size())) return;
    const Frame& f = frames_[size_t(vi)];
    if (!finite3(pos) || !finite3(normal) || !finite3(view)) return;
    k.out.volume = vi;

    // 1. Everything in the volume's local frame (rotation keeps lengths and dot products).
    const glm::vec3 p = rotate(f.toLocal, pos - f.center);
    const glm::vec3 n = safeNormalize(rotate(f.toLocal, normal), glm::vec3(0, 1, 0));
    const glm::vec3 vdir = safeNormalize(rotate(f.toLocal, view), n);

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
    if (fade <= 0.0f) return;

    // 3. Surface bias, base probe (unbiased point) and trilinear fractions (biased point).
    const glm::vec3 biased =
        opt.surfaceBias
            ? p + (opt.bakeBias ? kBakeBiasNormalWeight * n + kBakeBiasViewWeight * vdir
                                : kBiasNormalWeight * n + kBiasViewWeight * vdir) *
                      (kBiasScale * f.minCell)
            : p;
    glm::ivec3 base;
    glm::vec3 alpha;
    for (int a = 0; a < 3; ++a) {
        if (f.counts[a] <= 1) {
            base[a] = 0;
            alpha[a] = 0.0f;
            continue;
        }
        // Clamp in float first: a far-away point must not overflow the int conversion. g >= 0
        // then, so truncation is the floor (floorToInt's correction step would be dead weight
        // on the chain every lookup and every bake hit's key waits for).
        float g =
            std::min(std::max((p[a] + f.half[a]) * f.invCell[a], 0.0f), float(f.counts[a] - 2));
        base[a] = int(g);
        float gb = (biased[a] + f.half[a]) * f.invCell[a] - float(base[a]);
        alpha[a] = std::min(std::max(gb, 0.0f), 1.0f);
    }

    // 4. The 8 surrounding probes: their positions and texel addresses (the cell's, built
    //    once per run of lookups in it), prefetching the tiles (the loads are the cost of a
    //    lookup); finish() weights them in corner order.
    k.irrCoord = octInteriorCoord(n, kIrradianceInterior) + 1.0f;
    const Cell& c = cells.get(*this, f, vi, base);
    k.cell = &c;
    if (trace)
        for (int corner = 0; corner < 8; ++corner) {
            if (!c.inside[corner]) continue;
            trace->corners[corner].probe = {c.cx[corner], c.cy[corner], c.cz[corner]};
            trace->corners[corner].inGrid = true;
            trace->corners[corner].valid = c.valid[corner];
        }
    // Per corner: toPoint = biased - probe, dist = |toPoint|, dir = toPoint / dist (n if 0),
    // visibility coordinate = octInteriorCoord(dir, 14) + 1 (Octahedral.h, spelled out).
    const float interior = float(kVisibilityInterior);
    for (int i = 0; i < 8; ++i) {
        const float tx = biased.x - c.px[i], ty = biased.y - c.py[i], tz = biased.z - c.pz[i];
        const float d = std::sqrt(tx * tx + ty * ty + tz * tz);
        k.dist[i] = d;
        const bool some = d > 0.0f;
        // Divide unconditionally, then select: a conditional division would not vectorise.
        const float ux = tx / d, uy = ty / d, uz = tz / d;
        const float dx = some ? ux : n.x, dy = some ? uy : n.y, dz = some ? uz : n.z;
        const float l1 = std::abs(dx) + std::abs(dy) + std::abs(dz);
        const float u = dx / l1, v = dz / l1;
        const float fu = (1.0f - std::abs(v)) * (u >= 0.0f ? 1.0f : -1.0f);
        const float fv = (1.0f - std::abs(u)) * (v >= 0.0f ? 1.0f : -1.0f);
        const bool lower = dy < 0.0f;
        k.vx[i] = ((lower ? fu : u) * 0.5f + 0.5f) * interior + 1.0f;
        k.vy[i] = ((lower ? fv : v) * 0.5f + 0.5f) * interior + 1.0f;
    }
    // tileFootprint() of the 8 visibility fetches (a SIMD loop: the same operations), and
    // of the irradiance fetch once (its coordinate is the same in every corner's tile).
    for (int i = 0; i < 8; ++i) {
        const float a = k.vx[i] - 0.5f, b = k.vy[i] - 0.5f;
        int x0 = int(a), y0 = int(b);
        x0 = float(x0) > a ? x0 - 1 : x0;
        y0 = float(y0) > b ? y0 - 1 : y0;
        k.visFx[i] = a - float(x0);
        k.visFy[i] = b - float(y0);
        x0 = std::min(std::max(x0, 0), kVisibilityTile - 2);
        y0 = std::min(std::max(y0, 0), kVisibilityTile - 2);
        k.visOffset[i] = (y0 * kVisibilityTile + x0) * 2;
    }
    k.irrFoot = tileFootprint(k.irrCoord.x, k.irrCoord.y, kIrradianceTile);
    const int irrOffset = (k.irrFoot.y0 * kIrradianceTile + k.irrFoot.x0) * 3;
    for (int i = 0; i < 8; ++i) {
        if (!c.live[i]) continue;
        const float* v = c.visTile[i] + k.visOffset[i];
        __builtin_prefetch(v);
        __builtin_prefetch(v + kVisibilityTile * 2);
        __builtin_prefetch(c.irrTile[i] + irrOffset);
        __builtin_prefetch(c.irrTile[i] + irrOffset + kIrradianceTile * 3);
        if (trace) recordFootprints(trace->corners[i], {k.vx[i], k.vy[i]}, k.irrCoord);
    }
    if (trace) trace->probesRead = true;
    k.frame = &f;
    k.p = p;
    k.n = n;
    k.alpha = alpha;
    k.fade = fade;
    const bool rendered = opt.surfaceBias && !opt.bakeBias && opt.behindFade;
    k.behindInvWidth = rendered ? 1.0f / (kBehindRampCells * f.minCell) : 0.0f;
    k.behindFloor = rendered ? kBehindFloor : 0.0f;
    k.done = false;
}

PB_SAMPLER_CLONES IrradianceSample ProbeSampler::finish(const Lookup& k) const {
    if (k.done) return k.out;
    IrradianceSample out = k.out;
    const Frame& f = *k.frame;
    const Cell& c = *k.cell;
    const glm::vec3 &p = k.p, &n = k.n, &alpha = k.alpha;

    // The texel fetches: GL_LINEAR inside the tile (TileFootprint), lane by lane on 4-float
    // vectors: top/bottom row lerps along x, then along y (each lane
    // computes exactly the scalar expression, so the bits are the same).
    alignas(16) float mean[8], meanSq[8];
    Float4 irr[8];
    const int irrOffset = (k.irrFoot.y0 * kIrradianceTile + k.irrFoot.x0) * 3;
    const Float4 irrFx = splat(k.irrFoot.fx), irrFy = splat(k.irrFoot.fy);
    for (int i = 0; i < 8; ++i) {
        // Visibility: a row of the 2x2 footprint is 4 floats (mean, meanSq of x0 and x0+1).
        const float* v = c.visTile[i] + k.visOffset[i];
        const Float4 r0 = load4(v), r1 = load4(v + kVisibilityTile * 2);
        const Float4 left = __builtin_shufflevector(r0, r1, 0, 1, 4, 5);  // x0: top, bottom
        const Float4 right = __builtin_shufflevector(r0, r1, 2, 3, 6, 7); // x0 + 1
        const Float4 rows = left + (right - left) * splat(k.visFx[i]);    // top, bottom
        const Float4 bottom = __builtin_shufflevector(rows, rows, 2, 3, 2, 3);
        const Float4 vis = rows + (bottom - rows) * splat(k.visFy[i]);
        mean[i] = vis[0];
        meanSq[i] = vis[1];
        // Irradiance: RGB of x0 at t, of x0 + 1 at t + 3 (lane 3 is a neighbour's, unused).
        const float* t = c.irrTile[i] + irrOffset;
        const Float4 t00 = load4(t), t10 = load4(t + 3);
        const Float4 t01 = load4(t + kIrradianceTile * 3), t11 = load4(t + kIrradianceTile * 3 + 3);
        const Float4 top = t00 + (t10 - t00) * irrFx;
        const Float4 bot = t01 + (t11 - t01) * irrFx;
        irr[i] = top + (bot - top) * irrFy;
    }

    // The weights, per corner. Written without branches (`&` on conditions, selects, the
    // trilinear factors from arrays) so the compiler runs the 8 corners as one vector: with
    // `&&` and `i & 1 ? :` it kept the loop scalar, and its divisions and square root were a
    // third of a lookup.
    const float ax[2] = {1.0f - alpha.x, alpha.x}, ay[2] = {1.0f - alpha.y, alpha.y},
                az[2] = {1.0f - alpha.z, alpha.z};
    alignas(32) const float triX[8] = {ax[0], ax[1], ax[0], ax[1], ax[0], ax[1], ax[0], ax[1]};
    alignas(32) const float triY[8] = {ay[0], ay[0], ay[1], ay[1], ay[0], ay[0], ay[1], ay[1]};
    alignas(32) const float triZ[8] = {az[0], az[0], az[0], az[0], az[1], az[1], az[1], az[1]};
    alignas(32) float weight[8];
    for (int i = 0; i < 8; ++i) {
        // 4a. Wrap shading: probes behind the surface count less (never zero). dirToProbe =
        //     normalize(probe - p), n when that has no length.
        const float qx = c.px[i] - p.x, qy = c.py[i] - p.y, qz = c.pz[i] - p.z;
        const float len = std::sqrt(qx * qx + qy * qy + qz * qz);
        const bool some = (len > 0.0f) & (len <= std::numeric_limits<float>::max());
        const float ux = qx / len, uy = qy / len, uz = qz / len;
        const float dx = some ? ux : n.x, dy = some ? uy : n.y, dz = some ? uz : n.z;
        const float t = (dx * n.x + dy * n.y + dz * n.z + 1.0f) * 0.5f;
        float w = t * t + kWrapBias;

        // 4b. Chebyshev visibility from the probe towards the biased point.
        const float d01 = k.dist[i] * f.invMaxDistance;
        const float variance = std::max(meanSq[i] - mean[i] * mean[i], kVarianceFloor);
        const float dd = d01 - mean[i];
        const float cheb = variance / (variance + dd * dd);
        const float chebW = std::max(cheb * cheb * cheb, kChebyshevFloor);
        // An irradiance-only corner has no visibility: only free cells read it (ProbeState).
        w = (d01 > mean[i]) & (c.visMask[i] != 0) ? w * chebW : w;

        // 4c. Crush tiny weights (keeps a faint leak from dominating once normalised).
        const float crushed = w * ((w * w) / (kCrushThreshold * kCrushThreshold));
        w = w < kCrushThreshold ? crushed : w;

        // 4c'. Rendered points: probes behind the surface's plane fade out over
        //      kBehindRampCells (the height is finite: `len` 0 gives 0).
        const float height = qx * n.x + qy * n.y + qz * n.z;
        const float ramp = std::min(std::max(1.0f + height * k.behindInvWidth, 0.0f), 1.0f);
        w *= std::max(ramp, k.behindFloor);

        // 4d. Trilinear.
        const float tri = triX[i] * triY[i] * triZ[i];
        weight[i] = w * std::max(tri, kMinTrilinear);
    }

    // 4e. Sum in corner order (the order fixes the rounding; per lane as glm's vec3 math).
    Float4 sum4 = splat(0.0f);
    float sumW = 0.0f;
    for (int i = 0; i < 8; ++i) {
        if (!c.live[i]) continue;
        const float w = weight[i];
        sum4 += splat(w) * irr[i];
        sumW += w;
        ++out.probes;
        out.filled += c.filled[i] ? 1 : 0;
        out.irradianceOnly += c.ownVis[i] ? 0 : 1;
    }
    const glm::vec3 sumE(sum4[0], sum4[1], sum4[2]);

    // 5. Normalise, then apply the fade.
    if (!(sumW > 0.0f)) {
        out.probes = 0;
        out.filled = 0;
        out.irradianceOnly = 0;
        return out;
    }
    out.irradiance = sumE / sumW * k.fade;
    out.weight = k.fade;
    return out;
}

} // namespace pb::probes
