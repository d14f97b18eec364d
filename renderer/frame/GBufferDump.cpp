#include "frame/GBufferDump.h"

#include "core/Error.h"
#include "frame/DepthReadback.h"
#include "frame/Readback.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pb::render {

namespace {
image::Image8 toImage8(const image::ImageF& f, float (*map)(float)) {
    image::Image8 out;
    out.width = f.width;
    out.height = f.height;
    out.pixels.resize(size_t(f.width) * f.height * 4);
    for (size_t i = 0; i < size_t(f.width) * f.height; ++i)
        for (int c = 0; c < 4; ++c) {
            float v = c == 3 ? 1.0f : map(f.pixels[i * 4 + size_t(c)]);
            out.pixels[i * 4 + size_t(c)] = uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
        }
    return out;
}

} // namespace

void writeGBufferDump(const std::string& dir, FrameTargets& targets, const RenderView& view,
                      gl::ProgramCache& programs) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (!std::filesystem::is_directory(dir)) throw fileError(dir, "cannot create folder");
    for (size_t i = 0; i < kGBufferChannels.size(); ++i) {
        const GBufferChannel& c = kGBufferChannels[i];
        const gl::Texture& tex = targets.gbuffer.channel(i);
        std::string base = dir + "/" + c.name;
        if (gl::formatInfo(c.format).isFloat) {
            image::ImageF f = readFloat(tex);
            if (c.encoding == ChannelEncoding::OctNormal)
                image::writePng(base + ".png",
                                toImage8(f, [](float v) { return v * 0.5f + 0.5f; }));
            else
                image::writePfm(base + ".pfm", f);
        } else {
            image::Image8 img = readRgba8(tex);
            if (c.encoding == ChannelEncoding::Flags) // make bit 0 visible
                for (size_t p = 0; p < img.pixels.size(); p += 4)
                    img.pixels[p] = img.pixels[p + 1] = img.pixels[p + 2] =
                        (img.pixels[p] & 1u) ? 255 : 0;
            image::writePng(base + ".png", img);
        }
    }
    image::writePfm(dir + "/depth.pfm", readDepthDistance(targets, view, programs));
}

} // namespace pb::render
