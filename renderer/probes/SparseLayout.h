#pragma once
// Sparse probe storage: only some probes of a volume own a texture tile ("stored"); the
// others are absent and sample like invalid probes (weight 0). The stored tiles are packed,
// in probe index order, into a smaller texture array of the same kind, described by
// `packedCounts` as if it were a probe grid: packed slot s sits where probe s of a grid of
// `packedCounts` would, i.e. tile (s % pc.x, (s / pc.x) % pc.z) of layer s / (pc.x * pc.z).
// A volume whose probes are all stored packs to its own grid (slot = probe index): the dense
// layout is the special case, bit for bit.
//
// The indirection probe -> slot is the per-probe state the GPU already fetches (GpuProbes.h:
// the state texel's w = +(slot+1) valid, -(slot+1) invalid, 0 absent), so a sparse lookup
// costs no extra fetch. The file stores a presence bitmap per volume (ProbeFile.h).
#include "probes/ProbeSet.h"

#include <cstdint>
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
// True when some probe of the volume is absent (the volume uses a packed layout).
bool isSparse(const std::vector<ProbeState>& states);

// The tile (column, row, layer) of packed slot `slot` in a texture of `packed` tile counts:
// (s % pc.x, (s / pc.x) % pc.z, s / (pc.x * pc.z)), what the shader's ddgiTile computes from
// the state's w (shaders/common_ddgi.glsl).
glm::ivec3 packedTile(int slot, const glm::ivec3& packed);

// Where a volume's probe tiles lie in its GPU textures: the one description GpuProbes uploads
// by and the texture-cache model (renderer/costmodel) replays addresses from. Dense: probe
// (i, j, k) owns tile (i, k, layer j) of a grid of `counts`; sparse: only stored probes own a
// tile, packed in probe index order into `packedCounts`.
struct TileLayout {
    bool sparse = false;
    glm::ivec3 counts{1};       // the probe grid
    glm::ivec3 packedCounts{1}; // the tile grid of the textures (= counts unless sparse)
    std::vector<int> slots;     // per probe: its slot (dense: its index), -1 = absent
    // The tile (column, row, layer) of grid probe `q`; (-1, -1, -1) when it owns none.
    glm::ivec3 tileOf(const glm::ivec3& q) const;
};
// Throws pb::Error when `states` does not hold one state per probe of `v`.
TileLayout tileLayout(const ProbeVolume& v, const std::vector<ProbeState>& states);

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

// GPU bytes of the per-probe state texture (RGBA32F, every grid probe): for sparse volumes
// the indirection, counted by the memory report.
constexpr std::size_t kStateBytesPerProbe = 16;

} // namespace pb::probes
