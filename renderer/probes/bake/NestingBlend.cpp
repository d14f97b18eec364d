#include "probes/bake/NestingBlend.h"

#include "probes/Octahedral.h"

#include <memory>

namespace pb::probes {

bool blendsRing(const ProbeVolume& vol, bool hasParent, const glm::ivec3& c, const ProbeState& s) {
    if (!hasParent || vol.edgeBlend <= 0.0f) return false;
    bool ring = false;
    for (int a = 0; a < 3; ++a)
        ring = ring || c[a] == 0 || c[a] == vol.counts[a] - 1;
    // A relocated ring probe started in or against geometry: its box face lies in a wall, where
    // no camera sees a seam, and the parent's coarser probes straddle that wall - blending would
    // carry the next room's light in (issue 24: the rooms' partition, the dark room's corner).
    // It keeps its own irradiance.
    return ring && s.valid && s.offset == glm::vec3(0.0f);
}

void blendNestedRings(const std::vector<ProbeVolume>& volumes, const std::vector<int>& parents,
                      const std::vector<SamplerVolume>& views,
                      std::vector<ProbeTexture*>& targets) {
    // One sampler per parent, built once that parent's own ring is final (parent-first order):
    // the sampler copies the textures it reads.
    std::vector<std::unique_ptr<ProbeSampler>> parentSampler(volumes.size());
    // A probe's position is no surface: no edge fade and no surface bias (SampleOptions).
    SampleOptions atProbe;
    atProbe.edgeFade = false;
    atProbe.surfaceBias = false;
    for (int v : parentFirstOrder(parents)) {
        const int parent = parents[size_t(v)];
        const ProbeVolume& vol = volumes[size_t(v)];
        if (parent < 0 || vol.edgeBlend <= 0.0f) continue;
        if (!parentSampler[size_t(parent)])
            parentSampler[size_t(parent)] =
                std::make_unique<ProbeSampler>(std::vector<SamplerVolume>{views[size_t(parent)]});
        const ProbeSampler& sampler = *parentSampler[size_t(parent)];
        const glm::mat3 rot = vol.localToWorldRotation();
        const ProbeState* states = views[size_t(v)].states;
        ProbeTexture& tex = *targets[size_t(v)];
        for (int i = 0; i < vol.probeCount(); ++i) {
            glm::ivec3 c = vol.probeCoords(i);
            if (!blendsRing(vol, true, c, states[i])) continue;
            glm::vec3 pos = vol.toWorld(vol.gridLocal(c) + states[i].offset);
            float* tile = tileOrigin(tex, c, kIrradianceTile);
            for (int y = 0; y < kIrradianceInterior; ++y)
                for (int x = 0; x < kIrradianceInterior; ++x) {
                    glm::vec3 dir = rot * octTexelDirection(x, y, kIrradianceInterior);
                    IrradianceSample s = sampler.sampleVolume(0, pos, dir, dir, atProbe);
                    if (!(s.weight > 0.0f)) continue;
                    float* t = tile + (size_t(y + 1) * tex.shape.width + size_t(x + 1)) *
                                          size_t(tex.shape.channels);
                    for (int ch = 0; ch < 3; ++ch)
                        t[ch] += (s.irradiance[ch] - t[ch]) * vol.edgeBlend;
                }
            fillOctahedralBorder(tile, tex.shape.width, tex.shape.channels, kIrradianceInterior);
        }
    }
}

} // namespace pb::probes
