#pragma once
// What `bench --predict`, `predict` and `devices` share: where the device files are
// (profiles/devices, $PROBEBENCH_DEVICES first) and how a --predict list is resolved, "own"
// included.
#include "bench/devicemodel/DeviceSpec.h"
#include "profile/PlatformProfile.h"

#include <string>
#include <vector>

namespace pb::app {

std::vector<std::string> deviceSearchDirs();

// "NAME[,NAME...]", "all", or "own" (each profile's [budget] model). Throws pb::Error naming the
// option and the problem (an unknown device, a profile that names none under "own").
std::vector<devicemodel::DeviceSpec>
resolvePredictDevices(const std::string& list, const std::vector<profile::PlatformProfile>& profiles);

} // namespace pb::app
