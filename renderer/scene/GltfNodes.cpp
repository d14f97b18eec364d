#include "scene/GltfNodes.h"

#include "scene/DefaultView.h"
#include "scene/GltfMeshes.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace pb::scene::gltf {

namespace {

// Positions beyond this are refused, as checkExtent does for the geometry (GltfLoader.cpp).
constexpr float kMaxCoordinate = 1e10f;

bool finiteWithin(const glm::vec3& v, float limit) {
    return std::abs(v.x) <= limit && std::abs(v.y) <= limit && std::abs(v.z) <= limit;
}

glm::mat4 localMatrix(const Context& ctx, int index) {
    const tinygltf::Node& n = ctx.model.nodes[size_t(index)];
    auto check = [&](const std::vector<double>& v, size_t size, const char* what) {
        if (!v.empty() && v.size() != size)
            ctx.fail(ctx.nodeLabel(index) + ": " + what + " must have " + std::to_string(size) +
                     " numbers");
        for (double d : v)
            if (!std::isfinite(d)) ctx.fail(ctx.nodeLabel(index) + ": " + what + " is not finite");
    };
    check(n.matrix, 16, "matrix");
    check(n.translation, 3, "translation");
    check(n.rotation, 4, "rotation");
    check(n.scale, 3, "scale");
    if (!n.matrix.empty()) { // column-major, as glm
        glm::dmat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = n.matrix[size_t(i)];
        return glm::mat4(m);
    }
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (!n.translation.empty())
        t = glm::translate(glm::mat4(1.0f), glm::vec3(glm::make_vec3(n.translation.data())));
    if (!n.rotation.empty()) {
        const auto& q = n.rotation; // glTF stores x, y, z, w
        const glm::quat quat{float(q[3]), float(q[0]), float(q[1]), float(q[2])};
        const float len = glm::length(quat);
        if (!(len > 1e-6f)) ctx.fail(ctx.nodeLabel(index) + ": rotation is a zero quaternion");
        r = glm::mat4_cast(quat / len);
    }
    if (!n.scale.empty())
        s = glm::scale(glm::mat4(1.0f), glm::vec3(glm::make_vec3(n.scale.data())));
    return t * r * s;
}

bool extrasSayDynamic(const tinygltf::Node& n) {
    const tinygltf::Value* v = member(n.extras, "dynamic");
    return v && v->IsBool() && v->Get<bool>();
}

void addCamera(Context& ctx, int node, const glm::mat4& world) {
    const tinygltf::Node& n = ctx.model.nodes[size_t(node)];
    if (size_t(n.camera) >= ctx.model.cameras.size())
        ctx.fail(ctx.nodeLabel(node) + " refers to missing camera " + std::to_string(n.camera));
    const tinygltf::Camera& cam = ctx.model.cameras[size_t(n.camera)];
    if (cam.type != "perspective") {
        ctx.warn("camera '" + cam.name + "' is " + cam.type +
                 "; only perspective cameras become views");
        return;
    }
    View v;
    v.name = ctx.uniqueViewName(!cam.name.empty() ? cam.name
                                : !n.name.empty() ? n.name
                                                  : "camera" + std::to_string(n.camera));
    v.position = glm::vec3(world[3]);
    if (!finiteWithin(v.position, kMaxCoordinate))
        ctx.fail(ctx.nodeLabel(node) + ": camera position is not finite or beyond 1e10");
    // A glTF camera looks down its local -Z; the target only has to fix the direction.
    const glm::vec3 forward = glm::vec3(world * glm::vec4(0, 0, -1, 0));
    if (!(glm::length(forward) > 0.0f) || !finiteWithin(forward, 1e30f))
        ctx.fail(ctx.nodeLabel(node) + ": camera transform has no direction (zero scale)");
    v.target = v.position + glm::normalize(forward);
    const double yfov = cam.perspective.yfov * 180.0 / 3.14159265358979;
    if (!(yfov > 0.0 && yfov < 180.0))
        ctx.fail("camera '" + cam.name + "': yfov must be in (0, pi) radians");
    v.fovYDegrees = float(yfov);
    ctx.scene.views.push_back(v);
}

void addLight(Context& ctx, int node, const glm::mat4& world, const tinygltf::Value& ext) {
    const tinygltf::Value* index = member(ext, "light");
    if (!index || !index->IsInt() || index->Get<int>() < 0 ||
        size_t(index->Get<int>()) >= ctx.model.lights.size())
        ctx.fail(ctx.nodeLabel(node) + ": KHR_lights_punctual refers to a missing light");
    const tinygltf::Light& src = ctx.model.lights[size_t(index->Get<int>())];
    Light l;
    l.name = !src.name.empty() ? src.name : ctx.model.nodes[size_t(node)].name;
    if (src.type == "directional")
        l.type = LightType::Directional;
    else if (src.type == "spot")
        l.type = LightType::Spot;
    else if (src.type == "point")
        l.type = LightType::Point;
    else
        ctx.fail("light '" + src.name + "' has unknown type '" + src.type + "'");
    if (!src.color.empty()) {
        if (src.color.size() != 3) ctx.fail("light '" + src.name + "': color must have 3 numbers");
        l.color = glm::vec3(glm::make_vec3(src.color.data()));
    }
    l.intensity = float(src.intensity);
    l.range = float(src.range);
    l.innerConeAngle = float(src.spot.innerConeAngle);
    l.outerConeAngle = float(src.spot.outerConeAngle);
    if (!std::isfinite(l.intensity) || l.intensity < 0.0f || !(l.range >= 0.0f) ||
        !finiteWithin(l.color, 1e30f) || glm::any(glm::lessThan(l.color, glm::vec3(0.0f))))
        ctx.fail("light '" + src.name +
                 "' has a negative or non-finite colour, intensity or range");
    // The spec: 0 <= inner < outer <= pi/2 (the shader's smoothstep(cos outer, cos inner) is
    // undefined in GLSL unless cos outer < cos inner).
    if (l.type == LightType::Spot &&
        !(l.innerConeAngle >= 0.0f && l.innerConeAngle < l.outerConeAngle &&
          l.outerConeAngle <= 1.5707964f))
        ctx.fail("light '" + src.name + "': spot cone angles must be 0 <= inner < outer <= pi/2");
    l.position = glm::vec3(world[3]);
    if (!finiteWithin(l.position, kMaxCoordinate))
        ctx.fail(ctx.nodeLabel(node) + ": light position is not finite or beyond 1e10");
    const glm::vec3 dir = glm::vec3(world * glm::vec4(0, 0, -1, 0)); // lights point down -Z
    l.direction = glm::length(dir) > 0.0f && finiteWithin(dir, 1e30f) ? glm::normalize(dir)
                                                                      : glm::vec3(0, 0, -1);

    // The first directional light is the sun (shadow map, bake sun term, --sun).
    if (l.type == LightType::Directional && !ctx.sunFromFile) {
        ctx.sunFromFile = true;
        ctx.scene.sun.enabled = true;
        ctx.scene.sun.toSun = -l.direction;
        ctx.scene.sun.color = l.color;
        ctx.scene.sun.intensity = l.intensity;
        return;
    }
    ctx.scene.lights.push_back(l);
}

} // namespace

