// Footfall — numbers for the faces a query visits: a hash table on the
// face's address with open addressing, so that the searches and walks that
// touch a few faces of a large mesh make no allocation per face (a node-based
// std::unordered_map made hashing and allocation a fifth of a query's time).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "navmesh_impl.hpp"

namespace footfall {

/// Numbers faces 0, 1, 2, ... in the order they are first given.
class FaceNumbers {
 public:
  /// A table sized for about `expected` faces before it first grows.
  explicit FaceNumbers(std::size_t expected = 16) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    slots_.assign(capacity, Slot{});
  }

  /// The number of `f`, and true if it was given now.
  std::pair<int, bool> insert(Face f) {
    const void* key = &*f;
    for (std::size_t i = home(key);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i].key == key) return {slots_[i].number, false};
      if (slots_[i].key == nullptr) {
        slots_[i] = {key, size_};
        if (2 * static_cast<std::size_t>(++size_) > slots_.size()) grow();
        return {size_ - 1, true};
      }
    }
  }

  /// How many faces have a number.
  int size() const { return size_; }

 private:
  struct Slot {
    const void* key = nullptr;
    int number = 0;
  };

  /// Fibonacci hashing of the address: faces lie a fixed stride apart, and
  /// the multiplication spreads the bits that differ over the top ones.
  std::size_t home(const void* key) const {
    const auto bits = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(key));
    return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 32) & (slots_.size() - 1);
  }

  void grow() {
    std::vector<Slot> old(2 * slots_.size());
    old.swap(slots_);
    for (const Slot& s : old)
      if (s.key != nullptr)
        for (std::size_t i = home(s.key);; i = (i + 1) & (slots_.size() - 1))
          if (slots_[i].key == nullptr) {
            slots_[i] = s;
            break;
          }
  }

  std::vector<Slot> slots_;
  int size_ = 0;
};

}  // namespace footfall
