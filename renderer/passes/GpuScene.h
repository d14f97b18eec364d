#pragma once
// The scene's GPU resources: one vertex array per primitive, textures, and the list of draws.
// Built once per scene; passes only read it.
#include "gl/GlObject.h"
#include "gl/Texture.h"
#include "scene/Scene.h"

#include <vector>

namespace pb::render {

struct GpuPrimitive {
    gl::VertexArrayId vao;
    gl::BufferId vertices; // interleaved position(3) normal(3) uv(2), floats
    gl::BufferId indices;  // uint32
    GLsizei indexCount = 0;
};

class GpuScene {
public:
    explicit GpuScene(const scene::Scene& scene);

    const scene::Scene& scene() const { return *scene_; }
    const GpuPrimitive& primitive(int i) const { return primitives_[size_t(i)]; }
    // Textures by Scene::textures index; sRGB8_A8 with mipmaps.
    const gl::Texture& texture(int i) const { return textures_[size_t(i)]; }
    std::size_t gpuBytes() const { return bytes_; }

private:
    const scene::Scene* scene_;
    std::vector<GpuPrimitive> primitives_;
    std::vector<gl::Texture> textures_;
    std::size_t bytes_ = 0;
};

} // namespace pb::render
