#include "passes/GpuScene.h"

namespace pb::render {

GpuScene::GpuScene(const scene::Scene& scene) : scene_(&scene) {
    primitives_.reserve(scene.primitives.size());
    std::vector<float> interleaved;
    for (const scene::Primitive& p : scene.primitives) {
        GpuPrimitive g;
        size_t n = p.positions.size();
        interleaved.assign(n * 8, 0.0f);
        for (size_t v = 0; v < n; ++v) {
            float* d = &interleaved[v * 8];
            d[0] = p.positions[v].x, d[1] = p.positions[v].y, d[2] = p.positions[v].z;
            if (v < p.normals.size())
                d[3] = p.normals[v].x, d[4] = p.normals[v].y, d[5] = p.normals[v].z;
            if (v < p.uvs.size()) d[6] = p.uvs[v].x, d[7] = p.uvs[v].y;
        }
        g.vao = gl::genVertexArray();
        g.vertices = gl::genBuffer();
        g.indices = gl::genBuffer();
        g.indexCount = GLsizei(p.indices.size());
        glBindVertexArray(g.vao.id());
        glBindBuffer(GL_ARRAY_BUFFER, g.vertices.id());
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                     interleaved.data(), GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices.id());
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(p.indices.size() * sizeof(uint32_t)),
                     p.indices.data(), GL_STATIC_DRAW);
        const GLsizei stride = 8 * sizeof(float);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (void*)(3 * sizeof(float)));
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, (void*)(6 * sizeof(float)));
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        bytes_ += interleaved.size() * sizeof(float) + p.indices.size() * sizeof(uint32_t);
        primitives_.push_back(std::move(g));
    }
    for (const scene::Texture& t : scene.textures) {
        gl::TextureDesc d;
        d.format = gl::TextureFormat::SRGB8_A8;
        d.width = std::max(1, t.width);
        d.height = std::max(1, t.height);
        d.levels = 0;
        d.filter = gl::Filter::LinearMipmap;
        d.wrap = gl::Wrap::Repeat;
        gl::Texture tex(d);
        if (t.rgba8.size() >= size_t(d.width) * d.height * 4) {
            tex.upload(t.rgba8.data());
            tex.generateMipmaps();
        }
        bytes_ += tex.bytes();
        textures_.push_back(std::move(tex));
    }
}

} // namespace pb::render
