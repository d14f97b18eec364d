#include "SweepPlan.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "core/TomlRead.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace pb::sweep {
namespace {

class Parser : public TomlReader {
public:
    using TomlReader::TomlReader;

    std::string string(const toml::table& t, const char* key, const std::string& what,
                       bool required) const {
        const toml::node* n = t.get(key);
        if (!n) {
            if (required) fail(t.source(), what + ": missing key '" + key + "'");
            return {};
        }
        const auto* s = n->as_string();
        if (!s) fail(n->source(), what + ": key '" + key + "' must be a string");
        return s->get();
    }

    std::vector<std::string> strings(const toml::node& n, const std::string& what,
                                     const std::string& key) const {
        const toml::array* a = n.as_array();
        if (!a) fail(n.source(), what + ": key '" + key + "' must be an array of strings");
        std::vector<std::string> out;
        for (const toml::node& e : *a) {
            const auto* s = e.as_string();
            if (!s) fail(e.source(), what + ": key '" + key + "' must be an array of strings");
            out.push_back(s->get());
        }
        return out;
    }

    std::vector<std::string> strings(const toml::table& t, const char* key,
                                     const std::string& what, bool required) const {
        const toml::node* n = t.get(key);
        if (!n) {
            if (required) fail(t.source(), what + ": missing key '" + key + "'");
            return {};
        }
        return strings(*n, what, key);
    }

    int positive(const toml::table& t, const char* key, const std::string& what, int fallback,
                 int max) const {
        const toml::node* n = t.get(key);
        if (!n) return fallback;
        std::optional<std::int64_t> v = n->value_exact<std::int64_t>();
        if (!v || *v < 1 || *v > max)
            fail(n->source(), what + ": key '" + key + "' must be an integer in [1, " +
                                  std::to_string(max) + "]");
        return int(*v);
    }

    // Each entry of `key`, an array of tables; `what` names entry i.
    template <class F> void tables(const toml::table& root, const char* key, F&& each) const {
        const toml::node* n = root.get(key);
        if (!n) return;
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables())
            fail(n->source(), std::string("key '") + key + "' must be [[" + key + "]] tables");
        for (std::size_t i = 0; i < a->size(); ++i)
            each(*a->get(i)->as_table(), "[[" + std::string(key) + "]] #" + std::to_string(i + 1));
    }
};

void checkResolution(const Parser& P, const toml::table& t, const std::string& what,
                     const std::string& r) {
    int w = 0, h = 0;
    char x = 0, rest = 0;
    if (std::sscanf(r.c_str(), "%d %c %d %c", &w, &x, &h, &rest) != 3 || x != 'x' || w < 1 ||
        h < 1 || w > 16384 || h > 16384)
        P.fail(t["resolutions"].node()->source(),
               what + ": resolution '" + r + "' must be WxH, e.g. 64x36");
}

// A scene name or path as a file-name part: its stem, letters, digits, '-' and '_' only.
std::string fileStem(const std::string& scene) {
    std::string stem = std::filesystem::path(scene).stem().string(), out;
    for (char c : stem)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
    return out.empty() ? "scene" : out;
}

} // namespace

