#include "profile/PlatformProfile.h"

#include "profile/ProfileSettings.h"

#include <algorithm>
#include <cstdio>

namespace pb::profile {

nlohmann::json PlatformProfile::toJson() const {
    nlohmann::json j{{"name", name},
                     {"file", file},
                     {"description", description},
                     {"inherits", inherits},
                     {"switches", switches.valuesJson()}};
    // The non-switch settings under their TOML paths: {"output": {"width": 1280, ...}, ...}.
    for (const ProfileSetting& s : profileSettings()) {
        // Built in place, not as "/" + key: GCC 12 takes that concatenation, once inlined, for
        // an overlapping copy (a false -Wrestrict).
        std::string path = "/";
        path += s.key;
        std::replace(path.begin(), path.end(), '.', '/');
        nlohmann::json::json_pointer ptr(path);
        if (s.kind == ProfileSetting::Kind::Text)
            j[ptr] = s.getText(*this);
        else if (s.kind == ProfileSetting::Kind::Integer)
            j[ptr] = int(s.getNumber(*this));
        else
            j[ptr] = s.getNumber(*this);
    }
    return j;
}

std::string PlatformProfile::summaryLine() const {
    char head[160];
    std::snprintf(head, sizeof head, "%dx%d, %.4g ms, %.4g MiB, cache %s", width, height,
                  frameBudgetMs, giMemoryBudgetMiB, cachePreset.c_str());
    std::string out = head;
    std::string gi;
    for (const std::string& c : switches.changedSwitches())
        gi += (gi.empty() ? "" : " ") + c;
    out += "; " + (gi.empty() ? std::string("switches: defaults") : gi);
    return out;
}

bool PlatformProfile::sameSettings(const PlatformProfile& o) const {
    return switches == o.switches && width == o.width && height == o.height &&
           frameBudgetMs == o.frameBudgetMs && giMemoryBudgetMiB == o.giMemoryBudgetMiB &&
           budgetDevice == o.budgetDevice && modelDevice == o.modelDevice && cachePreset == o.cachePreset &&
           updateRaysPerFrame == o.updateRaysPerFrame &&
           updateUploadBytesPerFrame == o.updateUploadBytesPerFrame;
}

} // namespace pb::profile
