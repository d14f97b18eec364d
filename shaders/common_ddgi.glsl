// The DDGI irradiance lookup of ONE probe volume: the GLSL port of the CPU reference sampler
// (renderer/probes/ProbeSampler.cpp; renderer/probes/README.md "The sampler" is the spec).
// Same steps in the same order with the same float constants (DDGI_* defines, generated from
// ProbeSampler.h by renderer/passes/GpuProbes.cpp), so the two agree to 1e-3 relative.
// Used by the apply pass (gi_ddgi_apply.frag) and the point evaluator (gi_ddgi_points.frag):
// one function, never a copy. The caller picks the volume (one draw per volume) and space
// (camera-relative in the apply pass, world in the point evaluator: u_ddgiCenter follows).
//
// Variants: GI_LOOPS_FUSED | GI_LOOPS_SPLIT, GI_ORDER_XYZ | GI_ORDER_SLICE_FIRST,
// GI_PRECISION_FP32 | GI_PRECISION_FP16.
//
// Precision (gi.precision). `hfloat`/`hvec*` are the types of the fp16 part: probe weights
// (wrap, Chebyshev, crush, trilinear), the probe data as fetched and the irradiance sums.
// Positions, directions, grid coordinates and texture coordinates stay highp in both variants:
// in fp16 a coordinate into a 100-texel layer is off by a texel, a point 10 m from the volume
// centre by a centimetre (what a mobile shader keeps in fp32 too).
// A highp value enters the fp16 part only through ddgiHalf(): the rounding a GPU with 16-bit
// ALUs applies when a highp value is assigned to a mediump one. llvmpipe lowers an expression
// to fp16 only when its inputs are mediump (DESIGN.md); a mediump variable assigned from highp
// may stay fp32 there. unpackHalf2x16 is mediump by definition and its result is a half, so
// every value of the fp16 part is a real half on llvmpipe too, as on a mobile GPU
// (tests/gl/GiPrecisionTest.cpp: the sums overflow to Inf past 65504).
// Irradiance enters the fp16 sums straight from the mediump sampler, unless
// GI_GUARD_EXPOSURE_ON (gi.guard_exposure): then it is fetched in highp, multiplied by the
// frame's pre-exposure u_ddgiIrradianceScale (a power of two, FrameContext.h) and only then
// rounded by ddgiHalf(), so 1e6 lux irradiance at exposure 1e-6 enters the sums near 1, not as
// Inf, and 1e-6 near 1, not as a denormal. The caller's result is pre-exposed too.
// u_ddgiIrradianceScale also holds 1 / the probe file's storage scale (probes/StorageScale.h:
// irradiance far outside fp16's range is stored times a power of two), folded in on the CPU,
// so with the guard the storage scale costs nothing. Without the guard the probes are fetched
// as stored and ddgiSample multiplies its result once, in highp, by u_ddgiIrradianceScale
// (then exactly 1 / the storage scale; 1 for every ordinary bake). The stored maximum 2^14
// (StorageScale.h) also keeps the fp16 sums finite: the weights sum to about 1.2 at most.
#ifdef GI_PRECISION_FP16
#define hfloat mediump float
#define hvec2 mediump vec2
#define hvec3 mediump vec3
#define hvec4 mediump vec4
#define DDGI_PROBE_DATA_PRECISION mediump
mediump float ddgiHalf(highp float x) { return unpackHalf2x16(packHalf2x16(vec2(x, 0.0))).x; }
mediump vec3 ddgiHalf(highp vec3 v) {
    return vec3(unpackHalf2x16(packHalf2x16(v.xy)), unpackHalf2x16(packHalf2x16(v.zz)).x);
}
#else
#define hfloat highp float
#define hvec2 highp vec2
#define hvec3 highp vec3
#define hvec4 highp vec4
#define DDGI_PROBE_DATA_PRECISION highp
#define ddgiHalf(x) (x)
#endif