SweepPlan parseSweepPlan(const std::string& text, const std::string& path) {
    const toml::table root = parseTomlText(text, path);
    Parser P(path);
    P.checkKeys(root, {"name", "node_class", "bench", "bake", "command"}, "the plan");
    SweepPlan plan;
    plan.name = P.string(root, "name", "the plan", true);
    if (plan.name.empty()) P.fail(root["name"].node()->source(), "the plan: key 'name' is empty");
    plan.nodeClass = P.string(root, "node_class", "the plan", false);
    P.tables(root, "bench", [&](const toml::table& t, const std::string& what) {
        P.checkKeys(t, {"scenes", "profiles", "resolutions", "switch_sets", "repeat", "args"},
                    what);
        BenchAxes b;
        b.scenes = P.strings(t, "scenes", what, true);
        b.profiles = P.strings(t, "profiles", what, true);
        b.resolutions = P.strings(t, "resolutions", what, true);
        for (const std::string& r : b.resolutions)
            checkResolution(P, t, what, r);
        if (const toml::node* s = t.get("switch_sets")) {
            const toml::array* a = s->as_array();
            if (!a) P.fail(s->source(), what + ": key 'switch_sets' must be an array of arrays");
            for (const toml::node& e : *a) {
                b.switchSets.push_back(P.strings(e, what, "switch_sets"));
                for (const std::string& kv : b.switchSets.back())
                    if (kv.find('=') == std::string::npos)
                        P.fail(e.source(), what + ": switch '" + kv + "' must be key=value");
            }
        }
        b.repeat = P.positive(t, "repeat", what, 1, 1000);
        b.args = P.strings(t, "args", what, false);
        plan.bench.push_back(std::move(b));
    });
    P.tables(root, "bake", [&](const toml::table& t, const std::string& what) {
        P.checkKeys(t, {"scenes", "scenarios", "split", "parts", "args"}, what);
        BakeAxes b;
        b.scenes = P.strings(t, "scenes", what, true);
        b.scenarios = P.strings(t, "scenarios", what, true);
        const std::string split = P.string(t, "split", what, false);
        if (!split.empty() && split != "scenario")
            P.fail(t["split"].node()->source(),
                   what + ": key 'split' must be \"scenario\" (the only split a bake has)");
        b.parts = P.positive(t, "parts", what, 0, 4096);
        if (b.parts > int(b.scenarios.size()))
            P.fail(t["parts"].node()->source(),
                   what + ": " + std::to_string(b.parts) + " parts for " +
                       std::to_string(b.scenarios.size()) + " scenario(s)");
        b.args = P.strings(t, "args", what, false);
        plan.bake.push_back(std::move(b));
    });
    P.tables(root, "command", [&](const toml::table& t, const std::string& what) {
        P.checkKeys(t, {"name", "args", "output_option"}, what);
        CommandJob c;
        c.name = P.string(t, "name", what, true);
        c.args = P.strings(t, "args", what, true);
        c.outputOption = P.string(t, "output_option", what, true);
        if (c.args.empty()) P.fail(t.source(), what + ": key 'args' is empty");
        plan.commands.push_back(std::move(c));
    });
    return plan;
}

SweepPlan loadSweepPlan(const std::string& path) {
    const std::vector<unsigned char> bytes = readFileBytes(path);
    return parseSweepPlan(std::string(bytes.begin(), bytes.end()), path);
}

