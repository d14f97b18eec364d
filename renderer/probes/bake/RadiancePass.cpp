#include "probes/bake/RadiancePass.h"

#include "core/FloatLanes.h"
#include "core/Luminance.h"
#include "core/ParallelFor.h"
#include "probes/Octahedral.h"
#include "probes/ProbeLayout.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/bake/DirectLight.h"
#include "probes/bake/RayDirections.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pb::probes {

namespace {

constexpr float kUniformSpherePdf = float(1.0 / (4.0 * M_PI));

static_assert(kIrradianceInteriorTexels % 4 == 0, "addToFacingTexels takes four texels a step");

// The interior texels' directions, volume-local (as ProbeConvolution's), as rows of x, y and z
// so that four texels are one SIMD step.
struct TexelDirectionRows {
    float x[kIrradianceInteriorTexels], y[kIrradianceInteriorTexels], z[kIrradianceInteriorTexels];
};
const TexelDirectionRows& texelDirectionRows() {
    static const TexelDirectionRows rows = [] {
        TexelDirectionRows r{};
        for (int j = 0; j < kIrradianceInterior; ++j)
            for (int i = 0; i < kIrradianceInterior; ++i) {
                const glm::vec3 d = octTexelDirection(i, j, kIrradianceInterior);
                const int t = j * kIrradianceInterior + i;
                r.x[t] = d.x, r.y[t] = d.y, r.z[t] = d.z;
            }
        return r;
    }();
    return rows;
}

// One light sample's share c (radiance over the MIS denominator), arriving from the
// volume-local direction `local`, added to every interior texel facing it as c max(0, n_t.w):
// RGB into rgb (rows: the texels' R, then G, then B), its luminance and square into y1, y2
// (the texel variance's sums). Four texels a step, each lane the scalar arithmetic in the same
// order (the dot product as glm's, the luminance as Luminance.h's); a texel that does not face
// the sample adds +0, which leaves its sums (never -0: c >= 0) as they were.
void addToFacingTexels(const glm::vec3& c, const glm::vec3& local, float* rgb, float* y1,
                       float* y2) {
    const TexelDirectionRows& d = texelDirectionRows();
    constexpr int n = kIrradianceInteriorTexels;
    for (int t = 0; t < n; t += 4) {
        const Float4 cosT = load4(d.x + t) * local.x + load4(d.y + t) * local.y +
                            load4(d.z + t) * local.z;
        const Int4 facing = cosT > 0.0f;
        const Float4 r = Float4(Int4(c.r * cosT) & facing);
        const Float4 g = Float4(Int4(c.g * cosT) & facing);
        const Float4 b = Float4(Int4(c.b * cosT) & facing);
        store4(rgb + t, load4(rgb + t) + r);
        store4(rgb + n + t, load4(rgb + n + t) + g);
        store4(rgb + 2 * n + t, load4(rgb + 2 * n + t) + b);
        const Float4 y = 0.2126f * r + 0.7152f * g + 0.0722f * b;
        store4(y1 + t, load4(y1 + t) + y);
        store4(y2 + t, load4(y2 + t) + y * y);
    }
}

// The same light sample's share, projected onto SH: c Y(w) into sh[0..8].
void addToSh(const glm::vec3& c, const glm::vec3& local, glm::vec3* sh) {
    float y[kShL2Coefficients];
    shBasis(local, y);
    for (int k = 0; k < kShL2Coefficients; ++k)
        sh[k] += c * y[k];
}

// Solid-angle density of sampling direction `d` (unit) through emitter triangle k hit at
// distance t: pdfArea * t^2 / |cos_l|; infinite at grazing angles.
float emitterPdf(const raytrace::EmitterTable& table, int k, const glm::vec3& d, float t) {
    const float cosL = std::fabs(glm::dot(table.triangle(k).normal, d));
    if (!(cosL > 1e-6f)) return std::numeric_limits<float>::infinity();
    return table.pdfArea(k) * t * t / cosL;
}

} // namespace

