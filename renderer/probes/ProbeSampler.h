#pragma once
// The CPU reference of the DDGI irradiance lookup (plain C++/GLM, float math). The GPU apply
// pass must reproduce it to 1e-3 relative; README.md "Sampler" spells out every step in the
// order this file executes them, with the constants below.
//
// Volume choice: among the volumes whose INFLUENCE region contains the point, the one with
// the smallest box volume wins (ties: the first in the file). A child's influence region is
// its box; a root's is its box grown by kEdgeFadeCells cells per axis, over which its weight
// fades linearly from 1 (box face) to 0. Children need no fade: the bake blends their outer
// probe ring towards the parent (NestingBlend.h).
// Outside every volume the result is irradiance 0 with weight 0: the caller decides the
// fallback (e.g. ambient). All probes invalid, or all weights zero, also give weight 0 and
// irradiance 0 - never NaN.
#include "core/HugePages.h"
#include "probes/ProbeSet.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace pb::probes {

// Surface bias of a rendered point = (1.0 n + 0.0 v) * 0.25 * minCell: along the normal only.
// The view term (RTXGI's 0.8 v) moved a point seen at a grazing angle along the floor instead
// of off it - 15 degrees above a floor, 0.1 of a cell up instead of 0.25 - and its lookup then
// read the probe planes near the floor at grazing angles: the lattice printed on floors (issue
// 24, bench_lattice --elevation 15: Sponza's uniform grid scored 222, the normal-only bias 4.2).
constexpr float kBiasNormalWeight = 1.0f;
constexpr float kBiasViewWeight = 0.0f;
// The bake's own lookups at ray hits (SampleOptions::bakeBias) keep (0.2 n + 0.8 v): there the
// viewer is the probe, and the normal-only bias made the default placement's error worse on
// four of five shared scenes (bench_placement, up to +7.8% on Sponza).
constexpr float kBakeBiasNormalWeight = 0.2f;
constexpr float kBakeBiasViewWeight = 0.8f;
constexpr float kBiasScale = 0.25f;
constexpr float kWrapBias = 0.2f;        // backface weight ((dot(dirToProbe,n)+1)/2)^2 + 0.2
constexpr float kChebyshevFloor = 0.05f; // lower bound of the (cubed) Chebyshev weight
constexpr float kVarianceFloor = 1e-3f;  // in normalised distance units (maxDistance^2)
constexpr float kCrushThreshold = 0.2f;  // w < 0.2 -> w * w^2 / 0.2^2
constexpr float kMinTrilinear = 1e-3f;   // lower bound of the trilinear weight
constexpr float kEdgeFadeCells = 0.5f;   // fade width of root volumes, in cells
// Probes behind a rendered surface fade out: after the Chebyshev test and the crush, a corner's
// weight is multiplied by max(clamp(1 + h / (kBehindRampCells * minCell), 0, 1), kBehindFloor),
// h = dot(probe - p, n) the probe's height over the surface's plane (negative behind it). A
// probe plane a few tenths of a cell under a floor (Sponza's uniform grid: 0.35 - 0.6 m under
// the roof and the court, a scene with no inside, so nothing invalidates them) sees the sky
// from below, 2 - 10x the floor's irradiance; Chebyshev passed it wherever its visibility
// texel straddled the floor's edge on the horizon, and those few percent of weight printed the
// lattice (issue 24, bench_floor_corners; bench_lattice Sponza uniform 3.75 -> 1.18). The
// height, not the cosine of the direction to the probe: it is linear in the position (the
// cosine turns fast next to a probe). After the crush, which would cube the factor. The floor
// keeps a lookup whose 8 probes are all behind normalisable. Lookups at no rendered surface
// keep RTXGI's weight (SampleOptions::behindFade): bakes are unchanged.
constexpr float kBehindRampCells = 0.2f;
constexpr float kBehindFloor = 0.05f;

// One volume as the sampler sees it (the bake points these at its working textures). The
// sampler copies the textures at construction into a tile-major layout (a probe's tile
// contiguous): the values and the filtering are those of the GL layout - a fetch never leaves
// its tile thanks to the borders - but the copy avoids the 4 KiB row-pitch cache aliasing of
// wide volumes. Later changes to the textures are not seen: build a new sampler.
struct SamplerVolume {
    const ProbeVolume* volume = nullptr;
    const ProbeState* states = nullptr;       // probeCount() entries
    const ProbeTexture* irradiance = nullptr; // RGBA, irradianceShape(counts)
    const ProbeTexture* visibility = nullptr; // RG, visibilityShape(counts)
    bool root = true;
    // Absent probes outside geometry read as their nearest stored probe (AbsentProbeFill.h),
    // judged by this back-face threshold; NaN: no fill (the bake's working sets, where
    // nothing is absent yet).
    float fillThreshold = std::numeric_limits<float>::quiet_NaN();
};

