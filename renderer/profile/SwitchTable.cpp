#include "profile/SwitchTable.h"

#include "core/Error.h"
#include "profile/VolumeLod.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>

namespace pb::profile {

namespace {

template <class E> using Names = std::vector<std::pair<E, const char*>>;

// A Choice row bound to an enum field of GiSwitches; the names list is the allowed values in
// the order docs show them.
template <class E>
SwitchInfo choice(const char* key, E GiSwitches::*field, Names<E> names, const char* def,
                  DefineStyle style, const char* define, const char* doc) {
    SwitchInfo s;
    s.key = key;
    s.kind = SwitchKind::Choice;
    for (const auto& [value, name] : names)
        s.choices.push_back(name);
    s.defaultValue = def;
    s.doc = doc;
    s.defineStyle = style;
    s.define = define;
    s.get = [field, names](const Profile& p) -> std::string {
        for (const auto& [value, name] : names)
            if (p.gi.*field == value) return name;
        return "?";
    };
    s.set = [field, names](Profile& p, const std::string& text) {
        for (const auto& [value, name] : names)
            if (text == name) p.gi.*field = value;
    };
    return s;
}

SwitchInfo text(const char* key, std::string GiSwitches::*field, const char* def,
                std::function<std::string(const std::string&)> validate, const char* doc) {
    SwitchInfo s;
    s.key = key;
    s.kind = SwitchKind::Text;
    s.defaultValue = def;
    s.doc = doc;
    s.validate = std::move(validate);
    s.get = [field](const Profile& p) { return p.gi.*field; };
    s.set = [field](Profile& p, const std::string& v) { p.gi.*field = v; };
    return s;
}

Names<GiGuard> guardNames() {
    return {{GiGuard::Off, "off"}, {GiGuard::On, "on"}};
}

std::string volumeLodProblem(const std::string& v) {
    try {
        parseVolumeLod(v);
        return "";
    } catch (const Error& e) {
        return e.what();
    }
}

std::vector<SwitchInfo> buildTable() {
    using D = DefineStyle;
    return {
        choice("gi.technique", &GiSwitches::technique,
               Names<GiTechnique>{{GiTechnique::Ddgi, "ddgi"},
                                  {GiTechnique::ShL1, "sh_l1"},
                                  {GiTechnique::ShL2, "sh_l2"}},
               "ddgi", D::ChoiceFlag, "GI_TECHNIQUE",
               "indirect diffuse technique: DDGI probes (octahedral irradiance + visibility), or "
               "an SH L1 / L2 irradiance volume read with hardware trilinear 3D fetches, no "
               "visibility (same bake)"),
        choice("gi.sh_leak", &GiSwitches::shLeak,
               Names<GiShLeak>{{GiShLeak::None, "none"},
                               {GiShLeak::Weight, "weight"},
                               {GiShLeak::ValidityMask, "validity_mask"}},
               "none", D::ChoiceFlag, "GI_SH_LEAK",
               "SH techniques' leak reduction: none; weight (invalid probes weigh 0, lighting "
               "and weight filtered together and divided); validity_mask (8-bit mask of valid "
               "corners per cell, sample nudged off invalid corners)"),
        choice("gi.resolution", &GiSwitches::resolution,
               Names<GiResolution>{{GiResolution::Full, "full"},
                                   {GiResolution::Half, "half"},
                                   {GiResolution::Quarter, "quarter"}},
               "full", D::ChoiceFlag, "GI_RESOLUTION",
               "GI evaluation target size per axis (half = 1/2 on each axis); see gi.upsample"),
        choice("gi.target_format", &GiSwitches::targetFormat,
               Names<GiTargetFormat>{{GiTargetFormat::Rgba16f, "rgba16f"},
                                     {GiTargetFormat::R11g11b10f, "r11g11b10f"},
                                     {GiTargetFormat::Rgba32f, "rgba32f"}},
               "rgba16f", D::ChoiceFlag, "GI_TARGET",
               "format of the GI evaluation target (r11g11b10f has no alpha: weight packed)"),
        choice("gi.precision", &GiSwitches::precision,
               Names<GiPrecision>{{GiPrecision::Fp32, "fp32"}, {GiPrecision::Fp16, "fp16"}}, "fp32",
               D::ChoiceFlag, "GI_PRECISION",
               "shader arithmetic of the probe weights and irradiance sums"),
        choice("gi.loops", &GiSwitches::loops,
               Names<GiLoops>{{GiLoops::Fused, "fused"}, {GiLoops::Split, "split"}}, "fused",
               D::ChoiceFlag, "GI_LOOPS",
               "fused: one loop over the 8 probes; split: weights first, then irradiance"),
        choice("gi.probe_order", &GiSwitches::probeOrder,
               Names<GiProbeOrder>{{GiProbeOrder::Xyz, "xyz"},
                                   {GiProbeOrder::SliceFirst, "slice_first"}},
               "xyz", D::ChoiceFlag, "GI_ORDER",
               "probe visit order: x fastest, or the 4 probes of one texture slice first"),
        choice("gi.multi_volume", &GiSwitches::multiVolume,
               Names<GiMultiVolume>{{GiMultiVolume::Naive, "naive"},
                                    {GiMultiVolume::Stencil, "stencil"}},
               "naive", D::HostOnly, "",
               "naive: every volume drawn largest first, overwriting; stencil: once per pixel"),
        choice("gi.dynamic", &GiSwitches::dynamic,
               Names<GiDynamic>{{GiDynamic::PerPixel, "per_pixel"}, {GiDynamic::Sh, "sh"}},
               "per_pixel", D::ChoiceFlag, "GI_DYNAMIC",
               "GI of dynamic-object pixels: per-pixel probes, or L1 SH per object"),
        choice("gi.upsample", &GiSwitches::upsample,
               Names<GiUpsample>{{GiUpsample::Bilinear, "bilinear"},
                                 {GiUpsample::Bilateral, "bilateral"},
                                 {GiUpsample::Temporal, "temporal"}},
               "bilinear", D::HostOnly, "",
               "half/quarter GI to full resolution (upsample pass): bilinear, depth/normal-aware "
               "bilateral, or temporal history with jittered samples"),
        text("gi.volume_lod", &GiSwitches::volumeLod, "all", volumeLodProblem,
             "volumes left out: all | omit:A,B | min_spacing:M | budget_mib:MIB | "
             "rank_budget_mib:MIB (needs volumes --rank --write-ranks)"),
        // Guards (issue 8; `probebench stress` finds what they fix, README.md has the table).
        choice("gi.guard_exposure", &GiSwitches::guardExposure, guardNames(), "on", D::ChoiceFlag,
               "GI_GUARD_EXPOSURE",
               "pre-exposure: probe irradiance x the exposure's power of two before fp16 math "
               "and the GI/radiance targets; keeps 1e-6..1e6 lighting in range"),
        choice("gi.guard_clamp", &GiSwitches::guardClamp, guardNames(), "on", D::ChoiceFlag,
               "GI_GUARD_CLAMP",
               "NaN -> 0, overflow -> the format's max, no negatives, before the GI target and "
               "the radiance are stored"),
    };
}

std::string upper(std::string s) {
    for (char& c : s)
        c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string join(const std::vector<std::string>& v) {
    std::string out;
    for (const auto& s : v)
        out += (out.empty() ? "" : ", ") + s;
    return out;
}

const char* kindName(SwitchKind k) {
    return k == SwitchKind::Choice ? "choice" : k == SwitchKind::Number ? "number" : "text";
}

} // namespace

const std::vector<SwitchInfo>& switchTable() {
    static const std::vector<SwitchInfo> table = buildTable();
    return table;
}

const SwitchInfo* findSwitch(const std::string& key) {
    for (const SwitchInfo& s : switchTable())
        if (s.key == key) return &s;
    return nullptr;
}

std::string switchValueProblem(const SwitchInfo& info, const std::string& value) {
    switch (info.kind) {
    case SwitchKind::Choice:
        if (std::find(info.choices.begin(), info.choices.end(), value) != info.choices.end())
            return "";
        return "allowed values: " + join(info.choices);
    case SwitchKind::Number: {
        std::istringstream in(value);
        double v = 0;
        if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v) || v < info.minValue ||
            v > info.maxValue) {
            std::ostringstream range;
            range << "expected a number in [" << info.minValue << ", " << info.maxValue << "]";
            return range.str();
        }
        return "";
    }
    case SwitchKind::Text:
        return info.validate ? info.validate(value) : "";
    }
    return "";
}

