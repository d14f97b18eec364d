#include "probes/store/SparseLayout.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pb::probes {
namespace {

// The stored bytes of a texture as a grid of units: texels, or BC6H 4x4 blocks.
struct Units {
    int texels = 1;        // texels per unit along x and y
    std::size_t bytes = 0; // bytes per unit
};

Units unitsOf(const TextureShape& s, StorageFormat f) {
    if (f == StorageFormat::Bc6h) return {4, 16};
    return {1, std::size_t(s.channels) * (f == StorageFormat::Rgba32f ? 4u : 2u)};
}

// packedTile as a grid position (x, layer, z), the order probeCoords and copyTile use.
glm::ivec3 gridPositionOf(int slot, const glm::ivec3& grid) {
    const glm::ivec3 t = packedTile(slot, grid);
    return {t.x, t.z, t.y};
}

// Byte offset of row `r` (in units) of the tile at grid position `at` (x, layer, z) of a
// texture of `shape`: the layout copyTile and zeroUnslottedTiles share.
std::size_t tileRowOffset(const TextureShape& shape, const glm::ivec3& at, int tile, int r,
                          const Units& u) {
    const int tileUnits = tile / u.texels;
    const std::size_t row = std::size_t(shape.width / u.texels) * u.bytes;
    const std::size_t layer = row * std::size_t(shape.height / u.texels);
    return std::size_t(at.y) * layer + std::size_t(at.z * tileUnits + r) * row +
           std::size_t(at.x * tileUnits) * u.bytes;
}

// Copies one tile of stored bytes from grid position `from` of `src` to `to` of `dst`.
void copyTile(const ProbeTexture& src, const glm::ivec3& from, ProbeTexture& dst,
              const glm::ivec3& to, int tile, const Units& u) {
    const int tileUnits = tile / u.texels;
    for (int r = 0; r < tileUnits; ++r)
        std::memcpy(dst.stored.data() + tileRowOffset(dst.shape, to, tile, r, u),
                    src.stored.data() + tileRowOffset(src.shape, from, tile, r, u),
                    std::size_t(tileUnits) * u.bytes);
}

TextureShape shapeFor(const glm::ivec3& counts, int tile, int channels) {
    return {counts.x * tile, counts.z * tile, counts.y, channels};
}

} // namespace

glm::ivec3 packedCounts(std::size_t stored, const glm::ivec3& dense) {
    const std::size_t perLayer = std::size_t(dense.x) * std::size_t(dense.z);
    if (stored == 0) return {1, 1, 1};
    const std::size_t width = std::min<std::size_t>(std::size_t(dense.x), stored);
    const std::size_t layers = (stored + perLayer - 1) / perLayer;
    const std::size_t rows = (stored + width - 1) / width;
    return {int(width), int(layers), int((rows + layers - 1) / layers)};
}

std::vector<int> packedSlots(const std::vector<ProbeState>& states) {
    std::vector<int> slots(states.size(), -1);
    int next = 0;
    for (std::size_t i = 0; i < states.size(); ++i)
        if (states[i].stored) slots[i] = next++;
    return slots;
}

std::size_t storedCount(const std::vector<ProbeState>& states) {
    return std::size_t(
        std::count_if(states.begin(), states.end(), [](const ProbeState& p) { return p.stored; }));
}

std::size_t irradianceOnlyCount(const std::vector<ProbeState>& states) {
    return std::size_t(std::count_if(states.begin(), states.end(),
                                     [](const ProbeState& p) { return p.irradianceOnly; }));
}

std::vector<int> irradianceSlots(const std::vector<ProbeState>& states) {
    std::vector<int> slots = packedSlots(states);
    int next = int(storedCount(states));
    for (std::size_t i = 0; i < states.size(); ++i)
        if (states[i].irradianceOnly && !states[i].stored) slots[i] = next++;
    return slots;
}

glm::ivec3 visibilityPackedCounts(std::size_t stored, const glm::ivec3& irradiancePacked) {
    const std::size_t perLayer = std::size_t(irradiancePacked.x) * std::size_t(irradiancePacked.z);
    const std::size_t layers = std::max<std::size_t>(1, (stored + perLayer - 1) / perLayer);
    return {irradiancePacked.x, int(std::min<std::size_t>(layers, std::size_t(irradiancePacked.y))),
            irradiancePacked.z};
}

