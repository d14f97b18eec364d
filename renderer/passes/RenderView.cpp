#include "passes/RenderView.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace pb::render {

glm::mat4 RenderView::relFromLocal(const glm::mat4& worldFromLocal) const {
    glm::dmat4 m(worldFromLocal);
    m[3] -= glm::dvec4(eye, 0.0);
    return glm::mat4(m);
}

RenderView makeRenderView(const scene::View& view, const scene::Bounds& bounds, int width,
                          int height) {
    RenderView rv;
    rv.eye = glm::dvec3(view.position);
    glm::dvec3 dir = glm::dvec3(view.target) - rv.eye;
    if (glm::length(dir) <= 0.0 || !std::isfinite(glm::length(dir)))
        throw Error("camera '" + view.name + "': position and target coincide");
    rv.forward = glm::normalize(dir);
    rv.width = std::max(1, width);
    rv.height = std::max(1, height);
    rv.fovYDegrees = view.fovYDegrees;

    // Far: the farthest bounds corner; near: a fixed ratio of it (DEPTH32F keeps 1e-4 usable)
    // but never further than the nearest geometry could plausibly be.
    double farthest = 1.0;
    if (!bounds.empty())
        for (int i = 0; i < 8; ++i) {
            glm::dvec3 c((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                         (i & 4) ? bounds.max.z : bounds.min.z);
            farthest = std::max(farthest, glm::length(c - rv.eye));
        }
    rv.farPlane = float(farthest * 1.05);
    rv.nearPlane = std::max(rv.farPlane * 1e-4f, 1e-4f);

    glm::dvec3 up = std::abs(rv.forward.y) > 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    glm::dmat4 viewRot = glm::lookAt(glm::dvec3(0.0), rv.forward, up);
    glm::dmat4 proj = glm::perspective(glm::radians(double(rv.fovYDegrees)),
                                       double(rv.width) / double(rv.height), double(rv.nearPlane),
                                       double(rv.farPlane));
    glm::dmat4 clip = proj * viewRot;
    rv.clipFromRel = glm::mat4(clip);
    rv.relFromClip = glm::mat4(glm::inverse(clip));
    return rv;
}

} // namespace pb::render
