#include "profile/Profile.h"

#include "core/Error.h"
#include "core/Suggest.h"
#include "profile/SwitchTable.h"

namespace pb::profile {

namespace {
std::string knownKeys() {
    std::string out;
    for (const SwitchInfo& s : switchTable())
        out += (out.empty() ? "" : ", ") + s.key;
    return out;
}

const SwitchInfo& requireSwitch(const std::string& key, const std::string& context) {
    if (const SwitchInfo* s = findSwitch(key)) return *s;
    std::vector<std::string> keys;
    for (const SwitchInfo& s : switchTable())
        keys.push_back(s.key);
    throw Error(context + ": unknown switch '" + key + "'" + didYouMean(key, keys) +
                " (switches: " + knownKeys() + ")");
}
} // namespace

Profile::Profile() {
    for (const SwitchInfo& s : switchTable())
        s.set(*this, s.defaultValue);
}

void Profile::set(const std::string& key, const std::string& value) {
    const SwitchInfo& s = requireSwitch(key, key + "=" + value);
    std::string problem = switchValueProblem(s, value);
    if (!problem.empty()) throw Error(key + "=" + value + ": " + problem);
    s.set(*this, value);
}

void Profile::applyOverride(const std::string& assignment, const std::string& option) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error(option + " '" + assignment + "': expected key=value (switches: " + knownKeys() +
                    ")");
    std::string key = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    const SwitchInfo& s = requireSwitch(key, option + " " + assignment);
    std::string problem = switchValueProblem(s, value);
    if (!problem.empty()) throw Error(option + " " + assignment + ": " + problem);
    s.set(*this, value);
}

std::string Profile::get(const std::string& key) const {
    return requireSwitch(key, "profile").get(*this);
}

nlohmann::json Profile::valuesJson() const {
    nlohmann::json j = nlohmann::json::object();
    for (const SwitchInfo& s : switchTable())
        j[s.key] = s.get(*this);
    return j;
}

std::vector<std::string> Profile::changedSwitches() const {
    std::vector<std::string> out;
    for (const SwitchInfo& s : switchTable())
        if (s.get(*this) != s.defaultValue) out.push_back(s.key + "=" + s.get(*this));
    return out;
}

int resolutionDivisor(GiResolution r) {
    return r == GiResolution::Full ? 1 : r == GiResolution::Half ? 2 : 4;
}

} // namespace pb::profile
