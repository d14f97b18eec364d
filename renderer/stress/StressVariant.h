#pragma once
// What the stress sweep renders a case with: the profile switches (every row of the switch
// table) plus the probe storage format, which is a bake setting rather than a switch and is
// written `probes.format=rgba16f|rgba32f|bc6h` next to the switch keys.
//
// Variants come from `--variant NAME:key=value,key=value` and from platform profiles
// (`stress --profiles a,b`, apps/cmd_stress.cpp): both end as a StressVariant (name + Profile +
// storage), the only thing the sweep reads. Guards are the switch rows whose key starts with
// `gi.guard_` (SwitchTable.cpp): the sweep turns them off to show what breaks and on one at a time
// to name what fixes it.
#include "probes/StorageFormat.h"
#include "profile/Profile.h"

#include <string>
#include <vector>

namespace pb::stress {

inline constexpr const char* kStorageKey = "probes.format";

struct StressVariant {
    std::string name;
    profile::Profile profile;
    probes::StorageFormat storage = probes::StorageFormat::Rgba16f; // bake's default

    // Switch keys in table order, then probes.format.
    std::vector<std::string> keys() const;
    std::string get(const std::string& key) const;
    // Throws pb::Error naming `option` for an unknown key or value.
    void set(const std::string& key, const std::string& value,
             const std::string& option = "--variant");
    // "key=value,..." of every key; identical settings give identical strings (a cache key).
    std::string settingsKey() const;
    // Keys whose value differs from `other`'s, in keys() order.
    std::vector<std::string> differingKeys(const StressVariant& other) const;
};

bool isGuardKey(const std::string& key);
// Every guard switch of the table, in table order.
std::vector<std::string> guardKeys();
// A copy with every guard set to "off" (a guard's values are off|on).
StressVariant withoutGuards(StressVariant v);

// "NAME:key=value,key=value" (NAME alone = the table defaults). Throws pb::Error naming
// `option` and the problem (empty name, missing '=', unknown key or value).
StressVariant parseVariantSpec(const std::string& spec, const std::string& option = "--variant");

// The accuracy baseline: fp32, rgba32f target, full resolution, rgba32f probes, every guard
// on (guards are exact in fp32; on, the frame's own RGBA16F radiance target stays finite at
// any light level, so the baseline is a finite image to compare with).
StressVariant referenceVariant();

// The default sweep: the table defaults and each lossy switch alone, plus a handheld-like
// combination (bench6's profiles/handheld.toml switches).
std::vector<StressVariant> defaultVariants();

} // namespace pb::stress
