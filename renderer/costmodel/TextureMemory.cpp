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
// 3D Morton: x, y, z bits interleaved (x lowest) while each has bits.
std::uint64_t morton3(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bx, int by, int bz) {
    std::uint64_t out = 0;
    int bit = 0;
    for (int i = 0; i < std::max(bx, std::max(by, bz)); ++i) {
        if (i < bx) out |= std::uint64_t((x >> i) & 1u) << bit++;
        if (i < by) out |= std::uint64_t((y >> i) & 1u) << bit++;
        if (i < bz) out |= std::uint64_t((z >> i) & 1u) << bit++;
    }
    return out;
}
} // namespace

TextureMemory::TextureMemory(std::uint64_t base, int width, int height, int layers, int blockDim,
                             int elementBytes, MemoryLayout layout, bool volume)
    : base_(base), layers_(layers), blockDim_(blockDim), elementBytes_(elementBytes),
      layout_(layout) {
    elemW_ = (width + blockDim - 1) / blockDim;
    elemH_ = (height + blockDim - 1) / blockDim;
    if (volume && layout == MemoryLayout::Tiled) {
        brickBits_ = std::countr_zero(kTileBytes / std::uint64_t(elementBytes));
        brickBitsX_ = (brickBits_ + 2) / 3;
        brickBitsY_ = (brickBits_ + 1) / 3;
        brickBitsZ_ = brickBits_ / 3;
        bricksPerRow_ = (elemW_ + (1 << brickBitsX_) - 1) >> brickBitsX_;
        brickRows_ = (elemH_ + (1 << brickBitsY_) - 1) >> brickBitsY_;
        const int slabs = (layers + (1 << brickBitsZ_) - 1) >> brickBitsZ_;
        totalBytes_ = std::uint64_t(bricksPerRow_) * std::uint64_t(brickRows_) *
                      std::uint64_t(slabs) * kTileBytes;
        return;
    }
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
    if (brickBits_) {
        const std::uint32_t ez = std::uint32_t(layer);
        const std::uint64_t brick =
            (std::uint64_t(ez >> brickBitsZ_) * std::uint64_t(brickRows_) + (ey >> brickBitsY_)) *
                std::uint64_t(bricksPerRow_) +
            (ex >> brickBitsX_);
        const std::uint32_t mx = (1u << brickBitsX_) - 1, my = (1u << brickBitsY_) - 1,
                            mz = (1u << brickBitsZ_) - 1;
        return base_ + brick * kTileBytes +
               morton3(ex & mx, ey & my, ez & mz, brickBitsX_, brickBitsY_, brickBitsZ_) *
                   std::uint64_t(elementBytes_);
    }
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
