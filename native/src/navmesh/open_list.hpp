// Footfall — the path search's open list: (bound, node) entries, the least
// first, ties by the node's number. The least entry is kept beside a binary
// heap: the node a search expands next is often a child it has just made
// (its weighted bound falls as it heads for the goal), and such a child then
// never enters the heap. Entries come out in exactly the order of
// a plain priority queue.
#pragma once

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

#include "util/scratch_vector.hpp"

namespace footfall {

class OpenList {
 public:
  using Entry = std::pair<double, int>;

  bool empty() const { return !has_least_ && heap_.empty(); }

  /// The least entry; the list must not be empty.
  const Entry& top() const { return has_least_ ? least_ : heap_.front(); }

  void push(Entry entry) {
    if (has_least_) {
      if (entry < least_) std::swap(entry, least_);
      push_heap(entry);
    } else if (heap_.empty() || entry < heap_.front()) {
      least_ = entry;
      has_least_ = true;
    } else {
      push_heap(entry);
    }
  }

  void pop() {
    if (has_least_)
      has_least_ = false;
    else
      pop_heap();
  }

 private:
  void push_heap(Entry entry) {
    heap_.push_back(entry);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  }
  void pop_heap() {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    heap_.pop_back();
  }

  /// When set, no entry of the heap is less than it.
  Entry least_{};
  bool has_least_ = false;
  ScratchVector<Entry> heap_storage_;
  std::vector<Entry>& heap_ = *heap_storage_;  ///< A heap by std::greater: the least first.
};

}  // namespace footfall
