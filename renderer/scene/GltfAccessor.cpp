#include "scene/GltfAccessor.h"

#include <cstring>

namespace pb::scene::gltf {

namespace {

std::string typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    default:
        return "type " + std::to_string(type);
    }
}

// a + b <= limit without overflow.
bool fits(std::size_t a, std::size_t b, std::size_t limit) {
    return a <= limit && b <= limit - a;
}

float componentAsFloat(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float v = float(std::int8_t(*p));
        return normalized ? glm::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? *p / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t s;
        std::memcpy(&s, p, 2);
        return normalized ? glm::max(s / 32767.0f, -1.0f) : float(s);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t s;
        std::memcpy(&s, p, 2);
        return normalized ? s / 65535.0f : float(s);
    }
    default: { // UNSIGNED_INT (not valid for attributes, read anyway)
        std::uint32_t u;
        std::memcpy(&u, p, 4);
        return float(u);
    }
    }
}

template <int N> void readVectors(const AccessorView& v, std::vector<glm::vec<N, float>>& out) {
    out.assign(v.count, glm::vec<N, float>(0.0f));
    if (!v.data) return;
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) { // the common case, kept tight
        for (std::size_t i = 0; i < v.count; ++i)
            std::memcpy(&out[i], v.data + i * v.stride, sizeof(float) * N);
        return;
    }
    const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(v.componentType));
    for (std::size_t i = 0; i < v.count; ++i)
        for (int c = 0; c < N; ++c)
            out[i][c] = componentAsFloat(v.data + i * v.stride + size_t(c * size), v.componentType,
                                         v.normalized);
}

} // namespace

AccessorView viewAccessor(const Context& ctx, int index, const std::string& what, int type,
                          std::initializer_list<int> componentTypes) {
    const tinygltf::Model& m = ctx.model;
    const std::string name = "accessor " + std::to_string(index) + " (" + what + ")";
    if (index < 0 || size_t(index) >= m.accessors.size())
        ctx.fail(what + " refers to missing accessor " + std::to_string(index));
    const tinygltf::Accessor& a = m.accessors[size_t(index)];
    if (a.sparse.isSparse) ctx.fail(name + ": sparse accessors are not supported");
    if (a.type != type)
        ctx.fail(name + ": type is " + typeName(a.type) + ", expected " + typeName(type));
    bool known = false;
    for (int ct : componentTypes)
        known = known || ct == a.componentType;
    if (!known) ctx.fail(name + ": unsupported componentType " + std::to_string(a.componentType));
    if (a.count > kMaxElements) ctx.fail(name + ": absurd count " + std::to_string(a.count));

    AccessorView v;
    v.count = a.count;
    v.componentType = a.componentType;
    v.components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
    v.normalized = a.normalized;
    const std::size_t elementSize =
        size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType))) *
        size_t(v.components);
    v.stride = elementSize;
    if (a.bufferView < 0) return v; // the spec's all-zero accessor
    if (size_t(a.bufferView) >= m.bufferViews.size())
        ctx.fail(name + ": missing bufferView " + std::to_string(a.bufferView));
    const tinygltf::BufferView& bv = m.bufferViews[size_t(a.bufferView)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size())
        ctx.fail(name + ": bufferView " + std::to_string(a.bufferView) +
                 " refers to missing buffer " + std::to_string(bv.buffer));
    const std::vector<unsigned char>& buffer = m.buffers[size_t(bv.buffer)].data;
    if (!fits(bv.byteOffset, bv.byteLength, buffer.size()))
        ctx.fail("bufferView " + std::to_string(a.bufferView) + " (bytes " +
                 std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                 ") reaches past the end of buffer " + std::to_string(bv.buffer) + " (" +
                 std::to_string(buffer.size()) + " bytes)");
    if (bv.byteStride != 0) {
        if (bv.byteStride > 252) // the spec's limit; it also keeps the product below in range
            ctx.fail(name + ": byteStride " + std::to_string(bv.byteStride) + " is above 252");
        if (bv.byteStride < elementSize)
            ctx.fail(name + ": byteStride " + std::to_string(bv.byteStride) +
                     " is smaller than one element (" + std::to_string(elementSize) + " bytes)");
        v.stride = bv.byteStride;
    }
    // The last element ends at byteOffset + (count - 1) * stride + elementSize; count and
    // stride are bounded above, so the product cannot overflow.
    const std::size_t span = a.count == 0 ? 0 : (a.count - 1) * v.stride + elementSize;
    if (!fits(a.byteOffset, span, bv.byteLength))
        ctx.fail(name + ": " + std::to_string(a.count) + " elements from byte " +
                 std::to_string(a.byteOffset) + " reach past the end of bufferView " +
                 std::to_string(a.bufferView) + " (" + std::to_string(bv.byteLength) + " bytes)");
    v.data = buffer.data() + bv.byteOffset + a.byteOffset;
    return v;
}

void readVec2(const AccessorView& view, std::vector<glm::vec2>& out) {
    readVectors<2>(view, out);
}

void readVec3(const AccessorView& view, std::vector<glm::vec3>& out) {
    readVectors<3>(view, out);
}

void readIndices(const AccessorView& v, std::vector<std::uint32_t>& out) {
    out.resize(v.count);
    if (!v.data) {
        std::fill(out.begin(), out.end(), 0u);
        return;
    }
    const std::uint8_t* p = v.data;
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        for (std::size_t i = 0; i < v.count; ++i)
            out[i] = p[i * v.stride];
        break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        for (std::size_t i = 0; i < v.count; ++i) {
            std::uint16_t s;
            std::memcpy(&s, p + i * v.stride, 2);
            out[i] = s;
        }
        break;
    default:
        for (std::size_t i = 0; i < v.count; ++i)
            std::memcpy(&out[i], p + i * v.stride, 4);
        break;
    }
}

} // namespace pb::scene::gltf
