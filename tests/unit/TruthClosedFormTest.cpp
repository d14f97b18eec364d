// The path tracer (renderer/truth/) against closed forms: the white furnace (radiance
// E / (1 - a) inside a closed emitting box of albedo a), a sunlit Lambertian plane
// (albedo / pi * E_sun * cos), and a floor under a square area light (the view factor of a
// differential area to a parallel square). Statistical checks allow 5 standard errors as the
// tracer itself reports them, so they also test that report. The surface the camera sees
// reflects with its albedo as the GBuffer stores it (8-bit sRGB, GBufferAlbedo.h), the
// surfaces behind it with the exact one; the sunlit plane's exact check fails without that.
#include "scene/SceneBuilder.h"
#include "truth/GBufferAlbedo.h"
#include "truth/PathTracer.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb;

namespace {

constexpr float kTruthClosedFormPi = 3.14159265358979f;

scene::Scene darkScene() {
    scene::Scene s;
    s.name = "test";
    s.sun.enabled = false;
    s.sky.radiance = glm::vec3(0.0f);
    return s;
}

// A one-sided quad c + (+-u) + (+-v) facing cross(u, v).
void addQuad(scene::Scene& s, const glm::vec3& c, const glm::vec3& u, const glm::vec3& v, int material) {
    scene::Primitive p;
    p.material = material;
    glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (glm::vec3 q : {c - u - v, c + u - v, c + u + v, c - u + v}) {
        p.positions.push_back(q);
        p.normals.push_back(n);
        p.localBounds.extend(q);
    }
    p.indices = {0, 1, 2, 0, 2, 3};
    s.primitives.push_back(p);
    scene::Instance inst;
    inst.primitive = int(s.primitives.size()) - 1;
    s.instances.push_back(inst);
}

double meanLuminance(const image::ImageF& img) {
    double sum = 0.0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            sum += 0.2126 * img.at(x, y, 0) + 0.7152 * img.at(x, y, 1) + 0.0722 * img.at(x, y, 2);
    return sum / (double(img.width) * img.height);
}

// Differential area to a parallel rectangle a x b with its corner straight above, at height h.
double viewFactorCorner(double a, double b, double h) {
    double A = a / h, B = b / h;
    return 1.0 / (2.0 * M_PI) *
           (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
            B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B)));
}

} // namespace

class WhiteFurnace : public ::testing::TestWithParam<float> {};

TEST_P(WhiteFurnace, ClosedEmittingBoxGivesEOverOneMinusAlbedo) {
    const float albedo = GetParam();
    const glm::vec3 E(0.2f, 0.3f, 0.4f);
    scene::Scene s = darkScene();
    scene::SceneBuilder b(s);
    int m = b.material("furnace", glm::vec3(albedo), E);
    s.materials[size_t(m)].doubleSided = true; // seen, and emitting, from inside
    b.box("box", glm::vec3(-1.0f), glm::vec3(1.0f), m);
    scene::View v{"in", {0.1f, 0.2f, 0.3f}, {1.0f, 0.5f, -1.0f}, 90.0f};
    truth::TruthSettings ts;
    ts.width = ts.height = 16;
    ts.spp = 64;
    ts.maxDepth = 1024; // a^1024: no truncation bias worth naming
    truth::TruthResult r = truth::renderTruth(s, v, ts);
    // E emitted + the first hit's stored albedo times what arrives there, E / (1 - a).
    const glm::vec3 expected = E + truth::throughSrgb8(albedo) * E / (1.0f - albedo);
    const double expectedLum = 0.2126 * expected.r + 0.7152 * expected.g + 0.0722 * expected.b;
    ASSERT_TRUE(r.noise.varianceKnown);
    if (albedo > 0.0f) { // albedo 0: exact, no noise
        EXPECT_GT(r.noise.standardError, 0.0);
    }
    EXPECT_NEAR(r.noise.meanLuminance, meanLuminance(r.hdr), 1e-6 * expectedLum);
    EXPECT_NEAR(r.noise.meanLuminance, expectedLum, 5.0 * r.noise.standardError + 1e-4 * expectedLum)
        << "albedo " << albedo << ", SE " << r.noise.standardError;
    // Every channel, not only the luminance (loose: per-channel noise is not reported).
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int y = 0; y < ts.height; ++y)
            for (int x = 0; x < ts.width; ++x)
                sum += r.hdr.at(x, y, c);
        EXPECT_NEAR(sum / (ts.width * ts.height), expected[c], 0.02 * expected[c]) << "channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Albedos, WhiteFurnace, ::testing::Values(0.0f, 0.5f, 0.8f));

