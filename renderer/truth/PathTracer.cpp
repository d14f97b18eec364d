#include "truth/PathTracer.h"

#include "core/Error.h"
#include "core/Luminance.h"
#include "core/ParallelFor.h"
#include "raytrace/AliasTable.h"
#include "truth/CameraRays.h"
#include "truth/GBufferAlbedo.h"
#include "truth/ScrambledSobol.h"
#include "truth/TruthScene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace pb::truth {
namespace {

constexpr float kPi = glm::pi<float>();

float maxComponent(const glm::vec3& c) { return std::max(c.r, std::max(c.g, c.b)); }

// Cosine-weighted direction around n (Malley's method on a concentric-free disk mapping).
glm::vec3 cosineSample(const glm::vec3& n, float u1, float u2) {
    glm::vec3 t = std::abs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    glm::vec3 b1 = glm::normalize(glm::cross(n, t));
    glm::vec3 b2 = glm::cross(n, b1);
    float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    return glm::normalize(b1 * (r * std::cos(phi)) + b2 * (r * std::sin(phi)) + n * z);
}

float smoothstep(float e0, float e1, float x) {
    if (!(e1 > e0)) return x >= e1 ? 1.0f : 0.0f; // GLSL leaves e0 >= e1 undefined
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

float powerHeuristic(float a, float b) {
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

struct Integrator {
    const scene::Scene& scene;
    const TruthScene& ts;
    const raytrace::AliasTable& lights;
    int maxDepth;

    // Sun and punctual lights at x (delta lights: NEE only), as lighting_direct.frag weighs
    // them, but with a shadow ray each (the rasterizer shadows only the sun, by a shadow map).
    glm::vec3 deltaLights(const glm::vec3& x, const glm::vec3& ng, const glm::vec3& ns) const {
        glm::vec3 e(0.0f);
        const float eps = ts.epsilon();
        const glm::vec3 o = x + ng * eps;
        const float inf = std::numeric_limits<float>::infinity();
        if (scene.sun.enabled) {
            const glm::vec3 l = scene.sun.toSun;
            float ndl = glm::dot(ns, l);
            if (ndl > 0.0f && glm::dot(ng, l) > 0.0f && !ts.occluded(o, l, 0.0f, inf))
                e += scene.sun.color * scene.sun.intensity * ndl;
        }
        for (const scene::Light& light : scene.lights) {
            glm::vec3 l;
            float atten = 1.0f, dist = inf;
            if (light.type == scene::LightType::Directional) {
                l = -glm::normalize(light.direction);
            } else {
                glm::vec3 d = light.position - x;
                float dist2 = std::max(glm::dot(d, d), 1e-8f);
                dist = std::sqrt(dist2);
                l = d / dist;
                atten = 1.0f / dist2;
                if (light.range > 0.0f) {
                    float r = dist / light.range;
                    atten *= std::clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
                }
                if (light.type == scene::LightType::Spot)
                    atten *= smoothstep(std::cos(light.outerConeAngle), std::cos(light.innerConeAngle),
                                        glm::dot(-l, glm::normalize(light.direction)));
            }
            float ndl = glm::dot(ns, l);
            if (!(atten > 0.0f) || ndl <= 0.0f || glm::dot(ng, l) <= 0.0f) continue;
            if (ts.occluded(o, l, 0.0f, std::isinf(dist) ? inf : dist * (1.0f - 1e-4f))) continue;
            e += light.color * light.intensity * atten * ndl;
        }
        return e;
    }

    // One emissive triangle by power; returns the MIS-weighted irradiance estimate (before
    // albedo / pi).
    glm::vec3 emissiveLight(const glm::vec3& x, const glm::vec3& ng, const glm::vec3& ns, PathSampler& rng) const {
        if (lights.empty()) return glm::vec3(0.0f);
        float u0 = rng.next1D(), u1, u2;
        rng.next2D(u1, u2);
        std::size_t i = lights.pick(u0);
        const EmissiveTriangle& tri = ts.emissiveTriangles()[i];
        float su = std::sqrt(u1);
        float b1 = u2 * su, b2 = 1.0f - su; // Embree's (u, v): p = (1-u-v) a + u b + v c
        glm::vec3 p = tri.a * (1.0f - b1 - b2) + tri.b * b1 + tri.c * b2;
        glm::vec3 d = p - x;
        float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return glm::vec3(0.0f);
        float dist = std::sqrt(dist2);
        glm::vec3 wi = d / dist;
        float cosS = glm::dot(ns, wi);
        if (cosS <= 0.0f || glm::dot(ng, wi) <= 0.0f) return glm::vec3(0.0f);
        float cosL = -glm::dot(tri.normal, wi);
        if (tri.twoSided) cosL = std::abs(cosL);
        if (cosL <= 0.0f) return glm::vec3(0.0f);
        float pdfLight = float(lights.probability(i)) / tri.area * dist2 / cosL;
        if (!(pdfLight > 0.0f) || !std::isfinite(pdfLight)) return glm::vec3(0.0f);
        const float eps = ts.epsilon();
        if (ts.occluded(x + ng * eps, wi, 0.0f, dist - 2.0f * eps)) return glm::vec3(0.0f);
        float w = powerHeuristic(pdfLight, cosS / kPi);
        return ts.emission(tri, b1, b2) * (cosS * w / pdfLight);
    }

    // The solid-angle pdf with which emissiveLight would have chosen hit h seen from the
    // previous vertex.
    float lightPdf(const SurfaceHit& h, const glm::vec3& dir) const {
        int i = ts.emissiveIndex(h.geomID, h.primID);
        if (i < 0 || lights.empty()) return 0.0f;
        const EmissiveTriangle& tri = ts.emissiveTriangles()[size_t(i)];
        float cosL = std::abs(glm::dot(h.geometricNormal, dir));
        if (!(cosL > 0.0f)) return 0.0f;
        return float(lights.probability(size_t(i))) / tri.area * h.t * h.t / cosL;
    }

    glm::vec3 radiance(glm::vec3 o, glm::vec3 d, PathSampler& rng) const {
        glm::vec3 L(0.0f), beta(1.0f);
        float prevBsdfPdf = 0.0f;
        const float inf = std::numeric_limits<float>::infinity();
        for (int depth = 0;; ++depth) {
            SurfaceHit h = ts.intersect(o, d, 0.0f, inf, depth == 0);
            if (!h.hit()) {
                L += beta * scene.sky.radiance;
                break;
            }
            if (h.emitted != glm::vec3(0.0f)) {
                float w = depth == 0 ? 1.0f : powerHeuristic(prevBsdfPdf, lightPdf(h, d));
                L += beta * h.emitted * w;
            }
            if (depth >= maxDepth) break;
            // What the camera sees is shaded with the GBuffer's albedo (GBufferAlbedo.h).
            if (depth == 0) h.albedo = asGBufferStoresAlbedo(h.albedo);
            const glm::vec3 f = h.albedo / kPi;
            if (f == glm::vec3(0.0f)) break;
            const glm::vec3& ng = h.geometricNormal;
            const glm::vec3& ns = h.shadingNormal;
            L += beta * f * (deltaLights(h.position, ng, ns) + emissiveLight(h.position, ng, ns, rng));

            float u1, u2;
            rng.next2D(u1, u2);
            glm::vec3 wi = cosineSample(ns, u1, u2);
            float cosS = glm::dot(ns, wi);
            if (cosS <= 0.0f || glm::dot(ng, wi) <= 0.0f) break; // below the true surface
            beta *= h.albedo; // f cos / pdf with pdf = cos / pi
            prevBsdfPdf = cosS / kPi;
            if (depth >= 3) {
                float q = std::min(0.95f, maxComponent(beta));
                if (rng.next1D() >= q) break;
                beta /= q;
            }
            o = h.position + ng * ts.epsilon();
            d = wi;
        }
        if (!std::isfinite(L.x + L.y + L.z)) return glm::vec3(0.0f);
        return L;
    }
};

} // namespace

bool sceneHasLight(const scene::Scene& s) {
    auto positive = [](const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; };
    if (s.sun.enabled && s.sun.intensity > 0.0f && positive(s.sun.color)) return true;
    if (positive(s.sky.radiance)) return true;
    for (const scene::Light& l : s.lights)
        if (l.intensity > 0.0f && positive(l.color)) return true;
    for (const scene::Material& m : s.materials)
        if (!m.invisible() && positive(m.emissive)) return true;
    return false;
}

TruthResult renderTruth(const scene::Scene& scene, const scene::View& view,
                        const TruthSettings& settings,
                        const std::function<void(int done, int total)>& progress) {
    if (settings.spp < 1) throw Error("--spp: must be at least 1 (got " + std::to_string(settings.spp) + ")");
    if (settings.maxDepth < 1 || settings.maxDepth > 1024)
        throw Error("--max-depth: must be in [1, 1024] (got " + std::to_string(settings.maxDepth) + ")");
    if (settings.width < 1 || settings.height < 1 || settings.width > 16384 || settings.height > 16384)
        throw Error("--width/--height: must be in [1, 16384]");
    const auto start = std::chrono::steady_clock::now();
    const CameraRays camera(view, settings.width, settings.height);
    const TruthScene ts(scene);

    // A view that sees nothing has no truth to measure: one ray per pixel centre decides.
    const int W = settings.width, H = settings.height;
    bool seesGeometry = false;
    const float inf = std::numeric_limits<float>::infinity();
    for (int y = 0; y < H && !seesGeometry && !ts.empty(); ++y)
        for (int x = 0; x < W && !seesGeometry; ++x)
            seesGeometry = ts.intersect(camera.eye(), camera.direction(x, y, 0.5f, 0.5f), 0.0f, inf, true).hit();
    if (!seesGeometry)
        throw Error("camera '" + view.name + "': the view sees no geometry (scene '" + scene.name + "')");

    TruthResult result;
    result.hdr.width = W;
    result.hdr.height = H;
    result.hdr.channels = 4;
    result.hdr.pixels.assign(size_t(W) * size_t(H) * 4, 0.0f);
    if (!sceneHasLight(scene)) {
        result.note = "scene '" + scene.name + "' has no light (no sun, sky, punctual light or "
                      "emissive material): the truth is black";
        for (std::size_t i = 3; i < result.hdr.pixels.size(); i += 4)
            result.hdr.pixels[i] = 1.0f;
        result.noise.varianceKnown = settings.spp >= 2;
        return result;
    }

    std::vector<double> weights;
    for (const EmissiveTriangle& t : ts.emissiveTriangles())
        weights.push_back(double(t.area) * double(luminance(t.meanEmission)) * (t.twoSided ? 2.0 : 1.0));
    const raytrace::AliasTable lightTable(weights);
    const Integrator integrator{scene, ts, lightTable, settings.maxDepth};

    // Per pixel: the mean colour, and the variance of the mean of its luminance from the spread
    // of its kBatches independently scrambled batches (ScrambledSobol.h: within a batch the
    // samples are stratified, so their own spread would overstate the noise). pixelVariance
    // holds n times that variance, a per-sample variance, so the sums below read as before.
    std::vector<double> pixelVariance(size_t(W) * size_t(H), 0.0);
    const int n = settings.spp;
    const int batches = std::min(n, kBatches);
    parallelFor(
        size_t(H), settings.threads,
        [&](std::size_t row, int) {
            const int y = int(row);
            for (int x = 0; x < W; ++x) {
                const std::uint64_t pixel = std::uint64_t(y) * std::uint64_t(W) + std::uint64_t(x);
                glm::dvec3 sum(0.0);
                double batchSum[kBatches] = {};
                for (int s = 0; s < n; ++s) {
                    PathSampler sampler(settings.seed, pixel, std::uint32_t(s));
                    float jx, jy;
                    sampler.next2D(jx, jy);
                    glm::vec3 L = integrator.radiance(camera.eye(), camera.direction(x, y, jx, jy), sampler);
                    sum += glm::dvec3(L);
                    batchSum[s % kBatches] += double(luminance(L));
                }
                float* px = &result.hdr.pixels[size_t(pixel) * 4];
                px[0] = float(sum.x / n);
                px[1] = float(sum.y / n);
                px[2] = float(sum.z / n);
                px[3] = 1.0f;
                if (batches >= 2) {
                    // Var(mean) ~ sum_b (c_b / n)^2 (m_b - m)^2 * B / (B - 1): the usual estimate
                    // from B independent batch means, weighted by their sizes c_b.
                    double total = 0.0;
                    for (int b = 0; b < batches; ++b) total += batchSum[b];
                    const double mean = total / n;
                    double v = 0.0;
                    for (int b = 0; b < batches; ++b) {
                        // Batch b holds samples b, b + kBatches, ...
                        const double count = double((n - b + kBatches - 1) / kBatches);
                        const double w = count / n, d = batchSum[b] / count - mean;
                        v += w * w * d * d;
                    }
                    pixelVariance[size_t(pixel)] = n * v * batches / (batches - 1);
                }
            }
        },
        [&](std::size_t done) {
            if (progress) progress(int(done), H);
        });

    double lumTotal = 0.0, lumSquares = 0.0, varTotal = 0.0;
    for (std::size_t p = 0; p < pixelVariance.size(); ++p) {
        const float* px = &result.hdr.pixels[p * 4];
        const double lum = double(luminance(glm::vec3(px[0], px[1], px[2])));
        lumTotal += lum;
        lumSquares += lum * lum;
        varTotal += pixelVariance[p];
    }
    const double P = double(W) * double(H);
    result.noise.meanLuminance = lumTotal / P;
    result.noise.varianceKnown = n >= 2;
    if (n >= 2) {
        result.noise.standardError = std::sqrt(varTotal / n) / P;
        result.noise.relativeStandardError =
            result.noise.meanLuminance > 0.0 ? result.noise.standardError / result.noise.meanLuminance : 0.0;
        result.noise.relativeMseNoiseFloor = lumSquares > 0.0 ? varTotal / n / lumSquares : 0.0;
        result.noise.pixelRelativeStandardError =
            result.noise.meanLuminance > 0.0 ? std::sqrt(varTotal / P / n) / result.noise.meanLuminance : 0.0;
    }
    result.cameraRays = std::uint64_t(P) * std::uint64_t(n);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace pb::truth