#ifdef GI_GUARD_EXPOSURE_ON
#define DDGI_IRRADIANCE_PRECISION highp
#else
#define DDGI_IRRADIANCE_PRECISION DDGI_PROBE_DATA_PRECISION
#endif
uniform DDGI_IRRADIANCE_PRECISION sampler2DArray u_ddgiIrradiance; // RGB = E, tiles of DDGI_IRR_TILE^2 texels
uniform DDGI_PROBE_DATA_PRECISION sampler2DArray u_ddgiVisibility; // RG = mean, mean^2 of distance / maxDistance
uniform highp sampler2DArray u_ddgiState;      // per probe: xyz relocation (local), w = tile
uniform vec3 u_ddgiCenter;        // volume centre in the caller's space
uniform mat3 u_ddgiToLocal;       // R^T: caller's axes -> volume axes
uniform vec3 u_ddgiHalf;          // half extents
uniform vec3 u_ddgiFadeWidth;     // roots: edge fade width per axis; children: 0
uniform vec3 u_ddgiInvCell;       // 1 / cell; 0 on axes with one probe
uniform vec3 u_ddgiGridOrigin;    // probe (i,j,k) at origin + (i,j,k) * step (+ relocation)
uniform vec3 u_ddgiGridStep;
uniform ivec3 u_ddgiCounts;
uniform float u_ddgiBiasDistance; // DDGI_BIAS_SCALE * minCell, rounded on the CPU like there
uniform float u_ddgiInvMaxDistance;
uniform float u_ddgiIrradianceScale; // pre-exposure / storage scale (GpuProbes::bindVolume)
uniform vec2 u_ddgiIrrInvSize;    // 1 / (width, height) of an irradiance layer
uniform vec2 u_ddgiVisInvSize;
// Per-volume constants of the lookup, computed once per draw on the CPU (GpuProbes::bindVolume)
// instead of per pixel and probe here. Texture coordinate of a tile's texel: the tile's
// (column, row) times *TileScale, plus the octahedral coordinate in [-1,1]^2 times *Oct.xy,
// plus *Oct.zw - the same as (tile * TILE + (oct * 0.5 + 0.5) * INTERIOR + 1) / layer size.
uniform vec2 u_ddgiIrrTileScale;  // DDGI_IRR_TILE * u_ddgiIrrInvSize
uniform vec4 u_ddgiIrrOct;        // xy: DDGI_IRR_INTERIOR / 2 * inv size; zw: (interior / 2 + 1) * inv size
uniform vec2 u_ddgiVisTileScale;  // DDGI_VIS_TILE * u_ddgiVisInvSize
uniform vec4 u_ddgiVisOct;        // as u_ddgiIrrOct for the visibility layers
uniform vec3 u_ddgiMaxBase;       // max(counts - 2, 0): the base probe's largest coordinate
uniform vec3 u_ddgiBiasNormal;    // DDGI_BIAS_NORMAL * u_ddgiBiasDistance (x = y = z)
uniform vec3 u_ddgiBiasView;      // DDGI_BIAS_VIEW * u_ddgiBiasDistance
uniform float u_ddgiBehindInvWidth; // 1 / (kBehindRampCells * minCell) (ProbeSampler.h)

