#include "RenderPath.h"

#include "PathReport.h"
#include "camera/CameraPath.h"
#include "camera/DisocclusionMask.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "frame/DepthReadback.h"
#include "frame/Readback.h"
#include "passes/GiApplyPass.h"
#include "passes/GiUpsamplePass.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace fs = std::filesystem;

namespace pb::bench {

namespace {

camera::CameraPath resolvePath(const PathRenderRequest& r) {
    if (camera::isBuiltinPath(r.path)) return camera::makeBuiltinPath(r.path, *r.scene, r.start);
    if (fs::is_regular_file(r.path)) return camera::readCameraPathFile(r.path);
    std::string list;
    for (const auto& n : camera::builtinPathNames())
        list += (list.empty() ? "" : ", ") + n;
    throw Error("--path '" + r.path + "': not a built-in path (" + list + ") and no such file");
}

// Everything goes to a staging folder first and is moved into the output folder only when the
// whole run succeeded: a failure leaves no partial set of frames behind.
class Staging {
public:
    explicit Staging(const std::string& outDir) : out_(outDir) {
        std::error_code ec;
        fs::create_directories(out_, ec);
        if (!fs::is_directory(out_)) throw fileError(outDir, "cannot create the folder");
        dir_ = out_ / ".probebench-partial";
        fs::remove_all(dir_, ec);
        fs::create_directories(dir_, ec);
        if (ec) throw fileError(dir_.string(), "cannot create: " + ec.message());
    }
    ~Staging() {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void commit() {
        for (const auto& entry : fs::directory_iterator(dir_))
            fs::rename(entry.path(), out_ / entry.path().filename());
    }

private:
    fs::path out_, dir_;
};

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomic(path, text.data(), text.size());
}

// The full-resolution GI the lighting read: the upsample pass's output, or the apply pass's
// target at full resolution.
image::ImageF fullResolutionGi(const render::FrameRenderer& r) {
    if (const render::GiUpsamplePass* up = r.giUpsample()) return render::readFloat(*up->output());
    for (const auto& p : r.passes())
        if (auto* apply = dynamic_cast<const render::GiApplyPass*>(p.get()))
            return render::readFloat(*apply->target());
    throw Error("--compare-to full: the frame has no GI target");
}

void checkGl(gl::DebugOutput* debug, std::uint64_t mark) {
    if (!debug) return;
    if (auto errors = debug->errorsSince(mark); !errors.empty())
        throw Error("the GL reported " + std::to_string(errors.size()) +
                    " error(s) while rendering the path; nothing written:\n" +
                    gl::DebugOutput::format(errors));
}

} // namespace

int renderPath(const PathRenderRequest& r) {
    if (r.compareTo != "" && r.compareTo != "full")
        throw Error("--compare-to '" + r.compareTo + "': only 'full' is supported");
    if (r.compareTo == "full" && !r.gi.probes)
        throw Error("--compare-to full: needs --probes FILE (there is no GI to compare)");
    if (r.frames < 0) throw Error("--frames must be >= 0 (0 = the whole path)");
    const camera::CameraPath path = resolvePath(r);
    const int frames = r.frames > 0 ? r.frames : path.naturalFrameCount();
    const std::vector<camera::PathFrame> plan = camera::playPath(path, frames);
    const std::uint64_t mark = r.debug ? r.debug->mark() : 0;

    render::FrameRenderer renderer(*r.scene, r.settings, r.gi);
    std::unique_ptr<render::FrameRenderer> reference;
    if (r.compareTo == "full") {
        render::GiOptions full = r.gi;
        full.profile.set("gi.resolution", "full");
        reference = std::make_unique<render::FrameRenderer>(*r.scene, r.settings, full);
    }
    Staging staging(r.outDir);
    std::vector<PathFrameError> errors;
    image::ImageF prevDepth;
    camera::CameraState prevCamera;
    const scene::Bounds bounds = r.scene->worldBounds();
    std::cout << "path '" << path.name << "': " << frames << " frames at " << path.fps << " fps, "
              << r.width << "x" << r.height << "\n";
    for (const camera::PathFrame& f : plan) {
        const render::RenderView view = render::makeRenderView(f.view, bounds, r.width, r.height);
        if (f.cut) renderer.resetGiHistory();
        renderer.render(view);
        const image::Image8 image = renderer.readOutput();
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", f.index);
        image::writePng(staging.path(name), image);
        const render::GiUpsamplePass* up = renderer.giUpsample();
        std::fprintf(stderr, "frame %d/%d%s", f.index + 1, frames, f.cut ? " (cut)" : "");
        if (reference) {
            reference->render(view);
            const camera::CameraState cam = render::cameraState(view);
            image::ImageF depth =
                render::readDepthDistance(*renderer.targets(), view, renderer.programs());
            std::vector<camera::PixelHistory> mask;
            if (!f.cut) mask = camera::disocclusionMask(prevCamera, prevDepth, cam, depth);
            PathFrameError e =
                measurePathFrame(image, reference->readOutput(), fullResolutionGi(renderer),
                                 fullResolutionGi(*reference), mask);
            e.frame = f.index;
            e.time = f.time;
            e.cut = f.cut;
            e.historyUsed = up && up->historyUsed();
            errors.push_back(e);
            prevDepth = std::move(depth);
            prevCamera = cam;
            std::fprintf(stderr, ": PSNR %.2f dB, FLIP %.4f, GI rel. MAE %.4f", e.psnr, e.flipMean,
                         e.giRelMae);
        }
        std::fprintf(stderr, "\n");
        checkGl(r.debug, mark);
    }
    if (reference) {
        nlohmann::json about = {{"path", path.name},     {"fps", path.fps},
                                {"frame_count", frames}, {"width", r.width},
                                {"height", r.height},    {"scene", r.scene->name},
                                {"compare_to", "full"},  {"profile", r.gi.profile.valuesJson()}};
        writeText(staging.path("errors.csv"), pathErrorsCsv(errors));
        writeText(staging.path("errors.json"), pathErrorsJson(errors, about).dump(2) + "\n");
    }
    staging.commit();
    std::cout << "wrote " << frames << " frames to " << r.outDir << "/frame_NNNN.png"
              << (reference ? " and errors.csv, errors.json" : "") << "\n";
    if (reference) std::cout << pathSummaryText(errors);
    return 0;
}

} // namespace pb::bench
