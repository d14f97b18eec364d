#include "scene/DefaultView.h"

namespace pb::scene {

namespace {
// Eye height as a fraction of the bounds' height: near the floor of an interior (where a
// person stands in a one-storey building), low over an exterior's ground.
constexpr float kEyeHeight = 0.3f;
// How far from the centre towards one end of the longest horizontal axis (0.5 = at the end).
// 0.35 keeps the eye 15% of the length inside the bounds: clear of the end wall of an
// interior, still looking down almost the whole length of the scene.
constexpr float kEyeOffset = 0.35f;
// Looking slightly down (about 8 degrees) shows the floor, where probe GI is most visible.
constexpr float kDownSlope = 0.14f;
} // namespace

// Rule: stand inside the bounds, at 30% of their height, offset along the longest horizontal
// axis towards its + end, and look back along that axis, slightly down. For interiors this
// is a view down the length of the room or corridor (every pixel needs indirect light); for
// exteriors a view across the site from near its edge. Ties go to Z (glTF cameras look
// down -Z by convention, so Z-long scenes usually expect to be seen along Z).
View makeDefaultView(const Bounds& b) {
    View v;
    v.name = "default";
    if (b.empty()) { // nothing to look at (e.g. "empty"): the glTF camera default pose
        v.position = glm::vec3(0.0f);
        v.target = glm::vec3(0, 0, -1);
        return v;
    }
    const glm::vec3 size = b.size();
    const int axis = size.x > size.z ? 0 : 2;
    float length = size[axis];
    if (!(length > 0.0f)) length = glm::max(size.y, 1.0f); // a flat or point-like scene
    glm::vec3 eye = b.center();
    eye[axis] += kEyeOffset * length;
    eye.y = b.min.y + kEyeHeight * size.y;
    glm::vec3 forward(0.0f);
    forward[axis] = -1.0f;
    const float distance = 2.0f * kEyeOffset * length; // as far as the opposite offset point
    v.position = eye;
    v.target = eye + forward * distance - glm::vec3(0, kDownSlope * distance, 0);
    return v;
}

std::string uniqueViewName(const Scene& scene, const std::string& base) {
    const std::string stem = base.empty() ? std::string("view") : base;
    std::string name = stem;
    for (int i = 2; scene.findView(name); ++i)
        name = stem + "_" + std::to_string(i);
    return name;
}

} // namespace pb::scene
