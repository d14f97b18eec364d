#pragma once
// Helpers for the built-in procedural scenes: materials and closed boxes, in metres.
#include "scene/Scene.h"

#include <string>

namespace pb::scene {

class SceneBuilder {
public:
    explicit SceneBuilder(Scene& scene) : scene_(scene) {}

    int material(const std::string& name, const glm::vec3& albedo,
                 const glm::vec3& emissive = glm::vec3(0.0f));

    // A closed box spanning [min, max] (before the turn), turned by `yawDegrees` about the
    // vertical axis through its centre. Stored centred in its own local space and placed by
    // the instance transform, as glTF scenes are. Faces point outward and wind
    // counter-clockwise seen from outside; UVs are in metres, so textures would tile.
    void box(const std::string& name, const glm::vec3& min, const glm::vec3& max, int material,
             float yawDegrees = 0.0f, bool dynamic = false);

    View& view(const std::string& name, const glm::vec3& position, const glm::vec3& target,
               float fovYDegrees = 60.0f);

private:
    Scene& scene_;
};

} // namespace pb::scene