// The uniforms the 8-probe loops read, copied into registers once per lookup: a uniform read
// inside the loops costs llvmpipe a per-lane load at each use (common_ddgi_tile.glsl).
ivec3 ddgiLoopCounts, ddgiLoopLast;
vec3 ddgiLoopStep;
vec2 ddgiLoopVisTile, ddgiLoopIrrTile;
vec4 ddgiLoopVisOct;
float ddgiLoopInvMaxDistance, ddgiLoopBehindInvWidth;
// 1: the behind-surface fade (4c') applies; 0: the caller's point is no static surface (a
// dynamic object's pixel, GI_DYNAMIC_UNFADED in gi_ddgi_apply.frag): RTXGI's weights.
#ifdef GI_DYNAMIC_UNFADED
float ddgiBehindFadeScale = 1.0;
#define DDGI_BEHIND_INV_WIDTH (u_ddgiBehindInvWidth * ddgiBehindFadeScale)
#else
#define DDGI_BEHIND_INV_WIDTH u_ddgiBehindInvWidth
#endif
#ifdef GI_GUARD_EXPOSURE_ON
float ddgiLoopIrradianceScale;
#endif
void ddgiInitLoopConstants() {
    ddgiLoopCounts = u_ddgiCounts;
    ddgiLoopLast = u_ddgiCounts - 1;
    ddgiLoopStep = u_ddgiGridStep;
    ddgiLoopVisTile = u_ddgiVisTileScale;
    ddgiLoopIrrTile = u_ddgiIrrTileScale;
    ddgiLoopVisOct = u_ddgiVisOct;
    ddgiLoopInvMaxDistance = u_ddgiInvMaxDistance;
    ddgiLoopBehindInvWidth = DDGI_BEHIND_INV_WIDTH;
#ifdef GI_GUARD_EXPOSURE_ON
    ddgiLoopIrradianceScale = u_ddgiIrradianceScale;
#endif
}

vec3 ddgiLocal(vec3 pos) { return u_ddgiToLocal * (pos - u_ddgiCenter); }

// The volume's influence region: a child's box, a root's box grown by the fade width.
bool ddgiInfluences(vec3 local) {
    return all(lessThanEqual(abs(local), u_ddgiHalf + u_ddgiFadeWidth));
}

vec3 ddgiSafeNormalize(vec3 v, vec3 fallback) {
    float len = length(v);
    return len > 0.0 ? v / len : fallback;
}

// Edge fade at local point p: 1 inside the box, linear to 0 across a root's fade width per
// axis; a child (zero fade width) is 0 outside its box. Shared by DDGI and the SH volume.
// Selects, not an `if`: llvmpipe runs a branch's body under an execution mask whatever the
// lanes decide (as ddgiProbeWeight). The same values as the branch: unselected lanes' divisions
// by a zero width never reach the result.
float ddgiEdgeFade(vec3 p) {
    vec3 outside = abs(p) - u_ddgiHalf;
    vec3 ramp = clamp(1.0 - outside / u_ddgiFadeWidth, 0.0, 1.0);
    vec3 f = mix(vec3(1.0), mix(vec3(0.0), ramp, greaterThan(u_ddgiFadeWidth, vec3(0.0))),
                 greaterThan(outside, vec3(0.0)));
    return f.x * f.y * f.z;
}

// renderer/probes/Octahedral.h: +Y at the centre, the lower hemisphere folded to the corners.
// d need not be unit (the L1 norm divides it out), only non-zero.
vec2 ddgiOctEncode(vec3 d) {
    float l1 = abs(d.x) + abs(d.y) + abs(d.z);
    vec2 uv = d.xz * (1.0 / l1); // one division, not two
    vec2 s = vec2(uv.x >= 0.0 ? 1.0 : -1.0, uv.y >= 0.0 ? 1.0 : -1.0);
    return d.y < 0.0 ? (1.0 - abs(uv.yx)) * s : uv; // a select: no branch (ddgiProbeWeight)
}

// Tile-local continuous texel coordinate of `dir` (the 1-texel border included).
vec2 ddgiTileLocal(vec3 dir, float interior) {
    return (ddgiOctEncode(dir) * 0.5 + 0.5) * interior + 1.0;
}

// Corner i (0..7) of the 8 surrounding probes as an offset in {0,1}^3.
ivec3 ddgiCorner(int i) {
#ifdef GI_ORDER_SLICE_FIRST
    // The 4 probes of one texture slice (local Y plane) before the next slice.
    return ivec3(i & 1, (i >> 2) & 1, (i >> 1) & 1);
#else
    return ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
#endif
}

