#pragma once
// A minimal work-sharing loop on std::threads: items are claimed in chunks from an atomic
// counter. Results must not depend on which thread runs an item (the bake writes each
// probe's own slot), so output is identical for any thread count.
#include <cstddef>
#include <functional>

namespace pb {

// Threads to use for `requested` (0 = all hardware threads).
int resolveThreadCount(int requested);

// Runs body(item, threadIndex) for item in [0, count) on `threads` threads, the calling thread
// being thread 0. Between its chunks the calling thread invokes `tick(done)` about every
// 100 ms (progress), and once more with the final count. Rethrows the first exception a body
// threw, after all threads stopped.
void parallelFor(std::size_t count, int threads,
                 const std::function<void(std::size_t item, int thread)>& body,
                 const std::function<void(std::size_t done)>& tick = {});

} // namespace pb
