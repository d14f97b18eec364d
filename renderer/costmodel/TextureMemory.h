#pragma once
// Where a texel lives in memory: the byte address the cache model replays. A GPU's real
// layouts are mostly undocumented swizzles, so the layout is a parameter:
//   linear: each layer row-major, rows back to back (a linear texture; the layout the probe
//           data has in the file and in glTexImage3D's input);
//   tiled:  each layer cut into tiles of kTileBytes, tiles row-major, elements inside a tile
//           in Morton (Z) order - the shape of the 2D-local swizzles desktop, console and
//           mobile GPUs use for sampled textures (AMD's and NVIDIA's tilings, Mali/Adreno
//           block layouts), not any one of them exactly.
// Elements are texels, or 4x4 blocks for block-compressed formats (BC6H: 16 B per block).
// Layers follow each other; every texture starts on a kTextureAlignment boundary.
// A 3D texture (`volume`, the SH technique's) is tiled in 3D instead: kTileBytes bricks
// (8x8x8 texels of 8 B, 16x16x16 of 1 B), bricks x, then y, then layer-major, elements inside a
// brick in 3D Morton order (x lowest) - the "thick" tiling GPUs use for volume textures, so a
// trilinear 2x2x2 footprint lies in one to a few lines instead of one tile per layer.
#include <cstdint>
#include <string>

namespace pb::costmodel {

enum class MemoryLayout { Linear, Tiled };
const char* layoutName(MemoryLayout l);
// "linear" | "tiled"; throws pb::Error naming `option` otherwise.
MemoryLayout parseMemoryLayout(const std::string& text, const std::string& option = "--layout");

constexpr std::uint64_t kTileBytes = 4096;
constexpr std::uint64_t kTextureAlignment = 65536;

class TextureMemory {
public:
    TextureMemory() = default;
    // width/height in texels; blockDim 1 (texels) or 4 (4x4 blocks of elementBytes each).
    TextureMemory(std::uint64_t base, int width, int height, int layers, int blockDim,
                  int elementBytes, MemoryLayout layout, bool volume = false);
    std::uint64_t address(int x, int y, int layer) const; // texel (x, y) of a layer
    std::uint64_t base() const { return base_; }
    std::uint64_t bytes() const {
        return brickBits_ ? totalBytes_ : layerBytes_ * std::uint64_t(layers_);
    }
    // First free aligned address after this texture.
    std::uint64_t end() const;
    int blockDim() const { return blockDim_; }
    int elementBytes() const { return elementBytes_; }

private:
    std::uint64_t base_ = 0, layerBytes_ = 0;
    int layers_ = 0, blockDim_ = 1, elementBytes_ = 4;
    int elemW_ = 0, elemH_ = 0;         // elements per layer row / column
    int tileBitsX_ = 0, tileBitsY_ = 0; // tiled: tile = 2^bx x 2^by elements
    int tilesPerRow_ = 0;
    MemoryLayout layout_ = MemoryLayout::Tiled;
    // Tiled volume: brick = 2^bx x 2^by x 2^bz elements (brickBits_ = bx + by + bz, 0: 2D).
    int brickBits_ = 0, brickBitsX_ = 0, brickBitsY_ = 0, brickBitsZ_ = 0;
    int bricksPerRow_ = 0, brickRows_ = 0;
    std::uint64_t totalBytes_ = 0;
};

} // namespace pb::costmodel
