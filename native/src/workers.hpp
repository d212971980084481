// Footfall — a small pool of threads that runs one batch of independent jobs
// at a time (the searches of one scheduling tick).
#pragma once

#include <condition_variable>
#include <cstddef>
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
  /// Takes jobs of the current batch until none is left.
  void drain();

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  const std::function<void(std::size_t)>* job_ = nullptr;
  std::size_t next_ = 0, count_ = 0, running_ = 0;
  unsigned long batch_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace footfall