void RadianceSlab::reset(std::size_t probes, int rays) {
    rays_ = rays;
    const std::size_t n = probes * std::size_t(rays);
    radiance_.resize(n);
    pending_.resize(n);
    keys_.resize(n);
    pendingCount_.assign(probes, 0);
    slotSamples_.assign(probes, 0);
    slotLitSamples_.assign(probes, 0);
    // The light samples' sums are zeroed per slot by trace(), on the tracing threads: zeroing
    // a whole slab here (about 9 MB at 32 rays a probe) was a serial step before every slab.
    lightRgb_.resize(probes * kIrradianceInteriorTexels * 3);
    lightY_.resize(probes * kIrradianceInteriorTexels);
    lightY2_.resize(probes * kIrradianceInteriorTexels);
    litY_.resize(probes * kIrradianceInteriorTexels);
    litY2_.resize(probes * kIrradianceInteriorTexels);
    lightSh_.resize(probes * kShL2Coefficients);
}

void RadianceSlab::zeroLightSums(std::size_t slot) {
    constexpr std::size_t t = kIrradianceInteriorTexels;
    std::fill_n(lightRgb_.begin() + std::ptrdiff_t(slot * t * 3), t * 3, 0.0f);
    for (std::vector<float>* sums : {&lightY_, &lightY2_, &litY_, &litY2_})
        std::fill_n(sums->begin() + std::ptrdiff_t(slot * t), t, 0.0f);
    std::fill_n(lightSh_.begin() + std::ptrdiff_t(slot * kShL2Coefficients), kShL2Coefficients,
                glm::vec3(0.0f));
}

