// Footfall — a walker's way to its goal, for the crowd driver
// (crowd_planner.cpp): known, annotated, or measured anew on the navigation
// mesh of the layer of ground it stands on, to its goal or to where its way
// crosses to another layer (a bridge's deck over the street).
#pragma once

#include <optional>
#include <vector>

#include "behavior/local_goal.hpp"
#include "crowd/crowd_walker.hpp"
#include "footfall/crowd/navigation.hpp"

namespace footfall::crowd {

/// Where the crowd finds its ways: one navigation mesh (or none), or one per
/// layer of ground with levels above one another.
struct CrowdWays {
  const NavMesh* mesh = nullptr;
  const LayeredNavigation* layered = nullptr;

  /// The layer `state` stands on (its stance foot's level; 0 with one).
  int layer_of(const FootstepState& state) const;
  /// The mesh of `layer`.
  const NavMesh* mesh_of(int layer) const {
    return layered != nullptr ? &layered->mesh(layer) : mesh;
  }
  /// The mesh of the layer `state` stands on.
  const NavMesh* mesh_at(const FootstepState& state) const { return mesh_of(layer_of(state)); }
};

/// A walker's way on the layer it stands on.
struct LayerWay {
  Way way;
  /// Where the way goes on over another layer: the first point past the
  /// crossing. `way` then ends before the crossing, and its length counts the
  /// rest of the way to the goal.
  std::optional<Vec2> across;
};

/// Walker w's way from `from` to its current goal (way_toward) on the layer
/// `from` stands on: all of it there where it can, else (its goal on another
/// layer, or reached over one) as far as its way crosses to the next layer.
/// `seen` are the agents it sees, where they stand `now`.
LayerWay way_on(const Walker& w, const CrowdWays& ways, const CharacterParams& character,
                const FootstepState& from, const std::vector<std::size_t>& seen,
                const Snapshot& now);

}  // namespace footfall::crowd
