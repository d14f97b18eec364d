#include "raytrace/RayScene.h"

#include "core/Error.h"
#include "raytrace/StaticTriangles.h"
#include "raytrace/EmbreeIsa.h"

#include <array>
#include <atomic>
#include <cmath>
#include <mutex>

namespace pb::raytrace {
namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 meanLinearColour(const scene::Scene& s, int texture) {
    if (texture < 0 || texture >= int(s.textures.size())) return glm::vec3(1.0f);
    const scene::Texture& t = s.textures[size_t(texture)];
    std::size_t n = std::size_t(t.width) * t.height;
    if (n == 0 || t.rgba8.size() < n * 4) return glm::vec3(1.0f);
    std::array<float, 256> lut;
    for (int i = 0; i < 256; ++i)
        lut[size_t(i)] = srgbToLinear(float(i) / 255.0f);
    double sum[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            sum[c] += lut[t.rgba8[i * 4 + size_t(c)]];
    return glm::vec3(float(sum[0] / double(n)), float(sum[1] / double(n)),
                     float(sum[2] / double(n)));
}

void embreeError(void*, RTCError code, const char* message) {
    // Errors surface through rtcGetDeviceError checks below; nothing to do here.
    (void)code;
    (void)message;
}

} // namespace

std::vector<MaterialSummary> summariseMaterials(const scene::Scene& s) {
    std::vector<MaterialSummary> out;
    for (const scene::Material& m : s.materials) {
        MaterialSummary ms;
        ms.albedo = glm::clamp(glm::vec3(m.baseColor) * meanLinearColour(s, m.baseColorTexture),
                               0.0f, 1.0f);
        ms.emissive = glm::max(m.emissive, glm::vec3(0.0f));
        if (m.emissiveTexture >= 0) ms.emissive *= meanLinearColour(s, m.emissiveTexture);
        ms.doubleSided = m.doubleSided;
        ms.invisible = m.invisible();
        out.push_back(ms);
    }
    return out;
}

scene::Bounds staticBakeBounds(const scene::Scene& s) {
    scene::Bounds b;
    for (const scene::Instance& inst : s.instances) {
        if (!bakesInstance(s, inst)) continue;
        for (const glm::vec3& p : s.primitives[size_t(inst.primitive)].positions)
            b.extend(glm::vec3(inst.transform * glm::vec4(p, 1.0f)));
    }
    return b;
}

RayScene::RayScene(const scene::Scene& s) : recorder_(std::make_unique<Recorder>()) {
    const std::string config = embreeDeviceConfig(); // PB_EMBREE_ISA (EmbreeIsa.h)
    device_ = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (!device_) throw Error("Embree: cannot create a device");
    rtcSetDeviceErrorFunction(device_, embreeError, nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    auto mats = summariseMaterials(s);
    std::vector<EmissiveTriangle> emissive;

    for (const scene::Instance& inst : s.instances) {
        if (!bakesInstance(s, inst)) continue;
        const scene::Primitive& prim = s.primitives[size_t(inst.primitive)];
        std::size_t nv = prim.positions.size(), nt = prim.indices.size() / 3;
        if (nt == 0 || nv == 0) continue;
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* verts = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
        std::vector<glm::vec3> world(nv);
        for (std::size_t i = 0; i < nv; ++i) {
            world[i] = glm::vec3(inst.transform * glm::vec4(prim.positions[i], 1.0f));
            verts[3 * i] = world[i].x;
            verts[3 * i + 1] = world[i].y;
            verts[3 * i + 2] = world[i].z;
            bounds_.extend(world[i]);
        }
        bool mirrored = glm::determinant(glm::mat3(inst.transform)) < 0.0f;
        std::vector<glm::vec3> normals(nt);
        for (std::size_t t = 0; t < nt; ++t) {
            std::uint32_t a = prim.indices[3 * t], b = prim.indices[3 * t + 1],
                          c = prim.indices[3 * t + 2];
            if (a >= nv || b >= nv || c >= nv) a = b = c = 0; // degenerate: never hit
            idx[3 * t] = a;
            idx[3 * t + 1] = b;
            idx[3 * t + 2] = c;
            glm::vec3 n = glm::cross(world[b] - world[a], world[c] - world[a]);
            float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
            normals[t] = mirrored ? -n : n;
        }
        rtcCommitGeometry(g);
        unsigned id = rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        int m = prim.material;
        SurfaceInfo si;
        if (m >= 0 && m < int(mats.size()))
            si = {mats[size_t(m)].albedo, mats[size_t(m)].emissive, mats[size_t(m)].doubleSided};
        if (surfaces_.size() <= id) {
            surfaces_.resize(id + 1);
            ngSign_.resize(id + 1, 1.0f);
            normals_.resize(id + 1);
            vertices_.resize(id + 1);
            indices_.resize(id + 1);
        }
        surfaces_[id] = si;
        // Embree's ng is cross(v1 - v0, v2 - v0) (tests/unit/RaySceneHitTest.cpp checks it), the
        // counter-clockwise front of glTF; a mirroring transform turns the front around.
        ngSign_[id] = mirrored ? -1.0f : 1.0f;
        if (si.emissive != glm::vec3(0.0f))
            for (std::size_t t = 0; t < nt; ++t) {
                const unsigned* i = idx + 3 * t;
                emissive.push_back({world[i[0]], world[i[1]], world[i[2]], normals[t], si.emissive,
                                    si.doubleSided, 0.0f, id, unsigned(t)});
            }
        normals_[id] = std::move(normals);
        indices_[id].assign(idx, idx + 3 * nt);
        vertices_[id] = std::move(world);
        triangles_ += nt;
    }
    rtcCommitScene(scene_);
    emitters_ = EmitterTable(std::move(emissive));
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE)
        throw Error("Embree: building the bake scene failed (out of memory?)");
    glm::vec3 size = bounds_.size();
    float extent = std::max(size.x, std::max(size.y, size.z));
    float far =
        bounds_.empty() ? 0.0f : std::max(glm::length(bounds_.min), glm::length(bounds_.max));
    epsilon_ = std::max(1e-5f * extent + 1e-6f * far, 1e-6f);
}

void RayScene::triangleCorners(unsigned geomID, unsigned primID, glm::vec3& a, glm::vec3& b,
                               glm::vec3& c) const {
    const std::uint32_t* i = &indices_[geomID][3 * std::size_t(primID)];
    const std::vector<glm::vec3>& v = vertices_[geomID];
    a = v[i[0]];
    b = v[i[1]];
    c = v[i[2]];
}

struct RayScene::Recorder {
    std::atomic<bool> on{false};
    std::atomic<unsigned> session{0};
    std::mutex mutex;
    std::vector<std::unique_ptr<std::vector<RecordedRay>>> perThread;
};

void RayScene::startRecording() {
    std::lock_guard<std::mutex> lock(recorder_->mutex);
    recorder_->perThread.clear();
    ++recorder_->session;
    recorder_->on = true;
}

std::vector<RecordedRay> RayScene::stopRecording() {
    std::lock_guard<std::mutex> lock(recorder_->mutex);
    recorder_->on = false;
    ++recorder_->session;
    std::vector<RecordedRay> all;
    for (auto& v : recorder_->perThread)
        all.insert(all.end(), v->begin(), v->end());
    recorder_->perThread.clear();
    return all;
}

void RayScene::record(const RecordedRay& r) const {
    // Each thread appends to its own buffer (looked up once per session).
    thread_local const void* owner = nullptr;
    thread_local unsigned session = 0;
    thread_local std::vector<RecordedRay>* buffer = nullptr;
    unsigned current = recorder_->session.load();
    if (owner != this || session != current) {
        std::lock_guard<std::mutex> lock(recorder_->mutex);
        recorder_->perThread.push_back(std::make_unique<std::vector<RecordedRay>>());
        buffer = recorder_->perThread.back().get();
        owner = this;
        session = current;
    }
    buffer->push_back(r);
}

void initEmbreeRay(RTCRay& r, const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) {
    r.org_x = o.x;
    r.org_y = o.y;
    r.org_z = o.z;
    r.dir_x = d.x;
    r.dir_y = d.y;
    r.dir_z = d.z;
    r.tnear = tnear;
    r.tfar = tfar;
    r.time = 0.0f;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
}

namespace {
// One ray's closest hit, with the context of the caller.
inline void intersectOne(RTCScene scene, RTCIntersectContext& ctx, const glm::vec3& o,
                         const glm::vec3& d, float tnear, float tfar, RayHit& out) {
    RTCRayHit rh;
    initEmbreeRay(rh.ray, o, d, tnear, tfar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &ctx, &rh);
    out = RayHit{};
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        out.t = rh.ray.tfar;
        out.geomID = rh.hit.geomID;
        out.primID = rh.hit.primID;
        out.ng = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
        out.u = rh.hit.u;
        out.v = rh.hit.v;
    }
}
} // namespace

