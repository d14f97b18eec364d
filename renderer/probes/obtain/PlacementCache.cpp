#include "PlacementCache.h"

#include "core/Error.h"
#include "core/FileIO.h"

#include <cinttypes>
#include <cstdio>
#include <exception>
#include <iostream>

namespace pb::probes {
namespace {

// Hex strings: JSON numbers lose 64-bit integers in most readers.
std::string hex(std::uint64_t v) {
    char s[17];
    std::snprintf(s, sizeof s, "%016" PRIx64, v);
    return s;
}

std::optional<std::uint64_t> parseHex(const nlohmann::json& j) {
    if (!j.is_string() || j.get<std::string>().size() != 16) return std::nullopt;
    try {
        std::size_t used = 0;
        const std::uint64_t v = std::stoull(j.get<std::string>(), &used, 16);
        if (used == 16) return v;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

} // namespace

std::string placementCachePath(const std::string& probeFile) {
    return probeFile + ".placement.json";
}

std::optional<CachedPlacement> readPlacementCache(const std::string& probeFile,
                                                  std::uint64_t placementKey) {
    try {
        const std::vector<unsigned char> bytes = readFileBytes(placementCachePath(probeFile));
        const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end());
        const auto key = parseHex(j.value("placement_key", nlohmann::json()));
        const auto input = parseHex(j.value("input_hash", nlohmann::json()));
        if (!key || !input || *key != placementKey || !j.contains("placement") ||
            !j["placement"].is_object())
            return std::nullopt;
        return CachedPlacement{*key, *input, j["placement"]};
    } catch (const std::exception&) {
        return std::nullopt; // missing or damaged: place again
    }
}

void writePlacementCache(const std::string& probeFile, const CachedPlacement& c) {
    const nlohmann::json j{{"written_by", "probebench (renderer/probes/obtain/PlacementCache.h)"},
                           {"placement_key", hex(c.placementKey)},
                           {"input_hash", hex(c.inputHash)},
                           {"placement", c.placement}};
    const std::string text = j.dump(2) + "\n";
    try {
        writeFileAtomic(placementCachePath(probeFile), text.data(), text.size());
    } catch (const std::exception& e) {
        std::cerr << "note: the placement cache was not written (the next bake places again): "
                  << e.what() << "\n";
    }
}

} // namespace pb::probes
