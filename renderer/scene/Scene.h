#pragma once
// The CPU-side scene every part of probebench shares: the glTF loader and the built-in
// scenes produce it, the Embree bake and the GL renderer consume it. No GL in here.
//
// Conventions (nothing assumes metres near the origin: the shared scenes range from
// centimetres to hundreds of metres, some far from (0,0,0)):
//  - geometry is stored once per primitive in its local space; instances place it in the world;
//  - right-handed, +Y up (glTF);
//  - colours are linear; textures keep their 8-bit data and say whether it is sRGB-encoded;
//  - light intensities are in the units glTF uses (lux for the sun / directional lights,
//    candela for point and spot lights); the renderer and the bake interpret them the same way.
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <string>
#include <vector>

namespace pb::scene {

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};
    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void extend(const Bounds& b) {
        if (!b.empty()) { extend(b.min); extend(b.max); }
    }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 size() const { return empty() ? glm::vec3(0) : max - min; }
};

struct Texture {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba8; // width*height*4, rows top to bottom as in the image file
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f};     // linear RGBA factor
    int baseColorTexture = -1;     // index into Scene::textures (sRGB-encoded), -1 = none
    glm::vec3 emissive{0.0f};      // linear radiance factor (already times emissive_strength)
    int emissiveTexture = -1;      // index into Scene::textures (sRGB-encoded), -1 = none
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    // BLEND with base alpha 0 draws nothing (e.g. space_ship_hallway's "Glass"): the
    // renderer skips it and the bake lets rays pass through it. "0" is below one 8-bit step:
    // that Glass actually stores alpha 0.0017.
    bool invisible() const { return alphaMode == AlphaMode::Blend && baseColor.a < 1.0f / 255.0f; }
};

// Triangle list, always indexed (non-indexed glTF primitives get 0..n-1).
struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // same count as positions; generated when absent
    std::vector<glm::vec2> uvs;       // empty or same count as positions
    std::vector<std::uint32_t> indices;
    int material = 0;                 // index into Scene::materials
    Bounds localBounds;
    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Instance {
    std::string nodeName;
    int primitive = 0;                // index into Scene::primitives
    glm::mat4 transform{1.0f};        // local -> world
    bool dynamic = false;             // dynamic objects are not baked; they get GI another way
};

enum class LightType { Directional, Point, Spot };

struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;           // lux (directional) or candela (point, spot)
    glm::vec3 position{0.0f};         // world
    glm::vec3 direction{0, 0, -1};    // world, the direction the light travels
    float range = 0.0f;               // 0 = infinite
    float innerConeAngle = 0.0f;      // radians (spot)
    float outerConeAngle = 0.7853982f;
    bool castsShadows = false;        // only the sun casts shadow-mapped shadows for now
};

// The sun is kept apart from the punctual lights: it drives the shadow map and the bake's
// sun term, and `--sun` overrides it.
struct Sun {
    bool enabled = true;
    glm::vec3 toSun = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)); // unit, towards the sun
    glm::vec3 color{1.0f, 0.96f, 0.9f};
    float intensity = 3.0f;           // irradiance on a surface facing the sun (linear units)
};

struct Sky {
    glm::vec3 radiance{0.35f, 0.45f, 0.6f}; // constant radiance; a uniform sky L gives E = pi*L
    // The share of the sky the scene's surfaces see (meanSkyVisibility, SkyVisibility.h): the
    // flat ambient of frames without GI is pi * L * visibility. The loaders measure it; 0.25
    // (the old fixed pi/4) for scenes built by hand.
    float visibility = 0.25f;
};

struct View {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 target{0, 0, -1};
    float fovYDegrees = 60.0f;
};

struct Scene {
    std::string name;                 // built-in name or file stem
    std::string sourcePath;           // empty for built-in scenes
    std::vector<Primitive> primitives;
    std::vector<Material> materials;  // never empty (a default material is added if needed)
    std::vector<Texture> textures;
    std::vector<Instance> instances;
    std::vector<Light> lights;        // punctual lights (KHR_lights_punctual), sun excluded
    Sun sun;
    Sky sky;
    float exposure = 1.0f;            // linear scale before tonemapping
    std::vector<View> views;          // never empty after loading (a default view is added)
    std::vector<std::string> warnings;

    Bounds worldBounds() const;        // all instances
    Bounds staticWorldBounds() const;  // non-dynamic instances only
    std::size_t triangleCount() const; // over instances
    const View* findView(const std::string& name) const;
};

// A world-space point of `instance`'s primitive vertex.
glm::vec3 worldPosition(const Scene& s, const Instance& inst, std::uint32_t vertex);

} // namespace pb::scene
