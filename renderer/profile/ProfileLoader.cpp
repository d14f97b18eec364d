#include "profile/ProfileLoader.h"

#include "core/Error.h"
#include "core/Suggest.h"
#include "core/FileIO.h"
#include "core/TomlRead.h"
#include "profile/ProfileSettings.h"
#include "profile/SwitchTable.h"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

namespace pb::profile {

namespace fs = std::filesystem;

namespace {

constexpr const char* kInheritKey = "inherit";

struct Entry {
    std::string key;
    const toml::node* node = nullptr;
    int line = 0;
};

std::string knownLoaderKeys() {
    std::string out = kInheritKey;
    for (const ProfileSetting& s : profileSettings())
        out += ", " + s.key;
    for (const SwitchInfo& s : switchTable())
        out += ", " + s.key;
    return out;
}

bool knownSection(const std::string& prefix) {
    auto under = [&](const std::string& key) { return key.rfind(prefix + ".", 0) == 0; };
    for (const ProfileSetting& s : profileSettings())
        if (under(s.key)) return true;
    for (const SwitchInfo& s : switchTable())
        if (under(s.key)) return true;
    return false;
}

class Parser {
public:
    Parser(std::string path, const ProfileSearch& search)
        : path_(std::move(path)), search_(search) {}

    [[noreturn]] void fail(int line, const std::string& key, const std::string& problem) const {
        throw fileError(path_ + ":" + std::to_string(line), "key '" + key + "': " + problem);
    }

    // Every value as (dotted key, node), in file order. Tables are walked; a table no key
    // lives under is an unknown key itself.
    void flatten(const toml::table& t, const std::string& prefix, std::vector<Entry>& out) const {
        for (auto&& [k, v] : t) {
            std::string key =
                prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
            int line = int(k.source().begin.line);
            if (const toml::table* sub = v.as_table()) {
                if (!knownSection(key))
                    fail(line, key, "unknown table (known keys: " + knownLoaderKeys() + ")");
                flatten(*sub, key, out);
            } else {
                out.push_back({key, &v, line});
            }
        }
    }

    std::string text(const Entry& e, const std::string& expected) const {
        if (const auto* s = e.node->as_string()) return s->get();
        fail(e.line, e.key, "expected a string (" + expected + ")");
    }

    double number(const Entry& e, bool integer) const {
        if (e.node->is_integer()) return double(*e.node->value<std::int64_t>());
        if (!integer && e.node->is_floating_point()) return *e.node->value<double>();
        fail(e.line, e.key, integer ? "expected an integer" : "expected a number");
    }

    void applySetting(const ProfileSetting& s, const Entry& e, PlatformProfile& p) const {
        if (s.kind == ProfileSetting::Kind::Text) {
            std::string v = text(e, s.doc);
            if (s.key == "costmodel.cache_preset" && !search_.cachePresets.empty() &&
                std::find(search_.cachePresets.begin(), search_.cachePresets.end(), v) ==
                    search_.cachePresets.end()) {
                std::string list;
                for (const auto& n : search_.cachePresets)
                    list += (list.empty() ? "" : ", ") + n;
                fail(e.line, e.key, "unknown cache preset '" + v + "' (presets: " + list + ")");
            }
            s.setText(p, v);
            return;
        }
        double v = number(e, s.kind == ProfileSetting::Kind::Integer);
        std::string problem = settingRangeProblem(s, v);
        if (!problem.empty()) fail(e.line, e.key, problem);
        s.setNumber(p, v);
    }

    void applySwitch(const SwitchInfo& s, const Entry& e, PlatformProfile& p) const {
        std::string value;
        if (s.kind == SwitchKind::Number) {
            double v = number(e, false);
            char buf[64];
            auto r = std::to_chars(buf, buf + sizeof buf, v);
            value.assign(buf, r.ptr);
        } else {
            std::string expected = s.kind == SwitchKind::Choice
                                       ? "one of: " +
                                             [&] {
                                                 std::string l;
                                                 for (const auto& c : s.choices)
                                                     l += (l.empty() ? "" : ", ") + c;
                                                 return l;
                                             }()
                                       : s.doc;
            value = text(e, expected);
        }
        std::string problem = switchValueProblem(s, value);
        if (!problem.empty())
            fail(e.line, e.key, "'" + value + "' is not allowed (" + problem + ")");
        s.set(p.switches, value);
    }

