#pragma once
// A set-associative cache with least-recently-used replacement, the model of a GPU's L1 /
// texture cache the cost model replays texel addresses through. Read-only (textures): no
// write policy. Lines are `lineBytes` aligned; set = (address / lineBytes) mod sets.
#include <cstdint>
#include <string>
#include <vector>

namespace pb::costmodel {

struct CacheConfig {
    std::string name; // preset name or "custom"
    std::uint64_t sizeBytes = 16 * 1024;
    int lineBytes = 64;
    int ways = 4;
    std::string source; // where the figures come from (or "assumption")

    int sets() const { return int(sizeBytes / std::uint64_t(lineBytes) / std::uint64_t(ways)); }
    // Throws pb::Error naming the problem: the line size must be a power of two and the size a
    // whole number of sets (a multiple of lineBytes * ways).
    void validate() const;
    std::string describe() const; // "16 KiB, 64 B lines, 4-way"
};

class LruCache {
public:
    explicit LruCache(const CacheConfig& config);
    // Touches the line holding `address`; true on a hit. A miss fills the line, evicting the
    // set's least recently used one.
    bool access(std::uint64_t address);
    int lineBytes() const { return lineBytes_; }
    void clear();

private:
    int lineShift_ = 6, ways_ = 4;
    std::uint64_t sets_ = 1;
    std::uint64_t setMask_ = 0; // sets_ - 1 when sets_ is a power of two, else 0 (remainder)
    int lineBytes_ = 64;
    // Per set, `ways_` line numbers, most recently used first; ~0 = empty.
    std::vector<std::uint64_t> lines_;
};

} // namespace pb::costmodel
