// Footfall — the thread pool of workers.hpp.
#include "workers.hpp"

namespace footfall {

Workers::Workers(int count) {
  for (int i = 1; i < count; ++i) threads_.emplace_back([this] { work(); });
}

Workers::~Workers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void Workers::run(std::size_t n, const std::function<void(std::size_t)>& job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    next_ = 0;
    count_ = n;
    running_ = 0;
    error_ = nullptr;
    ++batch_;
  }
  wake_.notify_all();
  drain();
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [this] { return next_ >= count_ && running_ == 0; });
  job_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

void Workers::drain() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (job_ != nullptr && next_ < count_) {
    const std::size_t k = next_++;
    ++running_;
    const auto* job = job_;
    lock.unlock();
    std::exception_ptr error;
    try {
      (*job)(k);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error && !error_) error_ = error;
    --running_;
  }
  if (next_ >= count_ && running_ == 0) finished_.notify_all();
}

void Workers::work() {
  unsigned long seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || (batch_ != seen && job_ != nullptr); });
    if (stopping_) return;
    seen = batch_;
    lock.unlock();
    drain();
    lock.lock();
  }
}

}  // namespace footfall