// Sparse volumes pack their stored tiles (renderer/probes/store/SparseLayout.h); the state's w holds
// the tile's code (common_ddgi_tile.glsl), so the lookup costs no extra fetch, only a few
// shifts and masks. Compiled only for probe sets with a sparse volume (DDGI_SPARSE_TILES,
// GpuProbes::anySparse): dense sets find the tile from the probe's coordinates and keep their
// instructions. In a set with a sparse volume every volume's w holds its code (a dense
// volume's tile, (i, k, layer j), too): one path, no uniform branch (llvmpipe runs both
// sides of one).
#ifdef DDGI_SPARSE_TILES
#include "common_ddgi_tile.glsl"
#endif

// A dense volume's probe (i, j, k) owns tile (i, k, layer j).
ivec3 ddgiDenseTile(ivec3 q) {
    return ivec3(q.x, q.z, q.y);
}

// Visibility-and-position weight of probe q = base + off (README steps 4a-4d); < 0 when q is
// skipped (outside the grid, invalid or absent). `cellProbe`: where probe `base` would sit
// unrelocated (per lookup), so a corner adds only its constant step. GI_LOOPS_SPLIT passes
// `cellProbe` relative to `p` and `biased` relative to the cell's probe instead (ddgiSample):
// two vectors live across the corners instead of three, which the mobile compilers need to keep
// the split loops out of spills (bench/shaders/README.md); the fused path keeps the CPU
// sampler's exact order of operations. `tile`: where q's texels are;
// sparse sets also return the state's w (`stateW`, 1 when skipped), from which ddgiTile finds
// the tile again.
// Branch-free: llvmpipe runs both sides of a branch whose condition differs between the lanes
// and pays for the masks besides (a GPU's threads diverge likewise), so every step is computed
// and selected: a skipped probe is computed on its nearest grid probe and rejected at the end.
hfloat ddgiProbeWeight(ivec3 q, ivec3 off, vec3 cellProbe, vec3 p, hvec3 n, vec3 biased,
                       hvec3 alpha, out ivec3 tile
#ifdef DDGI_SPARSE_TILES
                       , out float stateW
#endif
) {
    ivec3 qc = min(q, ddgiLoopLast); // in the grid: q unless an axis has one probe
    vec4 state = texelFetch(u_ddgiState, ivec3(qc.x, qc.z, qc.y), 0);
    bool live = all(lessThan(q, ddgiLoopCounts)) && state.w >= 0.5;
#ifdef DDGI_SPARSE_TILES
    stateW = live ? state.w : 1.0;
    tile = ddgiTile(stateW); // w >= 1 here
#else
    tile = ddgiDenseTile(qc);
#endif
#ifdef GI_LOOPS_SPLIT
    vec3 d = vec3(off) * ddgiLoopStep + state.xyz; // the probe, relative to the cell's probe
    vec3 toProbe = cellProbe + d;
    vec3 toPoint = biased - d;
#else
    vec3 probe = cellProbe + vec3(off) * ddgiLoopStep + state.xyz;
    vec3 toProbe = probe - p;
    vec3 toPoint = biased - probe;
#endif

    // 4a. Wrap shading: probes behind the surface count less (never zero). The cosine of the
    // direction to the probe (n when the probe sits on the point) without normalising it.
    float len2 = dot(toProbe, toProbe);
    float height = dot(toProbe, vec3(n)); // the probe's height over the surface's plane
    hfloat t = len2 > 0.0 ? (ddgiHalf(height * inversesqrt(len2)) + 1.0) * 0.5 : 1.0;
    hfloat w = t * t + DDGI_WRAP_BIAS;

    // 4b. Chebyshev visibility from the probe towards the biased point (only where the point
    // is farther than the mean); n when the point sits on the probe. The direction is made unit
    // as on the CPU: the encoding does not need it, but its rounding without it moved the
    // texel coordinate enough that a weight on the crushed Chebyshev slope (~cheb^9) differed
    // from the CPU's by 1.2e-3 once the behind-surface fade (4c') left it dominant.
    float dist = sqrt(dot(toPoint, toPoint));
    vec2 visCoord = vec2(tile.xy) * ddgiLoopVisTile +
                    ddgiOctEncode(dist > 0.0 ? toPoint / dist : vec3(n)) * ddgiLoopVisOct.xy +
                    ddgiLoopVisOct.zw;
    hvec2 vis = texture(u_ddgiVisibility, vec3(visCoord, float(tile.z))).rg;
    hfloat d01 = ddgiHalf(dist * ddgiLoopInvMaxDistance);
    hfloat variance = max(vis.y - vis.x * vis.x, DDGI_VARIANCE_FLOOR);
    hfloat dd = d01 - vis.x;
    hfloat cheb = variance / (variance + dd * dd);
#ifdef DDGI_SPARSE_TILES
    // An irradiance-only probe (the code's bit 23 set, SparseLayout.h kNoVisibilityFlag) has no
    // visibility tile: only cells free of geometry read it, so it counts as seen (its fetch
    // above read some other tile and is ignored).
    bool ownVis = stateW <= 8388608.0; // code + 1 <= 2^23: no flag
#else
    bool ownVis = true;
#endif
    w *= d01 > vis.x && ownVis ? max(cheb * cheb * cheb, DDGI_CHEBYSHEV_FLOOR) : 1.0;

    // 4c. Crush tiny weights.
    w *= w < DDGI_CRUSH_THRESHOLD ? (w * w) * (1.0 / (DDGI_CRUSH_THRESHOLD * DDGI_CRUSH_THRESHOLD))
                                  : 1.0;
    // 4c'. Probes behind the surface's plane fade out (ProbeSampler.h kBehindRampCells).
    w *= ddgiHalf(max(clamp(1.0 + height * ddgiLoopBehindInvWidth, 0.0, 1.0), DDGI_BEHIND_FLOOR));

    // 4d. Trilinear.
    hfloat tri = (off.x != 0 ? alpha.x : 1.0 - alpha.x) * (off.y != 0 ? alpha.y : 1.0 - alpha.y) *
                 (off.z != 0 ? alpha.z : 1.0 - alpha.z);
    return live ? w * max(tri, DDGI_MIN_TRILINEAR) : -1.0;
}

