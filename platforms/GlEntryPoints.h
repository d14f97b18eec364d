#pragma once
// glad keeps one process-wide table of GL function pointers, filled by whichever backend
// loaded last. A backend made current again after another one loaded (both alive in one
// process) must reload it: these helpers track who filled it.
namespace pb::platform {

class Platform;

namespace detail {
inline const Platform* glEntryPointsOwner = nullptr;
}

inline bool ownsGlEntryPoints(const Platform* p) {
    return detail::glEntryPointsOwner == p;
}
inline void claimGlEntryPoints(const Platform* p) {
    detail::glEntryPointsOwner = p;
}
inline void releaseGlEntryPoints(const Platform* p) {
    if (detail::glEntryPointsOwner == p) detail::glEntryPointsOwner = nullptr;
}

} // namespace pb::platform
