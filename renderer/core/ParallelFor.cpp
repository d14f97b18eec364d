#include "core/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace pb {

int resolveThreadCount(int requested) {
    if (requested > 0) return requested;
    return std::max(1, int(std::thread::hardware_concurrency()));
}

void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t, int)>& body,
                 const std::function<void(std::size_t)>& tick) {
    // <= 0 means all cores, as everywhere a thread count is taken (resolveThreadCount).
    threads = std::min<int>(resolveThreadCount(threads), int(std::max<std::size_t>(count, 1)));
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> failed{false};
    // Guided chunks: up to 16 items per claim while much is left, fewer towards the end, so
    // no thread idles long waiting for another's last chunk (the bake runs ~40 of these
    // loops, each ending on such a barrier).
    const std::size_t maxChunk =
        std::max<std::size_t>(1, std::min<std::size_t>(16, count / (std::size_t(threads) * 8) + 1));
    auto claim = [&](std::size_t& begin, std::size_t& end) {
        std::size_t cur = next.load(std::memory_order_relaxed);
        for (;;) {
            if (cur >= count) return false;
            const std::size_t left = count - cur;
            const std::size_t n =
                std::max<std::size_t>(1, std::min(maxChunk, left / (std::size_t(threads) * 4)));
            if (next.compare_exchange_weak(cur, cur + n, std::memory_order_relaxed)) {
                begin = cur;
                end = cur + n;
                return true;
            }
        }
    };
    std::exception_ptr error;
    std::mutex m;

    // The calling thread is worker 0 and reports progress between its chunks, at most every
    // 100 ms. (A third thread that only waited and ticked cost ~1 ms of idle core per loop on a
    // 2-core machine: the wake-up of the waiter and the hand-over at the end of every loop.)
    using Clock = std::chrono::steady_clock;
    Clock::time_point lastTick = Clock::now();
    auto worker = [&](int t) {
        try {
            std::size_t begin = 0, end = 0;
            while (!failed.load(std::memory_order_relaxed) && claim(begin, end)) {
                for (std::size_t i = begin; i < end; ++i)
                    body(i, t);
                done.fetch_add(end - begin, std::memory_order_relaxed);
                if (t == 0 && tick && Clock::now() - lastTick >= std::chrono::milliseconds(100)) {
                    tick(done.load(std::memory_order_relaxed));
                    lastTick = Clock::now();
                }
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(m);
            if (!error) error = std::current_exception();
            failed = true;
        }
    };

    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back(worker, t);
    worker(0);
    for (auto& th : pool)
        th.join();
    if (error) std::rethrow_exception(error);
    if (tick) tick(done.load()); // the final count, however fast the work was
}

} // namespace pb
