#include "DeviceOptions.h"

#include "core/Error.h"

#include <algorithm>

namespace pb::app {

std::vector<std::string> deviceSearchDirs() {
    return devicemodel::deviceDirs(std::string(PB_PROFILES_DIR) + "/devices");
}

std::vector<devicemodel::DeviceSpec>
resolvePredictDevices(const std::string& list, const std::vector<profile::PlatformProfile>& profiles) {
    try {
        if (list != "own") return devicemodel::findDevices(list, deviceSearchDirs());
        std::vector<std::string> names;
        for (const profile::PlatformProfile& p : profiles) {
            if (p.modelDevice.empty())
                throw Error("profile '" + p.name + "' names no device ([budget] model)");
            if (std::find(names.begin(), names.end(), p.modelDevice) == names.end())
                names.push_back(p.modelDevice);
        }
        std::string joined;
        for (const std::string& n : names)
            joined += (joined.empty() ? "" : ",") + n;
        return devicemodel::findDevices(joined, deviceSearchDirs());
    } catch (const Error& e) {
        throw Error(std::string("--predict ") + list + ": " + e.what());
    }
}

} // namespace pb::app
