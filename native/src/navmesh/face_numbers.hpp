// Footfall — numbers for the faces a query visits, so that the searches and
// walks that touch a few faces of a large mesh make no allocation per face.
#pragma once

#include <utility>

#include "navmesh/navmesh_impl.hpp"
#include "util/open_hash_map.hpp"

namespace footfall {

/// Numbers faces 0, 1, 2, ... in the order they are first given. Most walks
/// see a few faces: the first 32 fit in the object itself.
class FaceNumbers {
 public:
  /// The number of `f`, and true if it was given now.
  std::pair<int, bool> insert(Face f) {
    const auto [number, added] = numbers_.insert(&*f, static_cast<int>(numbers_.size()));
    return {*number, added};
  }
  /// True if `f` has a number.
  bool contains(Face f) const { return numbers_.contains(&*f); }
  /// How many faces have a number.
  int size() const { return static_cast<int>(numbers_.size()); }

 private:
  util::OpenHashMap<const void*, int, util::AddressHash, 32> numbers_;
};

}  // namespace footfall
