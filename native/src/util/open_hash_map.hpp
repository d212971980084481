// Footfall — a hash map with open addressing for small keys (integers,
// addresses), for the hot loops that look up a few hundred keys and must not
// allocate per key: the footstep search's seen states, the faces a mesh query
// visits, the marks CGAL keeps while inserting a constraint. The first
// kInline slots are kept in the object; a larger table lives on the heap and
// keeps its memory through clear(), for the next use.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace footfall::util {

/// No value: the map is a set.
struct NoValue {};

/// A key and its value; a set's slot is the key alone.
template <class Key, class Value>
struct HashSlot {
  Key key{};
  Value value{};
};
template <class Key>
struct HashSlot<Key, NoValue> {
  Key key{};
  static inline NoValue value{};
};

/// Fibonacci hashing of an address: objects a fixed stride apart spread over
/// the top bits.
struct AddressHash {
  std::size_t operator()(const void* key) const {
    const auto bits = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(key));
    return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 32);
  }
};

/// Maps keys to values. `Key{}` marks an empty slot and is never a key.
/// Values and references to them stay put until the next insert.
template <class Key, class Value, class Hash, std::size_t kInline,
          template <class> class Allocator = std::allocator>
class OpenHashMap {
  static_assert((kInline & (kInline - 1)) == 0, "kInline must be a power of two");

 public:
  OpenHashMap() = default;
  OpenHashMap(const OpenHashMap&) = delete;
  OpenHashMap& operator=(const OpenHashMap&) = delete;

  /// The value of `key`, given `value` if it was not there, and true if it
  /// was put there now.
  std::pair<Value*, bool> insert(Key key, const Value& value = Value{}) {
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return {&slots_[i].value, false};
      if (slots_[i].key == Key{}) {
        slots_[i].key = key;
        slots_[i].value = value;
        if (2 * ++size_ > mask_ + 1) {
          grow();
          return {find(key), true};
        }
        return {&slots_[i].value, true};
      }
    }
  }

  /// The value of `key`, or null.
  Value* find(Key key) {
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return &slots_[i].value;
      if (slots_[i].key == Key{}) return nullptr;
    }
  }

  /// True if `key` is there.
  bool contains(Key key) const { return const_cast<OpenHashMap*>(this)->find(key) != nullptr; }

  /// How many keys are there.
  std::size_t size() const { return size_; }

  /// Empties the map, back to its inline slots; the heap table is kept.
  void clear() {
    slots_ = inline_.data();
    mask_ = kInline - 1;
    std::fill(inline_.begin(), inline_.end(), Slot{});
    size_ = 0;
  }

 private:
  using Slot = HashSlot<Key, Value>;

  std::size_t home(Key key) const { return Hash{}(key)&mask_; }

  void grow() {
    old_.assign(slots_, slots_ + mask_ + 1);
    const std::size_t capacity = 2 * old_.size();
    if (heap_.size() < capacity) heap_.resize(capacity);
    std::fill_n(heap_.begin(), capacity, Slot{});
    slots_ = heap_.data();
    mask_ = capacity - 1;
    for (const Slot& slot : old_) {
      if (slot.key == Key{}) continue;
      std::size_t i = home(slot.key);
      while (slots_[i].key != Key{}) i = (i + 1) & mask_;
      slots_[i] = slot;
    }
  }

  std::array<Slot, kInline> inline_{};
  std::vector<Slot, Allocator<Slot>> heap_;
  std::vector<Slot> old_;  ///< The slots being rehashed.
  Slot* slots_ = inline_.data();
  std::size_t mask_ = kInline - 1;
  std::size_t size_ = 0;
};

}  // namespace footfall::util
