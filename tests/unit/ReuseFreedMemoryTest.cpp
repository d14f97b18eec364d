// core/ReuseFreedMemory.h: after pb::reuseFreedMemory() (every test binary calls it before main,
// tests/support/ReuseFreedMemory.cpp), a block of tens of MiB - a bake's texture - comes from the
// heap, not from a mapping of its own, and a freed one is handed out again.
#include "core/ReuseFreedMemory.h"

#include <cstdlib>
#include <cstring>
#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

TEST(ReuseFreedMemory, LargeBlocksComeFromTheHeapAndAreReused) {
#if !defined(__GLIBC__)
    GTEST_SKIP() << "mallopt is glibc's";
#elif defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer's allocator ignores mallopt";
#else
    pb::reuseFreedMemory();
    constexpr std::size_t kBlock = std::size_t(64) << 20; // over glibc's largest mmap threshold
    const std::size_t mapped = mallinfo2().hblks;         // blocks served by mmap, now
    auto* a = static_cast<unsigned char*>(std::malloc(kBlock));
    ASSERT_NE(a, nullptr);
    std::memset(a, 1, kBlock);
    EXPECT_EQ(mallinfo2().hblks, mapped) << "a 64 MiB block got a mapping of its own";
    const std::size_t heapFree = mallinfo2().fordblks;
    std::free(a);
    EXPECT_GE(mallinfo2().fordblks, heapFree + kBlock) << "the freed block left the heap";
    auto* b = static_cast<unsigned char*>(std::malloc(kBlock));
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(mallinfo2().hblks, mapped);
    std::free(b);
#endif
}

} // namespace
