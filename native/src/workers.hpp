// Footfall — a small pool of threads that runs one batch of independent jobs
// at a time (the searches of one scheduling tick).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
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

 private:
  void work();
  /// Takes jobs of batch `batch` until none is left.
  void drain(std::uint32_t batch);

  std::vector<std::thread> threads_;
  /// The batch (high 32 bits) and its next job to take (low 32): a thread
  /// takes job k of the batch it saw by raising k, so that one which sees a
  /// batch late never takes a job of the next.
  std::atomic<std::uint64_t> ticket_{0};
  std::atomic<const std::function<void(std::size_t)>*> job_{nullptr};
  std::atomic<std::size_t> count_{0};
  std::atomic<std::size_t> unfinished_{0};  ///< Jobs of the batch not yet done.
  std::atomic<bool> stopping_{false};
  // Sleeping, for a thread that found nothing to do for a while: spinning
  // through the few hundred microseconds between ticks keeps the threads from
  // paying a wake-up each tick.
  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  std::exception_ptr error_;  ///< Under mutex_.
};

}  // namespace footfall
