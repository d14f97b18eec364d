#include "scene/GltfInputChecks.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "scene/ImageDecode.h"
#include "scene/ImageHeader.h"

#include <cstdint>
#include <cstring>
#include <filesystem>

namespace pb::scene::gltf {

namespace {

std::uint32_t littleEndian32(const unsigned char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

// Brackets outside strings; string escapes (\" and \\) are skipped. A malformed document is
// left for the JSON parser to describe.
void checkJsonNesting(const std::string& path, const unsigned char* text, std::size_t size) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < size; ++i) {
        const unsigned char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting)
                throw fileError(path, "JSON nested more than " + std::to_string(kMaxJsonNesting) +
                                          " levels deep");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// Anything that exists: readRegularFile then says why a FIFO or a folder cannot be read.
bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

std::string expandNothing(const std::string& path, void*) {
    return path;
}

bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void*) {
    try {
        *out = readFileBytes(path);
        return true;
    } catch (const std::exception& e) {
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
}

bool writeNothing(std::string* err, const std::string& path, const std::vector<unsigned char>&,
                  void*) {
    if (err) *err += path + ": the loader never writes files\n";
    return false;
}

std::string imageProblem(const tinygltf::Model& model, const tinygltf::Image& image,
                         const unsigned char* bytes, int size, std::uint64_t& totalPixels) {
    if (image.bufferView >= 0) {
        // tinygltf hands an image that lives in a bufferView to the decoder without checking
        // that the bufferView lies inside its buffer.
        const std::size_t bvIndex = std::size_t(image.bufferView);
        bool inside = bvIndex < model.bufferViews.size();
        if (inside) {
            const tinygltf::BufferView& bv = model.bufferViews[bvIndex];
            inside = bv.buffer >= 0 && std::size_t(bv.buffer) < model.buffers.size();
            if (inside) {
                const std::size_t bufferSize = model.buffers[std::size_t(bv.buffer)].data.size();
                inside = bv.byteOffset <= bufferSize && bv.byteLength <= bufferSize - bv.byteOffset;
            }
        }
        if (!inside) return "its bufferView reaches past the end of its buffer";
    }
    if (!bytes || size <= 0) return "no image data";
    const ImageHeader header = readImageHeader(bytes, std::size_t(size));
    if (header.kind == ImageHeader::Kind::Unknown)
        return "not a PNG or JPEG file (the formats glTF allows)";
    if (header.width == 0 || header.height == 0) return "corrupt image header (no size)";
    const std::uint64_t pixels = std::uint64_t(header.width) * header.height;
    const std::string size2 = std::to_string(header.width) + "x" + std::to_string(header.height);
    if (header.width > kMaxImageSide || header.height > kMaxImageSide || pixels > kMaxImagePixels)
        return "declares " + size2 + " pixels, more than a texture may have (" +
               std::to_string(kMaxImageSide) + " a side, " + std::to_string(kMaxImagePixels) +
               " in all)";
    totalPixels += pixels;
    if (totalPixels > kMaxTotalImagePixels)
        return "the images so far declare more than " + std::to_string(kMaxTotalImagePixels) +
               " pixels together (1 GiB as RGBA8)";
    return "";
}

} // namespace

void checkRawGltf(const std::string& path, const std::vector<unsigned char>& bytes) {
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (!binary) {
        checkJsonNesting(path, bytes.data(), bytes.size());
        return;
    }
    const std::size_t size = bytes.size();
    // tinygltf only says "Invalid glTF binary." for a cut-off file.
    if (size >= 12 && littleEndian32(bytes.data() + 8) > size)
        throw fileError(path, "truncated GLB: its header declares " +
                                  std::to_string(littleEndian32(bytes.data() + 8)) +
                                  " bytes, the file has " + std::to_string(size));
    if (size < 20) return; // tinygltf: "too short"
    const std::uint64_t jsonLength = littleEndian32(bytes.data() + 12);
    if (jsonLength > size - 20)
        throw fileError(path, "corrupt GLB: its JSON chunk (" + std::to_string(jsonLength) +
                                  " bytes) reaches past the end of the file");
    checkJsonNesting(path, bytes.data() + 20, std::size_t(jsonLength));
}

tinygltf::FsCallbacks regularFileCallbacks() {
    tinygltf::FsCallbacks fs{};
    fs.FileExists = &fileExists;
    fs.ExpandFilePath = &expandNothing;
    fs.ReadWholeFile = &readRegularFile;
    fs.WriteWholeFile = &writeNothing;
    fs.user_data = nullptr;
    return fs;
}

bool checkedImageLoader(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                        int width, int height, const unsigned char* bytes, int size,
                        void* userData) {
    auto* guard = static_cast<ImageGuard*>(userData);
    const std::string problem = imageProblem(*guard->model, *image, bytes, size, guard->pixels);
    if (!problem.empty()) {
        if (err) *err += "image " + std::to_string(index) + ": " + problem + "\n";
        return false;
    }
    // libpng / libjpeg-turbo, not tinygltf's stb_image (ImageDecode.h says why).
    Rgba8Image decoded;
    const std::string decodeProblem =
        decodeImageRgba8(bytes, std::size_t(size), kMaxImageSide, kMaxImagePixels, decoded);
    if (!decodeProblem.empty()) {
        if (err) *err += "image " + std::to_string(index) + ": " + decodeProblem + "\n";
        return false;
    }
    image->width = int(decoded.width);
    image->height = int(decoded.height);
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded.pixels);
    return true;
}

} // namespace pb::scene::gltf
