#include "respond/ResponseEvent.h"

#include "core/Error.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>
#include <toml++/toml.h>

namespace pb::respond {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string part;
    while (std::getline(in, part, sep))
        out.push_back(part);
    return out;
}

float number(const std::string& text, const std::string& where) {
    try {
        std::size_t used = 0;
        const float v = std::stof(text, &used);
        if (used == text.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    throw Error(where + ": '" + text + "' is not a finite number");
}

glm::vec3 vec3(const std::string& text, const std::string& where) {
    const auto parts = split(text, ',');
    if (parts.size() != 3) throw Error(where + ": expected X,Y,Z, got '" + text + "'");
    return {number(parts[0], where), number(parts[1], where), number(parts[2], where)};
}

const scene::Light* findLight(const scene::Scene& s, const std::string& name) {
    for (const auto& l : s.lights)
        if (l.name == name) return &l;
    return nullptr;
}

bool hasNode(const scene::Scene& s, const std::string& name) {
    for (const auto& i : s.instances)
        if (i.nodeName == name && !i.dynamic) return true;
    return false;
}

scene::Bounds nodeBounds(const scene::Scene& s, const std::string& name) {
    scene::Bounds b;
    for (const auto& i : s.instances) {
        if (i.nodeName != name || i.dynamic) continue;
        const scene::Bounds& lb = s.primitives[std::size_t(i.primitive)].localBounds;
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner{(c & 1) ? lb.max.x : lb.min.x, (c & 2) ? lb.max.y : lb.min.y,
                                   (c & 4) ? lb.max.z : lb.min.z};
            b.extend(glm::vec3(i.transform * glm::vec4(corner, 1.0f)));
        }
    }
    return b;
}

} // namespace

ResponseEvent parseEvent(const std::string& spec, const std::string& option) {
    const std::string where = option + " '" + spec + "'";
    ResponseEvent e;
    e.spec = spec;
    const auto at = spec.rfind('@');
    if (at == std::string::npos) throw Error(where + ": no @FRAME (e.g. sun:off@10)");
    const float frame = number(spec.substr(at + 1), where);
    if (frame != std::floor(frame)) throw Error(where + ": the frame must be a whole number");
    e.frame = int(frame);
    const auto p = split(spec.substr(0, at), ':');
    const std::string usage =
        ": expected sun:off|on|dir:X,Y,Z|scale:K, light:NAME:off|on|scale:K|move:X,Y,Z or "
        "node:NAME:remove|insert:X,Y,Z, then @FRAME";
    if (p.size() >= 2 && p[0] == "sun") {
        if (p.size() == 2 && p[1] == "off")
            e.kind = EventKind::SunOff;
        else if (p.size() == 2 && p[1] == "on")
            e.kind = EventKind::SunOn;
        else if (p.size() == 3 && p[1] == "dir") {
            e.kind = EventKind::SunDir;
            e.value = vec3(p[2], where);
            if (glm::length(e.value) < 1e-6f) throw Error(where + ": the sun direction is zero");
        } else if (p.size() == 3 && p[1] == "scale") {
            e.kind = EventKind::SunScale;
            e.scale = number(p[2], where);
        } else
            throw Error(where + usage);
    } else if (p.size() >= 3 && p[0] == "light") {
        e.name = p[1];
        if (p.size() == 3 && p[2] == "off")
            e.kind = EventKind::LightOff;
        else if (p.size() == 3 && p[2] == "on")
            e.kind = EventKind::LightOn;
        else if (p.size() == 4 && p[2] == "scale") {
            e.kind = EventKind::LightScale;
            e.scale = number(p[3], where);
        } else if (p.size() == 4 && p[2] == "move") {
            e.kind = EventKind::LightMove;
            e.value = vec3(p[3], where);
        } else
            throw Error(where + usage);
    } else if (p.size() >= 3 && p[0] == "node") {
        e.name = p[1];
        if (p.size() == 3 && p[2] == "remove")
            e.kind = EventKind::NodeRemove;
        else if (p.size() == 4 && p[2] == "insert") {
            e.kind = EventKind::NodeInsert;
            e.value = vec3(p[3], where);
        } else
            throw Error(where + usage);
    } else
        throw Error(where + usage);
    if (e.scale < 0.0f) throw Error(where + ": a scale must not be negative");
    return e;
}

