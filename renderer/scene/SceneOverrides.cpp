// --sun, --sky and --camera: the command-line overrides that apply to any scene.
#include "core/Error.h"
#include "scene/SceneLoader.h"

#include <charconv>
#include <cmath>

namespace pb::scene {

namespace {

std::string trim(const std::string& s) {
    const size_t first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// Comma-separated finite numbers; nullopt on anything else (empty fields, junk, nan, inf).
std::optional<std::vector<float>> parseNumbers(const std::string& spec) {
    std::vector<float> values;
    size_t start = 0;
    while (true) {
        const size_t comma = spec.find(',', start);
        const std::string field = trim(
            spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        float v = 0.0f;
        const char* end = field.data() + field.size();
        auto [ptr, ec] = std::from_chars(field.data(), end, v);
        if (field.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) return {};
        values.push_back(v);
        if (comma == std::string::npos) return values;
        start = comma + 1;
    }
}

Error optionError(const std::string& option, const std::string& spec, const std::string& problem) {
    return Error(option + " '" + spec + "': " + problem);
}

} // namespace

void applySunOverride(Scene& scene, const std::string& spec) {
    if (trim(spec) == "off") {
        scene.sun.enabled = false;
        return;
    }
    const auto values = parseNumbers(spec);
    if (!values || (values->size() != 3 && values->size() != 4))
        throw optionError("--sun", spec, "expected off or DIRX,DIRY,DIRZ[,INTENSITY]");
    const glm::vec3 dir((*values)[0], (*values)[1], (*values)[2]);
    const float len = glm::length(dir);
    if (!(len > 1e-6f) || !std::isfinite(len))
        throw optionError("--sun", spec, "the direction towards the sun must not be zero");
    if (values->size() == 4 && (*values)[3] < 0.0f)
        throw optionError("--sun", spec, "intensity must not be negative");
    scene.sun.enabled = true;
    scene.sun.toSun = dir / len;
    if (values->size() == 4) scene.sun.intensity = (*values)[3];
}

void applySkyOverride(Scene& scene, const std::string& spec) {
    const auto values = parseNumbers(spec);
    if (!values || values->size() != 3) throw optionError("--sky", spec, "expected R,G,B");
    for (float v : *values)
        if (v < 0.0f) throw optionError("--sky", spec, "radiance must not be negative");
    scene.sky.radiance = glm::vec3((*values)[0], (*values)[1], (*values)[2]);
}

View parseCameraSpec(const std::string& spec) {
    const auto values = parseNumbers(spec);
    if (!values || (values->size() != 6 && values->size() != 7))
        throw optionError("--camera", spec, "expected PX,PY,PZ,TX,TY,TZ[,FOVY_DEGREES]");
    const std::vector<float>& v = *values;
    View view;
    view.name = "camera";
    view.position = glm::vec3(v[0], v[1], v[2]);
    view.target = glm::vec3(v[3], v[4], v[5]);
    if (v.size() == 7) view.fovYDegrees = v[6];
    if (!(view.fovYDegrees > 0.0f && view.fovYDegrees < 180.0f))
        throw optionError("--camera", spec, "field of view must be in (0, 180) degrees");
    if (view.position == view.target)
        throw optionError("--camera", spec, "position and target must differ");
    return view;
}

} // namespace pb::scene
