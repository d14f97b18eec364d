#pragma once
// Sparse probe storage: only some probes of a volume own a texture tile ("stored"); the
// others are absent and sample like invalid probes (weight 0). The stored tiles are packed,
// in probe index order, into a smaller texture array of the same kind, described by
// `packedCounts` as if it were a probe grid: packed slot s sits where probe s of a grid of
// `packedCounts` would, i.e. tile (s % pc.x, (s / pc.x) % pc.z) of layer s / (pc.x * pc.z).
// A volume whose probes are all stored packs to its own grid (slot = probe index): the dense
// layout is the special case, bit for bit.
//
// The indirection probe -> tile rides on the per-probe state the GPU already fetches
// (GpuProbes.h: the state texel's w holds the tile's coordinates as bit fields, TileCode
// below), so a sparse lookup costs no extra fetch. The file stores a presence bitmap per
// volume (ProbeFile.h); the packing and the codes follow from it.
#include "probes/ProbeSet.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pb::probes {

// The packed grid for `stored` tiles of a volume with `dense` counts: rows of dense.x tiles
// (fewer when fewer are stored), spread evenly over as few layers as the dense layer size
// allows, so a layer is never larger than the dense one. At least one tile (GL has no empty
// texture). Equals `dense` when every probe is stored.
glm::ivec3 packedCounts(std::size_t stored, const glm::ivec3& dense);

// Per probe of `states`: its packed slot, or -1 when it is not stored.
std::vector<int> packedSlots(const std::vector<ProbeState>& states);
std::size_t storedCount(const std::vector<ProbeState>& states);
// Probes that own an irradiance tile but no visibility tile (ProbeState::irradianceOnly).
std::size_t irradianceOnlyCount(const std::vector<ProbeState>& states);
// Per probe: its slot in the packed IRRADIANCE texture: the stored probes first, with their
// packedSlots, then the irradiance-only probes in probe order; -1 for the rest. A stored
// probe's tile therefore sits at the same place in the irradiance and the visibility texture,
// and the visibility texture simply ends after the stored slots (visibilityPackedCounts).
std::vector<int> irradianceSlots(const std::vector<ProbeState>& states);
// The packed visibility grid that holds `stored` slots with the same columns and rows as
// `irradiancePacked` (so packedTile agrees in both), and only the layers they fill (at least 1).
glm::ivec3 visibilityPackedCounts(std::size_t stored, const glm::ivec3& irradiancePacked);
// True when some probe of the volume is absent (the volume uses a packed layout).
bool isSparse(const std::vector<ProbeState>& states);

// The tile (column, row, layer) of packed slot `slot` in a texture of `packed` tile counts:
// (s % pc.x, (s / pc.x) % pc.z, s / (pc.x * pc.z)): where packTiles puts it. The shader never
// divides: it reads the tile's code (TileCode) from the state's w.
glm::ivec3 packedTile(int slot, const glm::ivec3& packed);

// The tile indirection in the state texel's w (GpuProbes uploads it, ddgiTile in
// shaders/common_ddgi_tile.glsl decodes it): a tile's column, row and layer as bit fields of
// one integer, code = column | row << columnBits | layer << (columnBits + rowBits), each field
// as wide as the volume's tile grid needs, and w = +(code + 1) valid, -(code + 1) invalid with
// a tile, 0 absent. The decode is a float-to-int conversion, a subtraction, two shifts and two
// masks: no integer division, which llvmpipe (and GPUs) emulate at great cost. The state
// texture is RGBA32F, whose floats hold every integer up to 2^24 exactly, so the fields may
// use 24 bits (code + 1 <= 2^24). A volume within volumeProblem's limits (1024 probes per axis,
// 2^18 per volume) needs at most 20: sum ceil(log2 n) < log2(product) + 3 <= 21.
constexpr int kTileCodeBits = 24;
// The code's top bit: the probe owns an irradiance tile only (ProbeState::irradianceOnly), so
// a lookup gives it visibility weight 1 and reads no visibility texel of it. The fields then
// get kTileCodeBits - 1 bits (a volume within volumeProblem's limits needs at most 21).
constexpr std::uint32_t kNoVisibilityFlag = 1u << (kTileCodeBits - 1);
struct TileCode {
    int columnBits = 0, rowBits = 0, layerBits = 0; // the shader gets (columnBits, rowBits)
    // The state's w for a probe owning `tile` (column, row, layer); valid = false: negative;
    // ownVisibility = false: kNoVisibilityFlag set.
    float encode(const glm::ivec3& tile, bool valid, bool ownVisibility = true) const;
    // The tile from w (its sign and the flag ignored), with the shader's operations: for tests
    // and tools.
    glm::ivec3 decode(float w) const;
    // False when w carries kNoVisibilityFlag (the shader's test: w > 2^23).
    static bool ownsVisibility(float w);
};
// The code for a texture of `tileGrid` tiles (as packedCounts: x columns, y layers, z rows).
// Throws pb::Error naming `what` when its fields need more than kTileCodeBits bits.
TileCode tileCode(const glm::ivec3& tileGrid, const std::string& what);

