#pragma once
// Where one probe volume lands on the GI target, for gi.multi_volume and frustum culling
// (GL-free arithmetic on the view; the pass does the drawing).
//
// The box rasterised is the volume's INFLUENCE region (common_ddgi.glsl ddgiInfluences: a
// child's box, a root's box + fade width) grown by a small margin: the depth and stencil tests
// only have to be conservative, the shaders' exact influence test decides every pixel.
//
// Reduced gi.resolution: a GI texel stands for ONE GBuffer pixel (gi_ddgi_apply.frag:
// fragCoord * divisor + (divisor - 1) / 2), not for the texel's centre. `clipFromBox` includes
// the shift and scale that put that pixel's ray through the texel's centre, so the box is
// rasterised exactly as it is seen from the pixels the shader reads.
#include "passes/GpuProbes.h"
#include "passes/RenderView.h"

#include <glm/glm.hpp>

namespace pb::render {

struct GiVolumeRaster {
    bool visible = true;       // some part of the box may be inside the view frustum
    bool cameraInside = false; // the eye (or the near plane around it) may touch the box
    // Inside only: every point of the box lies in front of the far plane, so its back faces
    // can be depth-tested against the scene (otherwise: a full-screen triangle).
    bool backFacesInFrontOfFar = false;
    // The eye itself lies inside the influence box (no margin; on a face counts). Then a surface
    // seen through that box's back faces (depth GEQUAL) is inside it, with no shader test:
    // along each ray the box is the segment from the eye to the back face (it is convex).
    bool eyeInsideBox = false;
    glm::mat4 clipFromBox{1.0f}; // unit cube [-1,1]^3 -> clip space of the GI target
    // The same for the influence box itself, without the margin: where the raster decides
    // (eyeInsideBox), the margin would hand the band around the box to this volume.
    glm::mat4 clipFromInfluence{1.0f};
    // The GI target texels the box (with its margin) can cover: its faces clipped to the
    // near and side planes, projected, widened by one texel; x0, y0 inclusive, x1, y1
    // exclusive (glScissor's rectangle). Every texel whose surface lies in the influence is
    // inside it (the surface point lies in the box and in the view); empty (x0 >= x1 or
    // y0 >= y1) when no part of the box lies inside the frustum's near and side planes, though
    // the corner test above may keep it (a box beside the eye: rooms' dark room seen from the
    // doorway). The pass scissors each volume's draws to it and skips an empty one.
    glm::ivec4 screenRect{0, 0, 0, 0};
    bool onScreen() const { return screenRect.x < screenRect.z && screenRect.y < screenRect.w; }
};

// The texels of a giSize target that the unit cube [-1,1]^3 mapped by clipFromBox can cover
// (GiVolumeRaster::screenRect).
glm::ivec4 boxScreenRect(const glm::mat4& clipFromBox, const glm::ivec2& giSize);

// gbufferSize: the view's pixels; divisor: gi.resolution's (1, 2, 4); giSize: the GI
// target's texels (max(1, gbuffer / divisor) per axis).
GiVolumeRaster volumeRaster(const GpuProbeVolume& v, const RenderView& view,
                            const glm::ivec2& gbufferSize, int divisor, const glm::ivec2& giSize);

// Clip-space correction from the camera's projection to the GI target's raster (identity at
// full resolution): x' = s.x * x + t.x * w, likewise y.
glm::mat4 giRasterFromCameraClip(const glm::ivec2& gbufferSize, int divisor,
                                 const glm::ivec2& giSize);

} // namespace pb::render
