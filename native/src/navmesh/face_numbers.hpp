// Footfall — numbers for the faces a query visits: a hash table on the
// face's address with open addressing, so that the searches and walks that
// touch a few faces of a large mesh make no allocation per face (a node-based
// std::unordered_map made hashing and allocation a fifth of a query's time).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "navmesh/navmesh_impl.hpp"

namespace footfall {

/// Numbers faces 0, 1, 2, ... in the order they are first given. The first
/// kInline slots are kept in the object itself: most walks see a few faces,
/// and an allocation per walk cost more than the walk's hashing.
class FaceNumbers {
 public:
  FaceNumbers() = default;
  FaceNumbers(const FaceNumbers&) = delete;
  FaceNumbers& operator=(const FaceNumbers&) = delete;

  /// The number of `f`, and true if it was given now.
  std::pair<int, bool> insert(Face f) {
    const void* key = &*f;
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return {slots_[i].number, false};
      if (slots_[i].key == nullptr) {
        slots_[i] = {key, size_};
        if (2 * static_cast<std::size_t>(++size_) > mask_ + 1) grow();
        return {size_ - 1, true};
      }
    }
  }

  /// True if `f` has a number.
  bool contains(Face f) const {
    const void* key = &*f;
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return true;
      if (slots_[i].key == nullptr) return false;
    }
  }

  /// How many faces have a number.
  int size() const { return size_; }

 private:
  static constexpr std::size_t kInline = 32;
  struct Slot {
    const void* key = nullptr;
    int number = 0;
  };

  /// Fibonacci hashing of the address: faces lie a fixed stride apart, and
  /// the multiplication spreads the bits that differ over the top ones.
  std::size_t home(const void* key) const {
    const auto bits = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(key));
    return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 32) & mask_;
  }

  void grow() {
    std::vector<Slot> old(slots_, slots_ + mask_ + 1);
    heap_.assign(2 * old.size(), Slot{});
    slots_ = heap_.data();
    mask_ = heap_.size() - 1;
    for (const Slot& s : old)
      if (s.key != nullptr)
        for (std::size_t i = home(s.key);; i = (i + 1) & mask_)
          if (slots_[i].key == nullptr) {
            slots_[i] = s;
            break;
          }
  }

  std::array<Slot, kInline> inline_{};
  std::vector<Slot> heap_;
  Slot* slots_ = inline_.data();
  std::size_t mask_ = kInline - 1;
  int size_ = 0;
};

}  // namespace footfall
