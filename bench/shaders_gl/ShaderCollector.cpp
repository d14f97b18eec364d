#include "ShaderCollector.h"

#include "core/Error.h"
#include "frame/FrameRenderer.h"
#include "gl/Capabilities.h"
#include "gl/ProgramCache.h"
#include "passes/FrameTimer.h"
#include "passes/RenderView.h"

#include <map>

namespace pb::shaders {
namespace {

std::string firstLine(const std::string& text) {
    const size_t nl = text.find('\n');
    return nl == std::string::npos ? text : text.substr(0, nl) + " ...";
}

// Watches the program cache (which program is built) and the frame's sections (in which
// pass), and reads the driver's messages between a build's two calls.
class Recorder : public gl::ProgramBuildObserver, public render::FrameTimer {
public:
    Recorder(gl::DebugOutput& debug, TargetStatistics& out) : debug_(debug), out_(out) {}

    void startVariant(VariantStatistics* v) {
        variant_ = v;
        sections_.clear();
    }

    void begin(const char* section) override { sections_.push_back(section); }
    void end(const char*) override {
        if (!sections_.empty()) sections_.pop_back();
    }

    void beforeBuild(const std::string&, const std::string&, const gl::Defines&) override {
        debug_.discardNonErrors(); // keeps the debug output's cap per build, not per process
        mark_ = debug_.mark();
    }

    void afterBuild(const std::string& vertex, const std::string& fragment,
                    const gl::Defines& defines, bool built) override {
        ProgramStatistics p;
        p.pass = sections_.empty() ? "frame" : sections_.back();
        p.vertex = vertex;
        p.fragment = fragment;
        p.defines = gl::definesKey(defines);
        std::map<std::string, int> seen;
        for (const gl::DebugMessage& m : debug_.messagesSince(mark_)) {
            if (m.isError()) continue;
            std::optional<StageStatistics> s = parseStatisticsLine(m.text);
            if (!s) continue;
            // freedreno also compiles a binning variant of the vertex shader: "vertex-2".
            if (int n = ++seen[s->stage]; n > 1) s->stage += "-" + std::to_string(n);
            p.stages.push_back(std::move(*s));
        }
        if (!built) p.error = "the driver rejected it";
        const std::string key = p.key() + "|" + p.pass;
        int index = 0;
        if (auto it = index_.find(key); it != index_.end()) {
            index = it->second;
        } else {
            index = int(out_.programs.size());
            index_[key] = index;
            out_.programs.push_back(std::move(p));
        }
        if (variant_) variant_->programs.push_back(index);
    }

private:
    gl::DebugOutput& debug_;
    TargetStatistics& out_;
    VariantStatistics* variant_ = nullptr;
    std::vector<std::string> sections_;
    std::uint64_t mark_ = 0;
    std::map<std::string, int> index_;
};

} // namespace

TargetStatistics collectShaderStatistics(const CollectInputs& in,
                                         const std::vector<PlannedVariant>& variants,
                                         gl::DebugOutput& debug,
                                         const std::function<void(const std::string&)>& progress) {
    TargetStatistics out;
    const gl::GlCaps caps = gl::queryCaps();
    out.glVersion = caps.version;
    out.glRenderer = caps.renderer;
    out.glslVersion = caps.glslVersion;
    if (caps.software)
        throw Error("the context is " + caps.renderer +
                    ", a software renderer: the target's driver did not load");
    if (!debug.callbackInstalled())
        throw Error("the context has no KHR_debug callback: the driver's statistics cannot "
                    "be read");
    const render::RenderView view =
        render::makeRenderView(in.view, in.scene->worldBounds(), in.width, in.height);
    Recorder recorder(debug, out);
    out.variants.reserve(variants.size());
    for (const PlannedVariant& pv : variants) {
        out.variants.push_back(pv.meta);
        VariantStatistics& v = out.variants.back();
        v.programs.clear();
        if (progress) progress("variant " + v.id);
        recorder.startVariant(&v);
        const std::uint64_t mark = debug.mark();
        try {
            render::FrameRenderer renderer(*in.scene, render::defaultFrameSettings(*in.scene),
                                           {in.probes, 0, pv.switches});
            renderer.programs().setObserver(&recorder);
            renderer.render(view, &recorder);
            glFlush(); // not glFinish: some shims never signal a fence (lima)
            renderer.programs().setObserver(nullptr);
            if (renderer.giSkippedLastFrame())
                v.notRun = "the view sees no probe volume, so the GI passes built nothing";
        } catch (const Error& e) {
            v.notRun = firstLine(e.what());
        }
        recorder.startVariant(nullptr);
        if (const auto errors = debug.errorsSince(mark); v.notRun.empty() && !errors.empty())
            v.notRun = "GL error: " + firstLine(gl::DebugOutput::format(errors.front()));
    }
    return out;
}

} // namespace pb::shaders
