#include "costmodel/TextureCache.h"

#include "core/Error.h"

#include <bit>

namespace pb::costmodel {

namespace {
constexpr std::uint64_t kEmpty = ~std::uint64_t(0);

bool powerOfTwo(std::uint64_t v) {
    return v != 0 && std::has_single_bit(v);
}
} // namespace

void CacheConfig::validate() const {
    const std::string what = "cache '" + name + "': ";
    if (lineBytes < 4 || !powerOfTwo(std::uint64_t(lineBytes)) || lineBytes > 4096)
        throw Error(what + "line size must be a power of two in 4..4096 bytes");
    if (ways < 1 || ways > 256) throw Error(what + "associativity must be in 1..256 ways");
    if (sizeBytes == 0 || sizeBytes > (std::uint64_t(1) << 30))
        throw Error(what + "size must be in 1 B..1 GiB");
    // Any whole number of sets: real caches come in 24 KiB (Maxwell's texture L1) or 50 MiB
    // (Hopper's L2); a power-of-two set count indexes by mask, any other by remainder.
    if (sizeBytes % (std::uint64_t(lineBytes) * std::uint64_t(ways)) != 0 || sets() < 1)
        throw Error(what + "size must hold a whole number of sets (size >= line x ways)");
}

std::string CacheConfig::describe() const {
    std::string size = sizeBytes % 1024 == 0 ? std::to_string(sizeBytes / 1024) + " KiB"
                                             : std::to_string(sizeBytes) + " B";
    return size + ", " + std::to_string(lineBytes) + " B lines, " + std::to_string(ways) + "-way";
}

LruCache::LruCache(const CacheConfig& config) {
    config.validate();
    lineBytes_ = config.lineBytes;
    lineShift_ = std::countr_zero(std::uint64_t(config.lineBytes));
    ways_ = config.ways;
    sets_ = std::uint64_t(config.sets());
    setMask_ = powerOfTwo(sets_) ? sets_ - 1 : 0;
    lines_.assign(std::size_t(config.sets()) * std::size_t(ways_), kEmpty);
}

void LruCache::clear() {
    std::fill(lines_.begin(), lines_.end(), kEmpty);
}

bool LruCache::access(std::uint64_t address) {
    const std::uint64_t line = address >> lineShift_;
    const std::uint64_t index = setMask_ ? (line & setMask_) : (sets_ > 1 ? line % sets_ : 0);
    std::uint64_t* set = lines_.data() + std::size_t(index) * std::size_t(ways_);
    // Move-to-front: the set's array is its recency order, so the last slot is the victim.
    int at = ways_ - 1;
    bool hit = false;
    for (int w = 0; w < ways_; ++w)
        if (set[w] == line) {
            at = w;
            hit = true;
            break;
        }
    for (int w = at; w > 0; --w)
        set[w] = set[w - 1];
    set[0] = line;
    return hit;
}

} // namespace pb::costmodel
