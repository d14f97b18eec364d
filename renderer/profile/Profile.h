#pragma once
// The profile: every renderer switch (issue 4: the GI apply pass and its per-pixel
// optimizations) as one typed struct. What each switch means, its allowed values, its default
// and how it reaches the shaders lives in ONE table (SwitchTable.cpp); parsing (`--set
// key=value`, TOML profiles), the JSON description and the shader #defines are generated from it.
// Adding a switch = a field here + one table row + its use in the pass/shader.
//
// GL-free: the passes read a Profile, the GL code never lives here.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pb::profile {

enum class GiTechnique { Ddgi, ShL1, ShL2 };
enum class GiShLeak { None, Weight, ValidityMask };
enum class GiResolution { Full, Half, Quarter };
enum class GiTargetFormat { Rgba16f, R11g11b10f, Rgba32f };
enum class GiPrecision { Fp32, Fp16 };
enum class GiLoops { Fused, Split };
enum class GiProbeOrder { Xyz, SliceFirst };
enum class GiMultiVolume { Naive, Stencil };
enum class GiDynamic { PerPixel, Sh };
enum class GiUpsample { Bilinear, Bilateral, Temporal };
enum class GiGuard { Off, On }; // gi.guard_*: numerical guards (issue 8)

struct GiSwitches {
    GiTechnique technique;
    GiShLeak shLeak; // sh_l1 / sh_l2 only
    GiResolution resolution;
    GiTargetFormat targetFormat;
    GiPrecision precision;
    GiLoops loops;
    GiProbeOrder probeOrder;
    GiMultiVolume multiVolume;
    GiDynamic dynamic;
    GiUpsample upsample; // used when resolution is half or quarter
    std::string
        volumeLod; // "all" | "omit:NAME[,NAME...]" | "min_spacing:METRES" | "budget_mib:MIB"
    GiGuard guardExposure; // pre-exposed irradiance and radiance
    GiGuard guardClamp;    // finite, in-range values before every store
};

struct Profile {
    Profile(); // every switch at the table's default
    GiSwitches gi;

    // Sets one switch from its text form ("half", "0.5"). Throws pb::Error naming the key and
    // listing the allowed values (or the known keys) when either is wrong.
    void set(const std::string& key, const std::string& value);
    // "key=value" as given to --set; `option` names the source in errors.
    void applyOverride(const std::string& assignment, const std::string& option = "--set");
    // The text form of one switch's current value. Throws pb::Error for an unknown key.
    std::string get(const std::string& key) const;

    // {"gi.resolution": "full", ...}: the values, in table order.
    nlohmann::json valuesJson() const;
    // Switches whose value differs from the default, "key=value" each.
    std::vector<std::string> changedSwitches() const;
    bool operator==(const Profile& o) const { return valuesJson() == o.valuesJson(); }
};

// Divisor of the GI evaluation target's size per axis (1, 2, 4).
int resolutionDivisor(GiResolution r);

} // namespace pb::profile
