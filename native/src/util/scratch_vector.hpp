// Footfall — vectors that keep their capacity from one query to the next on
// the same thread. A query on the 10k-box scene walks behind thousands of
// corners (each walk a stack: an allocation apiece) and its search grows
// megabytes of nodes (fresh pages from the system on every query, copied at
// every doubling).
#pragma once

#include <utility>
#include <vector>

namespace footfall {

/// An empty vector with the capacity that the last one of its type on this
/// thread left behind; it leaves its own behind when it goes. Nested ones
/// still work: the inner one starts with none. Each thread keeps one such
/// buffer per type, as large as the largest search or walk it has run.
template <class T>
class ScratchVector {
 public:
  ScratchVector() : items_(std::move(kept())) { items_.clear(); }
  ~ScratchVector() { kept() = std::move(items_); }
  ScratchVector(const ScratchVector&) = delete;
  ScratchVector& operator=(const ScratchVector&) = delete;

  std::vector<T>& operator*() { return items_; }

 private:
  static std::vector<T>& kept() {
    thread_local std::vector<T> spare;
    return spare;
  }
  std::vector<T> items_;
};

}  // namespace footfall
