// image::readPng reads files users hand `probebench compare`: a round trip keeps every byte,
// and damaged or oversized files give an error naming the file instead of a crash.
#include "core/Error.h"
#include "core/FileIO.h"
#include "image/Image.h"
#include "support/TestEnv.h"

#include <cstdint>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

using namespace pb;

namespace {

image::Image8 gradient(int w, int h) {
    image::Image8 img;
    img.width = w;
    img.height = h;
    img.pixels.resize(std::size_t(w) * h * 4);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = std::uint8_t((i * 37 + i / 4) & 0xff);
    return img;
}

std::vector<char> bytesOf(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const std::filesystem::path& p, const std::vector<char>& bytes) {
    std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// PNG's chunk CRC (CRC-32, reflected polynomial 0xEDB88320) over the chunk type and data.
std::uint32_t crc32(const char* data, std::size_t size) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= std::uint8_t(data[i]);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

// The error message of readPng(path), or "" when it succeeded.
std::string readError(const std::filesystem::path& p) {
    try {
        image::readPng(p.string());
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(PngRead, RoundTripKeepsEveryByte) {
    const auto dir = test::outputDir();
    const image::Image8 written = gradient(7, 5);
    image::writePng((dir / "g.png").string(), written);
    const image::Image8 read = image::readPng((dir / "g.png").string());
    EXPECT_EQ(read.width, 7);
    EXPECT_EQ(read.height, 5);
    EXPECT_EQ(read.pixels, written.pixels);
}

TEST(PngRead, TruncatedFileNamesTheFile) {
    const auto dir = test::outputDir();
    image::writePng((dir / "g.png").string(), gradient(16, 16));
    std::vector<char> bytes = bytesOf(dir / "g.png");
    bytes.resize(bytes.size() / 2);
    writeBytes(dir / "cut.png", bytes);
    const std::string err = readError(dir / "cut.png");
    EXPECT_NE(err.find("cut.png"), std::string::npos) << err;
}

TEST(PngRead, NotAPngAndMissingFileAreErrors) {
    const auto dir = test::outputDir();
    writeBytes(dir / "text.png", {'h', 'e', 'l', 'l', 'o'});
    EXPECT_NE(readError(dir / "text.png").find("text.png"), std::string::npos);
    EXPECT_NE(readError(dir / "absent.png").find("absent.png"), std::string::npos);
}

TEST(PngRead, HugeHeaderIsRefusedBeforeAllocating) {
    const auto dir = test::outputDir();
    image::writePng((dir / "g.png").string(), gradient(2, 2));
    std::vector<char> bytes = bytesOf(dir / "g.png");
    // IHDR follows the 8-byte signature and the chunk length: type at 12, width at 16, height
    // at 20 (big endian), CRC at 29 over bytes 12..28. Claim 1,000,000 x 1,000,000 pixels
    // with a valid CRC, so the size check - not the CRC - refuses it.
    auto putBigEndian = [&](std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            bytes[at + i] = char((v >> (24 - 8 * i)) & 0xff);
    };
    putBigEndian(16, 1000000);
    putBigEndian(20, 1000000);
    putBigEndian(29, crc32(bytes.data() + 12, 17));
    writeBytes(dir / "huge.png", bytes);
    const std::string err = readError(dir / "huge.png");
    EXPECT_NE(err.find("huge.png"), std::string::npos) << err;
    EXPECT_NE(err.find("1000000x1000000"), std::string::npos) << err;
}
