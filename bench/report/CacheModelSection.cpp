#include "CacheModelSection.h"

#include "Html.h"

#include <cstdio>
#include <sstream>

namespace pb::bench {

namespace {

const char* kVariants[] = {"xyz/fused", "xyz/split", "slice_first/fused", "slice_first/split"};

std::string cellText(const CacheModelEntry& e, const char* variant) {
    const CacheModelVariant* v = e.find(variant);
    if (!v) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f%% / %.1f%s", 100 * v->hitRate, v->bytesMissedPerPixel,
                  e.profileVariant == variant ? " *" : "");
    return buf;
}

// An SH profile's one stream (CostModel.h: named "technique/leak"), "n/a" for DDGI profiles.
std::string shCellText(const CacheModelEntry& e) {
    for (const CacheModelVariant& v : e.variants)
        if (v.variant.rfind("sh_", 0) == 0) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s: %.2f%% / %.1f%s", v.variant.c_str(),
                          100 * v.hitRate, v.bytesMissedPerPixel,
                          e.profileVariant == v.variant ? " *" : "");
            return buf;
        }
    return "n/a";
}

// Relative change of bytes missed from variant a to b ("-4.1%"), "n/a" without both.
std::string change(const CacheModelEntry& e, const char* a, const char* b) {
    const CacheModelVariant *va = e.find(a), *vb = e.find(b);
    if (!va || !vb || !(va->bytesMissedPerPixel > 0)) return "n/a";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%+.1f%%",
                  100 * (vb->bytesMissedPerPixel / va->bytesMissedPerPixel - 1));
    return buf;
}

const char* kIntro =
    "Probe-texture hit rate / bytes missed per GI pixel in the cost model (renderer/costmodel: "
    "each variant's texel addresses, 8x8 tiles of 2x2 quads, warps of 32, through the "
    "profile's cache preset; * = the profile's variant; SH profiles: their one stream, one "
    "trilinear 3D fetch per coefficient texture + the mask). Hardware-independent; not a "
    "timing.";

} // namespace

const CacheModelVariant* CacheModelEntry::find(const std::string& variant) const {
    for (const CacheModelVariant& v : variants)
        if (v.variant == variant) return &v;
    return nullptr;
}

nlohmann::json cacheModelJson(const std::vector<CacheModelEntry>& entries) {
    nlohmann::json out = nlohmann::json::array();
    for (const CacheModelEntry& e : entries) {
        nlohmann::json vs = nlohmann::json::array();
        for (const CacheModelVariant& v : e.variants)
            vs.push_back({{"variant", v.variant},
                          {"probe_hit_rate", v.hitRate},
                          {"probe_bytes_missed_per_pixel", v.bytesMissedPerPixel}});
        out.push_back({{"profile", e.profile},
                       {"cache", e.cache},
                       {"width", e.width},
                       {"height", e.height},
                       {"profile_variant", e.profileVariant},
                       {"variants", vs}});
    }
    return out;
}

std::string cacheModelMarkdown(const std::vector<CacheModelEntry>& entries) {
    if (entries.empty()) return "";
    std::ostringstream out;
    out << "\nTexture-cache model: " << kIntro << "\n\n| profile | cache |";
    for (const char* v : kVariants)
        out << " " << v << " |";
    out << " SH (gi.technique/gi.sh_leak) | slice_first vs xyz | split vs fused |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
    for (const CacheModelEntry& e : entries) {
        out << "| " << e.profile << " | " << e.cache << " |";
        for (const char* v : kVariants)
            out << " " << cellText(e, v) << " |";
        out << " " << shCellText(e) << " |";
        out << " " << change(e, "xyz/fused", "slice_first/fused") << " | "
            << change(e, "xyz/fused", "xyz/split") << " |\n";
    }
    return out.str();
}

std::string cacheModelHtml(const std::vector<CacheModelEntry>& entries) {
    if (entries.empty()) return "";
    std::ostringstream h;
    h << "<h2>Texture-cache model</h2>\n<p class=\"note\">" << htmlEscape(kIntro)
      << " Columns: hit rate / bytes missed per pixel; the last two: bytes missed of "
         "slice_first/fused and xyz/split relative to xyz/fused.</p>\n"
      << "<table id=\"cache-model\"><tr><th class=\"l\">profile</th><th class=\"l\">cache</th>";
    for (const char* v : kVariants)
        h << "<th>" << v << "</th>";
    h << "<th>SH (gi.technique/gi.sh_leak)</th><th>slice_first vs xyz</th><th>split vs "
         "fused</th></tr>\n";
    for (const CacheModelEntry& e : entries) {
        h << "<tr><td class=\"l\">" << htmlEscape(e.profile) << "</td><td class=\"l\">"
          << htmlEscape(e.cache) << "</td>";
        for (const char* v : kVariants)
            h << "<td>" << htmlEscape(cellText(e, v)) << "</td>";
        h << "<td>" << htmlEscape(shCellText(e)) << "</td>";
        h << "<td>" << change(e, "xyz/fused", "slice_first/fused") << "</td><td>"
          << change(e, "xyz/fused", "xyz/split") << "</td></tr>\n";
    }
    h << "</table>\n";
    return h.str();
}

} // namespace pb::bench
