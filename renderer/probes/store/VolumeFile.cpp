#include "probes/store/VolumeFile.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "core/TomlRead.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <toml++/toml.h>

namespace pb::probes {
namespace {

class Parser : public TomlReader {
public:
    using TomlReader::TomlReader;

    const toml::node& require(const toml::table& t, const char* key,
                              const std::string& what) const {
        const toml::node* n = t.get(key);
        if (!n) fail(t.source(), what + ": missing key '" + key + "'");
        return *n;
    }

    std::vector<double> numbers(const toml::node& n, std::size_t count, const std::string& what,
                                const char* key) const {
        const toml::array* a = n.as_array();
        std::string expect = "key '" + std::string(key) + "' must be an array of " +
                             std::to_string(count) + " numbers";
        if (!a || a->size() != count) fail(n.source(), what + ": " + expect);
        std::vector<double> out;
        for (const toml::node& e : *a) {
            std::optional<double> d = e.value<double>();
            if (!d || !std::isfinite(*d)) fail(n.source(), what + ": " + expect);
            // Every number ends up a float: 1e300 is a finite double but an infinite float.
            if (std::abs(*d) > double(std::numeric_limits<float>::max()))
                fail(n.source(), what + ": key '" + key + "': a number is too large for a float");
            out.push_back(*d);
        }
        return out;
    }

    glm::vec3 vec3(const toml::node& n, const std::string& what, const char* key) const {
        auto v = numbers(n, 3, what, key);
        return glm::vec3(float(v[0]), float(v[1]), float(v[2]));
    }