// Irradiance of the probe whose tile is `tile` (ddgiTile); `irrCoord`: the texture coordinate
// of the texel in tile (0, 0) (ddgiIrrCoord), the same in every tile.
hvec3 ddgiProbeIrradiance(ivec3 tile, vec2 irrCoord) {
    vec2 c = vec2(tile.xy) * ddgiLoopIrrTile + irrCoord;
#ifdef GI_GUARD_EXPOSURE_ON
    return ddgiHalf(texture(u_ddgiIrradiance, vec3(c, float(tile.z))).rgb * ddgiLoopIrradianceScale);
#else
    return texture(u_ddgiIrradiance, vec3(c, float(tile.z))).rgb;
#endif
}

// ddgiProbeIrradiance's `irrCoord` of unit direction `dir`.
vec2 ddgiIrrCoord(vec3 dir) {
    return ddgiOctEncode(dir) * u_ddgiIrrOct.xy + u_ddgiIrrOct.zw;
}

// The irradiance of the probe whose tile is `tile` (ddgiProbeIrradiance), at weight `w` (< 0:
// skipped, a select rather than a branch), added to the sums.
void ddgiAddProbe(ivec3 tile, hfloat w, vec2 irrLocal, inout hvec3 sumE, inout hfloat sumW) {
    hvec3 e = ddgiProbeIrradiance(tile, irrLocal);
    sumE += w >= 0.0 ? w * e : vec3(0.0);
    sumW += max(w, 0.0);
}

