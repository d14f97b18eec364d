#pragma once
// Validated reads of glTF accessors: tinygltf parses the JSON but checks neither that an
// accessor lies inside its bufferView and buffer nor that its type fits its use.
#include "scene/GltfContext.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace pb::scene::gltf {

// Where the elements of one accessor lie, every byte checked to be inside its buffer.
struct AccessorView {
    const std::uint8_t* data = nullptr; // nullptr: no bufferView, all elements are zero
    std::size_t count = 0;
    std::size_t stride = 0; // bytes from one element to the next
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

// `what` names the accessor's use in errors ("POSITION of mesh 'x'"). `type` is the
// required TINYGLTF_TYPE_*; `componentTypes` the accepted TINYGLTF_COMPONENT_TYPE_*.
AccessorView viewAccessor(const Context& ctx, int accessor, const std::string& what, int type,
                          std::initializer_list<int> componentTypes);

// Vectors as floats, normalised integers converted as the glTF spec says.
void readVec2(const AccessorView& view, std::vector<glm::vec2>& out);
void readVec3(const AccessorView& view, std::vector<glm::vec3>& out);
void readIndices(const AccessorView& view, std::vector<std::uint32_t>& out);

} // namespace pb::scene::gltf