std::map<std::string, std::string> shaderDefines(const Profile& p) {
    std::map<std::string, std::string> d;
    for (const SwitchInfo& s : switchTable()) {
        if (s.defineStyle == DefineStyle::ChoiceFlag)
            d[s.define + "_" + upper(s.get(p))] = "";
        else if (s.defineStyle == DefineStyle::Value)
            d[s.define] = s.get(p);
    }
    return d;
}

nlohmann::json describeSwitches(const Profile& current) {
    nlohmann::json out = nlohmann::json::array();
    for (const SwitchInfo& s : switchTable()) {
        nlohmann::json j{{"key", s.key},
                         {"kind", kindName(s.kind)},
                         {"default", s.defaultValue},
                         {"value", s.get(current)},
                         {"doc", s.doc}};
        if (s.kind == SwitchKind::Choice) j["values"] = s.choices;
        if (s.kind == SwitchKind::Number) j["range"] = {s.minValue, s.maxValue};
        if (s.defineStyle == DefineStyle::ChoiceFlag)
            j["define"] = s.define + "_<VALUE>";
        else if (s.defineStyle == DefineStyle::Value)
            j["define"] = s.define;
        else
            j["define"] = nullptr;
        out.push_back(j);
    }
    return out;
}

std::string describeSwitchesText(const Profile& current) {
    std::ostringstream out;
    for (const SwitchInfo& s : switchTable()) {
        out << s.key << " = " << s.get(current);
        if (s.get(current) != s.defaultValue) out << "  (default " << s.defaultValue << ")";
        out << "\n    " << s.doc << "\n";
        if (s.kind == SwitchKind::Choice) out << "    values: " << join(s.choices) << "\n";
        if (s.defineStyle == DefineStyle::ChoiceFlag)
            out << "    shader: #define " << s.define << "_<VALUE>\n";
        else if (s.defineStyle == DefineStyle::Value)
            out << "    shader: #define " << s.define << " <value>\n";
    }
    return out.str();
}

} // namespace pb::profile
