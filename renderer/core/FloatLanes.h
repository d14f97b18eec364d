#pragma once
// Four float lanes (the GCC/Clang vector extension) for loops that must give, lane by lane,
// the bits a scalar loop gives: each lane does the same IEEE operation in the same order (the
// build targets baseline x86-64, so there is no FMA to contract into). Unaligned loads and
// stores through memcpy, which compiles to one SSE move.
#include <cstring>

namespace pb {

typedef float Float4 __attribute__((vector_size(16)));
typedef int Int4 __attribute__((vector_size(16))); // a comparison's lane mask (0 or -1)

inline Float4 load4(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof(v));
    return v;
}

inline void store4(float* p, const Float4& v) { std::memcpy(p, &v, sizeof(v)); }

} // namespace pb
