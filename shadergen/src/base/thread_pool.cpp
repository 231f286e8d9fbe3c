#include "base/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace shadergen {

unsigned resolve_thread_count(unsigned requested) {
  if (requested) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

namespace {

// The first exception any job threw; once set, no worker takes another job.
class FirstFailure {
 public:
  bool seen() const { return seen_.load(std::memory_order_acquire); }
  void record(std::exception_ptr error) {
    std::lock_guard lock(mutex_);
    if (!error_) error_ = std::move(error);
    seen_.store(true, std::memory_order_release);
  }
  // Called after every worker has stopped.
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::atomic<bool> seen_{false};
  std::mutex mutex_;
  std::exception_ptr error_;
};

}  // namespace

void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job,
                  const std::function<bool()>& cancelled) {
  std::atomic<std::size_t> next{0};
  FirstFailure failure;
  auto worker = [&] {
    try {
      for (;;) {
        if (failure.seen() || (cancelled && cancelled())) return;
        std::size_t index = next.fetch_add(1);
        if (index >= count) return;
        job(index);
      }
    } catch (...) {
      failure.record(std::current_exception());  // a thread must not let it escape: std::terminate
    }
  };
  std::size_t workers = std::min<std::size_t>(resolve_thread_count(threads), count);
  std::vector<std::thread> pool;
  pool.reserve(workers > 1 ? workers - 1 : 0);
  for (std::size_t i = 1; i < workers; ++i) {
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones already running share the jobs
    }
  }
  worker();
  for (std::thread& t : pool) t.join();
  failure.rethrow();
}

}  // namespace shadergen
