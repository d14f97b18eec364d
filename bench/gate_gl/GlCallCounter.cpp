#include "GlCallCounter.h"

#include "core/Error.h"

#include <glad/gl.h>

namespace pb::gate {

namespace {

GlCallCounter* active = nullptr;

// Every counted entry point, once: X(loader pointer, shim and saved-pointer name, type). The
// saved pointers, installing and uninstalling all come from this list, so they cannot drift.
#define PB_COUNTED_GL_CALLS(X)                                                                     \
    X(glad_glDrawArrays, drawArrays, PFNGLDRAWARRAYSPROC)                                          \
    X(glad_glDrawElements, drawElements, PFNGLDRAWELEMENTSPROC)                                    \
    X(glad_glDrawArraysInstanced, drawArraysInstanced, PFNGLDRAWARRAYSINSTANCEDPROC)               \
    X(glad_glDrawElementsInstanced, drawElementsInstanced, PFNGLDRAWELEMENTSINSTANCEDPROC)         \
    X(glad_glDrawRangeElements, drawRangeElements, PFNGLDRAWRANGEELEMENTSPROC)                     \
    X(glad_glUseProgram, useProgram, PFNGLUSEPROGRAMPROC)                                          \
    X(glad_glBindTexture, bindTexture, PFNGLBINDTEXTUREPROC)                                       \
    X(glad_glClear, clear, PFNGLCLEARPROC)                                                         \
    X(glad_glClearBufferfv, clearBufferfv, PFNGLCLEARBUFFERFVPROC)                                 \
    X(glad_glClearBufferiv, clearBufferiv, PFNGLCLEARBUFFERIVPROC)                                 \
    X(glad_glClearBufferuiv, clearBufferuiv, PFNGLCLEARBUFFERUIVPROC)                              \
    X(glad_glClearBufferfi, clearBufferfi, PFNGLCLEARBUFFERFIPROC)                                 \
    X(glad_glBindFramebuffer, bindFramebuffer, PFNGLBINDFRAMEBUFFERPROC)

// The driver's entry points while the shims are installed.
struct Originals {
#define PB_SAVED_POINTER(loader, name, type) type name;
    PB_COUNTED_GL_CALLS(PB_SAVED_POINTER)
#undef PB_SAVED_POINTER
} orig;

void GLAD_API_PTR drawArrays(GLenum m, GLint f, GLsizei n) {
    ++active->current().draws;
    orig.drawArrays(m, f, n);
}
void GLAD_API_PTR drawElements(GLenum m, GLsizei n, GLenum t, const void* i) {
    ++active->current().draws;
    orig.drawElements(m, n, t, i);
}
void GLAD_API_PTR drawArraysInstanced(GLenum m, GLint f, GLsizei n, GLsizei k) {
    ++active->current().draws;
    orig.drawArraysInstanced(m, f, n, k);
}
void GLAD_API_PTR drawElementsInstanced(GLenum m, GLsizei n, GLenum t, const void* i, GLsizei k) {
    ++active->current().draws;
    orig.drawElementsInstanced(m, n, t, i, k);
}
void GLAD_API_PTR drawRangeElements(GLenum m, GLuint s, GLuint e, GLsizei n, GLenum t,
                                    const void* i) {
    ++active->current().draws;
    orig.drawRangeElements(m, s, e, n, t, i);
}
void GLAD_API_PTR useProgram(GLuint p) {
    if (p) ++active->current().programs;
    orig.useProgram(p);
}
void GLAD_API_PTR bindTexture(GLenum target, GLuint t) {
    ++(t ? active->current().texBinds : active->current().texUnbinds);
    orig.bindTexture(target, t);
}
void GLAD_API_PTR clear(GLbitfield mask) {
    ++active->current().clears;
    orig.clear(mask);
}
void GLAD_API_PTR clearBufferfv(GLenum b, GLint d, const GLfloat* v) {
    ++active->current().clears;
    orig.clearBufferfv(b, d, v);
}
void GLAD_API_PTR clearBufferiv(GLenum b, GLint d, const GLint* v) {
    ++active->current().clears;
    orig.clearBufferiv(b, d, v);
}
void GLAD_API_PTR clearBufferuiv(GLenum b, GLint d, const GLuint* v) {
    ++active->current().clears;
    orig.clearBufferuiv(b, d, v);
}
void GLAD_API_PTR clearBufferfi(GLenum b, GLint d, GLfloat depth, GLint stencil) {
    ++active->current().clears;
    orig.clearBufferfi(b, d, depth, stencil);
}
void GLAD_API_PTR bindFramebuffer(GLenum target, GLuint fbo) {
    ++active->current().fboBinds;
    orig.bindFramebuffer(target, fbo);
}

// Swaps each loader pointer with its shim (install) or back (uninstall); a pointer the
// context never loaded stays null.
template <class F> void swapIn(F& loader, F& saved, F shim) {
    saved = loader;
    if (loader) loader = shim;
}
template <class F> void swapOut(F& loader, F saved) {
    if (saved) loader = saved;
}

} // namespace

GlCallCounter::GlCallCounter() {
    if (active) throw Error("GL call counter: another counter is installed");
    active = this;
    sections_.push_back({"frame", {}});
#define PB_SWAP_IN(loader, name, type) swapIn(loader, orig.name, &name);
    PB_COUNTED_GL_CALLS(PB_SWAP_IN)
#undef PB_SWAP_IN
}

GlCallCounter::~GlCallCounter() {
#define PB_SWAP_OUT(loader, name, type) swapOut(loader, orig.name);
    PB_COUNTED_GL_CALLS(PB_SWAP_OUT)
#undef PB_SWAP_OUT
    active = nullptr;
}

GlCallCounts& GlCallCounter::current() {
    return sections_[open_.empty() ? 0 : open_.back()].second;
}

void GlCallCounter::begin(const char* section) {
    size_t i = 0;
    while (i < sections_.size() && sections_[i].first != section)
        ++i;
    if (i == sections_.size()) sections_.push_back({section, {}});
    open_.push_back(i);
}

void GlCallCounter::end(const char*) {
    if (!open_.empty()) open_.pop_back();
}

} // namespace pb::gate

#undef PB_COUNTED_GL_CALLS // this file's own (a unity build would carry it on)
