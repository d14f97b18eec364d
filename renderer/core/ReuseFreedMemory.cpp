#include "core/ReuseFreedMemory.h"

#include <cstdlib> // defines __GLIBC__ on glibc (through <features.h>)

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pb {

void reuseFreedMemory() {
#if defined(__GLIBC__)
    // Blocks up to 1 GiB come from the heap (above it a mapping is still the better deal), and
    // free memory at the heap's top is returned only past 1 GiB. Setting either turns off
    // glibc's adaptive threshold.
    constexpr int kOneGiB = 1 << 30;
    mallopt(M_MMAP_THRESHOLD, kOneGiB);
    mallopt(M_TRIM_THRESHOLD, kOneGiB);
#endif
}

} // namespace pb
