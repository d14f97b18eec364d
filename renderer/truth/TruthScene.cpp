#include "truth/TruthScene.h"

#include "core/Error.h"
#include "raytrace/EmbreeIsa.h"
#include "raytrace/RayScene.h"
#include "truth/Srgb.h"

#include <cmath>

namespace pb::truth {
namespace {

// GL's bilinear filter on an sRGB8_A8 texture with REPEAT wrapping (glTF's default sampler):
// texels are decoded to linear before filtering, alpha is linear. No mipmaps: the truth
// super-samples each pixel instead.
glm::vec4 sampleTexture(const scene::Texture& t, glm::vec2 uv) {
    if (t.width <= 0 || t.height <= 0 || t.rgba8.size() < size_t(t.width) * t.height * 4)
        return glm::vec4(1.0f);
    float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return glm::vec4(1.0f);
    float fx = std::floor(x), fy = std::floor(y);
    float wx = x - fx, wy = y - fy;
    auto wrap = [](long long i, int n) { return int(((i % n) + n) % n); };
    glm::vec4 sum(0.0f);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            int tx = wrap((long long)fx + i, t.width), ty = wrap((long long)fy + j, t.height);
            const std::uint8_t* p = &t.rgba8[(size_t(ty) * size_t(t.width) + size_t(tx)) * 4];
            glm::vec4 c(srgb8ToLinear(p[0]), srgb8ToLinear(p[1]), srgb8ToLinear(p[2]),
                        float(p[3]) / 255.0f);
            sum += c * ((i ? wx : 1.0f - wx) * (j ? wy : 1.0f - wy));
        }
    return sum;
}

glm::vec3 meanTextureColour(const scene::Scene& s, int texture) {
    if (texture < 0 || texture >= int(s.textures.size())) return glm::vec3(1.0f);
    const scene::Texture& t = s.textures[size_t(texture)];
    std::size_t n = std::size_t(t.width) * std::size_t(t.height);
    if (n == 0 || t.rgba8.size() < n * 4) return glm::vec3(1.0f);
    double sum[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            sum[c] += srgb8ToLinear(t.rgba8[i * 4 + size_t(c)]);
    return glm::vec3(float(sum[0] / double(n)), float(sum[1] / double(n)), float(sum[2] / double(n)));
}

} // namespace

TruthScene::TruthScene(const scene::Scene& s) : scene_(s) {
    const std::string config = raytrace::embreeDeviceConfig(); // PB_EMBREE_ISA
    device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (!device_) throw Error("Embree: cannot create a device");
    rtc_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(rtc_, RTC_BUILD_QUALITY_HIGH);

    for (const scene::Instance& inst : s.instances) {
        if (inst.primitive < 0 || inst.primitive >= int(s.primitives.size())) continue;
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        const int m = prim.material >= 0 && prim.material < int(s.materials.size()) ? prim.material : -1;
        const scene::Material fallback;
        const scene::Material& mat = m >= 0 ? s.materials[size_t(m)] : fallback;
        if (mat.invisible()) continue; // GBufferPass draws nothing for it
        std::size_t nv = prim.positions.size(), nt = prim.indices.size() / 3;
        if (nt == 0 || nv == 0) continue;

        Geom g;
        g.material = m;
        g.alphaCutoff = mat.alphaMode == scene::AlphaMode::Mask    ? mat.alphaCutoff
                        : mat.alphaMode == scene::AlphaMode::Blend ? 0.5f
                                                                   : -1.0f;
        anyAlphaTest_ = anyAlphaTest_ || g.alphaCutoff >= 0.0f;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
        g.positions.resize(nv);
        g.normals.resize(nv);
        for (std::size_t i = 0; i < nv; ++i) {
            g.positions[i] = glm::vec3(inst.transform * glm::vec4(prim.positions[i], 1.0f));
            glm::vec3 n = i < prim.normals.size() ? normalMatrix * prim.normals[i] : glm::vec3(0);
            float len = glm::length(n);
            g.normals[i] = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f);
            bounds_.extend(g.positions[i]);
        }
        if (prim.uvs.size() == nv) g.uvs = prim.uvs;
        g.indices.resize(nt * 3);
        g.faceNormals.resize(nt);
        const bool mirrored = glm::determinant(glm::mat3(inst.transform)) < 0.0f;
        for (std::size_t t = 0; t < nt; ++t) {
            std::uint32_t a = prim.indices[3 * t], b = prim.indices[3 * t + 1], c = prim.indices[3 * t + 2];
            if (a >= nv || b >= nv || c >= nv) a = b = c = 0; // degenerate: never hit
            g.indices[3 * t] = a;
            g.indices[3 * t + 1] = b;
            g.indices[3 * t + 2] = c;
            glm::vec3 n = glm::cross(g.positions[b] - g.positions[a], g.positions[c] - g.positions[a]);
            float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
            g.faceNormals[t] = mirrored ? -n : n;
        }

        RTCGeometry rg = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* verts = static_cast<float*>(rtcSetNewGeometryBuffer(
            rg, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            rg, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
        for (std::size_t i = 0; i < nv; ++i) {
            verts[3 * i] = g.positions[i].x;
            verts[3 * i + 1] = g.positions[i].y;
            verts[3 * i + 2] = g.positions[i].z;
        }
        for (std::size_t i = 0; i < nt * 3; ++i)
            idx[i] = g.indices[i];
        rtcCommitGeometry(rg);
        unsigned id = rtcAttachGeometry(rtc_, rg);
        rtcReleaseGeometry(rg);

        // Emissive triangles: the light sampler's list, with a power estimate per triangle.
        glm::vec3 meanE = glm::max(mat.emissive, glm::vec3(0.0f)) * meanTextureColour(s, mat.emissiveTexture);
        if (meanE.x + meanE.y + meanE.z > 0.0f) {
            g.emissiveIndex.assign(nt, -1);
            for (std::size_t t = 0; t < nt; ++t) {
                const std::uint32_t* i3 = &g.indices[3 * t];
                EmissiveTriangle e;
                e.a = g.positions[i3[0]];
                e.b = g.positions[i3[1]];
                e.c = g.positions[i3[2]];
                e.area = 0.5f * glm::length(glm::cross(e.b - e.a, e.c - e.a));
                if (!(e.area > 0.0f)) continue;
                if (!g.uvs.empty()) {
                    e.uvA = g.uvs[i3[0]];
                    e.uvB = g.uvs[i3[1]];
                    e.uvC = g.uvs[i3[2]];
                }
                e.normal = g.faceNormals[t];
                e.twoSided = mat.doubleSided;
                e.material = m;
                e.geomID = id;
                e.primID = unsigned(t);
                e.meanEmission = meanE;
                g.emissiveIndex[t] = int(emissive_.size());
                emissive_.push_back(e);
            }
        }
        if (geoms_.size() <= id) geoms_.resize(id + 1);
        geoms_[id] = std::move(g);
    }
    rtcCommitScene(rtc_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE)
        throw Error("Embree: building the path tracer's scene failed (out of memory?)");
    glm::vec3 size = bounds_.size();
    float extent = std::max(size.x, std::max(size.y, size.z));
    float far = bounds_.empty() ? 0.0f : std::max(glm::length(bounds_.min), glm::length(bounds_.max));
    epsilon_ = std::max(1e-5f * extent + 1e-6f * far, 1e-6f);
}

TruthScene::~TruthScene() {
    if (rtc_) rtcReleaseScene(rtc_);
    if (device_) rtcReleaseDevice(device_);
}

int TruthScene::emissiveIndex(unsigned geomID, unsigned primID) const {
    if (geomID >= geoms_.size()) return -1;
    const Geom& g = geoms_[geomID];
    return primID < g.emissiveIndex.size() ? g.emissiveIndex[primID] : -1;
}

glm::vec2 TruthScene::uvAt(const Geom& g, unsigned prim, float u, float v) const {
    if (g.uvs.empty()) return glm::vec2(0.0f);
    const std::uint32_t* i3 = &g.indices[3 * size_t(prim)];
    return g.uvs[i3[0]] * (1.0f - u - v) + g.uvs[i3[1]] * u + g.uvs[i3[2]] * v;
}

glm::vec4 TruthScene::baseColour(const Geom& g, const glm::vec2& uv) const {
    if (g.material < 0) return glm::vec4(1.0f);
    const scene::Material& m = scene_.materials[size_t(g.material)];
    glm::vec4 base = m.baseColor;
    if (m.baseColorTexture >= 0 && m.baseColorTexture < int(scene_.textures.size()))
        base *= sampleTexture(scene_.textures[size_t(m.baseColorTexture)], uv);
    return base;
}

bool TruthScene::passes(const Geom& g, unsigned prim, float u, float v) const {
    if (g.alphaCutoff < 0.0f) return true;
    return !(baseColour(g, uvAt(g, prim, u, v)).a < g.alphaCutoff);
}

glm::vec3 TruthScene::emission(const EmissiveTriangle& tri, float u, float v) const {
    if (tri.material < 0) return glm::vec3(0.0f);
    const scene::Material& m = scene_.materials[size_t(tri.material)];
    glm::vec3 e = glm::max(m.emissive, glm::vec3(0.0f));
    if (m.emissiveTexture >= 0 && m.emissiveTexture < int(scene_.textures.size())) {
        glm::vec2 uv = tri.uvA * (1.0f - u - v) + tri.uvB * u + tri.uvC * v;
        e *= glm::vec3(sampleTexture(scene_.textures[size_t(m.emissiveTexture)], uv));
    }
    return e;
}

SurfaceHit TruthScene::shade(const glm::vec3& o, const glm::vec3& d, float t, unsigned geomID,
                             unsigned primID, float u, float v) const {
    const Geom& g = geoms_[geomID];
    SurfaceHit h;
    h.t = t;
    h.geomID = geomID;
    h.primID = primID;
    h.position = o + d * t;
    glm::vec3 ng = g.faceNormals[primID];
    const bool front = glm::dot(ng, d) < 0.0f;
    const std::uint32_t* i3 = &g.indices[3 * size_t(primID)];
    glm::vec3 ns = g.normals[i3[0]] * (1.0f - u - v) + g.normals[i3[1]] * u + g.normals[i3[2]] * v;
    float len = glm::length(ns);
    ns = len > 1e-6f && std::isfinite(len) ? ns / len : ng;
    // The side the ray arrived from; a shading normal pointing away from it (a bent vertex
    // normal at a silhouette) falls back to the face normal.
    if (!front) {
        ng = -ng;
        ns = -ns;
    }
    if (glm::dot(ns, ng) <= 0.0f) ns = ng;
    h.geometricNormal = ng;
    h.shadingNormal = ns;
    glm::vec2 uv = uvAt(g, primID, u, v);
    h.albedo = glm::clamp(glm::vec3(baseColour(g, uv)), 0.0f, 1.0f);
    if (primID < g.emissiveIndex.size() && g.emissiveIndex[primID] >= 0) {
        const EmissiveTriangle& e = emissive_[size_t(g.emissiveIndex[primID])];
        if (front || e.twoSided) h.emitted = emission(e, u, v);
    }
    return h;
}

SurfaceHit TruthScene::intersect(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar,
                                 bool camera) const {
    // Step through culled back faces and alpha-tested texels; bounded so a degenerate stack of
    // coplanar cut-outs cannot loop.
    for (int step = 0; step < 256; ++step) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh;
        raytrace::initEmbreeRay(rh.ray, o, d, tnear, tfar);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(rtc_, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
        const Geom& g = geoms_[rh.hit.geomID];
        bool skip = false;
        if (camera && !(g.material >= 0 && scene_.materials[size_t(g.material)].doubleSided))
            skip = glm::dot(g.faceNormals[rh.hit.primID], d) >= 0.0f;
        if (!skip) skip = !passes(g, rh.hit.primID, rh.hit.u, rh.hit.v);
        if (!skip) return shade(o, d, rh.ray.tfar, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v);
        tnear = std::nextafter(rh.ray.tfar, std::numeric_limits<float>::infinity());
    }
    return {};
}

bool TruthScene::occluded(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) const {
    if (anyAlphaTest_) return intersect(o, d, tnear, tfar, false).hit();
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r;
    raytrace::initEmbreeRay(r, o, d, tnear, tfar);
    rtcOccluded1(rtc_, &ctx, &r);
    return r.tfar < 0.0f; // Embree sets tfar to -inf on a hit
}

} // namespace pb::truth