    std::string string(const toml::node& n, const std::string& what, const char* key) const {
        const auto* s = n.as_string();
        if (!s) fail(n.source(), what + ": key '" + key + "' must be a string");
        return s->get();
    }
};

struct VolumeLines {
    toml::source_region table, parent, probes, extents;
};

ProbeVolume parseVolume(const Parser& P, const toml::table& t, std::size_t i, VolumeLines& lines) {
    std::string what = "[[volume]] #" + std::to_string(i + 1);
    P.checkKeys(t,
                {"name", "center", "half_extents", "probes", "rotation", "quaternion", "parent",
                 "edge_blend"},
                what);
    ProbeVolume v;
    lines.table = t.source();
    v.name = P.string(P.require(t, "name", what), what, "name");
    what = "volume '" + v.name + "'";
    if (v.name.empty()) P.fail(t["name"].node()->source(), what + ": key 'name' is empty");
    v.center = P.vec3(P.require(t, "center", what), what, "center");
    const toml::node& ext = P.require(t, "half_extents", what);
    lines.extents = ext.source();
    v.halfExtents = P.vec3(ext, what, "half_extents");
    if (!(v.halfExtents.x > 0 && v.halfExtents.y > 0 && v.halfExtents.z > 0))
        P.fail(ext.source(), what + ": key 'half_extents' must be positive on every axis");
    const toml::node& probes = P.require(t, "probes", what);
    lines.probes = probes.source();
    const toml::array* pa = probes.as_array();
    if (!pa || pa->size() != 3)
        P.fail(probes.source(), what + ": key 'probes' must be an array of 3 integers");
    for (int a = 0; a < 3; ++a) {
        // Integers only: toml++ 3.3 converts a float such as 5e300 to int64 without a range
        // check (undefined behaviour), so value<int64_t>() is never asked for one.
        const toml::node& n = (*pa)[size_t(a)];
        const std::optional<std::int64_t> c =
            n.is_integer() ? n.value<std::int64_t>() : std::nullopt;
        if (!c) P.fail(probes.source(), what + ": key 'probes' must be an array of 3 integers");
        if (*c < 1)
            P.fail(probes.source(), what + ": key 'probes': every axis needs at least 1 probe "
                                           "(a volume with zero probes bakes nothing)");
        if (*c > kMaxProbesPerAxis)
            P.fail(probes.source(), what + ": key 'probes': at most " +
                                        std::to_string(kMaxProbesPerAxis) + " per axis");
        v.counts[a] = int(*c);
    }
    const toml::node* rot = t.get("rotation");
    const toml::node* quat = t.get("quaternion");
    if (rot && quat) P.fail(quat->source(), what + ": give 'rotation' or 'quaternion', not both");
    if (rot) v.rotation = rotationFromEulerDegrees(P.vec3(*rot, what, "rotation"));
    if (quat) {
        auto q = P.numbers(*quat, 4, what, "quaternion");
        glm::quat g{float(q[3]), float(q[0]), float(q[1]), float(q[2])};
        float len = glm::length(glm::vec4(g.x, g.y, g.z, g.w));
        if (!(len > 1e-6f)) P.fail(quat->source(), what + ": key 'quaternion' is zero");
        v.rotation = glm::normalize(g);
    }
    if (const toml::node* p = t.get("parent")) {
        lines.parent = p->source();
        v.parent = P.string(*p, what, "parent");
    }
    if (const toml::node* b = t.get("edge_blend")) {
        std::optional<double> d = b->value<double>();
        if (!d || !(*d >= 0.0 && *d <= 1.0))
            P.fail(b->source(), what + ": key 'edge_blend' must be a number in [0, 1]");
        v.edgeBlend = float(*d);
    }
    std::string problem = volumeProblem(v);
    if (!problem.empty()) P.fail(t.source(), what + ": " + problem);
    return v;
}

ScenarioSpec parseScenario(const Parser& P, const toml::table& t, std::size_t i) {
    std::string what = "[[scenario]] #" + std::to_string(i + 1);
    P.checkKeys(t, {"name", "sun", "sky"}, what);
    ScenarioSpec s;
    s.name = P.string(P.require(t, "name", what), what, "name");
    what = "scenario '" + s.name + "'";
    if (s.name.empty()) P.fail(t.source(), what + ": key 'name' is empty");
    if (const toml::node* sun = t.get("sun")) {
        scene::Sun out;
        if (const auto* str = sun->as_string()) {
            if (str->get() != "off")
                P.fail(sun->source(), what + ": key 'sun' must be \"off\" or a table");
            out.enabled = false;
        } else if (const auto* st = sun->as_table()) {
            P.checkKeys(*st, {"direction", "intensity", "color"}, what + " sun");
            glm::vec3 dir = P.vec3(P.require(*st, "direction", what + " sun"), what, "direction");
            // Scaled first: the length of (3e38, 3e38, 0) overflows a float.
            const glm::vec3 a = glm::abs(dir);
            const float largest = std::max(a.x, std::max(a.y, a.z));
            if (!(largest > 0.0f)) P.fail(st->source(), what + ": sun direction must not be zero");
            out.toSun = glm::normalize(dir / largest);
            std::optional<double> in = P.require(*st, "intensity", what + " sun").value<double>();
            if (!in || !(*in >= 0.0) || *in > double(std::numeric_limits<float>::max()))
                P.fail(st->source(), what + ": sun intensity must be a finite number >= 0");
            out.intensity = float(*in);
            out.color = glm::vec3(1.0f);
            if (const toml::node* c = st->get("color")) {
                out.color = P.vec3(*c, what, "color");
                if (glm::any(glm::lessThan(out.color, glm::vec3(0.0f))))
                    P.fail(c->source(), what + ": sun color must be >= 0");
            }
        } else {
            P.fail(sun->source(), what + ": key 'sun' must be \"off\" or a table");
        }
        s.sun = out;
    }
    if (const toml::node* sky = t.get("sky")) {
        glm::vec3 l = P.vec3(*sky, what, "sky");
        if (l.x < 0 || l.y < 0 || l.z < 0) P.fail(sky->source(), what + ": sky must be >= 0");
        s.sky = scene::Sky{l};
    }
    return s;
}

template <class F>
void forEachTable(const Parser& P, const toml::table& root, const char* key, F fn) {
    const toml::node* n = root.get(key);
    if (!n) return;
    const toml::array* arr = n->as_array();
    if (!arr || !arr->is_array_of_tables())
        P.fail(n->source(), std::string("'") + key + "' must be written as [[" + key + "]] tables");
    for (std::size_t i = 0; i < arr->size(); ++i)
        fn(*(*arr)[i].as_table(), i);
}

} // namespace

VolumeFile parseVolumeToml(std::string_view text, const std::string& path) {
    Parser P(path);
    const toml::table root = parseTomlText(text, path);
    P.checkKeys(root, {"volume", "scenario"}, "the file");
    VolumeFile out;
    std::vector<VolumeLines> lines;
    forEachTable(P, root, "volume", [&](const toml::table& t, std::size_t i) {
        lines.emplace_back();
        out.volumes.push_back(parseVolume(P, t, i, lines.back()));
    });
    forEachTable(P, root, "scenario", [&](const toml::table& t, std::size_t i) {
        out.scenarios.push_back(parseScenario(P, t, i));
    });
    if (out.volumes.empty())
        throw fileError(path, "no [[volume]] tables (a volumes file needs at least one)");

    // Cross-volume rules, reported at the offending key.
    std::map<std::string, std::size_t> byName;
    for (std::size_t i = 0; i < out.volumes.size(); ++i)
        if (!byName.emplace(out.volumes[i].name, i).second)
            P.fail(lines[i].table, "duplicate volume name '" + out.volumes[i].name + "'");
    std::set<std::string> scenarioNames;
    for (const auto& s : out.scenarios)
        if (!scenarioNames.insert(s.name).second)
            throw fileError(path, "duplicate scenario name '" + s.name + "'");
    for (std::size_t i = 0; i < out.volumes.size(); ++i) {
        const ProbeVolume& v = out.volumes[i];
        if (v.parent.empty()) continue;
        auto it = byName.find(v.parent);
        if (it == byName.end())
            P.fail(lines[i].parent,
                   "volume '" + v.name + "': key 'parent': unknown volume '" + v.parent + "'");
        if (it->second == i) P.fail(lines[i].parent, "volume '" + v.name + "' is its own parent");
        std::string problem = nestingProblem(v, out.volumes[it->second]);
        if (!problem.empty()) P.fail(lines[i].parent, "key 'parent': " + problem);
    }
    validateVolumes(out.volumes, path); // cycles (a loop of equal boxes) and anything left
    return out;
}

namespace {

// Shortest text that reads back (as TOML does: a double, then cast to float) to exactly `f`.
std::string floatText(float f) {
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, f);
    std::string s(buf, r.ptr);
    if (float(std::strtod(s.c_str(), nullptr)) != f) {
        r = std::to_chars(buf, buf + sizeof buf, double(f));
        s.assign(buf, r.ptr);
    }
    // TOML needs a fraction or exponent to read a float.
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string vecText(std::initializer_list<float> v) {
    std::string out = "[";
    for (float f : v)
        out += (out.size() > 1 ? ", " : "") + floatText(f);
    return out + "]";
}

} // namespace

std::string volumeFileText(const std::vector<ProbeVolume>& volumes, const std::string& header) {
    std::string out;
    std::size_t begin = 0;
    while (begin < header.size()) {
        std::size_t end = header.find('\n', begin);
        if (end == std::string::npos) end = header.size();
        out += "# " + header.substr(begin, end - begin) + "\n";
        begin = end + 1;
    }
    for (const ProbeVolume& v : volumes) {
        if (!out.empty()) out += '\n';
        out += "[[volume]]\n";
        out += "name = " + quoted(v.name) + "\n";
        if (!v.parent.empty()) out += "parent = " + quoted(v.parent) + "\n";
        out += "center = " + vecText({v.center.x, v.center.y, v.center.z}) + "\n";
        out +=
            "half_extents = " + vecText({v.halfExtents.x, v.halfExtents.y, v.halfExtents.z}) + "\n";
        out += "probes = [" + std::to_string(v.counts.x) + ", " + std::to_string(v.counts.y) +
               ", " + std::to_string(v.counts.z) + "]\n";
        const glm::quat& q = v.rotation;
        if (!(q.x == 0.0f && q.y == 0.0f && q.z == 0.0f && q.w == 1.0f))
            out += "quaternion = " + vecText({q.x, q.y, q.z, q.w}) + "\n";
        if (!v.parent.empty()) out += "edge_blend = " + floatText(v.edgeBlend) + "\n";
    }
    return out;
}

void writeVolumeFile(const std::string& path, const std::vector<ProbeVolume>& volumes,
                     const std::string& header) {
    validateVolumes(volumes, path);
    std::string text = volumeFileText(volumes, header);
    writeFileAtomic(path, text.data(), text.size());
}

VolumeFile loadVolumeFile(const std::string& path) {
    std::vector<unsigned char> bytes = readFileBytes(path);
    return parseVolumeToml(
        std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
}

} // namespace pb::probes
