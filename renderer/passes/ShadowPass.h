#pragma once
// Sun shadows from two orthographic depth maps in one light frame (looking down the sun's
// direction, centred on the scene's bounds, depth over the scene's whole diameter so every
// caster is in both):
//  - the view map (shadowMapSize^2), fitted in light-space x/y to what the camera sees
//    (ShadowViewFit.h). Its texels are as small as the view allows: from inside a room they
//    are millimetres, so a 2 cm wall stays thicker than the depth bias and the sun no longer
//    leaks along the seams of a room it cannot reach (issue 42; ShadowSeamLeakTest);
//  - the scene map ((shadowMapSize / 4)^2, one bilinear tap), fitted to the whole scene: the
//    fallback for the few surfaces outside the view map (between the fit's rays, dynamic
//    objects). A sixteenth of the view map's texels, so the pass costs what one map did plus
//    its draws once more.
// Skipped (and no texture allocated) when the sun is off.
#include "passes/FrameContext.h"
#include "passes/ShadowViewFit.h"

#include <memory>
#include <optional>

namespace pb::scene {
class RayGrid;
}

namespace pb::render {

// The scene map's side for a frame's shadowMapSize (the device model counts both maps).
inline int sceneShadowMapSize(int shadowMapSize) { return std::max(shadowMapSize / 4, 1); }

class ShadowPass : public Pass {
public:
    ShadowPass();
    ~ShadowPass() override;
    const char* name() const override { return "shadow"; }
    void execute(FrameContext& frame) override;

private:
    struct Map {
        std::unique_ptr<gl::Texture> depth;
        std::unique_ptr<gl::Framebuffer> fbo;
    };
    void ensure(Map& map, int size, const char* label);

    // The fit's CPU rays run when the camera or the sun moved, not every frame: the bench
    // times the same view many times, and its CPU clock would count them.
    std::optional<LightSquare> fitFor(const RenderView& view, const glm::dmat4& lightFromWorld,
                                      const LightSquare& sceneSquare);

    Map view_, scene_;
    std::unique_ptr<scene::RayGrid> grid_; // built on the first sunlit frame
    const scene::Scene* gridScene_ = nullptr;
    struct FitKey {
        glm::dvec3 eye{0.0};
        glm::mat4 relFromClip{0.0f};
        float farPlane = 0.0f;
        glm::dmat4 lightFromWorld{0.0};
        bool operator==(const FitKey&) const = default;
    };
    std::optional<FitKey> fitKey_;
    std::optional<LightSquare> fit_;
};

} // namespace pb::render
