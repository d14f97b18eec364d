#include "profile/ProfileSettings.h"

#include <cmath>
#include <sstream>

namespace pb::profile {

namespace {

using Kind = ProfileSetting::Kind;

ProfileSetting number(const char* key, Kind kind, double lo, double hi, bool loExclusive,
                      const char* doc, double PlatformProfile::*field) {
    ProfileSetting s;
    s.key = key;
    s.kind = kind;
    s.minValue = lo;
    s.maxValue = hi;
    s.minExclusive = loExclusive;
    s.doc = doc;
    s.setNumber = [field](PlatformProfile& p, double v) { p.*field = v; };
    s.getNumber = [field](const PlatformProfile& p) { return p.*field; };
    return s;
}

ProfileSetting integer(const char* key, int lo, int hi, const char* doc,
                       int PlatformProfile::*field) {
    ProfileSetting s;
    s.key = key;
    s.kind = Kind::Integer;
    s.minValue = lo;
    s.maxValue = hi;
    s.doc = doc;
    s.setNumber = [field](PlatformProfile& p, double v) { p.*field = int(v); };
    s.getNumber = [field](const PlatformProfile& p) { return double(p.*field); };
    return s;
}

ProfileSetting textSetting(const char* key, bool required, const char* doc,
                           std::string PlatformProfile::*field) {
    ProfileSetting s;
    s.key = key;
    s.kind = Kind::Text;
    s.requiredAtRoot = required;
    s.doc = doc;
    s.setText = [field](PlatformProfile& p, const std::string& v) { p.*field = v; };
    s.getText = [field](const PlatformProfile& p) { return p.*field; };
    return s;
}

// A setting a root profile may leave out: it then keeps the PlatformProfile default.
ProfileSetting optional(ProfileSetting s) {
    s.requiredAtRoot = false;
    return s;
}

std::vector<ProfileSetting> buildSettings() {
    return {
        textSetting("description", false, "one line shown by `probebench profiles`",
                    &PlatformProfile::description),
        integer("output.width", 16, 16384, "output (GBuffer) width in pixels",
                &PlatformProfile::width),
        integer("output.height", 16, 16384, "output (GBuffer) height in pixels",
                &PlatformProfile::height),
        number("budget.frame_ms", Kind::Number, 0.0, 1000.0, true,
               "whole-frame budget on the target hardware (ms)", &PlatformProfile::frameBudgetMs),
        number("budget.gi_memory_mib", Kind::Number, 0.0, 65536.0, true,
               "GPU memory for the probe data of one scenario (MiB)",
               &PlatformProfile::giMemoryBudgetMiB),
        optional(textSetting("budget.device", false,
                             "the device the budgets are for, as its GL_RENDERER names it; the "
                             "bench colours the frame budget only when it times on it",
                             &PlatformProfile::budgetDevice)),
        optional(textSetting("budget.model", false,
                             "the device file (profiles/devices/NAME.toml) the budgets are "
                             "judged on by the device model (bench --predict own)",
                             &PlatformProfile::modelDevice)),
        optional(integer("update.rays_per_frame", 0, 1 << 30,
                         "probe update budget: rays per frame after a scene change (probebench "
                         "respond; 0 = no limit)",
                         &PlatformProfile::updateRaysPerFrame)),
        optional(integer("update.upload_bytes_per_frame", 0, 1 << 30,
                         "probe update budget: probe texture bytes uploaded per frame (0 = no "
                         "limit)",
                         &PlatformProfile::updateUploadBytesPerFrame)),
        textSetting("costmodel.cache_preset", true,
                    "texture-cache preset of the cost model (probebench costmodel --cache)",
                    &PlatformProfile::cachePreset),
    };
}

} // namespace

const std::vector<ProfileSetting>& profileSettings() {
    static const std::vector<ProfileSetting> table = buildSettings();
    return table;
}

const ProfileSetting* findProfileSetting(const std::string& key) {
    for (const ProfileSetting& s : profileSettings())
        if (s.key == key) return &s;
    return nullptr;
}

std::string settingRangeProblem(const ProfileSetting& s, double v) {
    bool ok =
        std::isfinite(v) && v <= s.maxValue && (s.minExclusive ? v > s.minValue : v >= s.minValue);
    if (s.kind == Kind::Integer && v != std::floor(v)) ok = false;
    if (ok) return "";
    std::ostringstream out;
    out << "must be " << (s.kind == Kind::Integer ? "an integer" : "a number") << " in "
        << (s.minExclusive ? "(" : "[") << s.minValue << ", " << s.maxValue << "]";
    return out.str();
}

} // namespace pb::profile
