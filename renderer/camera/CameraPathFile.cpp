// TOML camera paths (format: renderer/camera/README.md). Every mistake is reported as
// "FILE:LINE: problem" at the offending key.
#include "camera/CameraPath.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "core/TomlRead.h"

#include <cmath>
#include <filesystem>
#include <set>
#include <toml++/toml.h>

namespace pb::camera {

namespace {

class Reader : public TomlReader {
public:
    using TomlReader::TomlReader;

    double number(const toml::node& n, const std::string& what) const {
        std::optional<double> d = n.value<double>();
        if (!d || !std::isfinite(*d)) fail(n.source(), what + " must be a finite number");
        return *d;
    }

    glm::dvec3 vec3(const toml::node& n, const std::string& what) const {
        const toml::array* a = n.as_array();
        if (!a || a->size() != 3) fail(n.source(), what + " must be an array of 3 numbers");
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = number(*a->get(size_t(i)), what);
        return v;
    }
};

} // namespace

CameraPath parseCameraPathToml(const std::string& text, const std::string& path) {
    Reader R(path);
    const toml::table root = parseTomlText(text, path);
    R.checkKeys(root, {"name", "fps", "key"}, "the file");
    CameraPath out;
    out.name = std::filesystem::path(path).stem().string();
    if (const toml::node* n = root.get("name")) {
        if (!n->is_string()) R.fail(n->source(), "'name' must be a string");
        out.name = n->as_string()->get();
    }
    if (const toml::node* n = root.get("fps")) {
        out.fps = R.number(*n, "'fps'");
        if (out.fps <= 0 || out.fps > 1000) R.fail(n->source(), "'fps' must be in (0, 1000]");
    }
    const toml::node* keys = root.get("key");
    if (!keys) throw fileError(path, "no [[key]] tables (a path needs at least one keyframe)");
    const toml::array* arr = keys->as_array();
    if (!arr || !arr->is_array_of_tables())
        R.fail(keys->source(), "'key' must be written as [[key]] tables");
    for (size_t i = 0; i < arr->size(); ++i) {
        const toml::table& t = *arr->get(i)->as_table();
        const std::string what = "[[key]] #" + std::to_string(i + 1);
        R.checkKeys(t, {"time", "position", "target", "fov", "cut"}, what);
        CameraKey k;
        for (const char* required : {"time", "position", "target"})
            if (!t.get(required)) R.fail(t.source(), what + ": missing key '" + required + "'");
        k.time = R.number(*t.get("time"), what + ": 'time'");
        k.position = R.vec3(*t.get("position"), what + ": 'position'");
        k.target = R.vec3(*t.get("target"), what + ": 'target'");
        k.fovYDegrees = out.keys.empty() ? 60.0f : out.keys.back().fovYDegrees;
        if (const toml::node* n = t.get("fov")) {
            k.fovYDegrees = float(R.number(*n, what + ": 'fov'"));
            if (!(k.fovYDegrees > 1.0f && k.fovYDegrees < 179.0f))
                R.fail(n->source(), what + ": 'fov' must be in (1, 179) degrees");
        }
        if (const toml::node* n = t.get("cut")) {
            if (!n->is_boolean()) R.fail(n->source(), what + ": 'cut' must be true or false");
            k.cut = n->as_boolean()->get();
        }
        if (glm::length(k.target - k.position) <= 0.0)
            R.fail(t.source(), what + ": 'position' and 'target' coincide");
        if (i == 0 && k.time != 0.0)
            R.fail(t.get("time")->source(), what + ": the first key's 'time' must be 0");
        if (i > 0 && k.time <= out.keys.back().time)
            R.fail(t.get("time")->source(), what + ": 'time' must increase from key to key");
        out.keys.push_back(k);
    }
    if (out.keys.empty())
        throw fileError(path, "no [[key]] tables (a path needs at least one keyframe)");
    return out;
}

CameraPath readCameraPathFile(const std::string& path) {
    const std::vector<unsigned char> bytes = readFileBytes(path);
    return parseCameraPathToml(std::string(bytes.begin(), bytes.end()), path);
}

} // namespace pb::camera
