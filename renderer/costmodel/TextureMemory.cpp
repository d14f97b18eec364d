#include "costmodel/TextureMemory.h"

#include "core/Error.h"

#include <bit>

namespace pb::costmodel {

const char* layoutName(MemoryLayout l) {
    return l == MemoryLayout::Linear ? "linear" : "tiled";
}

MemoryLayout parseMemoryLayout(const std::string& text, const std::string& option) {
    if (text == "linear") return MemoryLayout::Linear;
    if (text == "tiled") return MemoryLayout::Tiled;
    throw Error(option + ": unknown memory layout '" + text + "' (allowed: linear, tiled)");
}

namespace {
// Interleaves x and y bits (x in the lowest bit) while both have bits; the wider axis' extra
// bits go on top.
std::uint64_t morton(std::uint32_t x, std::uint32_t y, int bitsX, int bitsY) {
    std::uint64_t out = 0;
    int bit = 0;
    for (int i = 0; i < std::max(bitsX, bitsY); ++i) {
        if (i < bitsX) out |= std::uint64_t((x >> i) & 1u) << bit++;
        if (i < bitsY) out |= std::uint64_t((y >> i) & 1u) << bit++;
    }
    return out;
}
} // namespace

TextureMemory::TextureMemory(std::uint64_t base, int width, int height, int layers, int blockDim,
                             int elementBytes, MemoryLayout layout)
    : base_(base), layers_(layers), blockDim_(blockDim), elementBytes_(elementBytes),
      layout_(layout) {
    elemW_ = (width + blockDim - 1) / blockDim;
    elemH_ = (height + blockDim - 1) / blockDim;
    if (layout == MemoryLayout::Linear) {
        layerBytes_ = std::uint64_t(elemW_) * std::uint64_t(elemH_) * std::uint64_t(elementBytes);
        return;
    }
    // Tiles of kTileBytes: as square as a power-of-two element count allows (x gets the odd
    // bit), e.g. 512 texels of 8 B = 32 x 16.
    const int bits = std::countr_zero(kTileBytes / std::uint64_t(elementBytes));
    tileBitsX_ = (bits + 1) / 2;
    tileBitsY_ = bits / 2;
    tilesPerRow_ = (elemW_ + (1 << tileBitsX_) - 1) >> tileBitsX_;
    const int tileRows = (elemH_ + (1 << tileBitsY_) - 1) >> tileBitsY_;
    layerBytes_ = std::uint64_t(tilesPerRow_) * std::uint64_t(tileRows) * kTileBytes;
}

std::uint64_t TextureMemory::address(int x, int y, int layer) const {
    const std::uint32_t ex = std::uint32_t(x / blockDim_), ey = std::uint32_t(y / blockDim_);
    std::uint64_t offset;
    if (layout_ == MemoryLayout::Linear) {
        offset = (std::uint64_t(ey) * std::uint64_t(elemW_) + ex) * std::uint64_t(elementBytes_);
    } else {
        const std::uint64_t tile =
            std::uint64_t(ey >> tileBitsY_) * std::uint64_t(tilesPerRow_) + (ex >> tileBitsX_);
        const std::uint32_t maskX = (1u << tileBitsX_) - 1, maskY = (1u << tileBitsY_) - 1;
        offset = tile * kTileBytes + morton(ex & maskX, ey & maskY, tileBitsX_, tileBitsY_) *
                                         std::uint64_t(elementBytes_);
    }
    return base_ + std::uint64_t(layer) * layerBytes_ + offset;
}

std::uint64_t TextureMemory::end() const {
    return (base_ + bytes() + kTextureAlignment - 1) / kTextureAlignment * kTextureAlignment;
}

} // namespace pb::costmodel
