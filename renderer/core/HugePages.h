#pragma once
// An allocator for the bake's large, randomly read arrays (the sampler's probe tiles: ~22 MiB
// for a 32x8x32 volume). With 4 KiB pages every lookup of a scattered hit also misses the
// TLB (a page walk per probe tile); blocks of 2 MiB and more are aligned to 2 MiB and marked
// MADV_HUGEPAGE, so where transparent huge pages are enabled ("madvise" or "always") the
// kernel backs them with 2 MiB pages. Only where the bytes live changes, never their values.
#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pb {

template <class T> struct HugePageAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage = std::size_t(2) << 20;

    HugePageAllocator() = default;
    template <class U> HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) {
            void* p = std::malloc(bytes ? bytes : 1);
            if (!p) throw std::bad_alloc();
            return static_cast<T*>(p);
        }
        const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        void* p = std::aligned_alloc(kHugePage, rounded);
        if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
        madvise(p, rounded, MADV_HUGEPAGE); // a hint: without THP it fails and nothing changes
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t) noexcept {
        std::free(p);
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
