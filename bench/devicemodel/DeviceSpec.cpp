#include "DeviceSpec.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Suggest.h"
#include "core/TomlRead.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

namespace pb::devicemodel {
namespace devicefile {

namespace fs = std::filesystem;

// One device file's keys, read with its line numbers in every error.
class DeviceReader : public TomlReader {
public:
    using TomlReader::TomlReader;

    const toml::table& section(const toml::table& root, const char* name) const {
        const toml::node* n = root.get(name);
        if (!n || !n->is_table()) fail(root.source(), std::string("missing section [") + name + "]");
        return *n->as_table();
    }
    std::string text(const toml::table& t, const char* key) const {
        const toml::node* n = t.get(key);
        if (!n) fail(t.source(), std::string("missing key '") + key + "'");
        if (!n->is_string()) fail(n->source(), std::string("'") + key + "' must be a string");
        std::string v = n->as_string()->get();
        if (v.empty()) fail(n->source(), std::string("'") + key + "' is empty");
        return v;
    }
    // A number in [lo, hi]; integers and floats both accepted.
    double number(const toml::table& t, const char* key, double lo, double hi) const {
        const toml::node* n = t.get(key);
        if (!n) fail(t.source(), std::string("missing key '") + key + "'");
        double v = 0;
        if (n->is_integer())
            v = double(n->as_integer()->get());
        else if (n->is_floating_point())
            v = n->as_floating_point()->get();
        else
            fail(n->source(), std::string("'") + key + "' must be a number");
        if (!(v >= lo && v <= hi)) {
            std::ostringstream s;
            s << "'" << key << "' = " << v << " is outside " << lo << ".." << hi;
            fail(n->source(), s.str());
        }
        return v;
    }
    int integer(const toml::table& t, const char* key, int lo, int hi) const {
        const double v = number(t, key, lo, hi);
        if (v != double(int(v))) fail(t.get(key)->source(), std::string("'") + key + "' must be a whole number");
        return int(v);
    }
    costmodel::CacheConfig cache(const toml::table& t, const char* prefix) const {
        const std::string p = prefix;
        costmodel::CacheConfig c;
        c.name = p;
        c.sizeBytes = std::uint64_t(integer(t, (p + "_kib").c_str(), 1, 1 << 20)) * 1024;
        c.lineBytes = integer(t, (p + "_line_bytes").c_str(), 16, 1024);
        c.ways = integer(t, (p + "_ways").c_str(), 1, 1024);
        c.source = path();
        try {
            c.validate();
        } catch (const Error& e) {
            fail(t.get((p + "_kib").c_str())->source(), p + " cache: " + e.what());
        }
        return c;
    }
};

const std::set<std::string> kClasses = {"handheld", "phone", "console", "pc", "datacentre"};

} // namespace devicefile
using namespace devicefile;

nlohmann::json DeviceSpec::toJson() const {
    auto cache = [](const costmodel::CacheConfig& c) {
        return nlohmann::json{{"kib", c.sizeBytes / 1024}, {"line_bytes", c.lineBytes}, {"ways", c.ways}};
    };
    return {{"name", name},
            {"label", label},
            {"compiler", compiler},
            {"class", deviceClass},
            {"file", file},
            {"cores", cores},
            {"clock_mhz", clockMhz},
            {"fp32_lanes_per_core", fp32LanesPerCore},
            {"fp16_rate", fp16Rate},
            {"texture_units_per_core", textureUnitsPerCore},
            {"trilinear_3d_rate", trilinear3dRate},
            {"wide_texel_rate", wideTexelRate},
            {"rop_pixels_per_clock", ropPixelsPerClock},
            {"draw_overhead_us", drawOverheadUs},
            {"bandwidth_gbs", bandwidthGBs},
            {"l1", cache(l1)},
            {"l2", cache(l2)}};
}

DeviceSpec loadDevice(const std::string& path) {
    const std::vector<unsigned char> bytes = readFileBytes(path);
    const std::string text(bytes.begin(), bytes.end());
    const toml::table root = parseTomlText(text, path);
    DeviceReader r(path);
    r.checkKeys(root, {"name", "label", "compiler", "class", "gpu", "memory"}, "the device file");
    DeviceSpec d;
    d.file = path;
    d.name = r.text(root, "name");
    const std::string stem = fs::path(path).stem().string();
    if (d.name != stem)
        r.fail(root.get("name")->source(), "name '" + d.name + "' must be the file's stem '" + stem + "'");
    d.label = r.text(root, "label");
    d.compiler = r.text(root, "compiler");
    d.deviceClass = r.text(root, "class");
    if (!kClasses.count(d.deviceClass))
        r.fail(root.get("class")->source(),
               "class '" + d.deviceClass + "' is not one of handheld, phone, console, pc, datacentre");

    const toml::table& gpu = r.section(root, "gpu");
    r.checkKeys(gpu,
                {"cores", "clock_mhz", "fp32_lanes_per_core", "fp16_rate", "texture_units_per_core",
                 "trilinear_3d_rate", "wide_texel_rate", "rop_pixels_per_clock", "draw_overhead_us"},
                "[gpu]");
    d.cores = r.integer(gpu, "cores", 1, 100000);
    d.clockMhz = r.number(gpu, "clock_mhz", 1, 10000);
    d.fp32LanesPerCore = r.integer(gpu, "fp32_lanes_per_core", 1, 4096);
    d.fp16Rate = r.number(gpu, "fp16_rate", 0.015625, 4);
    d.textureUnitsPerCore = r.integer(gpu, "texture_units_per_core", 1, 256);
    d.trilinear3dRate = r.number(gpu, "trilinear_3d_rate", 0.0625, 1);
    d.wideTexelRate = r.number(gpu, "wide_texel_rate", 0.0625, 1);
    d.ropPixelsPerClock = r.integer(gpu, "rop_pixels_per_clock", 1, 4096);
    d.drawOverheadUs = r.number(gpu, "draw_overhead_us", 0, 1000);

    const toml::table& mem = r.section(root, "memory");
    r.checkKeys(mem,
                {"bandwidth_gbs", "l1_kib", "l1_line_bytes", "l1_ways", "l2_kib", "l2_line_bytes",
                 "l2_ways"},
                "[memory]");
    d.bandwidthGBs = r.number(mem, "bandwidth_gbs", 0.1, 100000);
    d.l1 = r.cache(mem, "l1");
    d.l2 = r.cache(mem, "l2");
    d.l1.name = d.name + " L1";
    d.l2.name = d.name + " L2";
    return d;
}

std::vector<std::string> deviceDirs(const std::string& builtIn) {
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("PROBEBENCH_DEVICES")) {
        std::stringstream in(env);
        std::string dir;
        while (std::getline(in, dir, ':'))
            if (!dir.empty()) dirs.push_back(dir);
    }
    dirs.push_back(builtIn);
    return dirs;
}

