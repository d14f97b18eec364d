#include "scene/GltfMeshes.h"

#include "scene/GltfAccessor.h"
#include "scene/GltfTextureTransform.h"
#include "scene/MeshOps.h"

#include <cmath>

namespace pb::scene::gltf {

namespace {

constexpr auto kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
// Integer attribute types: normalised texture coordinates are core glTF; the rest are
// KHR_mesh_quantization, which costs nothing extra to accept.
constexpr auto kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr auto kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr auto kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr auto kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr auto kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

int findAttribute(const tinygltf::Primitive& p, const char* name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

// Converts one glTF primitive; false when it is skipped (counted in ctx, warned about later).
bool convertPrimitive(Context& ctx, int meshIndex, size_t primIndex, Primitive& out) {
    const tinygltf::Primitive& src = ctx.model.meshes[size_t(meshIndex)].primitives[primIndex];
    const std::string mesh = ctx.meshLabel(meshIndex);
    const int mode = src.mode < 0 ? TINYGLTF_MODE_TRIANGLES : src.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES) {
        ++ctx.skippedPrimitives["mode is not TRIANGLES"];
        ctx.skippedModes.insert(mode);
        return false;
    }
    const int position = findAttribute(src, "POSITION");
    if (position < 0) {
        ++ctx.skippedPrimitives["no POSITION"];
        return false;
    }

    const AccessorView positions =
        viewAccessor(ctx, position, "POSITION of " + mesh, TINYGLTF_TYPE_VEC3,
                     {kFloat, kByte, kUByte, kShort, kUShort});
    // Normals are read or generated for every vertex: charged with the positions.
    ctx.reserveGeometry(positions.count, 2 * sizeof(glm::vec3), "POSITION of " + mesh);
    readVec3(positions, out.positions);
    for (size_t i = 0; i < out.positions.size(); ++i) {
        const glm::vec3& p = out.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            ctx.fail("NaN or infinite position (vertex " + std::to_string(i) + ") in " + mesh);
    }
    const size_t vertexCount = out.positions.size();

    if (src.indices >= 0) {
        const AccessorView indices = viewAccessor(ctx, src.indices, "indices of " + mesh,
                                                  TINYGLTF_TYPE_SCALAR, {kUByte, kUShort, kUInt});
        ctx.reserveGeometry(indices.count, sizeof(std::uint32_t), "indices of " + mesh);
        readIndices(indices, out.indices);
        for (std::uint32_t index : out.indices)
            if (index >= vertexCount)
                ctx.fail("index " + std::to_string(index) + " out of range (" +
                         std::to_string(vertexCount) + " vertices) in " + mesh);
    } else {
        ctx.reserveGeometry(vertexCount, sizeof(std::uint32_t), "indices of " + mesh);
        out.indices.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i)
            out.indices[i] = std::uint32_t(i);
    }
    if (out.indices.size() % 3 != 0)
        ctx.fail(std::to_string(out.indices.size()) + " indices in " + mesh +
                 " are not a whole number of triangles");
    if (out.indices.empty()) {
        ++ctx.skippedPrimitives["no triangles"];
        return false;
    }

    const int normal = findAttribute(src, "NORMAL");
    bool haveNormals = false;
    if (normal >= 0) {
        const AccessorView normals = viewAccessor(ctx, normal, "NORMAL of " + mesh,
                                                  TINYGLTF_TYPE_VEC3, {kFloat, kByte, kShort});
        if (normals.count != vertexCount) // checked before anything is allocated for them
            ctx.fail("NORMAL of " + mesh + " has " + std::to_string(normals.count) +
                     " elements, POSITION " + std::to_string(vertexCount));
        readVec3(normals, out.normals);
        haveNormals = normalizeNormals(out.normals);
        if (!haveNormals) ++ctx.regeneratedNormals; // zero or NaN normals in the file
    }
    if (!haveNormals) generateSmoothNormals(out);

    const int uv = findAttribute(src, "TEXCOORD_0");
    if (uv >= 0) {
        const AccessorView uvs = viewAccessor(ctx, uv, "TEXCOORD_0 of " + mesh, TINYGLTF_TYPE_VEC2,
                                              {kFloat, kByte, kUByte, kShort, kUShort});
        if (uvs.count != vertexCount)
            ctx.fail("TEXCOORD_0 of " + mesh + " has " + std::to_string(uvs.count) +
                     " elements, POSITION " + std::to_string(vertexCount));
        ctx.reserveGeometry(uvs.count, sizeof(glm::vec2), "TEXCOORD_0 of " + mesh);
        readVec2(uvs, out.uvs);
        for (size_t i = 0; i < out.uvs.size(); ++i)
            if (!std::isfinite(out.uvs[i].x) || !std::isfinite(out.uvs[i].y))
                ctx.fail("NaN or infinite TEXCOORD_0 (vertex " + std::to_string(i) + ") in " +
                         mesh);
        if (const auto t = materialUvTransform(ctx, src.material))
            for (glm::vec2& p : out.uvs)
                p = glm::vec2(*t * glm::vec3(p, 1.0f));
    }

    if (src.material >= 0 && size_t(src.material) >= ctx.model.materials.size())
        ctx.fail(mesh + " refers to missing material " + std::to_string(src.material));
    // glTF materials are converted first and in order, so their indices carry over.
    out.material = src.material >= 0 ? src.material : defaultMaterial(ctx);
    out.localBounds = computeBounds(out.positions);
    return true;
}

} // namespace

int defaultMaterial(Context& ctx) {
    if (ctx.defaultMaterial < 0) {
        Material m;
        m.name = "default";
        // A file without any material says nothing about which side is the front, and some
        // have no consistent winding at all (sponza_decimated: no materials, winding unchecked
        // after decimation); culling back faces there would punch holes into it. The glTF
        // default material is single-sided, so that stays for files that have materials.
        m.doubleSided = ctx.model.materials.empty();
        ctx.defaultMaterial = int(ctx.scene.materials.size());
        ctx.scene.materials.push_back(m);
    }
    return ctx.defaultMaterial;
}

const std::vector<int>& meshPrimitives(Context& ctx, int mesh) {
    if (auto it = ctx.meshes.find(mesh); it != ctx.meshes.end()) return it->second;
    std::vector<int> prims;
    const tinygltf::Mesh& src = ctx.model.meshes[size_t(mesh)];
    for (size_t i = 0; i < src.primitives.size(); ++i) {
        Primitive p;
        if (!convertPrimitive(ctx, mesh, i, p)) continue;
        prims.push_back(int(ctx.scene.primitives.size()));
        ctx.scene.primitives.push_back(std::move(p));
    }
    return ctx.meshes.emplace(mesh, std::move(prims)).first->second;
}

} // namespace pb::scene::gltf
