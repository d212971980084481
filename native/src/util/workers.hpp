// Footfall — a small pool of threads that runs batches of independent jobs:
// one at a time (run()), or queued one behind the other (launch(), finish()),
// so that a batch's jobs start while the caller still waits for the last one.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace footfall {

class Workers {
 public:
  /// `count` threads in all, the caller's included (so 1 starts none).
  explicit Workers(int count);
  ~Workers();
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;

  /// Runs job(k) for every k in [0, n), on the pool and the calling thread,
  /// and returns when all have finished. The first exception a job throws is
  /// rethrown here.
  void run(std::size_t n, const std::function<void(std::size_t)>& job);

  /// Queues job(k) for every k in [0, n), in that order, behind every job
  /// queued before; the pool's threads take them at once. Returns the
  /// batch's number, for finish().
  std::uint64_t launch(std::size_t n, std::function<void(std::size_t)> job);
  /// Runs queued jobs on the calling thread, oldest first, until every job
  /// of batch `batch` has finished; then rethrows the first exception one of
  /// them threw. Every launched batch must be finished, in launch order.
  void finish(std::uint64_t batch);

 private:
  struct Batch {
    std::uint64_t number = 0;
    std::function<void(std::size_t)> job;
    std::atomic<std::size_t> unfinished{0};
    std::exception_ptr error;  ///< Under mutex_.
  };
  struct Item {
    Batch* batch;
    std::size_t k;
  };
  void work();
  /// Takes the oldest queued job and runs it; false if none was queued.
  bool run_one();

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::deque<Item> queue_;                      ///< Under mutex_.
  std::deque<std::unique_ptr<Batch>> batches_;  ///< Launched, not yet finished; under mutex_.
  std::uint64_t launched_ = 0;                  ///< Under mutex_.
  /// Jobs queued and not yet taken: read without the lock, by threads
  /// spinning for work. Sleeping, for a thread that found nothing to do for
  /// a while: spinning through the few hundred microseconds between ticks
  /// keeps the threads from paying a wake-up each tick.
  std::atomic<std::size_t> queued_{0};
  std::atomic<bool> stopping_{false};
  std::condition_variable wake_, finished_;
};

}  // namespace footfall