TEST(TruthClosedForm, SunlitPlaneIsAlbedoOverPiTimesIrradianceTimesCosine) {
    scene::Scene s = darkScene();
    scene::SceneBuilder b(s);
    const glm::vec3 albedo(0.6f, 0.5f, 0.4f);
    addQuad(s, glm::vec3(0.0f), glm::vec3(50, 0, 0), glm::vec3(0, 0, -50), b.material("floor", albedo));
    s.sun.enabled = true;
    s.sun.toSun = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    s.sun.color = glm::vec3(1.0f, 0.96f, 0.9f);
    s.sun.intensity = 3.0f;
    scene::View v{"down", {0.0f, 2.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 40.0f};
    truth::TruthSettings ts;
    ts.width = 12;
    ts.height = 8;
    ts.spp = 4;
    truth::TruthResult r = truth::renderTruth(s, v, ts);
    // Sun NEE is exact and every bounce escapes to the black sky: each pixel is the formula.
    const glm::vec3 expected = truth::asGBufferStoresAlbedo(albedo) / kTruthClosedFormPi *
                               s.sun.color * s.sun.intensity * s.sun.toSun.y;
    for (int y = 0; y < ts.height; ++y)
        for (int x = 0; x < ts.width; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(r.hdr.at(x, y, c), expected[c], 1e-5f * expected[c]) << x << "," << y;
    EXPECT_NEAR(r.noise.standardError, 0.0, 1e-6 * r.noise.meanLuminance);
}

TEST(TruthClosedForm, FloorUnderSquareLightFollowsTheViewFactor) {
    scene::Scene s = darkScene();
    scene::SceneBuilder b(s);
    const float albedo = 0.5f, Le = 2.0f, side = 1.0f, h = 1.0f;
    addQuad(s, glm::vec3(0.0f), glm::vec3(20, 0, 0), glm::vec3(0, 0, -20), b.material("floor", glm::vec3(albedo)));
    // The light faces down; black, so light the floor sends up is not returned.
    addQuad(s, glm::vec3(0, h, 0), glm::vec3(side / 2, 0, 0), glm::vec3(0, 0, side / 2),
            b.material("light", glm::vec3(0.0f), glm::vec3(Le)));
    // The camera looks straight down at the point under the light's centre, through a 1 degree
    // cone (the view factor changes by ~1e-4 over that footprint).
    scene::View v{"down", {0.0f, 0.5f, 0.0f}, {0.0f, 0.0f, 0.0f}, 1.0f};
    truth::TruthSettings ts;
    ts.width = ts.height = 8;
    ts.spp = 256;
    truth::TruthResult r = truth::renderTruth(s, v, ts);
    const double F = 4.0 * viewFactorCorner(side / 2, side / 2, h);
    const double expected = truth::throughSrgb8(albedo) * Le * F; // albedo / pi * (Le * pi * F)
    EXPECT_NEAR(r.noise.meanLuminance, expected, 5.0 * r.noise.standardError + 1e-3 * expected)
        << "F " << F << ", SE " << r.noise.standardError;
    EXPECT_LT(r.noise.relativeStandardError, 0.01); // NEE makes this an easy integral
}

TEST(TruthClosedForm, DirectOnlyDepthOneDropsTheInterreflection) {
    // In the furnace, depth 1 sees the emission plus one bounce of it: E (1 + a).
    const float albedo = 0.5f;
    scene::Scene s = darkScene();
    scene::SceneBuilder b(s);
    int m = b.material("furnace", glm::vec3(albedo), glm::vec3(1.0f));
    s.materials[size_t(m)].doubleSided = true;
    b.box("box", glm::vec3(-1.0f), glm::vec3(1.0f), m);
    truth::TruthSettings ts;
    ts.width = ts.height = 8;
    ts.spp = 128;
    ts.maxDepth = 1;
    truth::TruthResult r = truth::renderTruth(s, scene::View{"in", {0, 0, 0}, {0, 0, -1}, 90.0f}, ts);
    EXPECT_NEAR(r.noise.meanLuminance, 1.0 + truth::throughSrgb8(albedo),
                5.0 * r.noise.standardError + 1e-4);
}
