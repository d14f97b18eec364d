#pragma once
// A framebuffer over textures it does not own; checks completeness on creation.
#include "gl/GlObject.h"
#include "gl/Texture.h"

#include <string>
#include <vector>

namespace pb::gl {

class Framebuffer {
public:
    Framebuffer() = default;
    // colour[i] goes to GL_COLOR_ATTACHMENTi; depth may be null. Throws pb::Error when the
    // driver reports the combination incomplete (naming `label` and the status).
    Framebuffer(const std::string& label, const std::vector<const Texture*>& colour,
                const Texture* depth);
    void bind() const;
    int width() const { return width_; }
    int height() const { return height_; }
    GLuint id() const { return id_.id(); }

private:
    FramebufferId id_;
    int width_ = 0, height_ = 0;
};

} // namespace pb::gl
