#include "scene/GltfTextureTransform.h"

#include <cmath>

namespace pb::scene::gltf {

namespace {

// The transform of one textureInfo's extensions; nothing without KHR_texture_transform.
std::optional<glm::mat3> transformOf(Context& ctx, const tinygltf::ExtensionMap& extensions,
                                     const std::string& what) {
    auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end() || !it->second.IsObject()) return std::nullopt;
    const tinygltf::Value& ext = it->second;
    auto vec2 = [&](const char* key, glm::vec2 fallback) {
        const tinygltf::Value* v = member(ext, key);
        if (!v) return fallback;
        if (!v->IsArray() || v->ArrayLen() != 2 || !v->Get(0).IsNumber() || !v->Get(1).IsNumber())
            ctx.fail(what + ": KHR_texture_transform " + key + " must be two numbers");
        return glm::vec2(float(v->Get(0).GetNumberAsDouble()), float(v->Get(1).GetNumberAsDouble()));
    };
    const glm::vec2 offset = vec2("offset", glm::vec2(0.0f));
    const glm::vec2 scale = vec2("scale", glm::vec2(1.0f));
    const tinygltf::Value* r = member(ext, "rotation");
    const float rotation = r && r->IsNumber() ? float(r->GetNumberAsDouble()) : 0.0f;
    if (!std::isfinite(offset.x + offset.y + scale.x + scale.y + rotation))
        ctx.fail(what + ": KHR_texture_transform has a non-finite number");
    if (const tinygltf::Value* t = member(ext, "texCoord"); t && t->IsInt() && t->GetNumberAsInt() != 0)
        ctx.warn(what + ": KHR_texture_transform texCoord " + std::to_string(t->GetNumberAsInt()) +
                 " ignored (probebench reads TEXCOORD_0 only)");
    const float c = std::cos(rotation), s = std::sin(rotation);
    // Column-major: u' = c*sx*u + s*sy*v + ox, v' = -s*sx*u + c*sy*v + oy: the extension's
    // translation * rotation * scale with its rotation matrix read row by row, the direction
    // three.js's loader rotates (read column by column the README's GLSL literal would turn
    // the other way).
    return glm::mat3(glm::vec3(c * scale.x, -s * scale.x, 0.0f),
                     glm::vec3(s * scale.y, c * scale.y, 0.0f), glm::vec3(offset, 1.0f));
}

} // namespace

std::optional<glm::mat3> materialUvTransform(Context& ctx, int material) {
    if (material < 0 || std::size_t(material) >= ctx.model.materials.size()) return std::nullopt;
    const tinygltf::Material& m = ctx.model.materials[std::size_t(material)];
    const std::string label = ctx.label("material", material, m.name);
    const auto base = transformOf(ctx, m.pbrMetallicRoughness.baseColorTexture.extensions,
                                  label + " baseColorTexture");
    const auto emissive = transformOf(ctx, m.emissiveTexture.extensions, label + " emissiveTexture");
    if (m.pbrMetallicRoughness.baseColorTexture.index < 0) return emissive;
    if (m.emissiveTexture.index >= 0 && emissive.value_or(glm::mat3(1.0f)) != base.value_or(glm::mat3(1.0f)) &&
        ctx.uvTransformWarned.insert(material).second)
        ctx.warn(label + ": emissiveTexture's KHR_texture_transform differs from the base "
                         "colour's; both use the base colour's");
    return base;
}

} // namespace pb::scene::gltf
