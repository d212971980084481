// Footfall — the thread pool of workers.hpp.
#include "workers.hpp"

#include <chrono>
#include <stdexcept>

namespace footfall {
namespace {

/// How long a thread spins for the next batch, or for the end of one, before
/// it sleeps: longer than the driver's work between two ticks' batches.
constexpr std::chrono::microseconds kSpin{500};

/// Spins until `done()`, for at most kSpin; returns done().
template <class Done>
bool spin_until(const Done& done) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int i = 1;; ++i) {
    if (done()) return true;
    if (i % 64 == 0 && std::chrono::steady_clock::now() > until) return done();
    std::this_thread::yield();
  }
}

std::uint32_t batch_of(std::uint64_t ticket) { return static_cast<std::uint32_t>(ticket >> 32); }

}  // namespace

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
  if (n == 0) return;
  if (n >= 0xFFFFFFFFu) throw std::length_error("Workers::run: too many jobs in one batch");
  // The last batch is done, every job of it taken. Closed first, so that a
  // thread that sees the new count before the new batch cannot take a job.
  const std::uint32_t last = batch_of(ticket_.load(std::memory_order_relaxed));
  ticket_.store(static_cast<std::uint64_t>(last) << 32 | 0xFFFFFFFFu, std::memory_order_seq_cst);
  job_.store(&job, std::memory_order_relaxed);
  unfinished_.store(n, std::memory_order_relaxed);
  count_.store(n, std::memory_order_release);
  const std::uint32_t batch = last + 1;
  {
    // Under the lock, so that a thread about to sleep sees the new batch.
    std::lock_guard<std::mutex> lock(mutex_);
    error_ = nullptr;
    ticket_.store(static_cast<std::uint64_t>(batch) << 32, std::memory_order_release);
  }
  wake_.notify_all();
  drain(batch);
  const auto finished = [this] { return unfinished_.load(std::memory_order_acquire) == 0; };
  if (!spin_until(finished)) {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, finished);
  }
  std::exception_ptr error;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    error = error_;
  }
  if (error) std::rethrow_exception(error);
}

void Workers::drain(std::uint32_t batch) {
  std::uint64_t ticket = ticket_.load(std::memory_order_acquire);
  for (;;) {
    const std::uint64_t k = ticket & 0xFFFFFFFFu;
    if (batch_of(ticket) != batch || k >= count_.load(std::memory_order_acquire)) return;
    if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel)) continue;
    try {
      (*job_.load(std::memory_order_relaxed))(static_cast<std::size_t>(k));
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
    if (unfinished_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      { std::lock_guard<std::mutex> lock(mutex_); }  // the caller waits on it or sees 0
      finished_.notify_all();
    }
    ticket = ticket_.load(std::memory_order_acquire);
  }
}

void Workers::work() {
  std::uint32_t seen = 0;
  const auto news = [&] {
    return stopping_.load(std::memory_order_acquire) ||
           batch_of(ticket_.load(std::memory_order_acquire)) != seen;
  };
  for (;;) {
    if (!spin_until(news)) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, news);
    }
    if (stopping_.load(std::memory_order_acquire)) return;
    seen = batch_of(ticket_.load(std::memory_order_acquire));
    drain(seen);
  }
}

}  // namespace footfall
