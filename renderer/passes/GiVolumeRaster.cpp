#include "passes/GiVolumeRaster.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pb::render {

namespace {

// Grows the influence box so that rounding in the depth test (DEPTH32F) and in the shader's
// position reconstruction never reject a pixel the shader's test would accept.
glm::vec3 rasterHalfExtents(const GpuProbeVolume& v, double eyeDistance) {
    const glm::vec3 influence = v.half + v.fadeWidth;
    const float size = std::max({influence.x, influence.y, influence.z});
    const float margin = 1e-3f * (size + float(eyeDistance)) + 1e-4f;
    return influence + glm::vec3(margin);
}

using Polygon = std::vector<glm::vec4>;

// Sutherland-Hodgman in homogeneous clip space: keeps the part with dot(plane, p) >= 0.
Polygon clipPolygon(const Polygon& in, const glm::vec4& plane) {
    Polygon out;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const glm::vec4& a = in[i];
        const glm::vec4& b = in[(i + 1) % in.size()];
        const float da = glm::dot(plane, a), db = glm::dot(plane, b);
        if (da >= 0.0f) out.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

} // namespace

glm::ivec4 boxScreenRect(const glm::mat4& clipFromBox, const glm::ivec2& giSize) {
    // The unit cube's faces as corner indices (bit 0: x, bit 1: y, bit 2: z).
    static const int kFaces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    // Near (z >= -w) and the four sides (|x|, |y| <= w); the far plane is left out: farther
    // texels only make the rectangle larger. After the near plane w > 0 (a perspective view),
    // so the projection below is safe.
    static const glm::vec4 kPlanes[5] = {
        {0, 0, 1, 1}, {1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1}};
    glm::vec4 corners[8];
    for (int c = 0; c < 8; ++c)
        corners[c] = clipFromBox * glm::vec4((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f,
                                             (c & 4) ? 1.0f : -1.0f, 1.0f);
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const auto& face : kFaces) {
        Polygon poly{corners[face[0]], corners[face[1]], corners[face[2]], corners[face[3]]};
        for (const glm::vec4& plane : kPlanes)
            if (!poly.empty()) poly = clipPolygon(poly, plane);
        for (const glm::vec4& p : poly) {
            if (p.w <= 0.0f) continue; // only on the eye itself: a degenerate face, no area
            const glm::vec2 ndc = glm::vec2(p) / p.w;
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
        }
    }
    if (lo.x > hi.x) return glm::ivec4(0); // nothing of the box in the frustum
    // NDC -> texels; one texel more on each side covers the rounding of the clip arithmetic
    // and of the rasteriser's own (a texel is covered when its centre is).
    const glm::vec2 size(giSize);
    const glm::vec2 x0 = glm::floor((lo * 0.5f + 0.5f) * size) - 1.0f;
    const glm::vec2 x1 = glm::ceil((hi * 0.5f + 0.5f) * size) + 1.0f;
    return glm::ivec4(std::clamp(int(x0.x), 0, giSize.x), std::clamp(int(x0.y), 0, giSize.y),
                      std::clamp(int(x1.x), 0, giSize.x), std::clamp(int(x1.y), 0, giSize.y));
}

glm::mat4 giRasterFromCameraClip(const glm::ivec2& gbufferSize, int divisor,
                                 const glm::ivec2& giSize) {
    glm::mat4 m(1.0f);
    for (int a = 0; a < 2; ++a) {
        // GBuffer window X of the pixel a texel at window x stands for:
        //   X = divisor * x + c,  c = (divisor - 1) / 2 + 0.5 - divisor / 2 (integer division
        // first, as in the shader). Solving for x in NDC gives x_ndc' = s * x_ndc + t.
        const double full = gbufferSize[a], reduced = double(divisor) * giSize[a];
        const double c = double((divisor - 1) / 2) + 0.5 - 0.5 * divisor;
        const double s = full / reduced;
        m[a][a] = float(s);
        m[3][a] = float(s - 2.0 * c / reduced - 1.0);
    }
    return m;
}

GiVolumeRaster volumeRaster(const GpuProbeVolume& v, const RenderView& view,
                            const glm::ivec2& gbufferSize, int divisor, const glm::ivec2& giSize) {
    GiVolumeRaster r;
    const glm::dvec3 centreRel = v.center - view.eye;
    const glm::vec3 half = rasterHalfExtents(v, glm::length(centreRel));
    // toLocal = R^T, so the box's axes in rel space are the rows of toLocal.
    const glm::mat3 axes = glm::transpose(v.toLocal);
    glm::mat4 relFromBox(1.0f);
    for (int a = 0; a < 3; ++a)
        relFromBox[a] = glm::vec4(axes[a] * half[a], 0.0f);
    relFromBox[3] = glm::vec4(glm::vec3(centreRel), 1.0f);
    const glm::mat4 clipFromRel =
        giRasterFromCameraClip(gbufferSize, divisor, giSize) * view.clipFromRel;
    r.clipFromBox = clipFromRel * relFromBox;
    const glm::vec3 influence = v.half + v.fadeWidth;
    glm::mat4 relFromInfluence = relFromBox;
    for (int a = 0; a < 3; ++a)
        relFromInfluence[a] = glm::vec4(axes[a] * influence[a], 0.0f);
    r.clipFromInfluence = clipFromRel * relFromInfluence;

    // Inside: the eye's local position within the box grown by the distance from the eye to
    // the near plane's corners (the near plane then cannot clip the box's front faces away).
    const double tanY = std::tan(glm::radians(double(view.fovYDegrees)) * 0.5);
    const double aspect = double(view.width) / double(view.height);
    const double nearReach =
        double(view.nearPlane) * std::sqrt(1.0 + tanY * tanY * (1.0 + aspect * aspect));
    const glm::dvec3 eyeLocal = glm::dmat3(v.toLocal) * (-centreRel);
    // An eye on a face counts as inside (a camera in the doorway between two rooms' boxes:
    // rooms' worst-case view). An eye outside by d lets the back faces take surfaces between it
    // and the box, all within d of the box: with d below onFace, below the depth test's own
    // rounding.
    const double onFace = 1e-5 * (1.0 + double(std::max({influence.x, influence.y, influence.z})));
    r.cameraInside = true;
    r.eyeInsideBox = true;
    for (int a = 0; a < 3; ++a) {
        r.cameraInside = r.cameraInside && std::abs(eyeLocal[a]) <= double(half[a]) + nearReach;
        r.eyeInsideBox = r.eyeInsideBox && std::abs(eyeLocal[a]) <= double(influence[a]) + onFace;
    }

    // Culling: outside when all 8 corners lie beyond one clip plane (conservative).
    int outside[6] = {0, 0, 0, 0, 0, 0};
    double farthest = -1e300;
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 unit((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : -1.0f,
                             1.0f);
        const glm::vec4 rel = relFromBox * unit;
        farthest = std::max(farthest, glm::dot(glm::dvec3(rel), view.forward));
        const glm::vec4 clip = view.clipFromRel * rel;
        outside[0] += clip.x < -clip.w;
        outside[1] += clip.x > clip.w;
        outside[2] += clip.y < -clip.w;
        outside[3] += clip.y > clip.w;
        outside[4] += clip.z < -clip.w;
        outside[5] += clip.z > clip.w;
    }
    r.visible = std::none_of(outside, outside + 6, [](int n) { return n == 8; });
    r.backFacesInFrontOfFar = farthest < double(view.farPlane) * 0.999;
    // The rectangle of the influence box grown by the shader's rounding only (1e-5 of the
    // distances involved: ~100 float epsilons), not by the depth test's margin above: a
    // texel's reconstructed surface point lies on its own ray (depth rounding moves it along
    // the ray, not across), so if the shader finds it in the influence, that box seen through
    // the texel is in the frustum. The margin (5 mm here) would reach past the near plane
    // (0.6 mm in rooms) whenever the eye stands on a face (the doorway view), and cover the
    // whole screen.
    const float rounding = 1e-5f * (1.0f + std::max({influence.x, influence.y, influence.z}) +
                                    float(glm::length(centreRel)));
    glm::mat4 relFromRounded = relFromInfluence;
    for (int a = 0; a < 3; ++a)
        relFromRounded[a] = glm::vec4(axes[a] * (influence[a] + rounding), 0.0f);
    r.screenRect = boxScreenRect(clipFromRel * relFromRounded, giSize);
    return r;
}

} // namespace pb::render