struct IrradianceSample {
    glm::vec3 irradiance{0.0f}; // E (already multiplied by the edge fade when enabled)
    float weight = 0.0f;        // edge fade in [0,1]; 0 when nothing contributed
    int volume = -1;            // the volume used, -1 outside all
    int probes = 0;             // probes that contributed (valid, inside the grid)
    int filled = 0;             // of those, stand-ins for absent probes (AbsentProbeFill.h)
    int irradianceOnly = 0;     // of those, read without visibility (ProbeState::irradianceOnly)
};

// What one lookup reads, for the texture-cache model (renderer/costmodel): sampleVolume fills
// it from the same arithmetic that filters, so the model's addresses are the texels the
// sampler (and the shader) read. Corners in the sampler's order: corner = x + 2y + 4z.
struct CornerFetch {
    glm::ivec3 probe{0};    // grid coordinates (i, j, k): layer j, tile (i, k)
    bool inGrid = false;    // false: skipped before any fetch (the shader too)
    bool valid = false;     // the state was read; false: skipped after that read
    glm::ivec2 visTexel{0}; // top-left texel of the 2x2 visibility footprint (in the layer)
    glm::ivec2 irradianceTexel{0};
};
struct SampleTrace {
    bool probesRead = false; // false: returned before reading any probe (fade 0, bad input)
    CornerFetch corners[8];
};

// GL_LINEAR's footprint inside one tile of `tile` x `tile` texels at tile-local continuous
// coordinates: texels (x0, y0) .. (x0+1, y0+1) with weights fx, fy. Valid coordinates keep
// x0, y0 in [0, tile-2]; the clamp only guards against NaN input.
struct TileFootprint {
    int x0, y0;
    float fx, fy;
};
inline TileFootprint tileFootprint(float lx, float ly, int tile) {
    const float a = lx - 0.5f, b = ly - 0.5f;
    int x0 = int(a), y0 = int(b); // floor without libm's call (no SSE4.1)
    if (float(x0) > a) --x0;
    if (float(y0) > b) --y0;
    TileFootprint f{x0, y0, a - float(x0), b - float(y0)};
    f.x0 = std::min(std::max(f.x0, 0), tile - 2);
    f.y0 = std::min(std::max(f.y0, 0), tile - 2);
    return f;
}

struct SampleOptions {
    bool edgeFade = true; // the bake turns it off: hits near a root's face keep full weight
    // The surface bias (kBiasNormalWeight n + kBiasViewWeight v) * 0.25 * minCell keeps a SURFACE point from reading
    // its own wall's shadow. A query at a probe's position (the nesting blend) is no surface:
    // there the bias of the time (0.2 n + 0.8 v) moved the point up to a quarter of the
    // parent's cell - 25 cm in the rooms' house volume - towards the texel's direction, through the 5 cm partition beside the
    // probe, and the dark room's ring probes took the lit room's light (issue 24).
    bool surfaceBias = true;
    // The bake's bias weights (kBakeBias*) instead of the rendered point's (kBias*). A lookup
    // with bakeBias or without surfaceBias also keeps behind-surface probes at RTXGI's weight
    // (no kBehindRampCells fade): it is the bake's, not a rendered surface's.
    bool bakeBias = false;
    // false: no behind-surface fade (kBehindRampCells) either. The placement's lattice search
    // (PlacementError.cpp) turns it off: its choice of shift is part of the bake, and with the
    // fade it chose other shifts on the garden and the apartment (bench_lattice's stored
    // counts 4887 -> 4904, 4746 -> 4758); off, every bake is what it was. gi.dynamic=sh's
    // lookups at an object's centre (DynamicShPass) and mid-air lookups (midAirLookup(),
    // below) have it off too: no baked surface there.
    bool behindFade = true;
};

// The options of a lookup at no baked surface: a point on a dynamic object, a mid-air point
// (bench_placement's "air err", the mid-air tests). RTXGI's weights, no behind-surface fade: the
// probes behind such a point's tangent plane are not behind anything baked, and fading them
// drops light that is there (issue 24: the fade cost the default bake's mid-air error 2 - 10%
// on every shared scene). The renderer does the same for dynamic pixels (GI_DYNAMIC_UNFADED).
inline SampleOptions midAirLookup() {
    SampleOptions o;
    o.behindFade = false;
    return o;
}

// One lookup of a batch (ProbeSampler::sampleBatch).
struct SampleQuery {
    glm::vec3 pos, normal, view;
};

class ProbeSampler {
public:
    ProbeSampler(const ProbeSet& set, int scenario);
    explicit ProbeSampler(const std::vector<SamplerVolume>& volumes);