void traverseNodes(Context& ctx, const std::vector<std::string>& dynamicNodes) {
    const tinygltf::Model& m = ctx.model;
    const size_t count = m.nodes.size();

    std::vector<char> namedDynamic(count, 0);
    std::vector<std::string> unknown;
    for (const std::string& name : dynamicNodes) {
        bool found = false;
        for (size_t i = 0; i < count; ++i)
            if (m.nodes[i].name == name) namedDynamic[i] = found = true;
        if (!found) unknown.push_back("'" + name + "'");
    }
    if (!unknown.empty()) {
        std::string list;
        for (const std::string& u : unknown)
            list += (list.empty() ? "" : ", ") + u;
        ctx.fail("--dynamic: no node named " + list);
    }

    // Roots: the default scene's, else the first scene's, else every node nobody parents.
    std::vector<int> roots;
    if (!m.scenes.empty()) {
        const int s =
            m.defaultScene >= 0 && size_t(m.defaultScene) < m.scenes.size() ? m.defaultScene : 0;
        roots = m.scenes[size_t(s)].nodes;
    } else {
        std::vector<char> isChild(count, 0);
        for (const tinygltf::Node& n : m.nodes)
            for (int c : n.children)
                if (c >= 0 && size_t(c) < count) isChild[size_t(c)] = 1;
        for (size_t i = 0; i < count; ++i)
            if (!isChild[i]) roots.push_back(int(i));
    }

    // Depth-first with an explicit stack: a file with a deep chain of nodes cannot overflow
    // the call stack, and a node met twice (a cycle, or a second parent: the spec wants
    // disjoint strict trees) is an error instead of a hang or an exponential blow-up.
    enum : char { Unseen, OnPath, Done };
    std::vector<char> state(count, Unseen);
    struct Frame {
        int node;
        glm::mat4 world;
        bool dynamic;
        size_t nextChild;
    };
    std::vector<Frame> stack;
    auto enter = [&](int node, int parent, const glm::mat4& parentWorld, bool parentDynamic) {
        if (node < 0 || size_t(node) >= count)
            ctx.fail((parent < 0 ? std::string("scene") : ctx.nodeLabel(parent)) +
                     " refers to missing node " + std::to_string(node));
        if (state[size_t(node)] == OnPath)
            ctx.fail("cyclic node hierarchy: " + ctx.nodeLabel(node) + " is its own ancestor");
        if (state[size_t(node)] == Done)
            ctx.fail(ctx.nodeLabel(node) + " appears more than once in the node hierarchy");
        state[size_t(node)] = OnPath;
        const tinygltf::Node& n = m.nodes[size_t(node)];
        const glm::mat4 world = parentWorld * localMatrix(ctx, node);
        // A dynamic node moves its whole subtree.
        const bool dynamic = parentDynamic || namedDynamic[size_t(node)] || extrasSayDynamic(n);
        if (n.mesh >= 0) {
            if (size_t(n.mesh) >= m.meshes.size())
                ctx.fail(ctx.nodeLabel(node) + " refers to missing mesh " + std::to_string(n.mesh));
            const std::string name = n.name.empty() ? "node" + std::to_string(node) : n.name;
            const std::vector<int>& prims = meshPrimitives(ctx, n.mesh);
            if (prims.size() > kMaxInstances - ctx.scene.instances.size())
                ctx.fail("more than " + std::to_string(kMaxInstances) +
                         " mesh instances (nodes x primitives)");
            for (int prim : prims)
                ctx.scene.instances.push_back(Instance{name, prim, world, dynamic});
        }
        if (n.camera >= 0) addCamera(ctx, node, world);
        if (auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end())
            addLight(ctx, node, world, it->second);
        stack.push_back(Frame{node, world, dynamic, 0});
    };
    for (int root : roots) {
        enter(root, -1, glm::mat4(1.0f), false);
        while (!stack.empty()) {
            Frame& top = stack.back();
            const std::vector<int>& children = m.nodes[size_t(top.node)].children;
            if (top.nextChild < children.size()) {
                const int child = children[top.nextChild++];
                const Frame parent = top; // `enter` may reallocate the stack
                enter(child, parent.node, parent.world, parent.dynamic);
            } else {
                state[size_t(top.node)] = Done;
                stack.pop_back();
            }
        }
    }
}

} // namespace pb::scene::gltf
