// The crowd's thread pool (native/src/util/workers.hpp): every job of every batch
// runs exactly once, batches do not mix, a batch launched while another is
// still running runs too, and a job's exception reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include "util/workers.hpp"

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

TEST(Workers, BatchesLaunchedBehindOthersRunOnceAndFinishInOrder) {
  for (const int threads : {1, 2, 4}) {
    Workers workers(threads);
    // Two batches in flight at a time, as the crowd's pipelined ticks keep
    // them: each is finished after the next is launched.
    constexpr int kBatches = 200;
    std::vector<std::vector<std::atomic<int>>> runs;
    for (int b = 0; b < kBatches; ++b) runs.emplace_back(static_cast<std::size_t>(b % 13));
    std::uint64_t last = 0;
    for (int b = 0; b < kBatches; ++b) {
      auto& mine = runs[static_cast<std::size_t>(b)];
      const std::uint64_t batch =
          workers.launch(mine.size(), [&mine](std::size_t k) { mine[k].fetch_add(1); });
      if (b > 0) {
        workers.finish(last);
        for (const auto& count : runs[static_cast<std::size_t>(b - 1)])
          ASSERT_EQ(count.load(), 1) << threads << " threads, batch " << b - 1;
      }
      last = batch;
    }
    workers.finish(last);
    for (const auto& count : runs.back()) EXPECT_EQ(count.load(), 1);
    // Finishing out of order is misuse.
    const std::uint64_t first = workers.launch(1, [](std::size_t) {});
    const std::uint64_t second = workers.launch(1, [](std::size_t) {});
    EXPECT_THROW(workers.finish(second), std::logic_error);
    workers.finish(first);
    workers.finish(second);
  }
}

TEST(Workers, AnExceptionStaysWithItsBatch) {
  Workers workers(2);
  const std::uint64_t failing = workers.launch(20, [](std::size_t k) {
    if (k == 3) throw std::runtime_error("job 3");
  });
  std::atomic<int> runs{0};
  const std::uint64_t fine = workers.launch(20, [&](std::size_t) { runs.fetch_add(1); });
  EXPECT_THROW(workers.finish(failing), std::runtime_error);
  EXPECT_NO_THROW(workers.finish(fine));
  EXPECT_EQ(runs.load(), 20);
}

}  // namespace
}  // namespace footfall
