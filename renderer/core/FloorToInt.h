#pragma once
// floor() to an int without libm: on baseline x86-64 (no SSE4.1 `roundss`) std::floor is a
// call, and hot per-hit and per-lookup code took two or more of them. The same integer as
// int(std::floor(v)) for every v whose floor fits in an int.

namespace pb {

inline int floorToInt(float v) {
    const int i = int(v);
    return float(i) > v ? i - 1 : i;
}

} // namespace pb