void RayScene::intersect(const glm::vec3& o, const glm::vec3& d, RayHit& out, float tnear,
                         float tfar) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    if (recorder_->on.load(std::memory_order_relaxed)) record({o, d, tnear, tfar, false});
    intersectOne(scene_, ctx, o, d, tnear, tfar, out);
}

void RayScene::intersect(const glm::vec3& o, const glm::vec3* dirs, std::size_t n,
                         RayHit* out) const {
    RTCIntersectContext ctx; // Embree leaves it as it found it: one for all the rays
    rtcInitIntersectContext(&ctx);
    const float inf = std::numeric_limits<float>::infinity();
    const bool recording = recorder_->on.load(std::memory_order_relaxed);
    for (std::size_t i = 0; i < n; ++i) {
        if (recording) record({o, dirs[i], 0.0f, inf, false});
        intersectOne(scene_, ctx, o, dirs[i], 0.0f, inf, out[i]);
    }
}

float RayScene::portableDistance(const glm::vec3& o, const glm::vec3& d, const RayHit& h) const {
    if (!h.hit()) return h.t;
    glm::vec3 a, b, c;
    triangleCorners(h.geomID, h.primID, a, b, c);
    const glm::dvec3 da(a), n = glm::cross(glm::dvec3(b) - da, glm::dvec3(c) - da);
    const double den = glm::dot(glm::dvec3(d), n);
    if (!(std::abs(den) > 0.0)) return h.t;
    const double t = glm::dot(da - glm::dvec3(o), n) / den;
    return std::isfinite(t) && t >= 0.0 ? float(t) : h.t;
}

bool RayScene::occluded(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r;
    initEmbreeRay(r, o, d, tnear, tfar);
    if (recorder_->on.load(std::memory_order_relaxed)) record({o, d, tnear, tfar, true});
    rtcOccluded1(scene_, &ctx, &r);
    return r.tfar < 0.0f; // Embree sets tfar to -inf on a hit
}

RayScene::~RayScene() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

} // namespace pb::raytrace
