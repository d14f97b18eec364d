#include "FrameDemand.h"

#include "core/Error.h"
#include "costmodel/GiVariant.h"

namespace pb::devicemodel {
namespace demandrules {

using U64 = std::uint64_t;

const costmodel::CacheResult& cacheResult(const FrameDemandInputs& in) {
    const costmodel::CostReport& r = *in.cost;
    const std::string variant =
        in.switches.gi.technique == profile::GiTechnique::Ddgi
            ? costmodel::GiVariant{in.switches.gi.probeOrder, in.switches.gi.loops}.name()
            : r.profileVariant;
    for (const costmodel::CacheResult& c : r.results)
        if (c.variant == variant && c.cache.name == in.l2Cache) return c;
    throw Error("device model: the cost model has no result for variant " + variant +
                " through cache " + in.l2Cache);
}

void applyProgram(const FrameDemandInputs& in, PassDemand& d, bool textureFromProgram) {
    auto it = in.programs.find(d.pass);
    if (it == in.programs.end()) {
        d.aluBasis = "no program statistics";
        return;
    }
    d.aluCyclesPerFragment = it->second.aluCyclesPerFragment;
    d.aluBasis = it->second.aluBasis;
    if (textureFromProgram && it->second.textureInstructions > 0)
        d.samples += U64(double(d.fragments) * it->second.textureInstructions + 0.5);
}

PassDemand giApply(const FrameDemandInputs& in) {
    const costmodel::GiPassCounters& c = in.cost->counters;
    PassDemand d;
    d.pass = "gi-apply";
    int drawn = 0;
    for (const costmodel::VolumeCounters& v : c.volumes) {
        if (v.culled) continue;
        ++drawn;
        d.fragments += v.evaluated;
        // 32-bit texels or point reads: depth, normal, flags, state, visibility, SH mask.
        d.samples += v.depthFetches + v.normalFetches + v.flagsFetches + v.stateFetches +
                     v.visibilityFetches + v.shMaskFetches;
        d.wideSamples += v.irradianceFetches;             // RGBA16F, bilinear
        d.wideTrilinear3dSamples += v.shCoefficientFetches; // RGBA16F 3D, trilinear
    }
    applyProgram(in, d, false);
    const costmodel::CacheResult& l2 = cacheResult(in);
    d.bytesRead = (U64(l2.probeLines - l2.probeHits) + U64(l2.gbufferLines - l2.gbufferHits)) *
                  U64(l2.cache.lineBytes);
    const U64 bytes = U64(giTargetBytes(in.switches.gi.targetFormat));
    const U64 written = d.fragments + c.targetPixels; // cleared, then written per evaluation
    d.bytesWritten = written * bytes;
    d.pixelsWritten = written * ((bytes + 3) / 4);
    d.draws = in.switches.gi.multiVolume == profile::GiMultiVolume::Naive ? 1 + drawn : 1 + 3 * drawn;
    return d;
}

} // namespace demandrules
using namespace demandrules;

int giTargetBytes(profile::GiTargetFormat f) {
    switch (f) {
    case profile::GiTargetFormat::Rgba16f: return 8;
    case profile::GiTargetFormat::R11g11b10f: return 4;
    case profile::GiTargetFormat::Rgba32f: return 16;
    }
    return 8;
}

std::vector<PassDemand> frameDemand(const FrameDemandInputs& in) {
    if (!in.cost) throw Error("device model: no cost-model replay for the frame");
    const costmodel::GiPassCounters& c = in.cost->counters;
    const U64 pixels = U64(in.width) * U64(in.height);
    const U64 lowPixels = c.targetPixels;
    const bool giOn = !c.volumes.empty();
    // Covered share of the frame: the GI pixels of the replay over its target's pixels.
    const double covered = lowPixels ? double(c.giPixels) / double(lowPixels) : 1.0;
    const U64 giBytes = U64(giTargetBytes(in.switches.gi.targetFormat));
    const bool lowRes = in.switches.gi.resolution != profile::GiResolution::Full;
    std::vector<PassDemand> out;
    for (const std::string& pass : in.passes) {
        PassDemand d;
        d.pass = pass;
        if (pass == "shadow") {
            U64 texels = 0;
            for (int side : in.facts.shadowMapSizes) texels += U64(side) * U64(side);
            d.fragments = texels;
            applyProgram(in, d, true);
            d.bytesWritten = texels * 4;
            d.pixelsWritten = texels;
            d.draws = in.facts.meshes * int(in.facts.shadowMapSizes.size());
        } else if (pass == "gbuffer") {
            d.fragments = U64(double(pixels) * covered + 0.5);
            applyProgram(in, d, true);
            const U64 bpp = U64(in.facts.gbufferBytesPerPixel);
            d.bytesWritten = pixels * bpp;
            d.pixelsWritten = pixels * ((bpp + 3) / 4);
            d.draws = in.facts.meshes;
        } else if (pass == "gi-depth-copy") {
            d.fragments = lowPixels;
            applyProgram(in, d, false);
            d.samples = c.depthCopyFetches;
            d.bytesRead = c.depthCopyFetches * 4;
            d.bytesWritten = lowPixels * 4;
            d.pixelsWritten = lowPixels;
            d.draws = 1;
        } else if (pass == "gi-apply") {
            d = giApply(in);
        } else if (pass == "upsample") {
            d.fragments = pixels;
            applyProgram(in, d, true);
            d.bytesRead = lowPixels * (giBytes + 4) + pixels * 4;
            if (in.switches.gi.upsample == profile::GiUpsample::Temporal) d.bytesRead += pixels * 8;
            d.bytesWritten = pixels * 8;
            d.pixelsWritten = pixels * 2;
            d.draws = 1;
        } else if (pass == "direct") {
            d.fragments = pixels;
            applyProgram(in, d, true);
            d.bytesRead = pixels * U64(in.facts.gbufferBytesPerPixel);
            if (giOn) d.bytesRead += pixels * (lowRes ? 8 : giBytes);
            d.bytesWritten = pixels * 8;
            d.pixelsWritten = pixels * 2;
            d.draws = 1;
        } else if (pass == "composite") {
            d.fragments = pixels;
            applyProgram(in, d, true);
            d.bytesRead = pixels * 8;
            d.bytesWritten = pixels * 4;
            d.pixelsWritten = pixels;
            d.draws = 1;
        } else {
            d.aluBasis = "not modelled";
        }
        out.push_back(d);
    }
    return out;
}

} // namespace pb::devicemodel
