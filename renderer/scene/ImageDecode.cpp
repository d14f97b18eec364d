#include "scene/ImageDecode.h"

#include "scene/ImageHeader.h"

#include <csetjmp>
#include <cstdio> // jpeglib.h needs FILE
#include <cstring>
#include <jpeglib.h>
#include <png.h>

namespace pb::scene {

namespace {

// libjpeg-turbo's fuzzers stop progressive files after 500 scans: each scan re-decodes the
// whole image, so a small file with 10^5 scans would take minutes.
constexpr int kMaxJpegScans = 500;

bool sizeFits(std::uint32_t w, std::uint32_t h, std::uint32_t maxSide, std::uint64_t maxPixels) {
    return w > 0 && h > 0 && w <= maxSide && h <= maxSide && std::uint64_t(w) * h <= maxPixels;
}

std::string sizeProblem(std::uint32_t w, std::uint32_t h) {
    return std::to_string(w) + "x" + std::to_string(h) +
           " pixels: empty, or more than a texture may have";
}

std::string decodePng(const unsigned char* bytes, std::size_t size, std::uint32_t maxSide,
                      std::uint64_t maxPixels, Rgba8Image& out) {
    // libpng's simplified API: errors come back as a message, never as a longjmp through here.
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes, size))
        return std::string("PNG: ") + image.message;
    if (!sizeFits(image.width, image.height, maxSide, maxPixels)) {
        png_image_free(&image);
        return sizeProblem(image.width, image.height);
    }
    image.format = PNG_FORMAT_RGBA;
    out.width = image.width;
    out.height = image.height;
    out.pixels.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) {
        std::string problem = std::string("PNG: ") + image.message;
        png_image_free(&image);
        return problem;
    }
    return "";
}

// libjpeg reports fatal errors through error_exit, which must not return: it jumps back to
// decodeJpeg's setjmp with the message. Nothing with a destructor lives between the two.
struct JpegErrors {
    jpeg_error_mgr manager;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void jpegFail(j_common_ptr info) {
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    (*info->err->format_message)(info, errors->message);
    std::longjmp(errors->jump, 1);
}

void jpegQuiet(j_common_ptr, int) {} // warnings are not printed

void jpegProgress(j_common_ptr info) {
    const auto* d = reinterpret_cast<j_decompress_ptr>(info);
    if (info->is_decompressor && d->input_scan_number > kMaxJpegScans) {
        auto* errors = reinterpret_cast<JpegErrors*>(info->err);
        std::snprintf(errors->message, sizeof errors->message, "more than %d progressive scans",
                      kMaxJpegScans);
        std::longjmp(errors->jump, 1);
    }
}

std::string decodeJpeg(const unsigned char* bytes, std::size_t size, std::uint32_t maxSide,
                       std::uint64_t maxPixels, Rgba8Image& out) {
    jpeg_decompress_struct info;
    JpegErrors errors;
    jpeg_progress_mgr progress;
    std::memset(&info, 0, sizeof info);
    info.err = jpeg_std_error(&errors.manager);
    errors.manager.error_exit = &jpegFail;
    errors.manager.emit_message = &jpegQuiet;
    errors.message[0] = '\0';
    progress.progress_monitor = &jpegProgress;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return std::string("JPEG: ") + errors.message;
    }
    jpeg_create_decompress(&info);
    info.progress = &progress;
    jpeg_mem_src(&info, bytes, static_cast<unsigned long>(size));
    jpeg_read_header(&info, TRUE);
    if (!sizeFits(info.image_width, info.image_height, maxSide, maxPixels)) {
        jpeg_destroy_decompress(&info);
        return sizeProblem(info.image_width, info.image_height);
    }
    info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&info);
    out.width = info.output_width;
    out.height = info.output_height;
    out.pixels.resize(std::size_t(out.width) * out.height * 4);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = out.pixels.data() + std::size_t(info.output_scanline) * out.width * 4;
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return "";
}

} // namespace

std::string decodeImageRgba8(const unsigned char* bytes, std::size_t size, std::uint32_t maxSide,
                             std::uint64_t maxPixels, Rgba8Image& out) {
    switch (readImageHeader(bytes, size).kind) {
    case ImageHeader::Kind::Png:
        return decodePng(bytes, size, maxSide, maxPixels, out);
    case ImageHeader::Kind::Jpeg:
        return decodeJpeg(bytes, size, maxSide, maxPixels, out);
    default:
        return "not a PNG or JPEG file";
    }
}

} // namespace pb::scene