bool isSparse(const std::vector<ProbeState>& states) {
    return storedCount(states) != states.size();
}

glm::ivec3 packedTile(int slot, const glm::ivec3& packed) {
    return {slot % packed.x, (slot / packed.x) % packed.z, slot / (packed.x * packed.z)};
}

namespace {
// Bits that hold 0..n-1.
int fieldBits(int n) {
    int bits = 0;
    while (bits < 31 && (1 << bits) < n)
        ++bits;
    return bits;
}
} // namespace

TileCode tileCode(const glm::ivec3& tileGrid, const std::string& what) {
    if (glm::any(glm::lessThan(tileGrid, glm::ivec3(1)))) throw Error(what + ": empty tile grid");
    TileCode c;
    c.columnBits = fieldBits(tileGrid.x);
    c.rowBits = fieldBits(tileGrid.z);
    c.layerBits = fieldBits(tileGrid.y);
    const int bits = c.columnBits + c.rowBits + c.layerBits;
    if (bits > kTileCodeBits - 1) // the top bit is kNoVisibilityFlag
        throw Error(what + ": a tile grid of " + std::to_string(tileGrid.x) + " columns, " +
                    std::to_string(tileGrid.z) + " rows and " + std::to_string(tileGrid.y) +
                    " layers needs a " + std::to_string(bits) + "-bit tile code; the state " +
                    "texture (RGBA32F) holds " + std::to_string(kTileCodeBits - 1) + " bits exactly beside its flag");
    return c;
}

float TileCode::encode(const glm::ivec3& tile, bool valid, bool ownVisibility) const {
    const std::uint32_t code = std::uint32_t(tile.x) | std::uint32_t(tile.y) << columnBits |
                               std::uint32_t(tile.z) << (columnBits + rowBits) |
                               (ownVisibility ? 0u : kNoVisibilityFlag);
    const float w = float(code + 1); // exact: code < 2^kTileCodeBits
    return valid ? w : -w;
}

glm::ivec3 TileCode::decode(float w) const {
    // ddgiInitTileFields and ddgiTile, step by step.
    const glm::ivec4 f((1 << columnBits) - 1, columnBits, (1 << rowBits) - 1, columnBits + rowBits);
    const int code = (int(std::abs(w)) - 1) & int(kNoVisibilityFlag - 1);
    return {code & f.x, (code >> f.y) & f.z, code >> f.w};
}

bool TileCode::ownsVisibility(float w) {
    return std::abs(w) <= float(kNoVisibilityFlag); // code + 1 <= 2^23 (integers, exact)
}

TileLayout tileLayout(const ProbeVolume& v, const std::vector<ProbeState>& states,
                      const std::vector<int>& fillSource) {
    const std::string what = "probe volume '" + v.name + "'";
    if (states.size() != std::size_t(v.probeCount()))
        throw Error(what + ": probe state count does not match its grid");
    TileLayout t;
    t.counts = t.packedCounts = v.counts;
    t.slots = irradianceSlots(states);
    t.sparse = isSparse(states);
    t.storedSlots = int(storedCount(states));
    if (t.sparse)
        t.packedCounts =
            packedCounts(std::size_t(t.storedSlots) + irradianceOnlyCount(states), v.counts);
    t.visibilityPackedCounts = t.sparse
                                   ? visibilityPackedCounts(std::size_t(t.storedSlots), t.packedCounts)
                                   : t.packedCounts;
    t.code = tileCode(t.packedCounts, what);
    if (fillSource.size() == states.size()) t.fillSource = fillSource;
    return t;
}

glm::ivec3 TileLayout::tileOf(const glm::ivec3& q) const {
    if (!sparse) return {q.x, q.z, q.y};
    const int slot = slotRead(std::size_t((q.y * counts.z + q.z) * counts.x + q.x)); // probeIndex
    return slot < 0 ? glm::ivec3(-1) : packedTile(slot, packedCounts);
}

int TileLayout::slotRead(std::size_t index) const {
    if (fillSource.empty()) return slots[index];
    const int s = fillSource[index];
    return s < 0 ? -1 : slots[std::size_t(s)];
}

