// RayScene::portableDistance: a hit's distance that does not depend on how Embree rounds. Two
// Embree kernels (the x86-64 baseline SSE2 and this CPU's widest) stand in for two CPU vendors:
// their own t differ in the last bits on some rays, as Embree's approximate reciprocal differs
// between Intel and AMD; the portable t of the same triangle must be the same bits.
#include "raytrace/EmbreeIsa.h"
#include "raytrace/RayScene.h"
#include "scene/SceneLoader.h"

#include <cstdio>
#include <gtest/gtest.h>
#include <random>

namespace {

struct Ray {
    glm::vec3 o, d;
};

std::vector<Ray> randomRays(const pb::scene::Bounds& b, int n) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f), s(-1.0f, 1.0f);
    std::vector<Ray> rays(static_cast<std::size_t>(n));
    for (Ray& r : rays) {
        r.o = b.min + glm::vec3(u(rng), u(rng), u(rng)) * (b.max - b.min);
        r.d = glm::vec3(s(rng), s(rng), s(rng)) + 1e-3f;
    }
    return rays;
}

struct Traced {
    std::vector<pb::raytrace::RayHit> hits;
    std::vector<float> portable;
};

Traced portableHitDistanceTrace(const pb::scene::Scene& s, const std::vector<Ray>& rays,
                                const std::string& isa) {
    pb::raytrace::pinEmbreeIsa(isa);
    const pb::raytrace::RayScene scene(s);
    pb::raytrace::pinEmbreeIsa(""); // Embree chooses again, for the tests after this one
    Traced t;
    for (const Ray& r : rays) {
        t.hits.push_back(scene.intersect(r.o, r.d));
        t.portable.push_back(scene.portableDistance(r.o, r.d, t.hits.back()));
    }
    return t;
}

} // namespace

#if defined(__x86_64__)
TEST(PortableHitDistance, IsTheSameBitsWhereEmbreeKernelsRoundDifferently) {
    const std::string widest = pb::raytrace::embreeIsa();
    if (widest == "sse2") GTEST_SKIP() << "this CPU runs only Embree's SSE2 kernels: one kernel";
    int hits = 0, sameTriangle = 0, embreeDiffers = 0, portableDiffers = 0;
    double worstGap = 0.0; // portable vs Embree's t, relative
    for (const char* name : {"cornell", "courtyard", "rooms"}) {
        const pb::scene::Scene s = pb::scene::makeBuiltinScene(name);
        const std::vector<Ray> rays = randomRays(pb::raytrace::RayScene(s).bounds(), 20000);
        const Traced a = portableHitDistanceTrace(s, rays, "sse2"),
                     b = portableHitDistanceTrace(s, rays, widest);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const pb::raytrace::RayHit &ha = a.hits[i], &hb = b.hits[i];
            ASSERT_EQ(ha.hit(), hb.hit()) << name << " ray " << i;
            if (!ha.hit()) continue;
            ++hits;
            if (ha.geomID != hb.geomID || ha.primID != hb.primID) continue; // an edge: either
            ++sameTriangle;
            embreeDiffers += ha.t != hb.t ? 1 : 0;
            portableDiffers += a.portable[i] != b.portable[i] ? 1 : 0;
            worstGap = std::max(worstGap, std::abs(double(a.portable[i]) - ha.t) / ha.t);
        }
    }
    std::printf("[ portable t ] sse2 vs %s: %d hits, %d on the same triangle; Embree's t differ "
                "on %d, the portable t on %d; portable vs Embree's t at most %.2g relative\n",
                widest.c_str(), hits, sameTriangle, embreeDiffers, portableDiffers, worstGap);
    EXPECT_GT(sameTriangle, hits * 99 / 100);
    EXPECT_GT(embreeDiffers, 0) << "the kernels agree everywhere: nothing to tell apart";
    EXPECT_EQ(portableDiffers, 0);
    EXPECT_LT(worstGap, 1e-3); // the same hit (Embree's float t drifts on grazing rays)
}
#endif
