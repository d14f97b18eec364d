#pragma once
// Camera paths for `probebench render --path`: keyframes in time, played at a fixed frame
// rate, with cuts. Built-in paths are made from a scene's view; files are TOML (format in
// renderer/camera/README.md and readCameraPathFile). GL-free.
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pb::camera {

struct CameraKey {
    double time = 0;        // seconds, strictly increasing along the path
    glm::dvec3 position{0}; // world
    glm::dvec3 target{0, 0, -1};
    float fovYDegrees = 60.0f;
    bool cut = false; // jump to this key at its time (no blend from the previous one)
};

struct CameraPath {
    std::string name;
    double fps = 30.0;
    std::vector<CameraKey> keys; // never empty once built or read
    // Frames from time 0 to the last key inclusive at `fps`.
    int naturalFrameCount() const;
};

struct PathFrame {
    int index = 0;
    double time = 0;
    scene::View view; // named "<path> #<index>"
    bool cut = false; // frame 0, or the first frame at or after a cut key's time
};

// The camera at each of `frames` frames (time = index / fps). Between keys the position and the
// field of view are interpolated linearly and the view direction turns at a constant rate; a
// cut key is jumped to at its time; after the last key the camera holds still.
std::vector<PathFrame> playPath(const CameraPath& path, int frames);

// static, slow_pan, fast_turn, doorway_walk.
const std::vector<std::string>& builtinPathNames();
bool isBuiltinPath(const std::string& name);

// A built-in path starting at `start` (a view of `scene`):
//   static        `start` held for 2 s
//   slow_pan      turning left about the vertical axis at 10 deg/s for 4 s
//   fast_turn     turning left at 180 deg/s for 1 s (6 deg a frame), then 1 s still
//   doorway_walk  the rooms scene only (`start` is ignored): from the dark room through the
//                 doorway into the sunlit room at 1.5 m/s, eyes on a point beyond it, 4 s
// Throws pb::Error for an unknown name or doorway_walk on another scene.
CameraPath makeBuiltinPath(const std::string& name, const scene::Scene& scene,
                           const scene::View& start);

// Reads a TOML path file; throws pb::Error "FILE:LINE: problem" on any mistake.
CameraPath readCameraPathFile(const std::string& path);
CameraPath parseCameraPathToml(const std::string& text, const std::string& path);

} // namespace pb::camera
