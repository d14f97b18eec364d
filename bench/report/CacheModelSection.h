#pragma once
// The bench report's texture-cache section (issue 7, item 2): per profile, the probe-texture
// hit rate and bytes missed per GI pixel of every shader variant - xyz vs slice_first, fused
// vs split - through the profile's own cache preset, from the deterministic cost model
// (renderer/costmodel; runner/CacheModelRun.h fills it). Hardware-independent. GL-free.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pb::bench {

struct CacheModelVariant {
    std::string variant; // "xyz/fused", ...
    double hitRate = 0, bytesMissedPerPixel = 0;
};

struct CacheModelEntry {
    std::string profile, cache; // cache: "handheld: 16 KiB, 64 B lines, 4-way"
    int width = 0, height = 0;
    std::string profileVariant; // the variant the profile runs
    std::vector<CacheModelVariant> variants;
    const CacheModelVariant* find(const std::string& variant) const;
};

nlohmann::json cacheModelJson(const std::vector<CacheModelEntry>& entries);
std::string cacheModelMarkdown(const std::vector<CacheModelEntry>& entries); // "" when empty
std::string cacheModelHtml(const std::vector<CacheModelEntry>& entries);     // "" when empty

} // namespace pb::bench
