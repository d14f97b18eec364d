#include "platforms/OsMesaPlatform.h"
#include "platforms/DynamicLibrary.h"
#include "platforms/EsSemantics.h"
#include "platforms/GlEntryPoints.h"

// glad first: it stands in for <GL/gl.h>, which osmesa.h would otherwise pull in.
#include <glad/gl.h>
// (keep apart so include sorting cannot reorder them)
#include <GL/osmesa.h>

namespace pb::platform {
namespace {

constexpr int kBufferSize = 1; // pixels per side: nothing is drawn to the default framebuffer

struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs;
    decltype(&OSMesaMakeCurrent) makeCurrent;
    decltype(&OSMesaDestroyContext) destroyContext;
    decltype(&OSMesaGetCurrentContext) getCurrentContext;
    decltype(&OSMesaGetProcAddress) getProcAddress;
    std::string soname;
};

const OsMesaApi& osMesaApi() {
    static const OsMesaApi api = [] {
        // .so.8 is the current soname; older distributions ship .so.6.
        static const DynamicLibrary lib("osmesa", {"libOSMesa.so.8", "libOSMesa.so.6"});
        using Api = OsMesaApi;
        return Api{lib.require<decltype(Api::createContextAttribs)>("OSMesaCreateContextAttribs"),
                   lib.require<decltype(Api::makeCurrent)>("OSMesaMakeCurrent"),
                   lib.require<decltype(Api::destroyContext)>("OSMesaDestroyContext"),
                   lib.require<decltype(Api::getCurrentContext)>("OSMesaGetCurrentContext"),
                   lib.require<decltype(Api::getProcAddress)>("OSMesaGetProcAddress"),
                   lib.soname()};
    }();
    return api;
}

// Through OSMesaGetProcAddress, never through a linked libGL: with libGL loaded first, every
// gl* call under an OSMesa context would be a silent no-op (DESIGN.md).
GLADapiproc loadOsMesaGlFunction(const char* name) {
    return reinterpret_cast<GLADapiproc>(osMesaApi().getProcAddress(name));
}

} // namespace

OsMesaPlatform::OsMesaPlatform(const PlatformOptions& options) {
    if (options.device >= 0)
        throw PlatformError("osmesa: --device applies to the egl platform only");
    const OsMesaApi& api = osMesaApi();
    // OSMesa has no debug-context attribute; KHR_debug still reports once GL_DEBUG_OUTPUT is
    // enabled, which pb::gl::DebugOutput does.
    int major = 0, minor = 0;
    for (auto [maj, min] : {std::pair{4, 5}, std::pair{3, 3}}) {
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               0,
                               OSMESA_STENCIL_BITS,
                               0,
                               OSMESA_ACCUM_BITS,
                               0,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               maj,
                               OSMESA_CONTEXT_MINOR_VERSION,
                               min,
                               0};
        context_ = api.createContextAttribs(attribs, nullptr);
        if (context_) {
            major = maj;
            minor = min;
            break;
        }
    }
    if (!context_)
        throw PlatformError("osmesa: OSMesaCreateContextAttribs failed for core 4.5 and 3.3");

    auto ctx = static_cast<OSMesaContext>(context_);
    buffer_.assign(kBufferSize * kBufferSize * 4, 0);
    if (!api.makeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSize, kBufferSize)) {
        api.destroyContext(ctx);
        throw PlatformError("osmesa: OSMesaMakeCurrent failed");
    }
    if (!gladLoadGL(loadOsMesaGlFunction)) {
        api.makeCurrent(nullptr, nullptr, 0, 0, 0);
        api.destroyContext(ctx);
        throw PlatformError("osmesa: gladLoadGL found no GL entry points");
    }
    claimGlEntryPoints(this);
    enableEsSemantics();
    description_ = "OSMesa (" + api.soname + "), OpenGL core " + std::to_string(major) + "." +
                   std::to_string(minor) + " context, " + std::to_string(kBufferSize) + "x" +
                   std::to_string(kBufferSize) + " private buffer";
}

OsMesaPlatform::~OsMesaPlatform() {
    const OsMesaApi& api = osMesaApi();
    auto ctx = static_cast<OSMesaContext>(context_);
    if (api.getCurrentContext() == ctx) api.makeCurrent(nullptr, nullptr, 0, 0, 0);
    api.destroyContext(ctx);
    releaseGlEntryPoints(this);
}

void OsMesaPlatform::makeCurrent() {
    if (!osMesaApi().makeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(),
                                 GL_UNSIGNED_BYTE, kBufferSize, kBufferSize))
        throw PlatformError("osmesa: OSMesaMakeCurrent failed");
    if (ownsGlEntryPoints(this)) return;
    if (!gladLoadGL(loadOsMesaGlFunction))
        throw PlatformError("osmesa: gladLoadGL found no GL entry points");
    claimGlEntryPoints(this);
}

} // namespace pb::platform
