// ShadowViewFit: the sun's view map covers what the camera sees and little more. CPU only (no
// GL context); it lives with the GL tests because it links the render passes.
#include "passes/ShadowViewFit.h"
#include "scene/SceneBuilder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace pb;

namespace {

struct SunFrame {
    scene::Scene scene;
    glm::dmat4 lightFromWorld{1.0};
    render::LightSquare sceneSquare;
};

// A 4 x 3 x 4 m closed room on ground 60 m across, the sun straight above.
SunFrame roomOnWideGround() {
    SunFrame s;
    scene::SceneBuilder b(s.scene);
    const int white = b.material("white", {0.7f, 0.7f, 0.7f});
    b.box("ground", {-30, -0.2f, -30}, {30, 0, 30}, white);
    b.box("roof", {-2.1f, 3, -2.1f}, {2.1f, 3.1f, 2.1f}, white);
    b.box("north", {-2.1f, 0, 2}, {2.1f, 3, 2.1f}, white);
    b.box("south", {-2.1f, 0, -2.1f}, {2.1f, 3, -2}, white);
    b.box("east", {2, 0, -2}, {2.1f, 3, 2}, white);
    b.box("west", {-2.1f, 0, -2}, {-2, 3, 2}, white);
    const scene::Bounds bounds = s.scene.worldBounds();
    const double radius = 0.5 * glm::length(glm::dvec3(bounds.size()));
    s.lightFromWorld = glm::lookAt(glm::dvec3(bounds.center()) + glm::dvec3(0, radius, 0),
                                   glm::dvec3(bounds.center()), glm::dvec3(0, 0, 1));
    s.sceneSquare = {glm::dvec2(-radius), 2.0 * radius};
    return s;
}

render::RenderView viewFrom(const scene::Scene& s, glm::vec3 eye, glm::vec3 target) {
    scene::View v;
    v.name = "test";
    v.position = eye;
    v.target = target;
    v.fovYDegrees = 70.0f;
    return render::makeRenderView(v, s.worldBounds(), 320, 180);
}

} // namespace

TEST(ShadowViewFit, AViewInsideARoomGetsTheRoomsSquare) {
    const SunFrame s = roomOnWideGround();
    const scene::RayGrid grid(s.scene);
    const auto fit = render::fitShadowToView(grid, viewFrom(s.scene, {1.5f, 1.5f, -1.5f}, {-1, 0.5f, 1}),
                                             s.lightFromWorld, s.sceneSquare);
    ASSERT_TRUE(fit.has_value());
    // The room's inside is 4 m across; the fit holds it (seen from above: x and z of the room)
    // with its margin (8% a side) and snapping (up to two 1/64ths of the scene's square), and
    // is an order of magnitude smaller than the 85 m scene's square.
    EXPECT_GE(fit->size, 4.0);
    EXPECT_LE(fit->size, 4.0 * 1.16 + 2.0 * s.sceneSquare.size / 64.0);
    EXPECT_LT(fit->size, 0.1 * s.sceneSquare.size);
    const glm::dvec2 centre = fit->min + 0.5 * fit->size;
    EXPECT_LT(glm::length(centre), 1.5) << "the room is at the scene's centre";
}

TEST(ShadowViewFit, AViewOfTheWholeGroundIsBoundedByTheScenesSquare) {
    const SunFrame s = roomOnWideGround();
    const scene::RayGrid grid(s.scene);
    const auto fit = render::fitShadowToView(grid, viewFrom(s.scene, {0, 80, 0.1f}, {0, 0, 0}),
                                             s.lightFromWorld, s.sceneSquare);
    ASSERT_TRUE(fit.has_value());
    EXPECT_LE(fit->size, s.sceneSquare.size);
    EXPECT_GE(fit->min.x, s.sceneSquare.min.x);
    EXPECT_GE(fit->min.y, s.sceneSquare.min.y);
    EXPECT_LE(fit->min.x + fit->size, s.sceneSquare.min.x + s.sceneSquare.size + 1e-9);
}

TEST(ShadowViewFit, AViewOfOnlySkyHasNoFit) {
    const SunFrame s = roomOnWideGround();
    const scene::RayGrid grid(s.scene);
    const auto fit = render::fitShadowToView(grid, viewFrom(s.scene, {0, 10, 0}, {0, 20, 0.1f}),
                                             s.lightFromWorld, s.sceneSquare);
    EXPECT_FALSE(fit.has_value());
}