float TileLayout::stateW(std::size_t index, bool valid) const {
    // Dense: slot = index and packedCounts = counts, so this is tile (i, k, layer j) too.
    const int slot = slotRead(index);
    return slot < 0 ? 0.0f
                    : code.encode(packedTile(slot, packedCounts), valid, slot < storedSlots);
}

ProbeTexture packTiles(const ProbeTexture& dense, const std::vector<int>& slots,
                       const glm::ivec3& denseCounts, const glm::ivec3& packed, int tile,
                       StorageFormat f) {
    ProbeTexture out;
    out.storageScale = dense.storageScale; // the stored bytes move as they are
    out.shape = shapeFor(packed, tile, dense.shape.channels);
    out.stored.assign(storedBytes(out.shape, f), 0);
    if (dense.stored.size() != storedBytes(dense.shape, f) ||
        dense.shape != shapeFor(denseCounts, tile, dense.shape.channels))
        throw Error("packTiles: texture does not match its grid");
    const Units u = unitsOf(dense.shape, f);
    ProbeVolume grid;
    grid.counts = denseCounts;
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (slots[i] >= 0)
            copyTile(dense, grid.probeCoords(int(i)), out, gridPositionOf(slots[i], packed), tile,
                     u);
    return out;
}

ProbeTexture unpackTiles(const ProbeTexture& packed, const std::vector<int>& slots,
                         const glm::ivec3& denseCounts, const glm::ivec3& packedGrid, int tile,
                         StorageFormat f) {
    ProbeTexture out;
    out.storageScale = packed.storageScale; // decodeStored divides it out
    out.shape = shapeFor(denseCounts, tile, packed.shape.channels);
    out.stored.assign(storedBytes(out.shape, f), 0);
    const Units u = unitsOf(packed.shape, f);
    ProbeVolume grid;
    grid.counts = denseCounts;
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (slots[i] >= 0)
            copyTile(packed, gridPositionOf(slots[i], packedGrid), out, grid.probeCoords(int(i)),
                     tile, u);
    decodeStored(out, f);
    return out;
}

void zeroUnslottedTiles(ProbeTexture& t, const std::vector<int>& slots,
                        const glm::ivec3& denseCounts, int tile, StorageFormat f) {
    // quantise() leaves an RGBA32F texture's texels scaled; decoding unscales them.
    const bool texelWise = f != StorageFormat::Bc6h && t.storageScale == 1.0f;
    const bool bytes = !t.stored.empty() || !texelWise; // else texels alone (sanitise())
    if ((bytes && t.stored.size() != storedBytes(t.shape, f)) ||
        t.shape != shapeFor(denseCounts, tile, t.shape.channels))
        throw Error("zeroUnslottedTiles: texture does not match its grid");
    const Units u = unitsOf(t.shape, f);
    const int tileUnits = tile / u.texels;
    ProbeVolume grid;
    grid.counts = denseCounts;
    for (std::size_t i = 0; i < slots.size(); ++i) {
        if (slots[i] >= 0) continue;
        const glm::ivec3 at = grid.probeCoords(int(i)); // (x, layer, z), as copyTile reads it
        if (bytes)
            for (int r = 0; r < tileUnits; ++r)
                std::memset(t.stored.data() + tileRowOffset(t.shape, at, tile, r, u), 0,
                            std::size_t(tileUnits) * u.bytes);
        // RGBA32F and RGBA16F decode texel by texel, and a zero stored texel decodes to 0:
        // zeroing the same tiles' texels gives what decoding the whole texture again would,
        // without a pass over every texel (the placement's reference grid holds ~170 MiB).
        if (!texelWise) continue;
        float* origin = tileOrigin(t, at, tile);
        const std::size_t pitch = std::size_t(t.shape.width) * std::size_t(t.shape.channels);
        for (int r = 0; r < tile; ++r)
            std::fill_n(origin + std::size_t(r) * pitch, std::size_t(tile * t.shape.channels),
                        0.0f);
    }
    if (!texelWise) decodeStored(t, f); // a BC6H block's texels depend on each other
}

} // namespace pb::probes
