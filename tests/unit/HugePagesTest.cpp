// core/HugePages.h: freed blocks of 2 MiB and more go to the next allocation of the same
// rounded size, never to another size, and the blocks kept stay under kHugeBlockCacheBytes.
#include "core/HugePages.h"

#include <cstdint>
#include <cstdlib>
#include <gtest/gtest.h>

namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20;

} // namespace

TEST(HugePages, AFreedLargeBlockServesTheNextAllocationOfItsSize) {
    const std::size_t floats = 5 * kMiB / sizeof(float); // 5 MiB: a 6 MiB block
    const float* first = nullptr;
    {
        pb::HugePageVector<float> a(floats);
        a[0] = 1.0f;
        first = a.data();
    }
    const std::size_t kept = pb::keptHugeBlockBytes();
    EXPECT_GE(kept, 6 * kMiB);
    {
        pb::HugePageVector<float> other(9 * kMiB / sizeof(float)); // 10 MiB: not that block
        EXPECT_NE(other.data(), first);
        pb::HugePageVector<float> same(floats - 1000); // still rounds to 6 MiB
        EXPECT_EQ(same.data(), first);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(same.data()) % (2 * kMiB), 0u);
    }
    // Small blocks are not kept.
    const std::size_t before = pb::keptHugeBlockBytes();
    { pb::HugePageVector<float> small(1000); }
    EXPECT_EQ(pb::keptHugeBlockBytes(), before);
}

TEST(HugePages, TheOldestKeptBlocksAreFreedPastTheCap) {
    const std::size_t half = pb::kHugeBlockCacheBytes / 2;
    void* blocks[3];
    for (void*& b : blocks) {
        b = std::aligned_alloc(2 * kMiB, half); // never touched: only address space
        ASSERT_NE(b, nullptr);
    }
    for (void* b : blocks)
        pb::keepHugeBlock(b, half);
    EXPECT_LE(pb::keptHugeBlockBytes(), pb::kHugeBlockCacheBytes);
    // The newest two are kept, newest first; the oldest was freed.
    EXPECT_EQ(pb::takeHugeBlock(half), blocks[2]);
    EXPECT_EQ(pb::takeHugeBlock(half), blocks[1]);
    EXPECT_EQ(pb::takeHugeBlock(half), nullptr);
    std::free(blocks[1]);
    std::free(blocks[2]);
    // A block over the cap is freed at once.
    void* huge = std::aligned_alloc(2 * kMiB, pb::kHugeBlockCacheBytes + 2 * kMiB);
    ASSERT_NE(huge, nullptr);
    const std::size_t before = pb::keptHugeBlockBytes();
    pb::keepHugeBlock(huge, pb::kHugeBlockCacheBytes + 2 * kMiB);
    EXPECT_EQ(pb::keptHugeBlockBytes(), before);
}
