#pragma once
// `probebench render --path NAME|FILE --frames N --out-dir DIR [--compare-to full]`: plays a
// camera path (renderer/camera/CameraPath.h) and writes numbered PNG frames; with
// --compare-to full it also renders every frame with full-resolution GI (same everything else)
// and writes the per-frame error (PathReport.h) as errors.csv and errors.json.
#include "frame/FrameRenderer.h"
#include "gl/DebugOutput.h"
#include "profile/Profile.h"
#include "scene/Scene.h"

#include <string>

namespace pb::bench {

struct PathRenderRequest {
    const scene::Scene* scene = nullptr;
    scene::View start;    // where the built-in paths start (--view / --camera)
    render::GiOptions gi; // probes may be null (no GI)
    render::FrameSettings settings;
    std::string path; // built-in name or TOML file
    std::string outDir;
    std::string compareTo; // "" or "full"
    int frames = 0;        // 0 = the whole path
    int width = 1280, height = 720;
    gl::DebugOutput* debug = nullptr; // every GL error fails the run
};

// Throws pb::Error on bad options or a GL error; nothing is left in outDir then.
int renderPath(const PathRenderRequest& request);

} // namespace pb::bench