// Corner i's probe weight (ddgiProbeWeight; < 0 = skipped) and its tile. `stateW`: sparse sets,
// the probe's state w (ddgiSplitTile decodes it again); dense sets, 0.
hfloat ddgiCornerWeight(int i, ivec3 base, vec3 cellProbe, vec3 p, hvec3 nh, vec3 biased,
                        hvec3 alpha, out ivec3 tile, out float stateW) {
    ivec3 off = ddgiCorner(i);
#ifdef DDGI_SPARSE_TILES
    return ddgiProbeWeight(base + off, off, cellProbe, p, nh, biased, alpha, tile, stateW);
#else
    stateW = 0.0;
    return ddgiProbeWeight(base + off, off, cellProbe, p, nh, biased, alpha, tile);
#endif
}

// One corner of GI_LOOPS_FUSED's loop: probe i's weight and weighted irradiance added to the
// sums. ddgiSample calls it for i = 0..7 written out rather than in a `for`: NIR does not unroll
// a loop this long, and llvmpipe then runs it as a loop, recomputing per iteration what the
// unrolled code folds (each corner's offset and trilinear selects, the samplers' set-up):
// written out, 27% fewer instructions per evaluation and GI / floor 2.17 -> 1.83 on an AMD EPYC
// (studies/results/2026-11-29-p1-written-out-loops.md). The mobile compilers agree only in part
// (`probebench shaders`, bench/shaders/README.md): Mali-G52 and Adreno fold the written-out
// corners well, while Mali-G57 and V3D spill on them (as a real loop none of them spills, at
// about twice the instructions per corner). GI_LOOPS_SPLIT, which keeps eight weights live,
// runs as real loops for that reason.
// tests/unit/CostModelShaderTest.cpp reads these 8 calls as the fused loop.
void ddgiFusedCorner(int i, ivec3 base, vec3 cellProbe, vec3 p, hvec3 nh, vec3 biased,
                     hvec3 alpha, vec2 irrLocal, inout hvec3 sumE, inout hfloat sumW) {
    ivec3 tile;
    float stateW;
    hfloat w = ddgiCornerWeight(i, base, cellProbe, p, nh, biased, alpha, tile, stateW);
    ddgiAddProbe(tile, w, irrLocal, sumE, sumW);
}

// GI_LOOPS_SPLIT's first loop, corner i: ddgiCornerWeight without the tile, which the second
// loop gets from `stateW` or the corner again (ddgiSplitTile).
hfloat ddgiSplitWeight(int i, ivec3 base, vec3 cellProbe, vec3 p, hvec3 nh, vec3 biased,
                       hvec3 alpha, out float stateW) {
    ivec3 tile;
    return ddgiCornerWeight(i, base, cellProbe, p, nh, biased, alpha, tile, stateW);
}

// GI_LOOPS_SPLIT's second loop: corner i's tile, from ddgiSplitWeight's `stateW` (sparse) or
// the corner (dense).
ivec3 ddgiSplitTile(int i, ivec3 base, float stateW) {
#ifdef DDGI_SPARSE_TILES
    return ddgiTile(stateW);
#else
    return ddgiDenseTile(min(base + ddgiCorner(i), ddgiLoopLast));
#endif
}

