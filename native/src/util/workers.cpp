// Footfall — the thread pool of workers.hpp.
#include "util/workers.hpp"

#include <chrono>
#include <stdexcept>

namespace footfall {
namespace {

/// How long a thread spins for the next job, or for the end of a batch,
/// before it sleeps: longer than the driver's work between two ticks' batches.
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

}  // namespace

Workers::Workers(int count) {
  for (int i = 1; i < count; ++i) threads_.emplace_back([this] { work(); });
}

Workers::~Workers() {
  {
    // Jobs not yet taken are dropped (a caller that threw is not waiting
    // for them); those running finish first.
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queue_.clear();
    queued_ = 0;
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void Workers::run(std::size_t n, const std::function<void(std::size_t)>& job) {
  if (n == 0) return;
  finish(launch(n, job));
}

std::uint64_t Workers::launch(std::size_t n, std::function<void(std::size_t)> job) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto batch = std::make_unique<Batch>();
  batch->number = ++launched_;
  batch->job = std::move(job);
  batch->unfinished = n;
  for (std::size_t k = 0; k < n; ++k) queue_.push_back({batch.get(), k});
  queued_.fetch_add(n, std::memory_order_release);
  batches_.push_back(std::move(batch));
  wake_.notify_all();
  return launched_;
}

void Workers::finish(std::uint64_t number) {
  Batch* batch = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (batches_.empty() || batches_.front()->number != number)
      throw std::logic_error("Workers::finish: batches must be finished in launch order");
    batch = batches_.front().get();
  }
  const auto done = [batch] { return batch->unfinished.load(std::memory_order_acquire) == 0; };
  // Its own jobs first (they are queued ahead of later batches'), then the
  // next batches' while the pool's threads finish the last of its own.
  while (!done()) {
    if (run_one()) continue;
    if (!spin_until([&] { return done() || queued_.load(std::memory_order_acquire) > 0; })) {
      std::unique_lock<std::mutex> lock(mutex_);
      finished_.wait(lock, [&] { return done() || !queue_.empty(); });
    }
  }
  std::exception_ptr error;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    error = batch->error;
    batches_.pop_front();
  }
  if (error) std::rethrow_exception(error);
}

bool Workers::run_one() {
  Item item{};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (queue_.empty()) return false;
    item = queue_.front();
    queue_.pop_front();
    queued_.fetch_sub(1, std::memory_order_relaxed);
  }
  try {
    item.batch->job(item.k);
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!item.batch->error) item.batch->error = std::current_exception();
  }
  if (item.batch->unfinished.fetch_sub(1, std::memory_order_acq_rel) == 1) {
    { std::lock_guard<std::mutex> lock(mutex_); }  // a caller waits on it or sees 0
    finished_.notify_all();
  }
  return true;
}

void Workers::work() {
  const auto news = [this] {
    return stopping_.load(std::memory_order_acquire) || queued_.load(std::memory_order_acquire) > 0;
  };
  for (;;) {
    if (!spin_until(news)) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_.load() || !queue_.empty(); });
    }
    if (stopping_.load(std::memory_order_acquire)) return;
    run_one();
  }
}

}  // namespace footfall
