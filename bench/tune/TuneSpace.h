#pragma once
// The switch space `probebench tune` searches, derived from the switch table (one switch = one
// place: a new row is searched with no edit here). Every Choice row contributes its values;
// gi.volume_lod contributes levels computed from the probe set (TuneContext::volumeLodValues);
// Number and other Text rows keep the base profile's value (there is no finite list to try).
// Values are listed base value first. GL-free.
//
// Candidates are canonical: a switch whose value cannot change the frame's work is set to the
// base value, so equivalent configurations are measured once:
//   gi.upsample at gi.resolution=full (no upsample pass exists),
//   gi.dynamic when the scene has no dynamic objects (the frame skips the SH pass).
#include "profile/Profile.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pb::bench {

struct TuneContext {
    int dynamicObjects = 0;
    // gi.volume_lod values to try (the base's value is added first when missing).
    std::vector<std::string> volumeLodValues{"all"};
};

struct SwitchAxis {
    std::string key;
    std::vector<std::string> values; // values[0] = the base profile's
};

struct TuneSpace {
    profile::Profile base;
    TuneContext context;
    std::vector<SwitchAxis> axes;     // switches with more than one value, table order
    std::vector<std::string> fixed;   // "key: why" for each switch held at the base value
    std::size_t combinations() const; // product of the axes' sizes (before canonical de-dup)
};

// `only` (tune --search): the keys to search; empty = every switch but the guards
// (gi.guard_*: held at the base unless named). Throws pb::Error for an unknown key in `only`.
TuneSpace makeTuneSpace(const profile::Profile& base, const TuneContext& context,
                        const std::vector<std::string>& only = {});

// gi.guard_*: the switches that keep extreme inputs finite (renderer/stress).
bool isGuard(const std::string& key);

profile::Profile canonical(const profile::Profile& p, const TuneSpace& space);
// A stable identity of a canonical profile (its values as JSON text).
std::string candidateKey(const profile::Profile& p);
// "base" or the switches that differ from the base, "gi.resolution=half gi.loops=split".
std::string candidateLabel(const profile::Profile& p, const profile::Profile& base);

// Every distinct canonical combination, the base first.
std::vector<profile::Profile> enumerateSpace(const TuneSpace& space);

} // namespace pb::bench
