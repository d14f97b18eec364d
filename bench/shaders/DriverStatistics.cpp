#include "DriverStatistics.h"

#include <algorithm>
#include <cstdlib>

namespace pb::shaders {
namespace {

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    const size_t b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

std::vector<std::string> splitItems(const std::string& s) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < s.size()) {
        size_t comma = s.find(',', start);
        if (comma == std::string::npos) comma = s.size();
        if (std::string item = trim(s.substr(start, comma - start)); !item.empty())
            out.push_back(item);
        start = comma + 1;
    }
    return out;
}

bool parseNumber(const std::string& text, double& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end && *end == '\0';
}

// "VERT", "MESA_SHADER_FRAGMENT", ... -> "vertex", "fragment"; Bifrost's IDVS splits a vertex
// shader into a position and a varying shader, v3d compiles a binning (coordinate) shader.
std::string normalStage(const std::string& driverStage) {
    std::string s = driverStage;
    if (s.rfind("MESA_SHADER_", 0) == 0) s = s.substr(12);
    if (s == "VERT" || s == "VERTEX" || s == "POSITION") return "vertex";
    if (s == "VARYING") return "vertex-varying";
    if (s == "VERTEX_BIN") return "vertex-bin";
    if (s == "FRAG" || s == "FRAGMENT") return "fragment";
    if (s == "COMPUTE" || s == "COMPUTE_SHADER") return "compute";
    std::string lower = s;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return lower;
}

// nouveau writes gallium's pipe_shader_type, in gl_shader_stage order (p_defines.h in 22.3):
// vertex 0, tess control 1, tess evaluation 2, geometry 3, fragment 4, compute 5.
std::string nouveauStage(double type) {
    static const char* kNames[] = {"vertex",   "tess-control", "tess-evaluation",
                                   "geometry", "fragment",     "compute"};
    if (type >= 0 && type < 6) return kNames[int(type)];
    return "type-" + std::to_string(int(type));
}

// "<value> <name>" items; "6:43 spills:fills" gives two fields.
bool parseValueFirst(const std::vector<std::string>& items, StageStatistics& out) {
    for (const std::string& item : items) {
        const size_t space = item.find(' ');
        if (space == std::string::npos) return false;
        const std::string value = item.substr(0, space), name = trim(item.substr(space + 1));
        const size_t colon = value.find(':'), nameColon = name.find(':');
        if (colon != std::string::npos && nameColon != std::string::npos) {
            double a = 0, b = 0;
            if (!parseNumber(value.substr(0, colon), a) || !parseNumber(value.substr(colon + 1), b))
                return false;
            out.fields[name.substr(0, nameColon)] = a;
            out.fields[name.substr(nameColon + 1)] = b;
            continue;
        }
        double v = 0;
        if (!parseNumber(value, v)) return false;
        out.fields[name] = v;
    }
    return !out.fields.empty();
}

// "<name>: <value>" items (nouveau).
bool parseNameFirst(const std::vector<std::string>& items, StageStatistics& out) {
    for (const std::string& item : items) {
        const size_t colon = item.find(':');
        if (colon == std::string::npos) return false;
        double v = 0;
        if (!parseNumber(trim(item.substr(colon + 1)), v)) return false;
        out.fields[trim(item.substr(0, colon))] = v;
    }
    return !out.fields.empty();
}

} // namespace

std::optional<StageStatistics> parseStatisticsLine(const std::string& message) {
    const std::string line = trim(message);
    StageStatistics s;
    if (line.rfind("type: ", 0) == 0) {
        if (!parseNameFirst(splitItems(line), s) || !s.has("inst") || !s.has("gpr"))
            return std::nullopt;
        s.driverStage = "type " + std::to_string(int(s.field("type")));
        s.stage = nouveauStage(s.field("type"));
        return s;
    }
    const size_t marker = line.find(" shader: ");
    if (marker == std::string::npos || marker == 0) return std::nullopt;
    s.driverStage = line.substr(0, marker);
    if (s.driverStage.find(' ') != std::string::npos) return std::nullopt;
    if (!parseValueFirst(splitItems(line.substr(marker + 9)), s) || !s.has("inst"))
        return std::nullopt;
    s.stage = normalStage(s.driverStage);
    return s;
}

double StageStatistics::field(const std::string& name, double fallback) const {
    const auto it = fields.find(name);
    return it == fields.end() ? fallback : it->second;
}

double StageStatistics::instructions() const {
    return field("inst");
}
double StageStatistics::cycles() const {
    return field("cycles");
}
double StageStatistics::spills() const {
    return field("spills");
}
double StageStatistics::fills() const {
    return field("fills");
}

double StageStatistics::fullRegisters() const {
    if (has("full")) return field("full");
    if (has("max-temps")) return field("max-temps");
    if (has("registers")) return field("registers"); // Midgard: work registers
    return field("gpr");
}

double StageStatistics::halfRegisters() const {
    return field("half");
}

double StageStatistics::occupancy() const {
    if (has("waves")) return field("waves");
    return field("threads");
}

std::vector<std::pair<std::string, double>> StageStatistics::unitCycles() const {
    // Bifrost's units, then Valhall's; a line has one set or the other.
    static const char* kUnits[] = {"arith", "texture", "vary", "ldst", "fma",
                                   "cvt",   "sfu",     "v",    "t",    "ls"};
    std::vector<std::pair<std::string, double>> out;
    if (!has("cycles")) return out;
    for (const char* u : kUnits)
        if (has(u)) out.emplace_back(u, field(u));
    return out;
}

std::string StageStatistics::boundUnit() const {
    std::string best;
    double most = -1;
    for (const auto& [unit, c] : unitCycles())
        if (c > most) {
            most = c;
            best = unit;
        }
    return best;
}

} // namespace pb::shaders
