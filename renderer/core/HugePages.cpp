#include "core/HugePages.h"

#include <mutex>

namespace pb {

namespace {

// The kept blocks, oldest first, and their bytes in all; and the blocks handed out for a
// smaller request, with their real size (few: the search's reference grid's).
struct HugeBlockCache {
    std::mutex lock;
    std::vector<std::pair<void*, std::size_t>> blocks;
    std::size_t bytes = 0;
    std::vector<std::pair<void*, std::size_t>> lentLarger;
};

HugeBlockCache& cache() {
    // Never destroyed: blocks may be freed after main() returns. Room for as many blocks as
    // the cap holds (and one over it), so keeping one never allocates.
    static HugeBlockCache* c = [] {
        auto* made = new HugeBlockCache;
        made->blocks.reserve(kHugeBlockCacheBytes / (std::size_t(2) << 20) + 1);
        return made;
    }();
    return *c;
}

} // namespace

void* takeHugeBlock(std::size_t bytes) {
    HugeBlockCache& c = cache();
    const std::lock_guard<std::mutex> guard(c.lock);
    std::size_t best = c.blocks.size();
    for (std::size_t i = c.blocks.size(); i-- > 0;) { // the most recently kept first
        const std::size_t size = c.blocks[i].second;
        if (size >= bytes && size / kHugeBlockReuseFactor <= bytes &&
            (best == c.blocks.size() || size < c.blocks[best].second))
            best = i;
    }
    if (best == c.blocks.size()) return nullptr;
    const auto [p, size] = c.blocks[best];
    c.blocks.erase(c.blocks.begin() + std::ptrdiff_t(best));
    c.bytes -= size;
    if (size != bytes) c.lentLarger.emplace_back(p, size);
    return p;
}

std::size_t keptHugeBlockBytes() {
    HugeBlockCache& c = cache();
    const std::lock_guard<std::mutex> guard(c.lock);
    return c.bytes;
}

void releaseKeptHugeBlocks() {
    HugeBlockCache& c = cache();
    const std::lock_guard<std::mutex> guard(c.lock);
    for (const auto& [p, bytes] : c.blocks)
        std::free(p);
    c.blocks.clear();
    c.bytes = 0;
}

void keepHugeBlock(void* p, std::size_t bytes) {
    HugeBlockCache& c = cache();
    const std::lock_guard<std::mutex> guard(c.lock);
    for (std::size_t i = 0; i < c.lentLarger.size(); ++i)
        if (c.lentLarger[i].first == p) { // its real size
            bytes = c.lentLarger[i].second;
            c.lentLarger.erase(c.lentLarger.begin() + std::ptrdiff_t(i));
            break;
        }
    if (bytes > kHugeBlockCacheBytes) {
        std::free(p);
        return;
    }
    c.blocks.emplace_back(p, bytes);
    c.bytes += bytes;
    std::size_t drop = 0;
    while (c.bytes > kHugeBlockCacheBytes) { // the oldest go first
        c.bytes -= c.blocks[drop].second;
        std::free(c.blocks[drop++].first);
    }
    c.blocks.erase(c.blocks.begin(), c.blocks.begin() + std::ptrdiff_t(drop));
}

} // namespace pb
