// The path tracer reads the GBuffer's material, texel for texel: the base colour texture (sRGB
// decoded) scales the albedo, an emissive texture the emission, and MASK alpha cuts holes the
// camera and the light see through.
#include "scene/SceneBuilder.h"
#include "truth/GBufferAlbedo.h"
#include "truth/PathTracer.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace pb;

namespace {

constexpr float kTruthMaterialPi = 3.14159265358979f;

// A one-sided quad c + (+-u) + (+-v) facing cross(u, v), UVs (0,0)..(1,1).
void truthMaterialAddQuad(scene::Scene& s, const glm::vec3& c, const glm::vec3& u,
                          const glm::vec3& v, int material) {
    scene::Primitive p;
    p.material = material;
    glm::vec3 n = glm::normalize(glm::cross(u, v));
    p.positions = {c - u - v, c + u - v, c + u + v, c - u + v};
    p.normals.assign(4, n);
    p.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.indices = {0, 1, 2, 0, 2, 3};
    s.primitives.push_back(p);
    scene::Instance inst;
    inst.primitive = int(s.primitives.size()) - 1;
    s.instances.push_back(inst);
}

// A w x 1 texture, texel i = rgba[i].
int addTexture(scene::Scene& s, const std::vector<glm::u8vec4>& rgba) {
    scene::Texture t;
    t.width = int(rgba.size());
    t.height = 1;
    for (const auto& c : rgba)
        t.rgba8.insert(t.rgba8.end(), {c.r, c.g, c.b, c.a});
    s.textures.push_back(t);
    return int(s.textures.size()) - 1;
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

scene::Scene sunlit() {
    scene::Scene s;
    s.name = "test";
    s.sky.radiance = glm::vec3(0.0f);
    s.sun.enabled = true;
    s.sun.toSun = glm::vec3(0, 0, 1);
    s.sun.color = glm::vec3(1.0f);
    s.sun.intensity = 2.0f;
    return s;
}

truth::TruthSettings tiny() {
    truth::TruthSettings ts;
    ts.width = ts.height = 4;
    ts.spp = 4;
    return ts;
}

} // namespace

TEST(TruthMaterial, BaseColourTextureScalesTheAlbedo) {
    scene::Scene s = sunlit();
    scene::SceneBuilder b(s);
    int m = b.material("tex", glm::vec3(0.5f));
    s.materials[size_t(m)].baseColorTexture = addTexture(s, {{200, 100, 50, 255}});
    truthMaterialAddQuad(s, glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), m);
    auto r = truth::renderTruth(s, scene::View{"v", {0, 0, 3}, {0, 0, 0}, 10.0f}, tiny());
    const float texel[3] = {200, 100, 50};
    for (int c = 0; c < 3; ++c) {
        // The GBuffer stores factor x texel in 8-bit sRGB (GBufferAlbedo.h).
        const float albedo = truth::throughSrgb8(0.5f * srgbToLinear(texel[c] / 255.0f));
        const float expected = albedo / kTruthMaterialPi * 2.0f;
        EXPECT_NEAR(r.hdr.at(1, 1, c), expected, 1e-5f) << c;
    }
}

TEST(TruthMaterial, EmissiveTextureScalesTheEmission) {
    scene::Scene s = sunlit();
    s.sun.enabled = false;
    scene::SceneBuilder b(s);
    int m = b.material("glow", glm::vec3(0.0f), glm::vec3(3.0f));
    s.materials[size_t(m)].emissiveTexture = addTexture(s, {{255, 128, 0, 255}});
    truthMaterialAddQuad(s, glm::vec3(0.0f), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), m);
    auto r = truth::renderTruth(s, scene::View{"v", {0, 0, 3}, {0, 0, 0}, 10.0f}, tiny());
    EXPECT_NEAR(r.hdr.at(2, 2, 0), 3.0f, 1e-5f);
    EXPECT_NEAR(r.hdr.at(2, 2, 1), 3.0f * srgbToLinear(128.0f / 255.0f), 1e-5f);
    EXPECT_NEAR(r.hdr.at(2, 2, 2), 0.0f, 1e-6f);
}

TEST(TruthMaterial, MaskAlphaCutsAHoleForCameraAndLight) {
    // A sunlit floor at z = 0 under a MASK quad at z = 1 whose texture is transparent on its
    // left half (u < 0.5) and opaque on its right. Looking down from z = 3 the camera sees the
    // lit floor through the hole and the black cut-out quad elsewhere; the light passes the
    // hole only. (A 2-texel texture, bilinear: the halves are clean away from u = 0.5.)
    scene::Scene s = sunlit();
    scene::SceneBuilder b(s);
    int floor = b.material("floor", glm::vec3(0.5f));
    truthMaterialAddQuad(s, glm::vec3(0.0f), glm::vec3(5, 0, 0), glm::vec3(0, 5, 0), floor);
    int mask = b.material("mask", glm::vec3(0.0f));
    s.materials[size_t(mask)].alphaMode = scene::AlphaMode::Mask;
    s.materials[size_t(mask)].alphaCutoff = 0.5f;
    s.materials[size_t(mask)].baseColorTexture = addTexture(s, {{0, 0, 0, 0}, {0, 0, 0, 255}});
    truthMaterialAddQuad(s, glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), mask);
    truth::TruthSettings ts = tiny();
    ts.width = 8;
    ts.height = 2;
    // 8 pixels across x in [-0.8, 0.8] at the mask's depth (a narrow view of the quad).
    auto r = truth::renderTruth(s, scene::View{"v", {0, 0, 3}, {0, 0, 0}, 10.0f}, ts);
    const float lit = truth::throughSrgb8(0.5f) / kTruthMaterialPi * 2.0f;
    EXPECT_NEAR(r.hdr.at(0, 0, 0), lit, 1e-5f) << "through the hole to the lit floor";
    EXPECT_NEAR(r.hdr.at(7, 0, 0), 0.0f, 1e-6f) << "the opaque half, black";
}
