// thread_pool.h - runs independent jobs on N threads. Results are stored by job index by the
// callers, so the output never depends on which thread finished first.
#pragma once

#include <cstddef>
#include <functional>

namespace shadergen {

// Calls job(i) for every i in [0, count) on up to `threads` threads (0 = hardware threads) and
// returns when all have finished. `job` must be safe to call concurrently for distinct i.
// `cancelled` is polled between jobs: once it returns true no new job starts.
// If a job throws, no job starts after a worker has seen the failure, every worker finishes the
// job it is in, and then the first exception thrown (std::bad_alloc included) is rethrown here,
// in the calling thread, instead of ending the process with std::terminate.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job,
                  const std::function<bool()>& cancelled = {});

unsigned resolve_thread_count(unsigned requested);

}  // namespace shadergen
