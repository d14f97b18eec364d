#pragma once
// A probe volume: an oriented box with a regular grid of probes, optionally nested in a parent.
//
// Frame: world = center + rotation * local. Local +Y is "up": probe planes along local Y are
// the slices of the texture arrays. The grid runs corner to corner: probe (i,j,k) sits at
// local -halfExtents + (i,j,k) * cellSize; an axis with count 1 holds one probe at the centre.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

namespace pb::probes {

// Sanity limits: a texture row of 1024 visibility tiles is 16384 texels (the usual GL max);
// 2^18 probes are 384 MiB of rgba16f probe data and a few GiB of bake working memory.
constexpr int kMaxProbesPerAxis = 1024;
constexpr long long kMaxProbesPerVolume = 1 << 18;

// Visibility distances are clamped to kMaxDistanceScale * |cellSize| (1.5 cell diagonals).
constexpr float kMaxDistanceScale = 1.5f;

struct ProbeVolume {
    std::string name;
    glm::vec3 center{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; // local -> world, unit (glm: w, x, y, z)
    glm::vec3 halfExtents{1.0f};
    glm::ivec3 counts{2};
    std::string parent; // empty: a root volume
    // Children only: how far the outermost probe ring is blended towards the parent's
    // irradiance after each bounce pass (0 = not at all, 1 = replaced; NestingBlend.h).
    float edgeBlend = 1.0f;

    int probeCount() const { return counts.x * counts.y * counts.z; }

    // Every field that defines a volume, once, in the probe file's order: `f(label, field)` for
    // each. The probe file's writer and reader (store/ProbeFile.cpp) and the bake's input hash
    // (bake/BakeHash.cpp) all visit this list, so a field added here is written, read and
    // hashed - none of them can forget it. `Volume` is ProbeVolume or const ProbeVolume.
    template <class Volume, class F> static void forEachField(Volume& v, F&& f) {
        f("name", v.name);
        f("parent", v.parent);
        f("center", v.center);
        f("rotation", v.rotation);
        f("extents", v.halfExtents);
        f("counts", v.counts);
        f("edge blend", v.edgeBlend);
    }
    // Spacing per axis; an axis with one probe reports the box size (2 * halfExtent).
    glm::vec3 cellSize() const;
    // Smallest spacing over the axes with more than one probe (the box size if none has).
    float minCellSize() const;
    // Distance clamp of the visibility data; stored distances are divided by it.
    float maxDistance() const;
    float boxVolume() const { return 8.0f * halfExtents.x * halfExtents.y * halfExtents.z; }

    // Probe index: x fastest, then z, then y, matching the texture layout (slice = y).
    int probeIndex(const glm::ivec3& c) const { return (c.y * counts.z + c.z) * counts.x + c.x; }
    glm::ivec3 probeCoords(int index) const;
    glm::vec3 gridLocal(const glm::ivec3& c) const; // un-relocated local probe position

    glm::mat3 localToWorldRotation() const { return glm::mat3_cast(rotation); }
    glm::vec3 toWorld(const glm::vec3& local) const { return center + rotation * local; }
    glm::vec3 toLocal(const glm::vec3& world) const;
    // True when the world point lies in the box grown by `margin` (world units) per side.
    bool contains(const glm::vec3& world, float margin = 0.0f) const;
    // The 8 corners of the box in world space.
    std::vector<glm::vec3> worldCorners() const;
};

// Problem with one volume on its own (empty name, counts, extents, rotation); "" when fine.
std::string volumeProblem(const ProbeVolume& v);
// Problem with `child` nested in `parent` (a corner outside the parent box); "" when fine.
std::string nestingProblem(const ProbeVolume& child, const ProbeVolume& parent);

// Index of each volume's parent (-1 for roots). Throws pb::Error prefixed with `source` for
// an unknown parent, a cycle, duplicate names, or any volumeProblem / nestingProblem.
std::vector<int> validateVolumes(const std::vector<ProbeVolume>& volumes,
                                 const std::string& source);
// Volume indices ordered so every parent comes before its children (stable otherwise).
std::vector<int> parentFirstOrder(const std::vector<int>& parents);

// Euler angles in degrees -> rotation: world = Ry(y) * Rx(x) * Rz(z) * local (roll about Z
// first, then pitch about X, then yaw about the world Y axis). The TOML `rotation` key.
glm::quat rotationFromEulerDegrees(const glm::vec3& degrees);

} // namespace pb::probes
