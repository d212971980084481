// Footfall — ways over a scenario's ground: a navigation mesh for each layer
// of its ground (one where no levels lie above one another), joined where
// the layers meet, so that a way may climb from a street onto the bridge
// over it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/ground/ground.hpp"
#include "footfall/navmesh/navmesh.hpp"

namespace footfall {

/// The navigation mesh of one layer of a scenario's ground: navmesh_of's
/// domain and obstacles, each obstacle cut at the body's height above that
/// layer's ground under it (and left out where it lies wholly below that
/// ground: a bridge's pier under its deck), and the layer's walls.
NavMesh layer_navmesh(const Scenario& scenario, const GroundLayers& layers, int layer,
                      double margin = kNavMeshMargin);

/// A way over several layers: the path, and per point the layer it lies on
/// (where two points in a row lie on different layers, the way crosses
/// between them).
struct LayeredPath {
  PathResult path;
  std::vector<int> layers;
};

/// The navigation meshes of a scenario's layers (for its character: its
/// height, and the lower of its step limits), and shortest ways over them.
class LayeredNavigation {
 public:
  explicit LayeredNavigation(const Scenario& scenario, double margin = kNavMeshMargin);
  /// The same over `layers` found already (layers_for, for the scenario's
  /// character), whose ground must outlive it.
  LayeredNavigation(const Scenario& scenario, GroundLayers layers,
                    double margin = kNavMeshMargin);

  int layers() const { return static_cast<int>(meshes_.size()); }
  const NavMesh& mesh(int layer) const { return meshes_.at(layer); }
  /// The layer a point (`field`, for the message) stands on: without ground
  /// 0; with a height `z`, the standable level within 0.5 m of it; without
  /// one, the only standable level over `p`. Throws std::invalid_argument
  /// ("--from: over no ground to stand on", "--to: two levels at ..., 0.00
  /// and 2.89 m: give its height") where there is none or several.
  int layer_at(Vec2 p, std::optional<double> z, const std::string& field) const;
  /// The shortest way for a disc of the query's radius from `query.from` on
  /// layer `from_layer` to `query.to` on `to_layer`, on as many layers as it
  /// takes, crossing from one to the next where they meet (at points 1 m
  /// apart along each meeting). With ground, `heights` holds the ground's
  /// height under each point. A way on one layer is the mesh's own answer.
  PathResult find_path(const PathQuery& query, int from_layer, int to_layer) const;
  /// find_path's way, with each point's layer rather than its height.
  LayeredPath route(const PathQuery& query, int from_layer, int to_layer) const;
  /// The layer the foot of a body standing at `p` on ground at height `z`
  /// stands on: of the standable levels there, the nearest `z`'s (0 where
  /// there is none).
  int layer_under(Vec2 p, double z) const;

 private:
  void make_meshes(const Scenario& scenario, double margin);

  std::unique_ptr<const Ground> owned_;  // made from the scenario, or none: given
  const Ground* ground_;                 // the layers refer to it
  GroundLayers layers_;
  std::vector<NavMesh> meshes_;
};

}  // namespace footfall
