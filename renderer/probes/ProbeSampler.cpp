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
// the 8 corners in one vector (and a pair of lookups' 16 corners in two: preparePair,
// finishPair). Other architectures build the one version.
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
// A lookup's 8 corners into 8 lanes of a wider array, as one vector store each (8 scalar
// stores read back as one vector stall on store forwarding). Pointers in and out: a function
// taking or returning an 8-float vector would have two ABIs, with and without AVX.
[[gnu::always_inline]] inline void minus8(float* out, const float* a, float b) {
    for (int i = 0; i < 8; ++i)
        out[i] = a[i] - b;
}
[[gnu::always_inline]] inline void minus8(float* out, float a, const float* b) {
    for (int i = 0; i < 8; ++i)
        out[i] = a - b[i];
}
[[gnu::always_inline]] inline void splat8(float* out, float x) {
    for (int i = 0; i < 8; ++i)
        out[i] = x;
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
    glm::vec3 biased; // p moved off the surface (step 3): the point the corners see
    glm::vec2 irrCoord;
    float fade = 0.0f;
    // The behind-surface fade (kBehindRampCells): 1 / width (world units) and floor; 0 and 0
    // turn it off (the factor is then exactly 1).
    float behindInvWidth = 0.0f, behindFloor = 0.0f;
    alignas(16) float dist[8];             // |biased - probe|
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
    // Queries are prepared (addresses computed, tiles prefetched) kAhead queries before they
    // are finished, so that their cache misses overlap the arithmetic of the queries in
    // between; and two at a time (preparePair, finishPair), so that two lookups' dependency
    // chains overlap: one at a time, a lookup waited on its own square roots and divisions.
    static_assert(kAhead % 2 == 0, "a pair's two lookups take two neighbouring ring slots");
    Lookup ring[kAhead];
    CellCache cells;
    auto volumeOf = [&](std::size_t i) {
        return keys ? volumeOfKey(keys[i]) : selectVolume(q[i].pos);
    };
    for (std::size_t i = 0; i < count + kAhead; i += 2) {
        if (i >= kAhead) { // finish lookups j and j + 1
            const std::size_t j = i - kAhead;
            const Lookup& a = ring[j % kAhead];
            if (j + 1 < count) {
                const Lookup& b = ring[(j + 1) % kAhead];
                if (!a.done && !b.done)
                    finishPair(a, b, out + j);
                else
                    out[j] = finish(a), out[j + 1] = finish(b);
            } else if (j < count)
                out[j] = finish(a);
        }
        if (i + 1 < count) { // prepare lookups i and i + 1
            const int volumes[2] = {volumeOf(i), volumeOf(i + 1)};
            preparePair(volumes, q + i, opt, ring[i % kAhead], ring[(i + 1) % kAhead], cells);
        } else if (i < count)
            prepare(volumeOf(i), q[i].pos, q[i].normal, q[i].view, opt, ring[i % kAhead], cells);
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

namespace {

// Prepare's per-corner step: toPoint = (tx, ty, tz) = biased - probe, dist = |toPoint|, dir =
// toPoint / dist (n if 0), visibility coordinate = octInteriorCoord(dir, 14) + 1
// (Octahedral.h, spelled out). Branch-free, so that a loop over corners vectorises.
[[gnu::always_inline]] inline void cornerVisCoord(float tx, float ty, float tz, float nx, float ny,
                                                  float nz, float& dist, float& vx, float& vy) {
    const float interior = float(kVisibilityInterior);
    const float d = std::sqrt(tx * tx + ty * ty + tz * tz);
    dist = d;
    const bool some = d > 0.0f;
    // Divide unconditionally, then select: a conditional division would not vectorise.
    const float ux = tx / d, uy = ty / d, uz = tz / d;
    const float dx = some ? ux : nx, dy = some ? uy : ny, dz = some ? uz : nz;
    const float l1 = std::abs(dx) + std::abs(dy) + std::abs(dz);
    const float u = dx / l1, v = dz / l1;
    const float fu = (1.0f - std::abs(v)) * (u >= 0.0f ? 1.0f : -1.0f);
    const float fv = (1.0f - std::abs(u)) * (v >= 0.0f ? 1.0f : -1.0f);
    const bool lower = dy < 0.0f;
    vx = ((lower ? fu : u) * 0.5f + 0.5f) * interior + 1.0f;
    vy = ((lower ? fv : v) * 0.5f + 0.5f) * interior + 1.0f;
}

// tileFootprint() of a visibility fetch at (vx, vy), the same operations: the bilinear
// fractions and the float offset of its top-left texel in the tile.
[[gnu::always_inline]] inline void visFootprint(float vx, float vy, float& fx, float& fy,
                                                int& offset) {
    const float a = vx - 0.5f, b = vy - 0.5f;
    int x0 = int(a), y0 = int(b);
    x0 = float(x0) > a ? x0 - 1 : x0;
    y0 = float(y0) > b ? y0 - 1 : y0;
    fx = a - float(x0);
    fy = b - float(y0);
    x0 = std::min(std::max(x0, 0), kVisibilityTile - 2);
    y0 = std::min(std::max(y0, 0), kVisibilityTile - 2);
    offset = (y0 * kVisibilityTile + x0) * 2;
}

// One corner's weight, finish's steps 4a - 4d: (qx, qy, qz) = probe - point, n the unit
// normal, dist = |biased - probe|, (mean, meanSq) its visibility texel, visMask 0 for an
// irradiance-only corner, the behind-surface fade (kBehindRampCells: 0, 0 is off) and the
// trilinear factors. Written without branches (`&` on conditions, selects) so that a loop
// over corners runs as vectors: with `&&` it stayed scalar, and its divisions and square
// root were a third of a lookup.
[[gnu::always_inline]] inline float cornerWeight(float qx, float qy, float qz, float nx, float ny,
                                                 float nz, float dist, float invMaxDistance,
                                                 float mean, float meanSq, int visMask,
                                                 float behindInvWidth, float behindFloor,
                                                 float triX, float triY, float triZ) {
    // 4a. Wrap shading: probes behind the surface count less (never zero). dirToProbe =
    //     normalize(probe - p), n when that has no length.
    const float len = std::sqrt(qx * qx + qy * qy + qz * qz);
    const bool some = (len > 0.0f) & (len <= std::numeric_limits<float>::max());
    const float ux = qx / len, uy = qy / len, uz = qz / len;
    const float dx = some ? ux : nx, dy = some ? uy : ny, dz = some ? uz : nz;
    const float t = (dx * nx + dy * ny + dz * nz + 1.0f) * 0.5f;
    float w = t * t + kWrapBias;

    // 4b. Chebyshev visibility from the probe towards the biased point.
    const float d01 = dist * invMaxDistance;
    const float variance = std::max(meanSq - mean * mean, kVarianceFloor);
    const float dd = d01 - mean;
    const float cheb = variance / (variance + dd * dd);
    const float chebW = std::max(cheb * cheb * cheb, kChebyshevFloor);
    // An irradiance-only corner has no visibility: only free cells read it (ProbeState).
    w = (d01 > mean) & (visMask != 0) ? w * chebW : w;

    // 4c. Crush tiny weights (keeps a faint leak from dominating once normalised).
    const float crushed = w * ((w * w) / (kCrushThreshold * kCrushThreshold));
    w = w < kCrushThreshold ? crushed : w;

    // 4c'. Rendered points: probes behind the surface's plane fade out over
    //      kBehindRampCells (the height is finite: `len` 0 gives 0).
    const float height = qx * nx + qy * ny + qz * nz;
    const float ramp = std::min(std::max(1.0f + height * behindInvWidth, 0.0f), 1.0f);
    w *= std::max(ramp, behindFloor);

    // 4d. Trilinear.
    const float tri = triX * triY * triZ;
    return w * std::max(tri, kMinTrilinear);
}

} // namespace

// Steps 1 - 3 and the cell of one lookup; false when it ends there (k.done, k.out final).
[[gnu::always_inline]] inline bool
ProbeSampler::prepareHead(int vi, const glm::vec3& pos, const glm::vec3& normal,
                          const glm::vec3& view, SampleOptions opt, Lookup& k, CellCache& cells,
                          SampleTrace* trace) const {
    k.out = {};
    k.done = true;
    if (trace) *trace = SampleTrace{};
    if (vi < 0 || vi >= int(frames_.size())) return false;
    const Frame& f = frames_[size_t(vi)];
    if (!finite3(pos) || !finite3(normal) || !finite3(view)) return false;
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
    if (fade <= 0.0f) return false;

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

    // 4. The 8 surrounding probes (the cell's, built once per run of lookups in it);
    //    prepareCorners computes their texel addresses.
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
    k.frame = &f;
    k.p = p;
    k.n = n;
    k.biased = biased;
    k.alpha = alpha;
    k.fade = fade;
    const bool rendered = opt.surfaceBias && !opt.bakeBias && opt.behindFade;
    k.behindInvWidth = rendered ? 1.0f / (kBehindRampCells * f.minCell) : 0.0f;
    k.behindFloor = rendered ? kBehindFloor : 0.0f;
    k.done = false;
    return true;
}

// Step 4 of L prepared heads: the corners' visibility coordinates and the texel addresses,
// prefetching the tiles (the loads are the cost of a lookup); finish() weights them in
// corner order. One lookup computes straight into its arrays; two run their 16 corners as
// one loop, so that their dependency chains overlap.
template <int L>
[[gnu::always_inline]] inline void ProbeSampler::prepareCorners(Lookup* const* ks,
                                                                SampleTrace* trace) const {
    constexpr int N = 8 * L;
    alignas(32) float vx[N], vy[N];
    if constexpr (L == 1) {
        Lookup& k = *ks[0];
        const Cell& c = *k.cell;
        for (int i = 0; i < 8; ++i)
            cornerVisCoord(k.biased.x - c.px[i], k.biased.y - c.py[i], k.biased.z - c.pz[i], k.n.x,
                           k.n.y, k.n.z, k.dist[i], vx[i], vy[i]);
        for (int i = 0; i < 8; ++i)
            visFootprint(vx[i], vy[i], k.visFx[i], k.visFy[i], k.visOffset[i]);
    } else {
        alignas(32) float bx[N], by[N], bz[N], nx[N], ny[N], nz[N], dist[N];
        for (int l = 0; l < L; ++l) {
            const Lookup& k = *ks[l];
            const Cell& c = *k.cell;
            const int j = 8 * l;
            minus8(bx + j, k.biased.x, c.px);
            minus8(by + j, k.biased.y, c.py);
            minus8(bz + j, k.biased.z, c.pz);
            splat8(nx + j, k.n.x);
            splat8(ny + j, k.n.y);
            splat8(nz + j, k.n.z);
        }
        for (int i = 0; i < N; ++i)
            cornerVisCoord(bx[i], by[i], bz[i], nx[i], ny[i], nz[i], dist[i], vx[i], vy[i]);
        alignas(32) float visFx[N], visFy[N];
        alignas(32) int visOffset[N];
        for (int i = 0; i < N; ++i)
            visFootprint(vx[i], vy[i], visFx[i], visFy[i], visOffset[i]);
        for (int l = 0; l < L; ++l) {
            Lookup& k = *ks[l];
            std::memcpy(k.dist, dist + 8 * l, sizeof(k.dist));
            std::memcpy(k.visFx, visFx + 8 * l, sizeof(k.visFx));
            std::memcpy(k.visFy, visFy + 8 * l, sizeof(k.visFy));
            std::memcpy(k.visOffset, visOffset + 8 * l, sizeof(k.visOffset));
        }
    }
    // The irradiance fetch's footprint once a lookup (its coordinate is the same in every
    // corner's tile), then the prefetches.
    for (int l = 0; l < L; ++l) {
        Lookup& k = *ks[l];
        const Cell& c = *k.cell;
        k.irrFoot = tileFootprint(k.irrCoord.x, k.irrCoord.y, kIrradianceTile);
        const int irrOffset = (k.irrFoot.y0 * kIrradianceTile + k.irrFoot.x0) * 3;
        for (int i = 0; i < 8; ++i) {
            if (!c.live[i]) continue;
            const float* v = c.visTile[i] + k.visOffset[i];
            __builtin_prefetch(v);
            __builtin_prefetch(v + kVisibilityTile * 2);
            __builtin_prefetch(c.irrTile[i] + irrOffset);
            __builtin_prefetch(c.irrTile[i] + irrOffset + kIrradianceTile * 3);
            if (trace) recordFootprints(trace->corners[i], {vx[i], vy[i]}, k.irrCoord);
        }
    }
    if (trace) trace->probesRead = true;
}

PB_SAMPLER_CLONES void ProbeSampler::prepare(int vi, const glm::vec3& pos, const glm::vec3& normal,
                                             const glm::vec3& view, SampleOptions opt, Lookup& k,
                                             CellCache& cells, SampleTrace* trace) const {
    if (!prepareHead(vi, pos, normal, view, opt, k, cells, trace)) return;
    Lookup* ks[1] = {&k};
    prepareCorners<1>(ks, trace);
}

PB_SAMPLER_CLONES void ProbeSampler::preparePair(const int* vi, const SampleQuery* q,
                                                 SampleOptions opt, Lookup& a, Lookup& b,
                                                 CellCache& cells) const {
    const bool liveA = prepareHead(vi[0], q[0].pos, q[0].normal, q[0].view, opt, a, cells, nullptr);
    const bool liveB = prepareHead(vi[1], q[1].pos, q[1].normal, q[1].view, opt, b, cells, nullptr);
    Lookup* ks[2] = {&a, &b};
    if (liveA && liveB)
        prepareCorners<2>(ks, nullptr);
    else if (liveA || liveB)
        prepareCorners<1>(ks + (liveA ? 0 : 1), nullptr);
}

// finish of L lookups (none done), always inlined into finish and finishPair: one lookup
// weights its corners straight from its cell, two as one 16-lane loop (as prepareCorners).
template <int L>
[[gnu::always_inline]] inline void ProbeSampler::finishLanes(const Lookup* const* ks,
                                                             IrradianceSample* outs) const {
    constexpr int N = 8 * L;
    // The texel fetches: GL_LINEAR inside the tile (TileFootprint), lane by lane on 4-float
    // vectors: top/bottom row lerps along x, then along y (each lane computes exactly the
    // scalar expression, so the bits are the same).
    alignas(32) float mean[N], meanSq[N];
    Float4 irr[N];
    for (int l = 0; l < L; ++l) {
        const Lookup& k = *ks[l];
        const Cell& c = *k.cell;
        const int irrOffset = (k.irrFoot.y0 * kIrradianceTile + k.irrFoot.x0) * 3;
        const Float4 irrFx = splat(k.irrFoot.fx), irrFy = splat(k.irrFoot.fy);
        for (int i = 0; i < 8; ++i) {
            // Visibility: a row of the 2x2 footprint is 4 floats (mean, meanSq of x0, x0 + 1).
            const float* v = c.visTile[i] + k.visOffset[i];
            const Float4 r0 = load4(v), r1 = load4(v + kVisibilityTile * 2);
            const Float4 left = __builtin_shufflevector(r0, r1, 0, 1, 4, 5);  // x0: top, bottom
            const Float4 right = __builtin_shufflevector(r0, r1, 2, 3, 6, 7); // x0 + 1
            const Float4 rows = left + (right - left) * splat(k.visFx[i]);    // top, bottom
            const Float4 bottom = __builtin_shufflevector(rows, rows, 2, 3, 2, 3);
            const Float4 vis = rows + (bottom - rows) * splat(k.visFy[i]);
            mean[8 * l + i] = vis[0];
            meanSq[8 * l + i] = vis[1];
            // Irradiance: RGB of x0 at t, of x0 + 1 at t + 3 (lane 3 is a neighbour's, unused).
            const float* t = c.irrTile[i] + irrOffset;
            const Float4 t00 = load4(t), t10 = load4(t + 3);
            const Float4 t01 = load4(t + kIrradianceTile * 3),
                         t11 = load4(t + kIrradianceTile * 3 + 3);
            const Float4 top = t00 + (t10 - t00) * irrFx;
            const Float4 bot = t01 + (t11 - t01) * irrFx;
            irr[8 * l + i] = top + (bot - top) * irrFy;
        }
    }

    // The weights (cornerWeight), corner = x + 2y + 4z for the trilinear factors.
    alignas(32) float weight[N];
    auto trilinear = [](const Lookup& k, float* tx, float* ty, float* tz) {
        const float ax0 = 1.0f - k.alpha.x, ax1 = k.alpha.x, ay0 = 1.0f - k.alpha.y,
                    ay1 = k.alpha.y, az0 = 1.0f - k.alpha.z, az1 = k.alpha.z;
        // Built in registers and stored whole (8 scalar stores read back as one vector
        // would stall on store forwarding).
        const Float8 x = {ax0, ax1, ax0, ax1, ax0, ax1, ax0, ax1};
        const Float8 y = {ay0, ay0, ay1, ay1, ay0, ay0, ay1, ay1};
        const Float8 z = {az0, az0, az0, az0, az1, az1, az1, az1};
        std::memcpy(tx, &x, sizeof(x));
        std::memcpy(ty, &y, sizeof(y));
        std::memcpy(tz, &z, sizeof(z));
    };
    if constexpr (L == 1) {
        const Lookup& k = *ks[0];
        const Cell& c = *k.cell;
        const glm::vec3 &p = k.p, &n = k.n;
        const float invMax = k.frame->invMaxDistance;
        alignas(32) float triX[8], triY[8], triZ[8];
        trilinear(k, triX, triY, triZ);
        for (int i = 0; i < 8; ++i)
            weight[i] = cornerWeight(c.px[i] - p.x, c.py[i] - p.y, c.pz[i] - p.z, n.x, n.y, n.z,
                                     k.dist[i], invMax, mean[i], meanSq[i], c.visMask[i],
                                     k.behindInvWidth, k.behindFloor, triX[i], triY[i], triZ[i]);
    } else {
        // Per corner what the weights read: the probe relative to the point, and the
        // lookup's normal and constants repeated in its 8 lanes.
        alignas(32) float qx[N], qy[N], qz[N], nx[N], ny[N], nz[N], dist[N], invMax[N];
        alignas(32) float behindInv[N], behindFloor[N], triX[N], triY[N], triZ[N];
        alignas(32) int visMask[N];
        for (int l = 0; l < L; ++l) {
            const Lookup& k = *ks[l];
            const Cell& c = *k.cell;
            const int j = 8 * l;
            minus8(qx + j, c.px, k.p.x);
            minus8(qy + j, c.py, k.p.y);
            minus8(qz + j, c.pz, k.p.z);
            splat8(nx + j, k.n.x);
            splat8(ny + j, k.n.y);
            splat8(nz + j, k.n.z);
            std::memcpy(dist + j, k.dist, sizeof(k.dist));
            splat8(invMax + j, k.frame->invMaxDistance);
            splat8(behindInv + j, k.behindInvWidth);
            splat8(behindFloor + j, k.behindFloor);
            trilinear(k, triX + j, triY + j, triZ + j);
            std::memcpy(visMask + j, c.visMask, sizeof(c.visMask));
        }
        for (int i = 0; i < N; ++i)
            weight[i] = cornerWeight(qx[i], qy[i], qz[i], nx[i], ny[i], nz[i], dist[i], invMax[i],
                                     mean[i], meanSq[i], visMask[i], behindInv[i], behindFloor[i],
                                     triX[i], triY[i], triZ[i]);
    }

    for (int l = 0; l < L; ++l) {
        const Lookup& k = *ks[l];
        const Cell& c = *k.cell;
        IrradianceSample& out = outs[l];
        out = k.out;
        // 4e. Sum in corner order (the order fixes the rounding; per lane as glm's vec3 math).
        Float4 sum4 = splat(0.0f);
        float sumW = 0.0f;
        for (int i = 0; i < 8; ++i) {
            if (!c.live[i]) continue;
            const float w = weight[8 * l + i];
            sum4 += splat(w) * irr[8 * l + i];
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
            continue;
        }
        out.irradiance = sumE / sumW * k.fade;
        out.weight = k.fade;
    }
}

PB_SAMPLER_CLONES IrradianceSample ProbeSampler::finish(const Lookup& k) const {
    if (k.done) return k.out;
    const Lookup* ks[1] = {&k};
    IrradianceSample out;
    finishLanes<1>(ks, &out);
    return out;
}

PB_SAMPLER_CLONES void ProbeSampler::finishPair(const Lookup& a, const Lookup& b,
                                                IrradianceSample* out) const {
    const Lookup* ks[2] = {&a, &b};
    finishLanes<2>(ks, out);
}

} // namespace pb::probes
