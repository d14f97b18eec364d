#include "probes/bake/RadiancePass.h"

#include "probes/bake/DirectLight.h"
#include "core/ParallelFor.h"

#include <cmath>

namespace pb::probes {

void RadianceSlab::reset(std::size_t probes, int rays) {
    rays_ = rays;
    const std::size_t n = probes * std::size_t(rays);
    radiance_.resize(n);
    hits_.resize(n);
    pending_.resize(probes);
    keys_.resize(probes);
    for (auto& p : pending_)
        p.clear();
    for (auto& k : keys_)
        k.clear();
}

void RadianceSlab::trace(std::size_t slot, const RayScene& rs, const Scenario& sc,
                         const std::vector<scene::Light>& lights, const glm::mat3& rot,
                         const glm::vec3& origin, const std::vector<glm::vec3>& dirs,
                         const ProbeSampler* previous, RayCounters& counters) {
    const std::size_t n = std::size_t(rays_), first = slot * n;
    std::vector<Pending>& pending = pending_[slot];
    std::vector<std::uint32_t>& keys = keys_[slot];
    pending.clear();
    keys.clear();
    const float invPi = float(1.0 / M_PI);
    // All rays first, then the shading: the face normal of each hit is prefetched while the
    // following rays are traced (results are per ray: the order of the calls does not matter).
    RayHit* hits = hits_.data() + first;
    for (std::size_t i = 0; i < n; ++i) {
        hits[i] = rs.intersect(origin, rot * dirs[i]);
        rs.prefetchSurface(hits[i]);
    }
    counters.primary += n;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 d = rot * dirs[i];
        const RayHit& h = hits[i];
        glm::vec3 L;
        if (!h.hit()) {
            L = sc.sky.radiance;
        } else {
            const SurfaceInfo& surf = rs.surface(h.geomID);
            glm::vec3 nrm = rs.faceNormal(h.geomID, h.primID);
            bool back = glm::dot(nrm, d) > 0.0f;
            if (back && !surf.doubleSided) {
                L = glm::vec3(0.0f);
            } else {
                if (back) nrm = -nrm;
                L = surf.emissive;
                if (surf.albedo != glm::vec3(0.0f)) {
                    const glm::vec3 x = origin + d * h.t;
                    glm::vec3 e = directIrradiance(rs, sc, lights, x, nrm, counters.shadow);
                    if (previous) { // finished in convolve(), once lookUp() has E_indirect
                        pending.push_back(
                            {{x, nrm, -d}, e, surf.albedo * invPi, std::uint32_t(first + i)});
                        keys.push_back(previous->localityKey(x));
                    } else
                        L += surf.albedo * invPi * e;
                }
            }
        }
        radiance_[first + i] = glm::vec4(L, 0.0f);
    }
}

void RadianceSlab::lookUp(const ProbeSampler& previous, int threads) {
    // Counting sort of the pending hits by locality key (the grid cell of the previous pass
    // they fall in); an entry of `order` is slot << 32 | index within the slot.
    const std::size_t keys = previous.localityKeyCount();
    // The keys were computed by trace().
    std::vector<std::uint32_t> start(keys + 1, 0);
    std::size_t total = 0;
    for (const auto& slotKeys : keys_) {
        total += slotKeys.size();
        for (std::uint32_t k : slotKeys)
            ++start[k + 1];
    }
    for (std::size_t k = 0; k < keys; ++k)
        start[k + 1] += start[k];
    std::vector<std::uint64_t> order(total);
    for (std::size_t s = 0; s < keys_.size(); ++s)
        for (std::size_t j = 0; j < keys_[s].size(); ++j)
            order[start[keys_[s][j]]++] = std::uint64_t(s) << 32 | j;

    indirect_.resize(radiance_.size());
    constexpr std::size_t kChunk = 2048;
    std::vector<std::vector<SampleQuery>> queries(std::size_t(std::max(threads, 1)));
    std::vector<std::vector<IrradianceSample>> results(queries.size());
    SampleOptions noFade;
    noFade.edgeFade = false;
    parallelFor((total + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, int t) {
        const std::size_t lo = chunk * kChunk, hi = std::min(total, lo + kChunk);
        std::vector<SampleQuery>& q = queries[std::size_t(t)];
        std::vector<IrradianceSample>& out = results[std::size_t(t)];
        q.clear();
        for (std::size_t k = lo; k < hi; ++k)
            q.push_back(pending_[order[k] >> 32][order[k] & 0xffffffffu].query);
        out.resize(q.size());
        previous.sampleBatch(q.data(), q.size(), out.data(), noFade);
        for (std::size_t k = lo; k < hi; ++k)
            indirect_[pending_[order[k] >> 32][order[k] & 0xffffffffu].ray] =
                out[k - lo].irradiance;
    });
}

const glm::vec4* RadianceSlab::finish(std::size_t slot) {
    const std::size_t first = slot * std::size_t(rays_);
    for (const Pending& h : pending_[slot]) {
        // The per-ray expression: emissive + albedo/pi * (direct + indirect).
        glm::vec3 e = h.direct;
        e += indirect_[h.ray];
        glm::vec3 L = glm::vec3(radiance_[h.ray]) + h.albedoOverPi * e;
        radiance_[h.ray] = glm::vec4(L, 0.0f);
    }
    return &radiance_[first];
}

void RadianceSlab::convolve(std::size_t slot, const ProbeConvolution& conv, float* outRgb) {
    conv.irradiance(&finish(slot)->x, outRgb);
}

} // namespace pb::probes
