#include "thread_pool.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace shadergen {

unsigned resolve_thread_count(unsigned requested) {
    if (requested) return requested;
    return std::max(1u, std::thread::hardware_concurrency());
}

void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job,
                  const std::function<bool()>& cancelled) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (;;) {
            if (cancelled && cancelled()) return;
            std::size_t index = next.fetch_add(1);
            if (index >= count) return;
            job(index);
        }
    };
    std::size_t workers = std::min<std::size_t>(resolve_thread_count(threads), count);
    if (workers <= 1) {
        worker();
        return;
    }
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t i = 1; i < workers; ++i) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
}

}  // namespace shadergen
