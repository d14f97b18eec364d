#include "scene/GltfMaterials.h"

#include <cmath>

namespace pb::scene::gltf {

namespace {

// tinygltf decodes 8- or 16-bit images with 1..4 channels (4 unless told otherwise);
// the renderer wants 8-bit RGBA.
bool toRgba8(const tinygltf::Image& img, Texture& out) {
    const int comp = img.component, bytesPer = img.bits / 8;
    if (img.width < 1 || img.height < 1 || comp < 1 || comp > 4 || (bytesPer != 1 && bytesPer != 2))
        return false;
    const size_t pixels = size_t(img.width) * size_t(img.height);
    if (img.image.size() < pixels * size_t(comp * bytesPer)) return false;
    out.width = img.width;
    out.height = img.height;
    out.rgba8.resize(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
        std::uint8_t c[4] = {0, 0, 0, 255};
        for (int k = 0; k < comp; ++k) // 16-bit: little-endian, keep the high byte
            c[k] =
                img.image[(i * size_t(comp) + size_t(k)) * size_t(bytesPer) + size_t(bytesPer - 1)];
        if (comp <= 2) { // grey (+ alpha)
            c[3] = comp == 2 ? c[1] : 255;
            c[1] = c[2] = c[0];
        }
        for (int k = 0; k < 4; ++k)
            out.rgba8[i * 4 + size_t(k)] = c[k];
    }
    return true;
}

// Scene::textures index for glTF texture `index`, -1 when it has no usable image.
int textureFor(Context& ctx, int index, const std::string& material) {
    if (index < 0) return -1;
    const tinygltf::Model& m = ctx.model;
    if (size_t(index) >= m.textures.size())
        ctx.fail(material + " refers to missing texture " + std::to_string(index));
    const int source = m.textures[size_t(index)].source;
    if (source < 0 && m.textures[size_t(index)].extensions.count("KHR_texture_basisu")) {
        ctx.basisuOnlyTextures.insert(index); // one warning for all (GltfLoader)
        return -1;
    }
    if (source < 0) { // only some other extension's source (EXT_texture_webp, ...)
        ctx.warn("texture " + std::to_string(index) + " has no PNG/JPEG source; ignored");
        return -1;
    }
    if (size_t(source) >= m.images.size())
        ctx.fail("texture " + std::to_string(index) + " refers to missing image " +
                 std::to_string(source));
    if (auto it = ctx.imageToTexture.find(source); it != ctx.imageToTexture.end())
        return it->second;
    if (ctx.missingImages.count(source)) return -1; // the material's factor alone
    const tinygltf::Image& img = m.images[size_t(source)];
    Texture tex;
    tex.name = !img.name.empty() ? img.name : img.uri;
    int result = -1;
    if (toRgba8(img, tex)) {
        result = int(ctx.scene.textures.size());
        ctx.scene.textures.push_back(std::move(tex));
    } else {
        ctx.warn("image " + std::to_string(source) + " (" + tex.name +
                 ") could not be loaded; drawn without it");
    }
    ctx.imageToTexture[source] = result;
    return result;
}

float number(const tinygltf::Value* v, double fallback) {
    return float(v && v->IsNumber() ? v->GetNumberAsDouble() : fallback);
}

template <int N>
glm::vec<N, float> factor(Context& ctx, const std::vector<double>& v, const glm::vec<N, float>& def,
                          const std::string& what) {
    if (v.empty()) return def;
    if (v.size() != size_t(N)) ctx.fail(what + " must have " + std::to_string(N) + " numbers");
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) {
        out[i] = float(v[size_t(i)]);
        if (!std::isfinite(out[i]) || out[i] < 0.0f)
            ctx.fail(what + " has a negative or non-finite number");
    }
    return out;
}

} // namespace

void convertMaterials(Context& ctx) {
    const auto& src = ctx.model.materials;
    for (size_t i = 0; i < src.size(); ++i) {
        const tinygltf::Material& g = src[i];
        const std::string label = ctx.label("material", int(i), g.name);
        Material m;
        m.name = g.name.empty() ? "material" + std::to_string(i) : g.name;
        const auto& pbr = g.pbrMetallicRoughness;
        m.baseColor =
            factor<4>(ctx, pbr.baseColorFactor, glm::vec4(1.0f), label + " baseColorFactor");
        m.baseColor = glm::min(m.baseColor, glm::vec4(1.0f));
        m.baseColorTexture = textureFor(ctx, pbr.baseColorTexture.index, label);
        m.emissive = factor<3>(ctx, g.emissiveFactor, glm::vec3(0.0f), label + " emissiveFactor");
        if (auto it = g.extensions.find("KHR_materials_emissive_strength");
            it != g.extensions.end()) {
            const float strength = number(member(it->second, "emissiveStrength"), 1.0);
            if (!std::isfinite(strength) || strength < 0.0f)
                ctx.fail(label + " emissiveStrength must be a non-negative number");
            m.emissive *= strength;
            if (!std::isfinite(m.emissive.x + m.emissive.y + m.emissive.z)) // 1e30 x 1e30
                ctx.fail(label + " emissive x emissiveStrength is not a finite number");
        }
        m.emissiveTexture = textureFor(ctx, g.emissiveTexture.index, label);
        m.doubleSided = g.doubleSided;
        if (g.alphaMode == "MASK")
            m.alphaMode = AlphaMode::Mask;
        else if (g.alphaMode == "BLEND")
            m.alphaMode = AlphaMode::Blend;
        else if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty())
            ctx.warn(label + " has unknown alphaMode '" + g.alphaMode + "'; drawn opaque");
        m.alphaCutoff = float(g.alphaCutoff);
        if (!std::isfinite(m.alphaCutoff) || m.alphaCutoff < 0.0f)
            ctx.fail(label + " alphaCutoff must be a non-negative number");
        ctx.scene.materials.push_back(std::move(m));
    }
}

} // namespace pb::scene::gltf
