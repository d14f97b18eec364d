#include "core/HugePages.h"

#include <mutex>

namespace pb {

namespace {

// The kept blocks, oldest first, and their bytes in all.
struct HugeBlockCache {
    std::mutex lock;
    std::vector<std::pair<void*, std::size_t>> blocks;
    std::size_t bytes = 0;
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
    for (std::size_t i = c.blocks.size(); i-- > 0;) // the most recently kept first
        if (c.blocks[i].second == bytes) {
            void* p = c.blocks[i].first;
            c.blocks.erase(c.blocks.begin() + std::ptrdiff_t(i));
            c.bytes -= bytes;
            return p;
        }
    return nullptr;
}

std::size_t keptHugeBlockBytes() {
    HugeBlockCache& c = cache();
    const std::lock_guard<std::mutex> guard(c.lock);
    return c.bytes;
}

void keepHugeBlock(void* p, std::size_t bytes) {
    if (bytes > kHugeBlockCacheBytes) {
        std::free(p);
        return;
    }
    HugeBlockCache& c = cache();
    const std::lock_guard<std::mutex> guard(c.lock);
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
