#pragma once
// A minimal work-sharing loop on std::threads: items are claimed in chunks from an atomic
// counter. Results must not depend on which thread runs an item (the bake writes each
// probe's own slot), so output is identical for any thread count.
#include <cstddef>
#include <functional>

namespace pb {

// The size bodies align what each thread writes often (per-thread counters) to: two
// threads writing one cache line take turns owning it, a transfer per write. The bake's
// shadow-ray counters, 16 bytes per thread in one vector, cost it several percent so.
// (64: x86-64's line; std::hardware_destructive_interference_size warns in headers.)
constexpr std::size_t kCacheLine = 64;

// One thread's slot of a per-thread array (std::vector<PerThread<T>>(threads)).
template <class T> struct alignas(kCacheLine) PerThread { T value{}; };

// Threads to use for `requested` (0 = all hardware threads).
int resolveThreadCount(int requested);

// Runs body(item, threadIndex) for item in [0, count) on `threads` threads (<= 0: all hardware
// threads, resolveThreadCount; never more than `count`), the calling thread being thread 0.
// Between its chunks the calling thread invokes `tick(done)` about every 100 ms (progress), and
// once more with the final count. Rethrows the first exception a body
// threw, after all threads stopped.
void parallelFor(std::size_t count, int threads,
                 const std::function<void(std::size_t item, int thread)>& body,
                 const std::function<void(std::size_t done)>& tick = {});

} // namespace pb
