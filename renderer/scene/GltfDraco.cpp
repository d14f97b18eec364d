// KHR_draco_mesh_compression: each compressed primitive is decoded with libdraco into a new
// buffer (floats and uint32 indices), and the primitive is pointed at new accessors there.
#include "scene/GltfContext.h"
#include "scene/GltfDecompress.h"

#include <cstring>
#include <draco/compression/decode.h>

namespace pb::scene::gltf {

namespace {

// Appends `bytes` as a new bufferView of `buffer` and an accessor over it; returns the
// accessor's index.
int appendAccessor(tinygltf::Model& model, int buffer, const std::vector<unsigned char>& bytes,
                   std::size_t count, int type, int componentType) {
    tinygltf::Buffer& b = model.buffers[std::size_t(buffer)];
    tinygltf::BufferView bv;
    bv.buffer = buffer;
    bv.byteOffset = b.data.size();
    bv.byteLength = bytes.size();
    b.data.insert(b.data.end(), bytes.begin(), bytes.end());
    model.bufferViews.push_back(bv);
    tinygltf::Accessor a;
    a.bufferView = int(model.bufferViews.size() - 1);
    a.count = count;
    a.type = type;
    a.componentType = componentType;
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
}

std::unique_ptr<draco::Mesh> decodeMesh(const std::string& path, const std::string& what,
                                        const tinygltf::Model& model, int viewIndex) {
    if (viewIndex < 0 || std::size_t(viewIndex) >= model.bufferViews.size())
        throw fileError(path, what + ": KHR_draco_mesh_compression names missing bufferView " +
                                  std::to_string(viewIndex));
    const tinygltf::BufferView& bv = model.bufferViews[std::size_t(viewIndex)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size())
        throw fileError(path, what + ": bufferView " + std::to_string(viewIndex) +
                                  " names a missing buffer");
    const std::vector<unsigned char>& data = model.buffers[std::size_t(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        throw fileError(path, what + ": bufferView " + std::to_string(viewIndex) +
                                  " reaches past the end of its buffer");
    draco::DecoderBuffer in;
    in.Init(reinterpret_cast<const char*>(data.data() + bv.byteOffset), bv.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&in);
    if (!result.ok())
        throw fileError(path, what + ": KHR_draco_mesh_compression data is corrupt (" +
                                  printable(result.status().error_msg_string()) + ")");
    std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
    if (!mesh || mesh->num_points() > kMaxElements || mesh->num_faces() > kMaxElements / 3)
        throw fileError(path, what + ": KHR_draco_mesh_compression mesh is absurdly large");
    return mesh;
}

void decodePrimitive(const std::string& path, const std::string& what,
                     const tinygltf::Value& ext, tinygltf::Primitive& prim,
                     tinygltf::Model& model, std::size_t& totalBytes) {
    const tinygltf::Value* view = member(ext, "bufferView");
    const tinygltf::Value* attributes = member(ext, "attributes");
    if (!view || !view->IsInt() || !attributes || !attributes->IsObject())
        throw fileError(path, what + ": KHR_draco_mesh_compression needs bufferView and attributes");
    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(path, what, model, view->GetNumberAsInt());
    const std::size_t points = mesh->num_points();

    auto charge = [&](std::size_t bytes) {
        if (bytes > kMaxGeometryBytes - totalBytes)
            throw fileError(path, what + ": decoded Draco meshes would exceed " +
                                      std::to_string(kMaxGeometryBytes >> 20) + " MiB");
        totalBytes += bytes;
    };
    model.buffers.emplace_back();
    const int buffer = int(model.buffers.size() - 1);

    for (const std::string& name : attributes->Keys()) {
        const tinygltf::Value& id = attributes->Get(name);
        auto accessorIt = prim.attributes.find(name);
        if (!id.IsInt() || accessorIt == prim.attributes.end()) continue; // nothing refers to it
        const int accessor = accessorIt->second;
        if (accessor < 0 || std::size_t(accessor) >= model.accessors.size())
            throw fileError(path, what + ": " + printable(name) + " refers to missing accessor " +
                                      std::to_string(accessor));
        const int type = model.accessors[std::size_t(accessor)].type;
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(type));
        const draco::PointAttribute* attr =
            id.GetNumberAsInt() < 0 ? nullptr
                                    : mesh->GetAttributeByUniqueId(std::uint32_t(id.GetNumberAsInt()));
        if (!attr || components < 1 || components > 4)
            throw fileError(path, what + ": Draco attribute " + printable(name) +
                                      " is missing from the compressed data");
        charge(points * std::size_t(components) * sizeof(float));
        std::vector<unsigned char> bytes(points * std::size_t(components) * sizeof(float));
        float value[4] = {0, 0, 0, 0};
        for (std::size_t i = 0; i < points; ++i) {
            const draco::AttributeValueIndex v = attr->mapped_index(draco::PointIndex(std::uint32_t(i)));
            if (!attr->ConvertValue<float>(v, std::int8_t(components), value))
                throw fileError(path, what + ": Draco attribute " + printable(name) +
                                          " cannot be read as floats");
            std::memcpy(bytes.data() + i * std::size_t(components) * sizeof(float), value,
                        std::size_t(components) * sizeof(float));
        }
        accessorIt->second = appendAccessor(model, buffer, bytes, points, type,
                                            TINYGLTF_COMPONENT_TYPE_FLOAT);
    }

    const std::size_t indexCount = std::size_t(mesh->num_faces()) * 3;
    charge(indexCount * sizeof(std::uint32_t));
    std::vector<unsigned char> indices(indexCount * sizeof(std::uint32_t));
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = mesh->face(f)[k].value();
            std::memcpy(indices.data() + (std::size_t(f.value()) * 3 + std::size_t(k)) * 4, &index, 4);
        }
    prim.indices = appendAccessor(model, buffer, indices, indexCount, TINYGLTF_TYPE_SCALAR,
                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

} // namespace

void decodeDraco(const std::string& path, tinygltf::Model& model) {
    std::size_t totalBytes = 0;
    for (std::size_t m = 0; m < model.meshes.size(); ++m)
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& prim = model.meshes[m].primitives[p];
            auto it = prim.extensions.find("KHR_draco_mesh_compression");
            if (it == prim.extensions.end()) continue;
            // Point clouds and lines are skipped with the other non-triangle primitives.
            if (prim.mode >= 0 && prim.mode != TINYGLTF_MODE_TRIANGLES) continue;
            const std::string what =
                "primitive " + std::to_string(p) + " of mesh " + std::to_string(m);
            decodePrimitive(path, what, it->second, prim, model, totalBytes);
        }
}

} // namespace pb::scene::gltf
