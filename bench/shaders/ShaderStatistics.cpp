#include "ShaderStatistics.h"

#include "core/Error.h"

#include <algorithm>

namespace pb::shaders {

const StageStatistics* ProgramStatistics::stage(const std::string& name) const {
    for (const StageStatistics& s : stages)
        if (s.stage == name) return &s;
    return nullptr;
}

const VariantStatistics* TargetStatistics::variant(const std::string& id) const {
    for (const VariantStatistics& v : variants)
        if (v.id == id) return &v;
    return nullptr;
}

const ProgramStatistics* TargetStatistics::heaviestFragment(const VariantStatistics& v,
                                                            const std::string& pass) const {
    const ProgramStatistics* best = nullptr;
    double most = -1;
    for (int i : v.programs) {
        const ProgramStatistics& p = programs.at(size_t(i));
        const StageStatistics* f = p.stage("fragment");
        if (p.pass != pass || !f) continue;
        if (f->instructions() > most) {
            most = f->instructions();
            best = &p;
        }
    }
    return best;
}

std::vector<std::string> TargetStatistics::passes(const VariantStatistics& v) const {
    std::vector<std::string> out;
    for (int i : v.programs) {
        const std::string& pass = programs.at(size_t(i)).pass;
        if (std::find(out.begin(), out.end(), pass) == out.end()) out.push_back(pass);
    }
    return out;
}

nlohmann::json toJson(const StageStatistics& s) {
    nlohmann::json j = {{"stage", s.stage}, {"driver_stage", s.driverStage}, {"fields", s.fields}};
    // The figures the tables compare, under one name whatever the driver calls them.
    j["instructions"] = s.instructions();
    if (s.cycles() >= 0) j["cycles"] = s.cycles();
    if (const std::string b = s.boundUnit(); !b.empty()) j["bound_unit"] = b;
    if (s.fullRegisters() >= 0) j["registers_full"] = s.fullRegisters();
    if (s.halfRegisters() >= 0) j["registers_half"] = s.halfRegisters();
    if (s.occupancy() >= 0) j["occupancy"] = s.occupancy();
    if (s.spills() >= 0) j["spills"] = s.spills();
    if (s.fills() >= 0) j["fills"] = s.fills();
    return j;
}

namespace {

nlohmann::json programJson(const ProgramStatistics& p) {
    nlohmann::json stages = nlohmann::json::array();
    for (const StageStatistics& s : p.stages)
        stages.push_back(toJson(s));
    nlohmann::json j = {{"pass", p.pass},
                        {"vertex", p.vertex},
                        {"fragment", p.fragment},
                        {"defines", p.defines},
                        {"stages", stages}};
    if (!p.error.empty()) j["error"] = p.error;
    return j;
}

nlohmann::json variantJson(const VariantStatistics& v) {
    nlohmann::json j = {{"id", v.id},
                        {"label", v.label},
                        {"profile", v.profile},
                        {"role", v.role},
                        {"programs", v.programs}};
    if (!v.switchKey.empty()) j["switch"] = v.switchKey;
    if (!v.notRun.empty()) j["not_run"] = v.notRun;
    return j;
}

template <class T> T get(const nlohmann::json& j, const char* key, T fallback) {
    const auto it = j.find(key);
    return it == j.end() || it->is_null() ? fallback : it->get<T>();
}

} // namespace

nlohmann::json toJson(const TargetStatistics& t) {
    nlohmann::json programs = nlohmann::json::array(), variants = nlohmann::json::array();
    for (const ProgramStatistics& p : t.programs)
        programs.push_back(programJson(p));
    for (const VariantStatistics& v : t.variants)
        variants.push_back(variantJson(v));
    nlohmann::json j = {{"target", t.target},          {"device", t.device},
                        {"driver", t.driver},          {"gl_version", t.glVersion},
                        {"gl_renderer", t.glRenderer}, {"glsl_version", t.glslVersion},
                        {"programs", programs},        {"variants", variants}};
    if (!t.note.empty()) j["note"] = t.note;
    if (!t.error.empty()) j["error"] = t.error;
    return j;
}

nlohmann::json toJson(const ShaderStatisticsRun& r) {
    nlohmann::json pairs = nlohmann::json::array(), targets = nlohmann::json::array();
    for (const SwitchPair& p : r.pairs)
        pairs.push_back({{"profile", p.profile},
                         {"kind", p.kind},
                         {"switch", p.switchKey},
                         {"off_value", p.offValue},
                         {"on_value", p.onValue},
                         {"off_variant", p.offVariant},
                         {"on_variant", p.onVariant}});
    for (const TargetStatistics& t : r.targets)
        targets.push_back(toJson(t));
    return {{"mesa_version", r.mesaVersion},
            {"mesa_dir", r.mesaDir},
            {"scene", r.scene},
            {"probes", r.probes},
            {"camera", r.camera},
            {"width", r.width},
            {"height", r.height},
            {"switch_pairs", pairs},
            {"targets", targets}};
}

TargetStatistics targetStatisticsFromJson(const nlohmann::json& j) {
    try {
        TargetStatistics t;
        t.target = get<std::string>(j, "target", "");
        t.device = get<std::string>(j, "device", "");
        t.driver = get<std::string>(j, "driver", "");
        t.note = get<std::string>(j, "note", "");
        t.error = get<std::string>(j, "error", "");
        t.glVersion = get<std::string>(j, "gl_version", "");
        t.glRenderer = get<std::string>(j, "gl_renderer", "");
        t.glslVersion = get<std::string>(j, "glsl_version", "");
        for (const nlohmann::json& pj : j.value("programs", nlohmann::json::array())) {
            ProgramStatistics p;
            p.pass = pj.at("pass").get<std::string>();
            p.vertex = pj.at("vertex").get<std::string>();
            p.fragment = pj.at("fragment").get<std::string>();
            p.defines = pj.at("defines").get<std::string>();
            p.error = get<std::string>(pj, "error", "");
            for (const nlohmann::json& sj : pj.at("stages")) {
                StageStatistics s;
                s.stage = sj.at("stage").get<std::string>();
                s.driverStage = sj.at("driver_stage").get<std::string>();
                s.fields = sj.at("fields").get<std::map<std::string, double>>();
                p.stages.push_back(std::move(s));
            }
            t.programs.push_back(std::move(p));
        }
        for (const nlohmann::json& vj : j.value("variants", nlohmann::json::array())) {
            VariantStatistics v;
            v.id = vj.at("id").get<std::string>();
            v.label = get<std::string>(vj, "label", "");
            v.profile = get<std::string>(vj, "profile", "");
            v.role = get<std::string>(vj, "role", "");
            v.switchKey = get<std::string>(vj, "switch", "");
            v.notRun = get<std::string>(vj, "not_run", "");
            v.programs = vj.at("programs").get<std::vector<int>>();
            for (int i : v.programs)
                if (i < 0 || size_t(i) >= t.programs.size())
                    throw Error("variant " + v.id + " names program " + std::to_string(i) + " of " +
                                std::to_string(t.programs.size()));
            t.variants.push_back(std::move(v));
        }
        return t;
    } catch (const nlohmann::json::exception& e) {
        throw Error(std::string("shader statistics: malformed JSON (") + e.what() + ")");
    }
}

} // namespace pb::shaders
