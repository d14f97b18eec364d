#include "costmodel/CachePresets.h"

#include "core/Error.h"

namespace pb::costmodel {

const std::vector<CacheConfig>& cachePresets() {
    static const std::vector<CacheConfig> presets = {
        {"handheld", 16 * 1024, 64, 4,
         "assumption: mobile-class per-core texture L1 (Mali/Adreno/Tegra X1 class, 16-24 KiB); "
         "64 B lines and 4 ways as in the issue's example"},
        {"console-base", 16 * 1024, 64, 16,
         "GCN (PS4/Xbox One class): 16 KB vector L1 per CU, 64 B per clock to L2 (AMD GCN "
         "launch reviews, e.g. behardware.com HD 7970 review); 16 ways is an assumption"},
        {"pc-low", 32 * 1024, 128, 8,
         "assumption: entry desktop GPU, per-SM L1/texture 24-48 KiB (NVIDIA Maxwell/Pascal "
         "tuning guides: unified L1/texture cache); 128 B lines as on NVIDIA"},
        {"pc-high", 128 * 1024, 128, 16,
         "NVIDIA Ada (RTX 4090): 128 KB unified L1/shared per SM (NVIDIA developer forum, "
         "compute capability 8.9 carve-outs); 128 B lines; all of it as L1 and 16 ways are "
         "assumptions"},
    };
    return presets;
}

CacheConfig cachePresetFor(const std::string& profileName) {
    std::string known;
    for (const CacheConfig& c : cachePresets()) {
        if (c.name == profileName) return c;
        known += (known.empty() ? "" : ", ") + c.name;
    }
    throw Error("unknown cache preset '" + profileName + "' (known: " + known + ")");
}

} // namespace pb::costmodel
