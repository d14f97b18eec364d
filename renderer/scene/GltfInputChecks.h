#pragma once
// Checks on a glTF file's raw bytes and on what tinygltf would read or decode for it, made
// before tinygltf sees them: tinygltf trusts its input in a few places where a hostile file
// could crash it, hang it, or make it allocate gigabytes. Internal to renderer/scene.
#include <cstddef>
#include <string>
#include <tiny_gltf.h>
#include <vector>

namespace pb::scene::gltf {

// Nesting deeper than this is refused before parsing: tinygltf converts `extras` and
// `extensions` recursively, so [[[[...]]]] a few 10^4 deep overflows the stack. Real files
// nest about 10 deep.
constexpr int kMaxJsonNesting = 128;

// Images: each at most 16384 pixels a side and 2^26 pixels; all together at most 2^28 pixels
// (1 GiB as RGBA8), however many image entries share one compressed picture.
constexpr std::uint32_t kMaxImageSide = 16384;
constexpr std::uint64_t kMaxImagePixels = std::uint64_t(1) << 26;
constexpr std::uint64_t kMaxTotalImagePixels = std::uint64_t(1) << 28;

// Throws pb::Error "path: problem" for a GLB whose header or JSON chunk is inconsistent, or
// JSON nested deeper than kMaxJsonNesting.
void checkRawGltf(const std::string& path, const std::vector<unsigned char>& bytes);

// File access for tinygltf: regular files only (a buffer URI naming a FIFO or a device would
// block or never end), no path expansion, no writing.
tinygltf::FsCallbacks regularFileCallbacks();

// State of the image callback below while one file loads.
struct ImageGuard {
    const tinygltf::Model* model = nullptr; // being filled: buffers and views come first
    std::uint64_t pixels = 0;               // declared pixels of the images decoded so far
};

// tinygltf's image callback: a bufferView inside its buffer, a PNG or JPEG signature, the
// declared size within the limits above; then decoded with libpng / libjpeg-turbo
// (ImageDecode.h), never stb_image. User data: an ImageGuard.
bool checkedImageLoader(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                        int width, int height, const unsigned char* bytes, int size,
                        void* userData);

} // namespace pb::scene::gltf
