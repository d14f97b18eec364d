#pragma once
// Move-only owners of GL object names. A raw GLuint never crosses a module boundary: code
// outside renderer/gl passes these objects (or references to them) around.
#include <glad/gl.h>
#include <utility>

namespace pb::gl {

template <void (*Delete)(GLuint)>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint id) : id_(id) {}
    ~GlObject() { reset(); }
    GlObject(GlObject&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    GlObject& operator=(GlObject&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace detail {
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void deleteProgram(GLuint id) { glDeleteProgram(id); }
inline void deleteShader(GLuint id) { glDeleteShader(id); }
inline void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
inline void deleteSampler(GLuint id) { glDeleteSamplers(1, &id); }
} // namespace detail

using TextureId = GlObject<detail::deleteTexture>;
using BufferId = GlObject<detail::deleteBuffer>;
using FramebufferId = GlObject<detail::deleteFramebuffer>;
using VertexArrayId = GlObject<detail::deleteVertexArray>;
using ProgramId = GlObject<detail::deleteProgram>;
using ShaderId = GlObject<detail::deleteShader>;
using QueryId = GlObject<detail::deleteQuery>;
using SamplerId = GlObject<detail::deleteSampler>;

TextureId genTexture();
BufferId genBuffer();
FramebufferId genFramebuffer();
VertexArrayId genVertexArray();
QueryId genQuery();

} // namespace pb::gl