    // pos: world point; normal: world surface normal; view: unit vector from the surface
    // TOWARDS the viewer (use the normal when there is none). Vectors need not be unit.
    IrradianceSample sample(const glm::vec3& pos, const glm::vec3& normal, const glm::vec3& view,
                            SampleOptions opt = {}) const;
    // trace (optional): receives the texels this lookup reads (SampleTrace).
    IrradianceSample sampleVolume(int volume, const glm::vec3& pos, const glm::vec3& normal,
                                  const glm::vec3& view, SampleOptions opt = {},
                                  SampleTrace* trace = nullptr) const;
    // The same as sample() for each query, bit for bit, but pipelined: the probe tiles of
    // the next few queries are prefetched while the current ones are weighted, and the
    // queries go two at a time, their corners as one set of vectors (a lone lookup waits on
    // its own chain of square roots and divisions). out receives count results.
    // keys (optional): each query's localityKey, which names its volume (no selectVolume).
    void sampleBatch(const SampleQuery* queries, std::size_t count, IrradianceSample* out,
                     SampleOptions opt = {}, const std::uint32_t* keys = nullptr) const;
    int selectVolume(const glm::vec3& pos) const;
    // True when `pos` lies in the volume's influence region (the apply pass's discard test).
    bool influencesPoint(int volume, const glm::vec3& pos) const;
    std::size_t volumeCount() const { return frames_.size(); }
    // Lookups at points with the same key read the same 8 probes (the grid cell of the
    // unbiased point in the selected volume): sorting a batch by it makes lookups cache hits.
    // Keys are in [0, localityKeyCount()); 0 = outside every volume.
    std::uint32_t localityKey(const glm::vec3& pos) const;
    // localityKey of count points into out[0 .. count-1], the same keys, in one call: the bake
    // asks for a key per shaded hit (two calls a hit were 3% of its own CPU).
    void localityKeys(const glm::vec3* positions, std::size_t count, std::uint32_t* out) const;
    std::size_t localityKeyCount() const { return keyCount_; }

private:
    struct Frame {
        SamplerVolume src;
        glm::mat3 toLocal;
        glm::vec3 center, half, cell, invCell, fadeWidth;
        glm::vec3 gridOrigin, gridStep;        // probe (i,j,k) at gridOrigin + (i,j,k) * gridStep
        HugePageVector<float> irradianceTiles; // per probe: 8x8 texels, RGB
        HugePageVector<float> visibilityTiles; // per probe: 16x16 texels, mean + meanSq
        // Sparse sets: the states as lookups see them and, per probe, whose tile it reads
        // (AbsentProbeFill.h); both empty when nothing is filled.
        std::vector<ProbeState> lookupStates;
        std::vector<int> fillSource;
        glm::ivec3 counts;
        float minCell, invMaxDistance, boxVolume;
        std::uint32_t firstKey; // localityKey of the volume's probe 0
    };
    std::vector<Frame> frames_;
    std::size_t keyCount_ = 1;
    struct Lookup; // a lookup between its address phase (prepare) and its weights (finish)
    // What the lookups of one grid cell share: the 8 corner probes' positions, states and
    // tiles (ProbeSampler.cpp). A batch sorted by localityKey reads the same cell many times
    // in a row; CellCache builds it once per run of equal cells.
    struct Cell;
    class CellCache;
    // Both are also compiled for AVX2 and picked at load time (PB_SAMPLER_CLONES,
    // ProbeSampler.cpp): the 8 corners then run as one 8-lane vector instead of two 4-lane ones.
    void prepare(int volume, const glm::vec3& pos, const glm::vec3& normal, const glm::vec3& view,
                 SampleOptions opt, Lookup& k, CellCache& cells,
                 SampleTrace* trace = nullptr) const;
    // prepare of two queries at once, the same bits as two prepare calls (as finishPair).
    void preparePair(const int* volumes, const SampleQuery* queries, SampleOptions opt, Lookup& a,
                     Lookup& b, CellCache& cells) const;
    // prepare's two steps: the lookup's own (false when it ends there), then its corners,
    // for L lookups at once.
    bool prepareHead(int volume, const glm::vec3& pos, const glm::vec3& normal,
                     const glm::vec3& view, SampleOptions opt, Lookup& k, CellCache& cells,
                     SampleTrace* trace) const;
    template <int L> void prepareCorners(Lookup* const* ks, SampleTrace* trace) const;
    void buildCell(const Frame& f, int volume, const glm::ivec3& base, Cell& c) const;
    IrradianceSample finish(const Lookup& k) const;
    // finish of two lookups at once (neither done), the same bits as two finish calls: their
    // 16 corners run as one set of vectors, so the two lookups' dependency chains overlap.
    void finishPair(const Lookup& a, const Lookup& b, IrradianceSample* out) const;
    // The body of both: L lookups, their 8L corners as one loop.
    template <int L> void finishLanes(const Lookup* const* ks, IrradianceSample* out) const;
    void init(const std::vector<SamplerVolume>& volumes);
    // selectVolume, and the point in the chosen volume's frame (unset when none is).
    int selectVolume(const glm::vec3& pos, glm::vec3& local) const;
    // The volume a localityKey lies in (-1 for key 0, outside every volume).
    int volumeOfKey(std::uint32_t key) const;
    bool influences(const Frame& f, const glm::vec3& local) const;
};

// GL_LINEAR with CLAMP_TO_EDGE on one layer of `t` at continuous texel coordinates (x, y)
// (texel i spans [i, i+1), its centre is i + 0.5): out receives t.shape.channels floats.
void bilinearFetch(const ProbeTexture& t, float x, float y, int layer, float* out);

// Continuous texel coordinates of direction `localDir` in probe `c`'s tile.
glm::vec2 tileCoord(const glm::ivec3& c, const glm::vec3& localDir, int interior);

} // namespace pb::probes
