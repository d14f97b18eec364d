#pragma once
// A platform profile: the GI switches one class of hardware runs with (the switch table's
// Profile), plus what the benchmark needs to judge it - output resolution, frame budget, GI
// memory budget and the cost model's texture-cache preset. Loaded from profiles/*.toml
// (ProfileLoader.h); GL-free.
#include "profile/Profile.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pb::profile {

// What "GI memory" counts wherever it is reported or budgeted ([budget] gi_memory_mib, the
// bench's GI MiB column and JSON, tune's --budget-mib and candidates): one definition, so a
// profile that fits in one fits in the other (issue 25, item 5). The bytes are
// render::GiMemory (renderer/frame/GiMemory.h): counted from a rendered frame's allocations
// (bench) or estimated without GL (tune), cross-checked by tests/gl/FrameSkipTest.cpp.
inline constexpr char kGiMemoryDefinition[] =
    "GI memory = probe textures kept by gi.volume_lod (one scenario) + GI targets (evaluation, "
    "upsample/history, dynamic SH)";

struct PlatformProfile {
    std::string name;                  // file stem ("handheld")
    std::string file;                  // the TOML it came from ("" when built in code)
    std::string description;           // one line for listings
    std::vector<std::string> inherits; // parent chain, nearest first ("console-base", ...)
    Profile switches;                  // every GI switch (table defaults where unset)
    int width = 1280, height = 720;    // output resolution
    double frameBudgetMs = 16.7;       // whole frame on the target hardware
    double giMemoryBudgetMiB = 8.0;    // GI memory (kGiMemoryDefinition), MiB
    // The device the budgets are for, as its GL_RENDERER names it ("Tegra X1"); "" = the
    // profile's target hardware, unnamed. A bench judges the frame budget only on that device.
    std::string budgetDevice;
    // The device file (profiles/devices/NAME.toml) the device model judges the budgets on
    // (`bench --predict own`); "" = none named.
    std::string modelDevice;
    std::string cachePreset;           // costmodel::cachePresetFor name
    // Incremental probe updates after a scene change (`probebench respond --profile`): the
    // rays and the probe-texture upload bytes one frame may spend; 0 = no limit.
    int updateRaysPerFrame = 0;
    int updateUploadBytesPerFrame = 0;

    // {name, file, description, inherits, output, budget, costmodel, switches}
    nlohmann::json toJson() const;
    // "1280x720, 33.3 ms, 4 MiB, cache handheld; gi: resolution=half, ..." (switches that
    // differ from the table defaults).
    std::string summaryLine() const;
    bool sameSettings(const PlatformProfile& o) const; // everything but name/file/description
};

} // namespace pb::profile
