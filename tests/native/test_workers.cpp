// The crowd's thread pool (native/src/workers.hpp): every job of every batch
// runs exactly once, batches do not mix, and a job's exception reaches the
// caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "workers.hpp"

namespace footfall {
namespace {

TEST(Workers, RunsEveryJobOfEveryBatchOnce) {
  for (const int threads : {1, 2, 4}) {
    Workers workers(threads);
    // Batches of every size from 0 up, back to back, and some after a pause
    // long enough for the pool's threads to go to sleep.
    for (std::size_t n = 0; n < 300; ++n) {
      std::vector<std::atomic<int>> runs(n);
      workers.run(n, [&](std::size_t k) { runs[k].fetch_add(1); });
      for (std::size_t k = 0; k < n; ++k)
        ASSERT_EQ(runs[k].load(), 1) << threads << " threads, batch of " << n << ", job " << k;
      if (n % 100 == 99) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
}

TEST(Workers, AJobsExceptionReachesTheCaller) {
  Workers workers(2);
  std::atomic<int> runs{0};
  EXPECT_THROW(workers.run(50,
                           [&](std::size_t k) {
                             runs.fetch_add(1);
                             if (k == 17) throw std::runtime_error("job 17");
                           }),
               std::runtime_error);
  EXPECT_EQ(runs.load(), 50);  // the others still ran
  // The pool goes on working after it.
  std::atomic<int> after{0};
  workers.run(10, [&](std::size_t) { after.fetch_add(1); });
  EXPECT_EQ(after.load(), 10);
}

}  // namespace
}  // namespace footfall