void RadianceSlab::trace(std::size_t slot, const raytrace::RayScene& rs, const Scenario& sc,
                         const std::vector<scene::Light>& lights, const glm::mat3& rot,
                         const glm::vec3& origin, const std::vector<glm::vec3>& dirs,
                         const ProbeSampler* previous, RayCounters& counters,
                         const EmitterSampling& nee, std::uint64_t probeKey) {
    const std::size_t n = std::size_t(rays_), first = slot * n;
    zeroLightSums(slot);
    Pending* pending = pending_.data() + first;
    std::uint32_t* keys = keys_.data() + first;
    std::uint32_t pendingCount = 0;
    const float invPi = float(1.0 / M_PI);
    const raytrace::EmitterTable& emitters = rs.emitters();
    const float nPu = float(n) * kUniformSpherePdf;
    // All rays first, then the shading: what the shading reads from the lit-surface table is
    // prefetched while the following rays are traced (results are per ray: the order of the
    // calls does not matter). The normal and barycentrics come with the hit (RayHit).
    // The hits and their lit-surface slots are read only below, for this probe: per-thread
    // scratch of one probe's rays stays in L1, where a slab-sized array (8 MB at 2^18 rays)
    // streamed through the caches and evicted the BVH that the next rays traverse.
    // Each ray's world direction and its hit's normal are kept too, computed once for the
    // loops below (the same expressions, so the same values).
    thread_local std::vector<raytrace::RayHit> hitScratch;
    thread_local std::vector<glm::vec3> dirScratch, normalScratch;
    thread_local std::vector<std::int64_t> litSlotScratch;
    // The queued hits' points, whose locality keys are asked for in one call after the loop.
    thread_local std::vector<glm::vec3> pointScratch;
    pointScratch.resize(n);
    glm::vec3* hitPoints = pointScratch.data();
    hitScratch.resize(n);
    dirScratch.resize(n);
    normalScratch.resize(n);
    raytrace::RayHit* hits = hitScratch.data();
    glm::vec3* rayDirs = dirScratch.data();
    glm::vec3* normals = normalScratch.data();
    for (std::size_t i = 0; i < n; ++i)
        rayDirs[i] = rot * dirs[i];
    rs.intersect(origin, rayDirs, n, hits);
    // The normals in a loop of their own: between two Embree calls a normal's square root and
    // division were a dependent chain the next call waited on; here the rays' chains overlap.
    for (std::size_t i = 0; i < n; ++i) {
        if (!hits[i].hit()) continue;
        normals[i] = rs.hitNormal(hits[i]);
        if (nee.lit) nee.lit->prefetchTriangle(hits[i].geomID, hits[i].primID);
    }
    counters.primary += n;
    // Emitters that fill a large part of the probe's sphere (a quarter or more of its rays hit
    // one) are sampled well by the rays, whose normalised convolution is exact for a uniform
    // radiance: light samples would only add their own noise there, so such a probe keeps its
    // rays alone. The emitter samples are for small and distant emitters.
    int m = 0;
    if (!emitters.empty() && nee.samples > 0 && !nee.incrementOnly) {
        std::size_t emitterHits = 0;
        for (std::size_t i = 0; i < n; ++i)
            emitterHits += hits[i].hit() && emitters.find(hits[i].geomID, hits[i].primID) >= 0;
        if (4 * emitterHits < n) m = nee.samples;
    }
    slotSamples_[slot] = m;
    const int ml = nee.lit && !nee.lit->empty() && !nee.incrementOnly ? nee.litSamples : 0;
    slotLitSamples_[slot] = ml;
    // The lit-surface density of each hit the shading below weights: its slot first, and a
    // prefetch, so the random reads of the large density array overlap (same values).
    std::int64_t* litSlots = nullptr;
    if (ml > 0) {
        litSlotScratch.resize(n);
        litSlots = litSlotScratch.data();
        for (std::size_t i = 0; i < n; ++i) {
            const raytrace::RayHit& h = hits[i];
            litSlots[i] = -1;
            if (!h.hit() || rs.surface(h.geomID).albedo == glm::vec3(0.0f)) continue;
            const bool back = glm::dot(normals[i], rayDirs[i]) > 0.0f;
            if (back && !rs.surface(h.geomID).doubleSided) continue;
            litSlots[i] = nee.lit->slotOfBarycentric(h.geomID, h.primID, back, h.u, h.v);
            nee.lit->prefetchSlot(litSlots[i]);
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 d = rayDirs[i];
        const raytrace::RayHit& h = hits[i];
        glm::vec3 L;
        if (!h.hit()) {
            L = nee.incrementOnly ? glm::vec3(0.0f) : sc.sky.radiance;
        } else if (nee.incrementOnly) { // only the previous increment, looked up at the hit
            L = glm::vec3(0.0f);
            const raytrace::SurfaceInfo& surf = rs.surface(h.geomID);
            glm::vec3 nrm = normals[i];
            const bool back = glm::dot(nrm, d) > 0.0f;
            if (previous && surf.albedo != glm::vec3(0.0f) && (!back || surf.doubleSided)) {
                const glm::vec3 x = origin + d * h.t;
                pending[pendingCount] = {{x, back ? -nrm : nrm, -d}, glm::vec3(0.0f),
                                         surf.albedo * invPi, std::uint32_t(first + i)};
                hitPoints[pendingCount++] = x;
            }
        } else {
            const raytrace::SurfaceInfo& surf = rs.surface(h.geomID);
            glm::vec3 nrm = normals[i];
            bool back = glm::dot(nrm, d) > 0.0f;
            if (back && !surf.doubleSided) {
                L = glm::vec3(0.0f);
            } else {
                if (back) nrm = -nrm;
                L = surf.emissive;
                if (m > 0 && L != glm::vec3(0.0f)) { // the balance heuristic's ray weight
                    const int k = emitters.find(h.geomID, h.primID);
                    if (k >= 0) L *= nPu / (nPu + float(m) * emitterPdf(emitters, k, d, h.t));
                }
                if (surf.albedo != glm::vec3(0.0f)) {
                    const glm::vec3 x = origin + d * h.t;
                    glm::vec3 e = directIrradiance(rs, sc, lights, x, nrm, counters.shadow);
                    float weight = 1.0f; // the balance heuristic's, against lit-surface samples
                    if (ml > 0) {
                        const float pdfA = nee.lit->pdfAtSlot(litSlots[i]);
                        const float cosL = std::fabs(glm::dot(nrm, d));
                        if (pdfA > 0.0f)
                            weight = cosL > 1e-6f
                                         ? nPu / (nPu + float(ml) * pdfA * h.t * h.t / cosL)
                                         : 0.0f;
                    }
                    e *= weight;
                    if (previous) { // finished in convolve(), once lookUp() has E_indirect
                        pending[pendingCount] = {
                            {x, nrm, -d}, e, surf.albedo * invPi, std::uint32_t(first + i)};
                        hitPoints[pendingCount++] = x;
                    } else
                        L += surf.albedo * invPi * e;
                }
            }
        }
        radiance_[first + i] = glm::vec4(L, 0.0f);
    }
    pendingCount_[slot] = pendingCount;
    if (pendingCount > 0) previous->localityKeys(hitPoints, pendingCount, keys);
    if (ml > 0) traceLitSamples(slot, rs, sc, lights, rot, origin, nee, probeKey, counters);
    if (m == 0) return;

    // The emitter samples: M points on the emitters, each visible one added to every texel
    // facing it (volume-local directions, as the rays' convolution).
    std::uint64_t state = nee.stream ^ (probeKey * 0x9e3779b97f4a7c15ull);
    splitmix64(state);
    const glm::mat3 toLocal = glm::transpose(rot);
    float* rgb = lightRgb_.data() + slot * kIrradianceInteriorTexels * 3;
    float* y1 = lightY_.data() + slot * kIrradianceInteriorTexels;
    float* y2 = lightY2_.data() + slot * kIrradianceInteriorTexels;
    for (int j = 0; j < m; ++j) {
        const float u0 = uniformFloat(state), u1 = uniformFloat(state), u2 = uniformFloat(state);
        const raytrace::EmitterSample s = emitters.sample(u0, u1, u2);
        const raytrace::EmissiveTriangle& tri = emitters.triangle(s.triangle);
        glm::vec3 w = s.point - origin;
        const float dist = glm::length(w);
        if (!(dist > 0.0f)) continue;
        w /= dist;
        const float cosL = glm::dot(tri.normal, -w);
        if (!(cosL > 0.0f) && !tri.doubleSided) continue; // its back: emits nothing here
        const float pdf = emitterPdf(emitters, s.triangle, w, dist);
        if (!std::isfinite(pdf)) continue;
        ++counters.shadow;
        const float eps = rs.epsilon();
        if (rs.occluded(origin, w, 0.0f, std::max(dist - 2.0f * eps, 0.0f))) continue;
        const glm::vec3 c = tri.radiance / (nPu + float(m) * pdf);
        addToFacingTexels(c, toLocal * w, rgb, y1, y2);
        if (nee.projectSh) addToSh(c, toLocal * w, lightSh_.data() + slot * kShL2Coefficients);
    }
}

void RadianceSlab::traceLitSamples(std::size_t slot, const raytrace::RayScene& rs, const Scenario& sc,
                                   const std::vector<scene::Light>& lights, const glm::mat3& rot,
                                   const glm::vec3& origin, const EmitterSampling& nee,
                                   std::uint64_t probeKey, RayCounters& counters) {
    const int ml = slotLitSamples_[slot];
    const float nPu = float(rays_) * kUniformSpherePdf;
    // A stream of their own ("lit "), each probe by its key.
    std::uint64_t state = nee.stream ^ 0x6c697420ull ^ (probeKey * 0xbf58476d1ce4e5b9ull);
    splitmix64(state);
    const glm::mat3 toLocal = glm::transpose(rot);
    float* rgb = lightRgb_.data() + slot * kIrradianceInteriorTexels * 3;
    float* y1 = litY_.data() + slot * kIrradianceInteriorTexels;
    float* y2 = litY2_.data() + slot * kIrradianceInteriorTexels;
    const float eps = rs.epsilon();
    // The samples' numbers first (the stream's order), then the table reads in two prefetched
    // steps (alias column, entry): both tables are large and read at random.
    thread_local std::vector<float> us;
    thread_local std::vector<std::size_t> picks;
    us.resize(3 * std::size_t(ml));
    picks.resize(std::size_t(ml));
    for (int j = 0; j < 3 * ml; ++j)
        us[std::size_t(j)] = uniformFloat(state);
    for (int j = 0; j < ml; ++j)
        nee.lit->prefetchPick(us[3 * std::size_t(j)]);
    for (int j = 0; j < ml; ++j) {
        picks[std::size_t(j)] = nee.lit->pickEntry(us[3 * std::size_t(j)]);
        nee.lit->prefetchEntry(picks[std::size_t(j)]);
    }
    for (int j = 0; j < ml; ++j) {
        const float u1 = us[3 * std::size_t(j) + 1], u2 = us[3 * std::size_t(j) + 2];
        const LitPatchSample s = nee.lit->sampleEntry(picks[std::size_t(j)], u1, u2);
        glm::vec3 w = s.point - origin;
        const float dist = glm::length(w);
        if (!(dist > 0.0f)) continue;
        w /= dist;
        const float cosL = glm::dot(s.normal, -w);
        if (!(cosL > 1e-6f)) continue; // the probe sees the other side (another entry, or black)
        ++counters.shadow;
        if (rs.occluded(origin, w, 0.0f, std::max(dist - 2.0f * eps, 0.0f))) continue;
        const glm::vec3 e = directIrradiance(rs, sc, lights, s.point, s.normal, counters.shadow);
        if (e == glm::vec3(0.0f)) continue;
        const float pdf = s.pdfArea * dist * dist / cosL;
        const glm::vec3 c = s.albedoOverPi * e / (nPu + float(ml) * pdf);
        addToFacingTexels(c, toLocal * w, rgb, y1, y2);
        if (nee.projectSh) addToSh(c, toLocal * w, lightSh_.data() + slot * kShL2Coefficients);
    }
}

void RadianceSlab::lookUp(const ProbeSampler& previous, int threads) {
    // Counting sort of the pending hits by locality key (the grid cell of the previous pass
    // they fall in); an entry of `order` is a place in pending_.
    const std::size_t keys = previous.localityKeyCount(), rays = std::size_t(rays_);
    // The keys were computed by trace().
    std::vector<std::uint32_t> start(keys + 1, 0);
    std::size_t total = 0;
    for (std::size_t s = 0; s < pendingCount_.size(); ++s) {
        total += pendingCount_[s];
        for (std::size_t j = 0; j < pendingCount_[s]; ++j)
            ++start[keys_[s * rays + j] + 1];
    }
    for (std::size_t k = 0; k < keys; ++k)
        start[k + 1] += start[k];
    std::vector<std::size_t> order(total);
    for (std::size_t s = 0; s < pendingCount_.size(); ++s)
        for (std::size_t j = 0; j < pendingCount_[s]; ++j)
            order[start[keys_[s * rays + j]]++] = s * rays + j;

    constexpr std::size_t kChunk = 2048;
    // The hits are read in key order, i.e. at random: each one's line is prefetched this many
    // hits before it is read.
    constexpr std::size_t kGatherAhead = 16;
    std::vector<std::vector<SampleQuery>> queries(std::size_t(std::max(threads, 1)));
    std::vector<std::vector<std::uint32_t>> queryKeys(queries.size());
    std::vector<std::vector<IrradianceSample>> results(queries.size());
    SampleOptions noFade;
    noFade.edgeFade = false;
    noFade.bakeBias = true; // viewed from the probe (ProbeSampler.h)
    parallelFor((total + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, int t) {
        const std::size_t lo = chunk * kChunk, hi = std::min(total, lo + kChunk);
        std::vector<SampleQuery>& q = queries[std::size_t(t)];
        std::vector<IrradianceSample>& out = results[std::size_t(t)];
        std::vector<std::uint32_t>& qk = queryKeys[std::size_t(t)];
        q.clear();
        qk.clear();
        for (std::size_t k = lo; k < hi; ++k) {
            if (k + kGatherAhead < hi) __builtin_prefetch(&pending_[order[k + kGatherAhead]]);
            q.push_back(pending_[order[k]].query);
            qk.push_back(keys_[order[k]]);
        }
        out.resize(q.size());
        previous.sampleBatch(q.data(), q.size(), out.data(), noFade, qk.data());
        // E_direct + E_indirect, the sum finish() needs, kept in the hit itself (its line was
        // just read): no per-ray array written and read back at random.
        for (std::size_t k = lo; k < hi; ++k)
            pending_[order[k]].irradiance += out[k - lo].irradiance;
    });
}

const glm::vec4* RadianceSlab::finish(std::size_t slot) {
    const std::size_t first = slot * std::size_t(rays_);
    const Pending* pending = pending_.data() + first;
    for (std::uint32_t j = 0; j < pendingCount_[slot]; ++j) {
        const Pending& h = pending[j];
        // The per-ray expression: emissive + albedo/pi * (direct + indirect), the sum lookUp()
        // left in `irradiance`.
        glm::vec3 L = glm::vec3(radiance_[h.ray]) + h.albedoOverPi * h.irradiance;
        radiance_[h.ray] = glm::vec4(L, 0.0f);
    }
    return &radiance_[first];
}

void RadianceSlab::convolve(std::size_t slot, const ProbeConvolution& conv, float* outRgb) {
    conv.irradiance(&finish(slot)->x, outRgb);
    if (slotSamples_[slot] == 0 && slotLitSamples_[slot] == 0) return;
    const float* rgb = lightRgb_.data() + slot * kIrradianceInteriorTexels * 3;
    for (int t = 0; t < kIrradianceInteriorTexels; ++t)
        for (int ch = 0; ch < 3; ++ch) // rows of R, G, B (addToFacingTexels)
            outRgb[3 * t + ch] += rgb[ch * kIrradianceInteriorTexels + t];
}

void RadianceSlab::texelVariance(std::size_t slot, const ProbeConvolution& conv,
                                 float* outVar) const {
    conv.irradianceLumaVariance(&radiance_[slot * std::size_t(rays_)].x, outVar);
    // Each light part is a sum of M samples: its variance is M times their sample variance.
    auto addSumVariance = [&](int m, const float* y1, const float* y2) {
        if (m < 2) return;
        for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
            const float s2 = std::max(0.0f, (y2[t] - y1[t] * y1[t] / float(m)) / float(m - 1));
            outVar[t] += float(m) * s2;
        }
    };
    addSumVariance(slotSamples_[slot], lightY_.data() + slot * kIrradianceInteriorTexels,
                   lightY2_.data() + slot * kIrradianceInteriorTexels);
    addSumVariance(slotLitSamples_[slot], litY_.data() + slot * kIrradianceInteriorTexels,
                   litY2_.data() + slot * kIrradianceInteriorTexels);
}

void RadianceSlab::projectSh(std::size_t slot, const ProbeConvolution& conv, glm::vec3* out) const {
    const std::size_t first = slot * std::size_t(rays_);
    const float w = float(4.0 * M_PI) / float(rays_);
    // RGB + unused lanes: per channel the same multiplies and adds, in the same order, as
    // the vec3 expression out[k] += (L * w) * y[k], four lanes at a time.
    Float4 acc[kShL2Coefficients];
    for (int k = 0; k < kShL2Coefficients; ++k) {
        const glm::vec3& a = lightSh_[slot * kShL2Coefficients + std::size_t(k)];
        acc[k] = Float4{a.x, a.y, a.z, 0.0f};
    }
    for (std::size_t i = 0; i < std::size_t(rays_); ++i) {
        const float* y = conv.shBasisOfRay(int(i));
        const Float4 L = load4(&radiance_[first + i].x) * w;
        for (int k = 0; k < kShL2Coefficients; ++k)
            acc[k] += L * y[k];
    }
    for (int k = 0; k < kShL2Coefficients; ++k)
        out[k] = glm::vec3(acc[k][0], acc[k][1], acc[k][2]);
}

} // namespace pb::probes