// Where a volume's probe tiles lie in its GPU textures: the one description GpuProbes uploads
// by and the texture-cache model (renderer/costmodel) replays addresses from. Dense: probe
// (i, j, k) owns tile (i, k, layer j) of a grid of `counts`; sparse: only stored probes own a
// tile, packed in probe index order into `packedCounts`. Every volume, dense or sparse,
// carries its tiles' codes in the state's w (stateW), so the shader of a set with a sparse
// volume finds every volume's tiles the same way.
struct TileLayout {
    bool sparse = false;
    glm::ivec3 counts{1};       // the probe grid
    glm::ivec3 packedCounts{1}; // the irradiance texture's tile grid (= counts unless sparse)
    // The visibility texture's: packedCounts' columns and rows, the stored slots' layers only.
    glm::ivec3 visibilityPackedCounts{1};
    std::vector<int> slots; // per probe: its irradiance slot (irradianceSlots), -1 = absent
    int storedSlots = 0;    // slots below this own a visibility tile too
    // Per probe: the probe whose tile a lookup reads (AbsentProbeFill.h: an absent probe
    // outside geometry reads its nearest stored one); empty: each its own.
    std::vector<int> fillSource;
    TileCode code;              // of packedCounts
    // The tile (column, row, layer) grid probe `q` reads (its own, or its fill source's);
    // (-1, -1, -1) when it reads none.
    glm::ivec3 tileOf(const glm::ivec3& q) const;
    // The state texel's w of probe `index` (probe index order): the code of the tile it reads,
    // signed by `valid`, flagged when that tile has no visibility (kNoVisibilityFlag); 0 when it
    // reads none (absent, not filled).
    float stateW(std::size_t index, bool valid) const;
    // The packed slot probe `index` reads (through fillSource); -1 none.
    int slotRead(std::size_t index) const;
};
// Throws pb::Error when `states` does not hold one state per probe of `v`, or when the tile
// grid exceeds the code's range (TileCode). `fillSource`: as fillSources (AbsentProbeFill.h),
// empty for none.
TileLayout tileLayout(const ProbeVolume& v, const std::vector<ProbeState>& states,
                      const std::vector<int>& fillSource = {});

// The stored bytes of `dense` (a volume texture in format `f`, tiles of `tile` texels) with
// only the slotted tiles, packed into `packed` counts. Works on the stored bytes (BC6H: whole
// 4x4 blocks; tiles are multiples of 4), so nothing is re-encoded. `texels` stays empty.
ProbeTexture packTiles(const ProbeTexture& dense, const std::vector<int>& slots,
                       const glm::ivec3& denseCounts, const glm::ivec3& packed, int tile,
                       StorageFormat f);
// The inverse: a dense texture of `denseCounts` whose slotted tiles come from `packed` and
// the others are zero bytes; texels decoded from the stored bytes.
ProbeTexture unpackTiles(const ProbeTexture& packed, const std::vector<int>& slots,
                         const glm::ivec3& denseCounts, const glm::ivec3& packedCounts, int tile,
                         StorageFormat f);
// unpackTiles(packTiles(t, ...)) done in place: the stored bytes of the tiles without a slot
// zeroed, and the texels decoded again. The same bytes and texels, without the two copies
// (sparse storage applies it to every texture of every bake, the lattice search's trials too).
// The texels must be what the stored bytes decode to, as quantise() and the file reader leave
// them: RGBA32F and RGBA16F then zero the texels of those tiles alone. A texture without stored
// bytes (sanitise()) has only its texels zeroed.
void zeroUnslottedTiles(ProbeTexture& t, const std::vector<int>& slots,
                        const glm::ivec3& denseCounts, int tile, StorageFormat f);

// GPU bytes of the per-probe state texture (RGBA32F, every grid probe): for sparse volumes
// the indirection, counted by the memory report.
constexpr std::size_t kStateBytesPerProbe = 16;

} // namespace pb::probes
