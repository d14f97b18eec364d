#pragma once
// The keys of a profile file that are not GI switches (output size, budgets, cache preset,
// description), as one table like the switch table: the loader, the writer and `probebench
// profiles` iterate it. GI switches are NOT listed here: every row of SwitchTable.cpp is a
// profile key by itself ("gi.resolution" = `[gi] resolution = ...`).
#include "profile/PlatformProfile.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::profile {

struct ProfileSetting {
    enum class Kind { Integer, Number, Text };
    std::string key; // dotted TOML path, e.g. "output.width"
    Kind kind = Kind::Number;
    double minValue = 0, maxValue = 0; // Integer/Number: inclusive range
    bool minExclusive = false;         // Number: (min, max]
    bool requiredAtRoot = true;        // a profile without `inherit` must set it
    std::string doc;
    std::function<void(PlatformProfile&, double)> setNumber;
    std::function<void(PlatformProfile&, const std::string&)> setText;
    std::function<double(const PlatformProfile&)> getNumber;
    std::function<std::string(const PlatformProfile&)> getText;
};

const std::vector<ProfileSetting>& profileSettings();
const ProfileSetting* findProfileSetting(const std::string& key); // nullptr when unknown

// Why `value` is out of range for the Integer/Number setting ("" when fine).
std::string settingRangeProblem(const ProfileSetting& s, double value);

} // namespace pb::profile