    const std::string& path() const { return path_; }

private:
    std::string path_;
    const ProfileSearch& search_;
};

std::string canonical(const std::string& path) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(fs::path(path), ec);
    return ec ? path : c.string();
}

std::string resolveInherit(const std::string& name, const std::string& fromPath,
                           const ProfileSearch& search, const Parser& P, int line) {
    fs::path base = fs::path(fromPath).parent_path();
    if (looksLikeProfilePath(name)) {
        fs::path p = fs::path(name).is_absolute() ? fs::path(name) : base / name;
        if (!fs::is_regular_file(p)) P.fail(line, kInheritKey, "no such file " + p.string());
        return p.string();
    }
    std::vector<fs::path> dirs{base.empty() ? fs::path(".") : base};
    for (const auto& d : search.dirs)
        dirs.emplace_back(d);
    for (const auto& d : dirs)
        if (fs::is_regular_file(d / (name + ".toml"))) return (d / (name + ".toml")).string();
    std::string list;
    for (const auto& n : profileNames(search))
        list += (list.empty() ? "" : ", ") + n;
    P.fail(line, kInheritKey, "no profile '" + name + "' (profiles: " + list + ")");
}

PlatformProfile loadChain(const std::string& path, const ProfileSearch& search,
                          std::vector<std::string>& chain);

PlatformProfile parseChain(const std::string& text, const std::string& path,
                           const ProfileSearch& search, std::vector<std::string>& chain) {
    Parser P(path, search);
    const toml::table root = parseTomlText(text, path);
    std::vector<Entry> entries;
    P.flatten(root, "", entries);
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.line < b.line; });

    PlatformProfile p;
    bool inherited = false;
    for (const Entry& e : entries) {
        if (e.key != kInheritKey) continue;
        std::string parentPath =
            resolveInherit(P.text(e, "a profile name or a .toml path"), path, search, P, e.line);
        std::string id = canonical(parentPath);
        if (std::find(chain.begin(), chain.end(), id) != chain.end()) {
            std::string cycle;
            for (const auto& c : chain)
                cycle += fs::path(c).stem().string() + " -> ";
            P.fail(e.line, kInheritKey,
                   "inheritance cycle: " + cycle + fs::path(id).stem().string());
        }
        PlatformProfile parent = loadChain(parentPath, search, chain);
        p = parent;
        p.inherits.insert(p.inherits.begin(), parent.name);
        p.description.clear(); // a description is the file's own
        inherited = true;
    }
    p.name = fs::path(path).stem().string();
    p.file = path;

    std::set<std::string> given;
    for (const Entry& e : entries) {
        if (e.key == kInheritKey) continue;
        given.insert(e.key);
        if (const ProfileSetting* s = findProfileSetting(e.key))
            P.applySetting(*s, e, p);
        else if (const SwitchInfo* s = findSwitch(e.key))
            P.applySwitch(*s, e, p);
        else
            P.fail(e.line, e.key, "unknown key (known keys: " + knownLoaderKeys() + ")");
    }
    if (!inherited)
        for (const ProfileSetting& s : profileSettings())
            if (s.requiredAtRoot && !given.count(s.key))
                throw fileError(path, "missing key '" + s.key + "' (" + s.doc +
                                          "; a profile without 'inherit' sets every setting)");
    return p;
}

PlatformProfile loadChain(const std::string& path, const ProfileSearch& search,
                          std::vector<std::string>& chain) {
    std::vector<unsigned char> bytes = readFileBytes(path);
    chain.push_back(canonical(path));
    PlatformProfile p = parseChain(std::string(bytes.begin(), bytes.end()), path, search, chain);
    chain.pop_back();
    return p;
}

} // namespace

bool looksLikeProfilePath(const std::string& s) {
    return s.find('/') != std::string::npos ||
           (s.size() > 5 && s.compare(s.size() - 5, 5, ".toml") == 0);
}

