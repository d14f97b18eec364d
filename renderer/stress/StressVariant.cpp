#include "stress/StressVariant.h"

#include "core/Error.h"
#include "profile/SwitchTable.h"

#include <algorithm>

namespace pb::stress {

std::vector<std::string> StressVariant::keys() const {
    std::vector<std::string> out;
    for (const profile::SwitchInfo& s : profile::switchTable())
        out.push_back(s.key);
    out.push_back(kStorageKey);
    return out;
}

std::string StressVariant::get(const std::string& key) const {
    if (key == kStorageKey) return probes::formatName(storage);
    return profile.get(key);
}

void StressVariant::set(const std::string& key, const std::string& value,
                        const std::string& option) {
    if (key == kStorageKey) {
        storage = probes::parseStorageFormat(value, option + " " + key);
        return;
    }
    profile.applyOverride(key + "=" + value, option);
}

std::string StressVariant::settingsKey() const {
    std::string out;
    for (const std::string& k : keys())
        out += (out.empty() ? "" : ",") + k + "=" + get(k);
    return out;
}

std::vector<std::string> StressVariant::differingKeys(const StressVariant& other) const {
    std::vector<std::string> out;
    for (const std::string& k : keys())
        if (get(k) != other.get(k)) out.push_back(k);
    return out;
}

bool isGuardKey(const std::string& key) {
    return key.rfind("gi.guard_", 0) == 0;
}

std::vector<std::string> guardKeys() {
    std::vector<std::string> out;
    for (const profile::SwitchInfo& s : profile::switchTable())
        if (isGuardKey(s.key)) out.push_back(s.key);
    return out;
}

StressVariant withoutGuards(StressVariant v) {
    for (const std::string& g : guardKeys())
        v.profile.set(g, "off");
    return v;
}

StressVariant parseVariantSpec(const std::string& spec, const std::string& option) {
    const auto colon = spec.find(':');
    StressVariant v;
    v.name = spec.substr(0, colon);
    if (v.name.empty())
        throw Error(option + " '" + spec + "': expected NAME or NAME:key=value,key=value");
    if (colon == std::string::npos) return v;
    const std::string list = spec.substr(colon + 1);
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string item = list.substr(start, comma - start);
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw Error(option + " '" + spec + "': '" + item + "' is not key=value");
        v.set(item.substr(0, eq), item.substr(eq + 1), option + " '" + v.name + "'");
        start = comma + 1;
    }
    return v;
}

StressVariant referenceVariant() {
    StressVariant v;
    v.name = "reference";
    v.profile.set("gi.precision", "fp32");
    v.profile.set("gi.target_format", "rgba32f");
    v.profile.set("gi.resolution", "full");
    v.storage = probes::StorageFormat::Rgba32f;
    for (const std::string& g : guardKeys())
        v.profile.set(g, "on");
    return v;
}

std::vector<StressVariant> defaultVariants() {
    return {
        parseVariantSpec("defaults"),
        parseVariantSpec("fp16:gi.precision=fp16"),
        parseVariantSpec("r11g11b10f:gi.target_format=r11g11b10f"),
        parseVariantSpec("bc6h:probes.format=bc6h"),
        parseVariantSpec("quarter:gi.resolution=quarter"),
        parseVariantSpec("handheld:gi.resolution=half,gi.target_format=r11g11b10f,"
                         "gi.precision=fp16,gi.loops=split,gi.probe_order=slice_first,"
                         "gi.multi_volume=stencil,probes.format=bc6h"),
    };
}

} // namespace pb::stress
