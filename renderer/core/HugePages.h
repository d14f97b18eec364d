#pragma once
// An allocator for the bake's large, randomly read arrays (the sampler's probe tiles: ~22 MiB
// for a 32x8x32 volume). With 4 KiB pages every lookup of a scattered hit also misses the
// TLB (a page walk per probe tile); blocks of 2 MiB and more are aligned to 2 MiB and marked
// MADV_HUGEPAGE, so where transparent huge pages are enabled ("madvise" or "always") the
// kernel backs them with 2 MiB pages. Only where the bytes live changes, never their values.
//
// Freed blocks of 2 MiB and more are kept (up to kHugeBlockCacheBytes in all) for the next
// allocation they can hold: the lattice search's trial bakes allocate and free the same texture
// and tile sizes over and over, on worker threads whose malloc arenas hand blocks that large
// back to the kernel on free, so each trial page-faulted and the kernel zeroed its memory again
// (about 10% of the garden's default bake's CPU samples in `clear_page_erms`). An allocation
// takes the smallest kept block that holds it, up to kHugeBlockReuseFactor times its size: the
// search's reference grid frees a few blocks of 50 - 120 MiB that the trials and the bake after
// it can use instead of faulting in fresh ones, while a small array does not pin a block many
// times its size.
// A kept block's bytes are whatever its last user left: as with any allocation here, users
// write before they read (see construct() below).
#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pb {

constexpr std::size_t kHugeBlockCacheBytes = std::size_t(512) << 20;
constexpr std::size_t kHugeBlockReuseFactor = 8;

// The smallest kept block of at least `bytes` (a multiple of 2 MiB) and at most
// kHugeBlockReuseFactor * bytes, the most recently kept of equal ones; nullptr if none.
// Thread-safe. A block handed out must come back through keepHugeBlock (with `bytes`).
void* takeHugeBlock(std::size_t bytes);
// Keeps `p` (from takeHugeBlock(bytes), which remembers a larger block's real size, or a
// 2 MiB-aligned aligned_alloc of `bytes`), freeing the oldest kept blocks past
// kHugeBlockCacheBytes. Thread-safe.
void keepHugeBlock(void* p, std::size_t bytes);
// The bytes kept now (for tests and diagnostics).
std::size_t keptHugeBlockBytes();
// Frees every kept block (tests start from an empty cache).
void releaseKeptHugeBlocks();

template <class T> struct HugePageAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage = std::size_t(2) << 20;
    static constexpr std::size_t rounded(std::size_t bytes) {
        return (bytes + kHugePage - 1) / kHugePage * kHugePage;
    }

    HugePageAllocator() = default;
    template <class U> HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) {
            void* p = std::malloc(bytes ? bytes : 1);
            if (!p) throw std::bad_alloc();
            return static_cast<T*>(p);
        }
        const std::size_t size = rounded(bytes);
        if (void* kept = takeHugeBlock(size)) return static_cast<T*>(kept);
        void* p = std::aligned_alloc(kHugePage, size);
        if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
        madvise(p, size, MADV_HUGEPAGE); // a hint: without THP it fails and nothing changes
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) {
            std::free(p);
            return;
        }
        keepHugeBlock(p, rounded(bytes));
    }
    // vector(n) and resize(n) default-initialise (no zero fill for floats): these arrays are
    // written in full right after, often by several threads, which then also take the page
    // faults in parallel.
    template <class U> void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args> void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <class U> bool operator==(const HugePageAllocator<U>&) const {
        return true;
    }
};

template <class T> using HugePageVector = std::vector<T, HugePageAllocator<T>>;

} // namespace pb
