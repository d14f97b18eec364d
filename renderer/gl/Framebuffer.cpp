#include "gl/Framebuffer.h"

#include "core/Error.h"
#include "gl/DebugLabels.h"

#include <cstdio>

namespace pb::gl {

Framebuffer::Framebuffer(const std::string& label, const std::vector<const Texture*>& colour,
                         const Texture* depth)
    : id_(genFramebuffer()) {
    glBindFramebuffer(GL_FRAMEBUFFER, id_.id());
    std::vector<GLenum> drawBuffers;
    for (size_t i = 0; i < colour.size(); ++i) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D,
                               colour[i]->id(), 0);
        drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        width_ = colour[i]->desc().width;
        height_ = colour[i]->desc().height;
    }
    if (depth) {
        GLenum attach = formatInfo(depth->desc().format).hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT
                                                                    : GL_DEPTH_ATTACHMENT;
        glFramebufferTexture2D(GL_FRAMEBUFFER, attach, GL_TEXTURE_2D, depth->id(), 0);
        width_ = depth->desc().width;
        height_ = depth->desc().height;
    }
    if (drawBuffers.empty()) {
        GLenum none = GL_NONE;
        glDrawBuffers(1, &none);
        glReadBuffer(GL_NONE);
    } else {
        glDrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
    }
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    labelObject(GL_FRAMEBUFFER, id_.id(), label);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "0x%04X", status);
        throw Error("framebuffer '" + label + "' is incomplete on this driver (status " + buf +
                    ")");
    }
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id_.id());
    glViewport(0, 0, width_, height_);
}

} // namespace pb::gl