std::vector<SweepJob> expandSweepPlan(const SweepPlan& plan, const std::string& path) {
    std::vector<SweepJob> jobs;
    auto add = [&](std::string kind, std::vector<std::string> args, std::string output,
                   nlohmann::json labels) {
        SweepJob j{jobs.size(), std::move(kind), std::move(args), std::move(output),
                   std::move(labels)};
        jobs.push_back(std::move(j));
    };
    const std::string out = kOutPlaceholder;
    for (const BenchAxes& b : plan.bench) {
        const std::vector<std::vector<std::string>> sets =
            b.switchSets.empty() ? std::vector<std::vector<std::string>>{{}} : b.switchSets;
        for (const std::string& scene : b.scenes)
            for (const std::string& profile : b.profiles)
                for (const std::vector<std::string>& set : sets)
                    for (const std::string& res : b.resolutions)
                        for (int r = 0; r < b.repeat; ++r) {
                            const std::string w = res.substr(0, res.find('x')),
                                              h = res.substr(res.find('x') + 1);
                            const std::string output =
                                "jobs/" + jobNumberText(jobs.size()) + ".json";
                            std::vector<std::string> args{"bench",   "--scene",  scene,
                                                          "--profile", profile, "--width",
                                                          w,         "--height", h};
                            for (const std::string& kv : set) {
                                args.push_back("--set");
                                args.push_back(kv);
                            }
                            args.insert(args.end(), b.args.begin(), b.args.end());
                            bool cacheGiven = false;
                            for (const std::string& a : b.args)
                                cacheGiven = cacheGiven || a == "--cache-dir";
                            // One probe cache for the whole sweep, on the shared folder: the
                            // first job to need a bake writes it (atomically), the rest read it.
                            if (!cacheGiven) {
                                args.push_back("--cache-dir");
                                args.push_back(out + "/cache");
                            }
                            args.push_back("--json");
                            args.push_back(out + "/" + output);
                            add("bench", std::move(args), output,
                                {{"scene", scene},
                                 {"profile", profile},
                                 {"switches", set},
                                 {"resolution", res},
                                 {"repeat", r}});
                        }
    }
    for (const BakeAxes& b : plan.bake)
        for (const std::string& scene : b.scenes) {
            const int parts = b.parts > 0 ? b.parts : int(b.scenarios.size());
            const std::string stem = "bakes/" + jobNumberText(jobs.size()) + "-" + fileStem(scene);
            for (int p = 0; p < parts; ++p) {
                const std::string part = std::to_string(p) + "/" + std::to_string(parts);
                const std::string output = stem + ".part" + std::to_string(p) + ".pbpart";
                std::vector<std::string> args{"bake", "--scene", scene};
                for (const std::string& s : b.scenarios) {
                    args.push_back("--scenario");
                    args.push_back(s);
                }
                args.insert(args.end(), b.args.begin(), b.args.end());
                for (const std::string& a :
                     {std::string("--split"), std::string("scenario"), std::string("--part"), part,
                      std::string("--json"), std::string("--out"), out + "/" + output})
                    args.push_back(a);
                add("bake-part", std::move(args), output,
                    {{"scene", scene},
                     {"scenarios", b.scenarios},
                     {"part", p},
                     {"parts", parts},
                     {"merged", stem + ".pbp"}});
            }
        }
    for (const CommandJob& c : plan.commands) {
        const std::string output = "jobs/" + jobNumberText(jobs.size()) + ".json";
        std::vector<std::string> args = c.args;
        args.push_back(c.outputOption);
        args.push_back(out + "/" + output);
        add("command", std::move(args), output, {{"name", c.name}});
    }
    if (jobs.empty())
        throw fileError(path, "the plan expands to no jobs (give a [[bench]], [[bake]] or "
                              "[[command]] table with at least one entry per axis)");
    return jobs;
}

std::vector<BakeGroup> bakeGroups(const std::vector<SweepJob>& jobs) {
    std::vector<BakeGroup> groups;
    for (const SweepJob& j : jobs) {
        if (j.kind != "bake-part") continue;
        if (j.labels.at("part").get<int>() == 0)
            groups.push_back({j.labels.at("scene").get<std::string>(), {},
                              j.labels.at("merged").get<std::string>()});
        groups.back().jobs.push_back(j.index);
    }
    return groups;
}

std::string jobNumberText(std::size_t job) {
    char b[24];
    std::snprintf(b, sizeof b, "%04zu", job);
    return b;
}

std::string planId(const std::vector<SweepJob>& jobs) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    auto mix = [&](const std::string& s) {
        for (unsigned char c : s + '\0') {
            h ^= c;
            h *= 0x100000001b3ull;
        }
    };
    for (const SweepJob& j : jobs) {
        mix(j.kind);
        mix(j.output);
        for (const std::string& a : j.args)
            mix(a);
        mix("\n");
    }
    char b[17];
    std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
    return b;
}

std::vector<std::string> substituteOut(const std::vector<std::string>& args,
                                       const std::string& outDir) {
    std::vector<std::string> out;
    const std::string key = kOutPlaceholder;
    for (std::string a : args) {
        for (std::size_t at = a.find(key); at != std::string::npos;
             at = a.find(key, at + outDir.size()))
            a.replace(at, key.size(), outDir);
        out.push_back(std::move(a));
    }
    return out;
}

nlohmann::json jobJson(const SweepJob& j) {
    return {{"index", j.index},
            {"kind", j.kind},
            {"args", j.args},
            {"output", j.output},
            {"labels", j.labels}};
}

SweepJob jobFromJson(const nlohmann::json& j) {
    return {j.at("index").get<std::size_t>(), j.at("kind").get<std::string>(),
            j.at("args").get<std::vector<std::string>>(), j.at("output").get<std::string>(),
            j.at("labels")};
}

} // namespace pb::sweep