std::vector<ResponseEvent> readTimeline(const std::string& path) {
    toml::table t;
    try {
        t = toml::parse_file(path);
    } catch (const toml::parse_error& err) {
        throw fileError(path, std::string(err.description()));
    }
    std::vector<ResponseEvent> out;
    const toml::array* events = t["event"].as_array();
    if (!events || events->empty()) throw fileError(path, "no [[event]] table");
    for (const auto& node : *events) {
        const toml::table* ev = node.as_table();
        const auto spec = ev ? (*ev)["spec"].value<std::string>() : std::nullopt;
        if (!spec) throw fileError(path, "every [[event]] needs spec = \"...\"");
        out.push_back(parseEvent(*spec, path));
    }
    return out;
}

void checkEvent(const ResponseEvent& e, const World& world, int frames) {
    const std::string where = "--event '" + e.spec + "'";
    if (e.frame < 0 || e.frame >= frames)
        throw Error(where + ": frame " + std::to_string(e.frame) + " is outside the run (0.." +
                    std::to_string(frames - 1) + ", --frames " + std::to_string(frames) + ")");
    const bool light = e.kind == EventKind::LightOff || e.kind == EventKind::LightOn ||
                       e.kind == EventKind::LightScale || e.kind == EventKind::LightMove;
    if (light && !findLight(world.scene, e.name)) {
        std::string names;
        for (const auto& l : world.scene.lights)
            names += (names.empty() ? "" : ", ") + l.name;
        throw Error(where + ": the scene has no light '" + e.name +
                    "' (lights: " + (names.empty() ? "none" : names) + ")");
    }
    const bool node = e.kind == EventKind::NodeRemove || e.kind == EventKind::NodeInsert;
    if (node && !hasNode(world.scene, e.name))
        throw Error(where + ": the scene has no static node '" + e.name + "'");
}

Change applyEvent(const ResponseEvent& e, World& w, const World& initial) {
    Change c;
    scene::Sun& sun = w.scenario.sun;
    switch (e.kind) {
    case EventKind::SunOff:
        sun.enabled = false;
        c.global = true;
        break;
    case EventKind::SunOn:
        sun.enabled = true;
        if (!initial.scenario.sun.enabled && sun.intensity <= 0.0f) sun.intensity = 3.0f;
        c.global = true;
        break;
    case EventKind::SunDir:
        sun.toSun = glm::normalize(e.value);
        c.global = true;
        break;
    case EventKind::SunScale:
        sun.intensity *= e.scale;
        c.global = true;
        break;
    case EventKind::LightOff:
    case EventKind::LightOn:
    case EventKind::LightScale:
    case EventKind::LightMove:
        for (auto& l : w.scene.lights) {
            if (l.name != e.name) continue;
            c.points.push_back(l.position);
            if (l.type == scene::LightType::Directional) c.global = true;
            if (e.kind == EventKind::LightOff) l.intensity = 0.0f;
            if (e.kind == EventKind::LightScale) l.intensity *= e.scale;
            if (e.kind == EventKind::LightOn)
                if (const scene::Light* l0 = findLight(initial.scene, e.name))
                    l.intensity = l0->intensity;
            if (e.kind == EventKind::LightMove) {
                l.position = e.value;
                c.points.push_back(e.value);
            }
        }
        break;
    case EventKind::NodeRemove: {
        c.points.push_back(nodeBounds(w.scene, e.name).center());
        std::erase_if(w.scene.instances,
                      [&](const scene::Instance& i) { return i.nodeName == e.name && !i.dynamic; });
        break;
    }
    case EventKind::NodeInsert: {
        const glm::vec3 shift = e.value - nodeBounds(w.scene, e.name).center();
        std::vector<scene::Instance> copies;
        for (const auto& i : w.scene.instances)
            if (i.nodeName == e.name && !i.dynamic) {
                scene::Instance copy = i;
                copy.nodeName = e.name + "_inserted";
                copy.transform = glm::translate(glm::mat4(1.0f), shift) * i.transform;
                copies.push_back(copy);
            }
        w.scene.instances.insert(w.scene.instances.end(), copies.begin(), copies.end());
        c.points.push_back(e.value);
        break;
    }
    }
    // The renderer's direct light reads the scene's sun: keep the two in step.
    w.scene.sun = w.scenario.sun;
    return c;
}

} // namespace pb::respond
