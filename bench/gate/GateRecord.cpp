#include "GateRecord.h"

#include "bench/shaders/ShaderTargets.h"
#include "core/Error.h"
#include "core/FileIO.h"

#include <cmath>
#include <limits>

namespace pb::gate {

namespace {

using nlohmann::json;

// Reads j[key] as T; `where` is the path of j in the file ("profiles[2].accuracy").
template <class T> T field(const json& j, const std::string& key, const std::string& where) {
    const std::string at = where.empty() ? key : where + "." + key;
    if (!j.is_object() || !j.contains(key)) throw Error(at + ": missing");
    try {
        return j.at(key).get<T>();
    } catch (const json::exception&) {
        throw Error(at + ": wrong type");
    }
}

template <class T>
T optionalField(const json& j, const std::string& key, const std::string& where, T fallback) {
    return j.is_object() && j.contains(key) ? field<T>(j, key, where) : fallback;
}

json countersJson(const Counters& c) {
    json o = json::object();
    for (const auto& [k, v] : c)
        o[k] = v;
    return o;
}

Counters countersFrom(const json& j, const std::string& where) {
    if (!j.is_object()) throw Error(where + ": must be an object of integers");
    Counters c;
    for (const auto& [k, v] : j.items()) {
        if (!v.is_number_integer()) throw Error(where + "." + k + ": must be an integer");
        c.emplace_back(k, v.get<std::int64_t>());
    }
    return c;
}

// JSON has no infinity: an identical image's PSNR is stored as null.
json psnrJson(double db) {
    return std::isfinite(db) ? json(db) : json(nullptr);
}
double psnrFrom(const json& j, const std::string& where) {
    if (!j.contains("psnr")) throw Error(where + ".psnr: missing");
    if (j.at("psnr").is_null()) return std::numeric_limits<double>::infinity();
    return field<double>(j, "psnr", where);
}

json suiteJson(const GateSuite& s) {
    const TimingSettings& t = s.timing;
    const AccuracyTolerance& a = s.tolerance;
    return {{"scene", s.scene},
            {"volumes", s.volumes},
            {"camera", s.camera},
            {"width", s.width},
            {"height", s.height},
            {"profiles", s.profiles},
            {"reference", s.reference},
            {"timing",
             {{"method", t.method},
              {"frames", t.frames},
              {"warmup", t.warmup},
              {"min_rounds", t.minRounds},
              {"max_rounds", t.maxRounds},
              {"quick_max_rounds", t.quickMaxRounds},
              {"round_step", t.roundStep},
              {"time_budget_s", t.timeBudgetSeconds},
              {"quick_time_budget_s", t.quickTimeBudgetSeconds},
              {"alpha", t.alpha},
              {"threshold", t.threshold},
              {"ratio_threshold", t.ratioThreshold}}},
            {"accuracy_tolerance",
             {{"flip_mean_abs", a.flipAbs},
              {"flip_mean_rel", a.flipRel},
              {"psnr_db", a.psnrDb},
              {"rel_mse_gi_abs", a.relMseAbs},
              {"rel_mse_gi_rel", a.relMseRel}}},
            {"callgrind_tolerance", s.callgrindTolerance},
            {"shader_targets", s.shaderTargets}};
}

GateSuite suiteFrom(const json& j, const std::string& where) {
    GateSuite s;
    s.scene = field<std::string>(j, "scene", where);
    s.volumes = field<std::string>(j, "volumes", where);
    s.camera = field<std::string>(j, "camera", where);
    s.width = field<int>(j, "width", where);
    s.height = field<int>(j, "height", where);
    s.profiles = field<std::vector<std::string>>(j, "profiles", where);
    s.reference = field<std::string>(j, "reference", where);
    const json& t = j.contains("timing") ? j.at("timing") : json::object();
    const std::string tw = where + ".timing";
    TimingSettings& ts = s.timing;
    ts.method = optionalField(t, "method", tw, ts.method);
    ts.frames = optionalField(t, "frames", tw, ts.frames);
    ts.warmup = optionalField(t, "warmup", tw, ts.warmup);
    ts.minRounds = optionalField(t, "min_rounds", tw, ts.minRounds);
    ts.maxRounds = optionalField(t, "max_rounds", tw, ts.maxRounds);
    ts.quickMaxRounds = optionalField(t, "quick_max_rounds", tw, ts.quickMaxRounds);
    ts.roundStep = optionalField(t, "round_step", tw, ts.roundStep);
    ts.timeBudgetSeconds = optionalField(t, "time_budget_s", tw, ts.timeBudgetSeconds);
    ts.quickTimeBudgetSeconds =
        optionalField(t, "quick_time_budget_s", tw, ts.quickTimeBudgetSeconds);
    ts.alpha = optionalField(t, "alpha", tw, ts.alpha);
    ts.threshold = optionalField(t, "threshold", tw, ts.threshold);
    ts.ratioThreshold = optionalField(t, "ratio_threshold", tw, ts.ratioThreshold);
    const json& a = j.contains("accuracy_tolerance") ? j.at("accuracy_tolerance") : json::object();
    const std::string aw = where + ".accuracy_tolerance";
    AccuracyTolerance& at = s.tolerance;
    at.flipAbs = optionalField(a, "flip_mean_abs", aw, at.flipAbs);
    at.flipRel = optionalField(a, "flip_mean_rel", aw, at.flipRel);
    at.psnrDb = optionalField(a, "psnr_db", aw, at.psnrDb);
    at.relMseAbs = optionalField(a, "rel_mse_gi_abs", aw, at.relMseAbs);
    at.relMseRel = optionalField(a, "rel_mse_gi_rel", aw, at.relMseRel);
    s.callgrindTolerance = optionalField(j, "callgrind_tolerance", where, s.callgrindTolerance);
    // Baselines written before the shader statistics were gated get the default targets.
    s.shaderTargets = optionalField(j, "shader_targets", where, s.shaderTargets);
    for (const std::string& t : s.shaderTargets) {
        try {
            shaders::findShaderTarget(t);
        } catch (const Error& e) {
            throw Error(where + ".shader_targets: " + e.what());
        }
    }
    if (s.width < 16 || s.height < 16 || s.width > 16384 || s.height > 16384)
        throw Error(where + ".width/height: must be in 16..16384");
    if (s.profiles.empty()) throw Error(where + ".profiles: empty");
    if (ts.frames < 1 || ts.warmup < 1 || ts.minRounds < 2 || ts.maxRounds < ts.minRounds ||
        ts.quickMaxRounds < ts.minRounds || ts.roundStep < 1)
        throw Error(tw + ": frames, warmup and round_step must be >= 1, min_rounds >= 2, and "
                         "the budgets at least min_rounds");
    if (!(ts.alpha > 0 && ts.alpha < 1) || !(ts.threshold > 0) || !(ts.ratioThreshold > 0))
        throw Error(tw + ": alpha must be in (0,1) and the thresholds positive");
    return s;
}

json keyJson(const CallgrindKey& k) {
    return {{"mesa", k.mesa}, {"llvm", k.llvm}, {"compiler", k.compiler}, {"valgrind", k.valgrind}};
}

// {"key": {...}, "targets": {target: {profile: {pass: counters}}}}: nested objects, so the
// file's keys sort as everywhere else in it.
json shaderRecordJson(const ShaderRecord& r) {
    json targets = json::object();
    for (const ShaderTargetRecord& t : r.targets) {
        json profiles = json::object();
        for (const ShaderPassRecord& p : t.passes)
            profiles[p.profile][p.pass] = countersJson(p.counters);
        targets[t.target] = profiles;
    }
    return {{"key", {{"mesa", r.key.mesa}, {"drivers", r.key.drivers}}}, {"targets", targets}};
}

ShaderRecord shaderRecordFrom(const json& j, const std::string& where) {
    ShaderRecord r;
    const json& k = j.is_object() ? j.value("key", json()) : json();
    r.key.mesa = field<std::string>(k, "mesa", where + ".key");
    r.key.drivers = field<std::vector<std::string>>(k, "drivers", where + ".key");
    const json& targets = j.is_object() ? j.value("targets", json()) : json();
    if (!targets.is_object()) throw Error(where + ".targets: must be an object");
    for (const auto& [target, profiles] : targets.items()) {
        const std::string tw = where + ".targets." + target;
        if (!profiles.is_object()) throw Error(tw + ": must be an object of profiles");
        ShaderTargetRecord t{target, {}};
        for (const auto& [profile, passes] : profiles.items()) {
            if (!passes.is_object())
                throw Error(tw + "." + profile + ": must be an object of passes");
            for (const auto& [pass, counters] : passes.items())
                t.passes.push_back(
                    {profile, pass, countersFrom(counters, tw + "." + profile + "." + pass)});
        }
        r.targets.push_back(std::move(t));
    }
    return r;
}

} // namespace

const std::int64_t* ProfileRecord::counter(const std::string& key) const {
    for (const auto& [k, v] : counters)
        if (k == key) return &v;
    return nullptr;
}

bool CallgrindKey::operator==(const CallgrindKey& o) const {
    return mesa == o.mesa && llvm == o.llvm && compiler == o.compiler && valgrind == o.valgrind;
}

std::string CallgrindKey::text() const {
    return mesa + ", LLVM " + llvm + ", " + compiler + ", " + valgrind;
}

const Counters* CallgrindRecord::profile(const std::string& name) const {
    for (const auto& [n, c] : profiles)
        if (n == name) return &c;
    return nullptr;
}

bool ShaderKey::operator==(const ShaderKey& o) const {
    return mesa == o.mesa && drivers == o.drivers;
}

std::string ShaderKey::text() const {
    std::string list;
    for (const std::string& d : drivers)
        list += (list.empty() ? "" : ", ") + d;
    return "Mesa " + mesa + " (" + list + ")";
}

const ShaderPassRecord* ShaderTargetRecord::pass(const std::string& profile,
                                                 const std::string& name) const {
    for (const ShaderPassRecord& p : passes)
        if (p.profile == profile && p.pass == name) return &p;
    return nullptr;
}

const ShaderTargetRecord* ShaderRecord::target(const std::string& name) const {
    for (const ShaderTargetRecord& t : targets)
        if (t.target == name) return &t;
    return nullptr;
}

const ProfileRecord* GateRecord::profile(const std::string& name) const {
    for (const ProfileRecord& p : profiles)
        if (p.name == name) return &p;
    return nullptr;
}

const CallgrindRecord* GateRecord::callgrindFor(const CallgrindKey& key) const {
    for (const CallgrindRecord& c : callgrind)
        if (c.key == key) return &c;
    return nullptr;
}

const ShaderRecord* GateRecord::shadersFor(const ShaderKey& key) const {
    for (const ShaderRecord& s : shaders)
        if (s.key == key) return &s;
    return nullptr;
}

json recordJson(const GateRecord& r) {
    json profiles = json::array();
    for (const ProfileRecord& p : r.profiles) {
        json o{{"name", p.name},
               {"counters", countersJson(p.counters)},
               {"gl_evaluated_pixels", countersJson(p.glPixels)},
               {"gl_apply_invocations", countersJson(p.glInvocations)},
               {"ratio_samples", p.ratioSamples}};
        if (p.accuracy.measured)
            o["accuracy"] = {{"flip_mean", p.accuracy.flipMean},
                             {"psnr", psnrJson(p.accuracy.psnr)},
                             {"rel_mse_gi", p.accuracy.relMseGi}};
        profiles.push_back(o);
    }
    json callgrind = json::array();
    for (const CallgrindRecord& c : r.callgrind) {
        json ps = json::object();
        for (const auto& [name, counters] : c.profiles)
            ps[name] = countersJson(counters);
        callgrind.push_back({{"key", keyJson(c.key)}, {"profiles", ps}});
    }
    json shaderRecords = json::array();
    for (const ShaderRecord& s : r.shaders)
        shaderRecords.push_back(shaderRecordJson(s));
    const json environment{{"embree_isa", r.environment.embreeIsa},
                           {"gl_renderer", r.environment.glRenderer},
                           {"cpu", r.environment.cpu}};
    return {
        {"schema", kGateSchema},      {"suite", suiteJson(r.suite)}, {"recorded", r.recorded},
        {"environment", environment}, {"probes", r.probes},          {"bake", r.bake},
        {"profiles", profiles},       {"callgrind", callgrind},      {"shaders", shaderRecords}};
}

GateRecord recordFromJson(const json& j, const std::string& source) {
    try {
        if (!j.is_object()) throw Error("not a JSON object");
        const std::string schema = field<std::string>(j, "schema", "");
        if (schema != kGateSchema)
            throw Error("schema: '" + schema + "', expected '" + kGateSchema + "'");
        GateRecord r;
        r.suite = suiteFrom(j.contains("suite") ? j.at("suite") : json(), "suite");
        r.recorded = j.value("recorded", json::object());
        // Optional: baselines written before it was recorded have none (compared as unknown).
        if (j.contains("environment")) {
            const json& e = j.at("environment");
            r.environment.embreeIsa = field<std::string>(e, "embree_isa", "environment");
            r.environment.glRenderer = field<std::string>(e, "gl_renderer", "environment");
            r.environment.cpu = optionalField(e, "cpu", "environment", std::string());
        }
        r.probes = field<std::string>(j, "probes", "");
        r.bake = optionalField(j, "bake", "", std::string()); // older baselines: none
        const json& ps = j.contains("profiles") ? j.at("profiles") : json();
        if (!ps.is_array()) throw Error("profiles: must be an array");
        for (size_t i = 0; i < ps.size(); ++i) {
            const std::string w = "profiles[" + std::to_string(i) + "]";
            ProfileRecord p;
            p.name = field<std::string>(ps[i], "name", w);
            p.counters = countersFrom(ps[i].value("counters", json()), w + ".counters");
            if (ps[i].contains("gl_evaluated_pixels"))
                p.glPixels =
                    countersFrom(ps[i].at("gl_evaluated_pixels"), w + ".gl_evaluated_pixels");
            if (ps[i].contains("gl_apply_invocations")) // older baselines: none
                p.glInvocations =
                    countersFrom(ps[i].at("gl_apply_invocations"), w + ".gl_apply_invocations");
            p.ratioSamples = optionalField(ps[i], "ratio_samples", w, std::vector<double>{});
            if (ps[i].contains("accuracy")) {
                const json& a = ps[i].at("accuracy");
                p.accuracy.measured = true;
                p.accuracy.flipMean = field<double>(a, "flip_mean", w + ".accuracy");
                p.accuracy.psnr = psnrFrom(a, w + ".accuracy");
                p.accuracy.relMseGi = field<double>(a, "rel_mse_gi", w + ".accuracy");
            }
            r.profiles.push_back(std::move(p));
        }
        const json& cg = j.value("callgrind", json::array());
        if (!cg.is_array()) throw Error("callgrind: must be an array");
        for (size_t i = 0; i < cg.size(); ++i) {
            const std::string w = "callgrind[" + std::to_string(i) + "]";
            CallgrindRecord c;
            const json& k = cg[i].value("key", json());
            c.key = {field<std::string>(k, "mesa", w + ".key"),
                     field<std::string>(k, "llvm", w + ".key"),
                     field<std::string>(k, "compiler", w + ".key"),
                     field<std::string>(k, "valgrind", w + ".key")};
            const json& ps2 = cg[i].value("profiles", json());
            if (!ps2.is_object()) throw Error(w + ".profiles: must be an object");
            for (const auto& [name, counters] : ps2.items())
                c.profiles.emplace_back(name, countersFrom(counters, w + ".profiles." + name));
            r.callgrind.push_back(std::move(c));
        }
        const json& sh = j.value("shaders", json::array()); // older baselines: none
        if (!sh.is_array()) throw Error("shaders: must be an array");
        for (size_t i = 0; i < sh.size(); ++i)
            r.shaders.push_back(shaderRecordFrom(sh[i], "shaders[" + std::to_string(i) + "]"));
        return r;
    } catch (const Error& e) {
        throw fileError(source, e.what());
    }
}

std::string committedProbesPath(const std::string& baselinePath) {
    const std::string ext = ".json";
    std::string stem = baselinePath;
    if (stem.size() > ext.size() && stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0)
        stem.resize(stem.size() - ext.size());
    return stem + ".probes.gz";
}

GateRecord readGateRecord(const std::string& path) {
    const std::vector<unsigned char> bytes = readFileBytes(path);
    json j = json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (j.is_discarded()) throw fileError(path, "not valid JSON");
    return recordFromJson(j, path);
}

void writeGateRecord(const std::string& path, const GateRecord& r) {
    const std::string text = recordJson(r).dump(2) + "\n";
    writeFileAtomic(path, text.data(), text.size());
}

} // namespace pb::gate
