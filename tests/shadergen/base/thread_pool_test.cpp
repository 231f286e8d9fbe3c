// parallel_for's failure contract: a job's exception reaches the caller, after every worker has
// stopped, and no job starts once the failure has been seen.
#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "base/thread_pool.h"

namespace {

using shadergen::parallel_for;

// On one thread the order is fixed: jobs 0..3 run, job 3 throws, 4..9 never start.
TEST(ParallelFor, SerialFailureStopsBeforeTheNextJob) {
  std::vector<int> started(10, 0);
  try {
    parallel_for(10, 1, [&](std::size_t i) {
      ++started[i];
      if (i == 3) throw std::runtime_error("job 3 failed");
    });
    FAIL() << "the exception did not reach the caller";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 3 failed");
  }
  EXPECT_EQ(started, (std::vector<int>{1, 1, 1, 1, 0, 0, 0, 0, 0, 0}));
}

// The exception's type survives the trip between threads: out of memory stays std::bad_alloc.
TEST(ParallelFor, BadAllocInAWorkerReachesTheCaller) {
  EXPECT_THROW(parallel_for(64, 4,
                            [](std::size_t i) {
                              if (i == 17) throw std::bad_alloc();
                            }),
               std::bad_alloc);
}

// Two jobs throw at once on two threads: the caller gets one of them (it used to be
// std::terminate), and only after both workers are out of their jobs.
TEST(ParallelFor, ConcurrentFailuresGiveOneExceptionAfterEveryJobHasLeft) {
  std::atomic<int> arrived{0};
  std::atomic<int> inside{0};
  std::string caught;
  try {
    parallel_for(2, 2, [&](std::size_t i) {
      ++inside;
      ++arrived;
      while (arrived.load() < 2) std::this_thread::yield();  // both jobs are running
      --inside;
      throw std::runtime_error("job " + std::to_string(i));
    });
  } catch (const std::runtime_error& e) {
    caught = e.what();
    EXPECT_EQ(inside.load(), 0) << "parallel_for returned while a job was still running";
  }
  EXPECT_TRUE(caught == "job 0" || caught == "job 1") << caught;
}

TEST(ParallelFor, WithoutFailuresEveryJobRunsOnce) {
  std::vector<std::atomic<int>> runs(1000);
  parallel_for(runs.size(), 4, [&](std::size_t i) { ++runs[i]; });
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << i;
}

}  // namespace