// Irradiance at local point `p` (ddgiLocal of the caller's position: the caller has it from the
// influence test) for surface normal `normal` seen from direction `view` (caller's space;
// surface -> viewer; need not be unit). rgb = E * fade, a = weight (fade; 0 = no data).
hvec4 ddgiSample(vec3 p, vec3 normal, vec3 view) {
#ifdef DDGI_SPARSE_TILES
    ddgiInitTileFields();
#endif
    ddgiInitLoopConstants();
    // 1. Local frame.
    vec3 n = ddgiSafeNormalize(u_ddgiToLocal * normal, vec3(0.0, 1.0, 0.0));
    vec3 v = ddgiSafeNormalize(u_ddgiToLocal * view, n);

    // 2. Edge fade (roots; children have a zero fade width and fade 0 outside the box). A
    // point with no fade is looked up all the same and given 0 at the end (no branch).
    float fade = ddgiEdgeFade(p);

    // 3. Surface bias; base probe from the unbiased point, fractions from the biased one.
    vec3 biased = p + (n * u_ddgiBiasNormal + v * u_ddgiBiasView);
    vec3 g = clamp((p + u_ddgiHalf) * u_ddgiInvCell, vec3(0.0), u_ddgiMaxBase);
    ivec3 base = ivec3(floor(g));
    hvec3 alpha = ddgiHalf(clamp((biased + u_ddgiHalf) * u_ddgiInvCell - vec3(base), 0.0, 1.0));
    hvec3 nh = ddgiHalf(n);

    // 4. The 8 surrounding probes.
    vec3 cellProbe = u_ddgiGridOrigin + vec3(base) * u_ddgiGridStep;
#ifdef GI_LOOPS_SPLIT
    biased -= cellProbe; // relative to the cell's probe, and the cell's probe to p
    cellProbe -= p;      // (ddgiProbeWeight)
#endif
    vec2 irrLocal = ddgiIrrCoord(n);
    hvec3 sumE = vec3(0.0);
    hfloat sumW = 0.0;
#ifdef GI_LOOPS_SPLIT
    // All visibility weights first (the visibility fetches back to back), then irradiance.
    // Real loops, unlike the fused corners: written out, the eight weights and states and every
    // corner's temporaries were live at once, and each mobile compiler spilled or bloated
    // (Mesa 22.3: Mali-G52 6:43 spills:fills, G57 22:246, V3D 56:109, Adreno 3x the
    // instructions, Tegra X1 78 registers; bench/shaders/README.md). As loops only the weights and
    // states cross from the first loop to the second: 8 halves and 8 floats, kept in vectors
    // (a dynamic component write is a select; an array indexed in a loop is unrolled back or
    // put in memory). Sparse sets keep each probe's state w and decode its tile again; dense sets
    // recompute the tile from the corner (ddgiSplitTile).
    hvec4 weightsLo, weightsHi;
    vec4 statesLo, statesHi; // sparse: each probe's state w; dense: unused (ddgiSplitWeight)
    for (int i = 0; i < 8; ++i) {
        float state;
        hfloat w = ddgiSplitWeight(i, base, cellProbe, p, nh, biased, alpha, state);
        if (i < 4) {
            weightsLo[i] = w;
            statesLo[i] = state;
        } else {
            weightsHi[i - 4] = w;
            statesHi[i - 4] = state;
        }
    }
    for (int i = 0; i < 8; ++i) {
        hfloat w = i < 4 ? weightsLo[i & 3] : weightsHi[i & 3];
        float state = i < 4 ? statesLo[i & 3] : statesHi[i & 3];
        ddgiAddProbe(ddgiSplitTile(i, base, state), w, irrLocal, sumE, sumW);
    }
#else
    // The fused loop over corners 0..7, written out (ddgiFusedCorner says why).
    ddgiFusedCorner(0, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(1, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(2, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(3, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(4, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(5, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(6, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
    ddgiFusedCorner(7, base, cellProbe, p, nh, biased, alpha, irrLocal, sumE, sumW);
#endif

    // 5. Normalise, then fade.
    hfloat fadeH = ddgiHalf(fade);
#ifdef GI_GUARD_EXPOSURE_ON
    hvec4 result = vec4(sumE / sumW * fadeH, fadeH);
#else
    // highp: 1 / the storage scale of a dim scenario (2^-25 at light x1e-4) is not an fp16.
    hvec4 result = vec4(sumE / sumW * fadeH * u_ddgiIrradianceScale, fadeH);
#endif
    return fade > 0.0 && sumW > 0.0 ? result : vec4(0.0);
}