std::vector<std::string> deviceNames(const std::vector<std::string>& dirs) {
    std::set<std::string> names;
    for (const std::string& d : dirs) {
        std::error_code ec;
        for (const auto& f : fs::directory_iterator(d, ec))
            if (f.path().extension() == ".toml") names.insert(f.path().stem().string());
    }
    return {names.begin(), names.end()};
}

DeviceSpec findDevice(const std::string& nameOrPath, const std::vector<std::string>& dirs) {
    if (nameOrPath.size() > 5 && nameOrPath.substr(nameOrPath.size() - 5) == ".toml")
        return loadDevice(nameOrPath);
    for (const std::string& d : dirs) {
        const fs::path p = fs::path(d) / (nameOrPath + ".toml");
        std::error_code ec;
        if (fs::is_regular_file(p, ec)) return loadDevice(p.string());
    }
    const std::vector<std::string> names = deviceNames(dirs);
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
    throw Error("device '" + nameOrPath + "': no such device" + didYouMean(nameOrPath, names) +
                " (devices: " + (list.empty() ? "none found" : list) + "; or give a .toml path)");
}

std::vector<DeviceSpec> findDevices(const std::string& list, const std::vector<std::string>& dirs) {
    std::vector<std::string> names;
    if (list == "all") {
        names = deviceNames(dirs);
    } else {
        std::stringstream in(list);
        std::string n;
        while (std::getline(in, n, ','))
            if (!n.empty() && std::find(names.begin(), names.end(), n) == names.end())
                names.push_back(n);
    }
    if (names.empty()) throw Error("no device named in '" + list + "'");
    std::vector<DeviceSpec> out;
    for (const std::string& n : names)
        out.push_back(findDevice(n, dirs));
    return out;
}

} // namespace pb::devicemodel
