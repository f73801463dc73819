#pragma once
// The one way whitted runs work on several threads: items [0, n) handed out one at a time, in
// increasing order, to `workers` threads (the calling thread is one of them). Used by the
// renderer (an item is a tile) and the BVH builder (an item is a chunk or a subtree). Results
// never depend on which thread ran an item, so callers stay deterministic for any thread count.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace whitted {

// The threads to use when `asked` were asked for (0 = every hardware thread), never more than
// there are items (at least one).
inline int worker_count(int asked, std::size_t items) {
    const int all = int(std::max(1u, std::thread::hardware_concurrency()));
    const int n = asked > 0 ? asked : all;
    return int(std::max<std::size_t>(1, std::min<std::size_t>(std::size_t(n), std::max<std::size_t>(items, 1))));
}

// Calls body(item, worker) for every item in [0, n), worker in [0, workers) naming the thread
// (for per-thread scratch state the caller sized with the same `workers`). Returns when all are done.
template <class Body>
void parallel_for(std::size_t n, int workers, Body&& body) {
    if (workers <= 1 || n <= 1) {
        for (std::size_t i = 0; i < n; ++i) body(i, 0);
        return;
    }
    alignas(64) std::atomic<std::size_t> next{0};
    auto run = [&](int worker) {
        for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < n;) body(i, worker);
    };
    std::vector<std::thread> pool;
    pool.reserve(std::size_t(workers - 1));
    for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
    run(0);
    for (auto& t : pool) t.join();
}

}  // namespace whitted
