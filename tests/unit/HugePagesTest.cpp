// core/HugePages.h: freed blocks of 2 MiB and more go to the next allocation they hold (the
// smallest such, up to kHugeBlockReuseFactor times its size), never to a larger one, come back
// whole, and the blocks kept stay under kHugeBlockCacheBytes.
#include "core/HugePages.h"

#include <cstdint>
#include <cstdlib>
#include <gtest/gtest.h>

namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20;

} // namespace

TEST(HugePages, AFreedLargeBlockServesTheNextAllocationOfItsSize) {
    pb::releaseKeptHugeBlocks(); // what earlier tests kept would serve these allocations
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

TEST(HugePages, ASmallerAllocationTakesTheSmallestKeptBlockThatHoldsIt) {
    pb::releaseKeptHugeBlocks(); // what earlier tests kept would serve these allocations
    // Blocks of 40, 12 and 100 MiB kept, never touched: only address space.
    void* b40 = std::aligned_alloc(2 * kMiB, 40 * kMiB);
    void* b12 = std::aligned_alloc(2 * kMiB, 12 * kMiB);
    void* b100 = std::aligned_alloc(2 * kMiB, 100 * kMiB);
    ASSERT_TRUE(b40 && b12 && b100);
    pb::keepHugeBlock(b40, 40 * kMiB);
    pb::keepHugeBlock(b12, 12 * kMiB);
    pb::keepHugeBlock(b100, 100 * kMiB);
    const std::size_t kept = pb::keptHugeBlockBytes();
    {
        pb::HugePageVector<float> a(9 * kMiB / sizeof(float)); // 10 MiB: the 12 MiB block
        EXPECT_EQ(a.data(), b12);
        pb::HugePageVector<float> b(30 * kMiB / sizeof(float)); // 30 MiB: the 40 MiB one
        EXPECT_EQ(b.data(), b40);
        EXPECT_EQ(pb::keptHugeBlockBytes(), kept - 52 * kMiB);
        // 4 MiB: the 100 MiB block is over kHugeBlockReuseFactor times that, so a fresh block.
        pb::HugePageVector<float> c(4 * kMiB / sizeof(float));
        EXPECT_NE(c.data(), b100);
    } // a and b come back as the blocks they were, 12 and 40 MiB (c as its own 4 MiB)
    EXPECT_EQ(pb::keptHugeBlockBytes(), kept + 4 * kMiB);
    EXPECT_EQ(pb::takeHugeBlock(12 * kMiB), b12);
    EXPECT_EQ(pb::takeHugeBlock(40 * kMiB), b40);
    EXPECT_EQ(pb::takeHugeBlock(100 * kMiB), b100);
    std::free(b12);
    std::free(b40);
    std::free(b100);
}

TEST(HugePages, TheOldestKeptBlocksAreFreedPastTheCap) {
    pb::releaseKeptHugeBlocks(); // what earlier tests kept would serve these allocations
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
