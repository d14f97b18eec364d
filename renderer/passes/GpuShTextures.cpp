#include "passes/GpuShTextures.h"

#include "core/Error.h"
#include "probes/sh/ShAbsentFill.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/sh/ShSampler.h"

namespace pb::render {

int shCoefficientCount(profile::GiTechnique t) {
    return t == profile::GiTechnique::ShL1   ? probes::kShL1Coefficients
           : t == profile::GiTechnique::ShL2 ? probes::kShL2Coefficients
                                             : 0;
}

std::size_t shBytesPerProbe(profile::GiTechnique t) {
    return probes::shGpuBytesPerProbe(shCoefficientCount(t));
}

std::uint8_t shCellMask(const probes::ProbeVolume& v, const std::vector<probes::ProbeState>& s,
                        const glm::ivec3& base) {
    std::uint8_t mask = 0;
    for (int c = 0; c < 8; ++c) {
        const glm::ivec3 q =
            glm::min(base + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1), v.counts - 1);
        if (probes::shProbeValid(s[size_t(v.probeIndex(q))])) mask = std::uint8_t(mask | (1u << c));
    }
    return mask;
}

namespace {
gl::Texture volumeTexture(gl::TextureFormat f, const glm::ivec3& counts, const void* data,
                          const std::string& label) {
    gl::TextureDesc d;
    d.format = f;
    d.width = counts.x;
    d.height = counts.z; // rows along local Z, depth (layers) along local Y
    d.layers = counts.y;
    d.volume = true;
    d.filter = gl::Filter::Linear;
    gl::Texture t = [&] {
        try {
            return gl::Texture(d);
        } catch (const Error& e) { // past the context's limits: say which volume
            throw Error(label + ": " + e.what());
        }
    }();
    t.upload(data);
    t.label(label);
    return t;
}
} // namespace

std::vector<gl::Texture> uploadShVolume(const probes::ProbeSet& set, int scenario, int vi,
                                        profile::GiTechnique technique, profile::GiShLeak leak,
                                        const std::string& label) {
    if (!set.hasSh()) throw Error(probes::noShMessage("the probe set"));
    const probes::ProbeVolume& v = set.volumes[size_t(vi)];
    // Absent probes read as their nearest stored one, as in ShSampler (probes/sh/ShAbsentFill.h).
    const probes::ShLookupVolume lookup =
        probes::shLookupVolume(v, set.states[size_t(vi)], set.sh[size_t(scenario)][size_t(vi)],
                               set.settings.backfaceThreshold);
    const std::vector<probes::ProbeState>& states = lookup.states;
    const std::vector<glm::vec3>& sh = lookup.sh;
    const int n = shCoefficientCount(technique);
    const int textures = n == probes::kShL1Coefficients ? 3 : 7;
    const std::size_t probes = std::size_t(v.probeCount());
    // Texel order x fastest, then z (rows), then y (layers): the probe index order.
    std::vector<std::vector<float>> texels(size_t(textures), std::vector<float>(probes * 4, 0));
    std::vector<std::uint8_t> validity(probes, 0);
    for (std::size_t p = 0; p < probes; ++p) {
        const bool valid = probes::shProbeValid(states[p]);
        // `weight` stores lighting premultiplied by the weight (0 or 1 here).
        const float w = leak == profile::GiShLeak::Weight && !valid ? 0.0f : 1.0f;
        const glm::vec3* c = sh.data() + p * probes::kShL2Coefficients;
        for (int ch = 0; ch < 3; ++ch)
            for (int k = 0; k < 4; ++k)
                texels[size_t(ch)][p * 4 + size_t(k)] = c[k][ch] * w;
        if (n == probes::kShL2Coefficients)
            for (int ch = 0; ch < 3; ++ch)
                for (int k = 0; k < 5; ++k) {
                    const int at = ch * 5 + k;
                    texels[size_t(3 + at / 4)][p * 4 + size_t(at % 4)] = c[4 + k][ch] * w;
                }
        if (leak != profile::GiShLeak::None)
            validity[p] = shCellMask(v, states, v.probeCoords(int(p)));
        else
            validity[p] = valid ? 255 : 0;
    }
    std::vector<gl::Texture> g; // in the order of their units (GpuTechniqueSh::bindTextures)
    for (int t = 0; t < textures; ++t)
        g.push_back(volumeTexture(gl::TextureFormat::RGBA16F, v.counts, texels[size_t(t)].data(),
                                  label + " sh" + std::to_string(t)));
    g.push_back(
        volumeTexture(gl::TextureFormat::R8, v.counts, validity.data(), label + " sh validity"));
    return g;
}

} // namespace pb::render
