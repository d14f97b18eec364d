#include "camera/Reprojection.h"

#include <glm/gtc/matrix_transform.hpp>

namespace pb::camera {

glm::mat4 prevClipFromCurrentRel(const CameraState& prev, const CameraState& cur) {
    const glm::dvec3 offset = cur.eye - prev.eye;
    return glm::mat4(glm::dmat4(prev.clipFromRel) * glm::translate(glm::dmat4(1.0), offset));
}

glm::vec3 eyeOffset(const CameraState& prev, const CameraState& cur) {
    return glm::vec3(cur.eye - prev.eye);
}

bool isSameCamera(const CameraState& a, const CameraState& b) {
    return a.eye == b.eye && a.clipFromRel == b.clipFromRel && a.width == b.width &&
           a.height == b.height;
}

glm::vec3 relFromWindow(const CameraState& cam, glm::vec2 window, float depth) {
    const glm::vec2 ndc = window / glm::vec2(cam.width, cam.height) * 2.0f - 1.0f;
    const glm::vec4 relH = cam.relFromClip * glm::vec4(ndc, depth * 2.0f - 1.0f, 1.0f);
    return glm::vec3(relH) / relH.w;
}

PixelReprojection reprojectPixel(const CameraState& prev, const CameraState& cur, glm::vec2 window,
                                 float depth) {
    const glm::vec3 rel = relFromWindow(cur, window, depth);
    const glm::vec4 clip = prevClipFromCurrentRel(prev, cur) * glm::vec4(rel, 1.0f);
    PixelReprojection r;
    r.prevDistance = glm::length(rel + eyeOffset(prev, cur));
    r.inFront = clip.w > 0.0f;
    if (!r.inFront) return r;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    r.prevWindow = (ndc * 0.5f + 0.5f) * glm::vec2(prev.width, prev.height);
    r.onScreen = r.prevWindow.x >= 0.0f && r.prevWindow.y >= 0.0f &&
                 r.prevWindow.x <= float(prev.width) && r.prevWindow.y <= float(prev.height);
    return r;
}

} // namespace pb::camera