PlatformProfile loadProfileFile(const std::string& path, const ProfileSearch& search) {
    std::vector<std::string> chain;
    return loadChain(path, search, chain);
}

PlatformProfile parseProfileToml(const std::string& text, const std::string& path,
                                 const ProfileSearch& search) {
    std::vector<std::string> chain{canonical(path)};
    return parseChain(text, path, search, chain);
}

PlatformProfile loadProfile(const std::string& nameOrPath, const ProfileSearch& search) {
    if (looksLikeProfilePath(nameOrPath)) {
        if (!fs::is_regular_file(nameOrPath)) throw fileError(nameOrPath, "no such profile file");
        return loadProfileFile(nameOrPath, search);
    }
    for (const auto& d : search.dirs) {
        fs::path p = fs::path(d) / (nameOrPath + ".toml");
        if (fs::is_regular_file(p)) return loadProfileFile(p.string(), search);
    }
    std::string list;
    const std::vector<std::string> names = profileNames(search);
    for (const auto& n : names)
        list += (list.empty() ? "" : ", ") + n;
    throw Error("profile '" + nameOrPath + "': no such profile" + didYouMean(nameOrPath, names) +
                " (profiles: " +
                (list.empty() ? "none found" : list) + "; or give a .toml path)");
}

std::vector<std::string> profileNames(const ProfileSearch& search) {
    std::set<std::string> names;
    for (const auto& d : search.dirs) {
        std::error_code ec;
        for (const auto& f : fs::directory_iterator(d, ec))
            if (f.is_regular_file() && f.path().extension() == ".toml")
                names.insert(f.path().stem().string());
    }
    std::vector<std::string> out;
    if (names.erase("reference")) out.push_back("reference");
    out.insert(out.end(), names.begin(), names.end());
    return out;
}

namespace {

std::string tomlString(const std::string& v) {
    std::string out = "\"";
    for (char c : v) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(c));
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

// Shortest text that reads back as the same double, always with a '.' or exponent (a float).
std::string tomlFloat(double v) {
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::string s(buf, r.ptr);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

struct Line {
    std::string section, leaf, value, doc;
};

void addLine(std::vector<Line>& lines, const std::string& key, std::string value, std::string doc) {
    auto dot = key.rfind('.');
    lines.push_back({dot == std::string::npos ? "" : key.substr(0, dot),
                     dot == std::string::npos ? key : key.substr(dot + 1), std::move(value),
                     std::move(doc)});
}

} // namespace

std::string profileToml(const PlatformProfile& p) {
    std::vector<Line> lines;
    for (const ProfileSetting& s : profileSettings()) {
        std::string v = s.kind == ProfileSetting::Kind::Text ? tomlString(s.getText(p))
                        : s.kind == ProfileSetting::Kind::Integer
                            ? std::to_string(int(s.getNumber(p)))
                            : tomlFloat(s.getNumber(p));
        addLine(lines, s.key, v, s.doc);
    }
    for (const SwitchInfo& s : switchTable())
        addLine(lines, s.key,
                s.kind == SwitchKind::Number ? tomlFloat(std::stod(s.get(p.switches)))
                                             : tomlString(s.get(p.switches)),
                s.doc);
    std::ostringstream out;
    out << "# profile '" << p.name << "'";
    if (!p.inherits.empty()) {
        out << " (inherits";
        for (const auto& n : p.inherits)
            out << " " << n;
        out << ")";
    }
    out << ", every key explicit (no inherit); written by `probebench profiles --show`\n";
    std::vector<std::string> sections; // in table order, top level ("") first
    sections.push_back("");
    for (const Line& l : lines)
        if (std::find(sections.begin(), sections.end(), l.section) == sections.end())
            sections.push_back(l.section);
    for (const std::string& sec : sections) {
        if (!sec.empty()) out << "\n[" << sec << "]\n";
        for (const Line& l : lines)
            if (l.section == sec) out << l.leaf << " = " << l.value << "  # " << l.doc << "\n";
    }
    return out.str();
}

} // namespace pb::profile
