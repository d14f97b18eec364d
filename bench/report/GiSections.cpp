#include "GiSections.h"

namespace pb::bench {

bool isGiSection(const std::string& name) {
    if (name == "gi-fetch-floor") return false;
    return name.rfind("gi-", 0) == 0 || name == "upsample";
}

} // namespace pb::bench
