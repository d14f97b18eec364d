#pragma once
// 64-bit FNV-1a: the probe file's checksum and the bake cache's input hash. Not
// cryptographic; it catches truncation, bit flips and changed inputs, which is all we need.
// And splitmix64, the seed mixer of the bake's and the truth's random streams.
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

namespace pb {

class Hasher {
public:
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            h_ ^= p[i];
            h_ *= 0x100000001b3ull;
        }
    }
    template <class T> void pod(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof(T));
    }
    void str(const std::string& s) {
        pod(std::uint64_t(s.size()));
        bytes(s.data(), s.size());
    }
    std::uint64_t value() const { return h_; }

private:
    std::uint64_t h_ = 0xcbf29ce484222325ull;
};

// splitmix64 (Steele, Lea and Flood 2014): advances `state` by the golden-ratio increment and
// returns it mixed. The bake's ray rotations and the truth's sample keys draw from it.
inline std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

inline std::uint64_t fnv1a64(const void* data, std::size_t size) {
    Hasher h;
    h.bytes(data, size);
    return h.value();
}

} // namespace pb
