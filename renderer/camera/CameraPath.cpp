#include "camera/CameraPath.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace pb::camera {

namespace {

constexpr double kKeyStep = 0.125; // seconds between the keys of the analytic built-ins

glm::dvec3 rotateY(const glm::dvec3& v, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

// The view direction turns at a constant rate between keys (spherical interpolation of the
// directions; the distance to the target is interpolated linearly).
glm::dvec3 lookBetween(const glm::dvec3& a, const glm::dvec3& b, double u) {
    const double la = glm::length(a), lb = glm::length(b);
    const glm::dvec3 da = a / la, db = b / lb;
    const double angle = std::acos(std::clamp(glm::dot(da, db), -1.0, 1.0));
    glm::dvec3 d;
    if (angle < 1e-9)
        d = da;
    else if (angle > glm::pi<double>() - 1e-6) // opposite: no unique arc, blend through
        d = glm::normalize(glm::mix(da, db, u) + glm::dvec3(1e-6, 0, 0));
    else
        d = (std::sin((1.0 - u) * angle) * da + std::sin(u * angle) * db) / std::sin(angle);
    return d * glm::mix(la, lb, u);
}

CameraKey keyOf(const scene::View& v, double time) {
    CameraKey k;
    k.time = time;
    k.position = glm::dvec3(v.position);
    k.target = glm::dvec3(v.target);
    k.fovYDegrees = v.fovYDegrees;
    return k;
}

// Turning left (counter-clockwise seen from above) at `degPerSecond` for `seconds`, then
// holding for `hold` seconds.
CameraPath turning(const std::string& name, const scene::View& start, double degPerSecond,
                   double seconds, double hold) {
    CameraPath p;
    p.name = name;
    const CameraKey first = keyOf(start, 0.0);
    const glm::dvec3 look = first.target - first.position;
    for (double t = 0.0; t <= seconds + 1e-9; t += kKeyStep) {
        CameraKey k = first;
        k.time = t;
        k.target = first.position + rotateY(look, glm::radians(degPerSecond * t));
        p.keys.push_back(k);
    }
    if (hold > 0) {
        CameraKey k = p.keys.back();
        k.time += hold;
        p.keys.push_back(k);
    }
    return p;
}

CameraPath doorwayWalk(const scene::Scene& s) {
    if (s.name != "rooms" || !s.findView("doorway"))
        throw Error("--path doorway_walk: needs the built-in 'rooms' scene (its doorway); scene '" +
                    s.name + "' has none");
    // The partition is at x = 0 with a doorway z in [-0.45, 0.45], y in [0, 2.1]: walk along
    // z = 0 at eye height 1.6 from the dark room (x = 3) into the sunlit room (x = -3), looking
    // at a point on the sunlit room's far wall, so the door jambs sweep out of view and uncover
    // the room behind them.
    CameraPath p;
    p.name = "doorway_walk";
    const glm::dvec3 from(3.0, 1.6, 0.0), to(-3.0, 1.6, 0.0), lookAt(-4.0, 1.0, 0.6);
    const double speed = 1.5, seconds = glm::length(to - from) / speed;
    for (double t = 0.0; t <= seconds + 1e-9; t += kKeyStep) {
        CameraKey k;
        k.time = t;
        k.position = glm::mix(from, to, std::min(1.0, t / seconds));
        k.target = lookAt;
        k.fovYDegrees = 60.0f;
        p.keys.push_back(k);
    }
    return p;
}

} // namespace

int CameraPath::naturalFrameCount() const {
    if (keys.empty()) return 0;
    return int(std::floor(keys.back().time * fps + 1e-6)) + 1;
}

std::vector<PathFrame> playPath(const CameraPath& path, int frames) {
    std::vector<PathFrame> out;
    if (path.keys.empty()) return out;
    size_t seg = 0;         // keys[seg] is the last key at or before the frame's time
    size_t lastCutSeen = 0; // index of the latest cut key already applied
    for (int i = 0; i < frames; ++i) {
        PathFrame f;
        f.index = i;
        f.time = double(i) / path.fps;
        f.cut = i == 0;
        while (seg + 1 < path.keys.size() && path.keys[seg + 1].time <= f.time + 1e-9)
            ++seg;
        for (size_t k = lastCutSeen + 1; k <= seg; ++k)
            if (path.keys[k].cut) f.cut = true;
        lastCutSeen = std::max(lastCutSeen, seg);
        CameraKey c = path.keys[seg];
        if (seg + 1 < path.keys.size() && !path.keys[seg + 1].cut) {
            const CameraKey& b = path.keys[seg + 1];
            const double u = (f.time - c.time) / (b.time - c.time);
            c.position = glm::mix(c.position, b.position, u);
            c.target = c.position +
                       lookBetween(c.target - path.keys[seg].position, b.target - b.position, u);
            c.fovYDegrees = float(glm::mix(double(c.fovYDegrees), double(b.fovYDegrees), u));
        }
        f.view.name = path.name + " #" + std::to_string(i);
        f.view.position = glm::vec3(c.position);
        f.view.target = glm::vec3(c.target);
        f.view.fovYDegrees = c.fovYDegrees;
        out.push_back(f);
    }
    return out;
}

const std::vector<std::string>& builtinPathNames() {
    static const std::vector<std::string> names = {"static", "slow_pan", "fast_turn",
                                                   "doorway_walk"};
    return names;
}

bool isBuiltinPath(const std::string& name) {
    const auto& n = builtinPathNames();
    return std::find(n.begin(), n.end(), name) != n.end();
}

CameraPath makeBuiltinPath(const std::string& name, const scene::Scene& scene,
                           const scene::View& start) {
    if (name == "static") {
        CameraPath p;
        p.name = name;
        p.keys = {keyOf(start, 0.0), keyOf(start, 2.0)};
        return p;
    }
    if (name == "slow_pan") return turning(name, start, 10.0, 4.0, 0.0);
    if (name == "fast_turn") return turning(name, start, 180.0, 1.0, 1.0);
    if (name == "doorway_walk") return doorwayWalk(scene);
    std::string list;
    for (const auto& n : builtinPathNames())
        list += (list.empty() ? "" : ", ") + n;
    throw Error("--path '" + name + "': not a built-in path (" + list + ") or a path file");
}

} // namespace pb::camera
