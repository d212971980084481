// Footfall — the full-body planner's scenes (Juarez-Perez and Kallmann,
// section 4): a door behind clutter, a corridor of three narrow sections,
// random environments, and the two limits (a gap too narrow, an open field).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "footfall/crowd/scenario.hpp"

namespace footfall {

/// A scene and the queries to ask in it: from `start` to each goal. The
/// scenario holds one agent, from `start` to the first goal.
struct BehaviorScene {
  Scenario scenario;
  Vec2 start;
  std::vector<Vec2> goals;
};

/// Figure 5: cabinets before a door in a long wall; the path bends around
/// the cabinets, and the door passes the arms held in but not their swing.
BehaviorScene door_scene();
/// Figure 6: a corridor of three sections in a row: walls the swinging arms
/// hit; then knee-high boxes, narrower, that the arms swing over; then walls
/// closer than the shoulders, `last_gap` apart. [m]
BehaviorScene corridor_scene(double last_gap = 0.45);
/// A room whose only door is `door` wide (by default narrower than
/// side-stepping needs). [m]
BehaviorScene gap_scene(double door = 0.3);
/// Nothing near the way.
BehaviorScene open_field_scene();
/// Figures 7-8: boxes, low and tall, tables and shelves of random sizes
/// around the start (`dense`: about three times as many), and 100 goals at
/// the distance of `steps` normal steps from it, each clear of obstacles.
BehaviorScene random_behavior_scene(bool dense, int steps, std::uint64_t seed = 1);

/// The scene of this name: "door", "corridor", "gap", "open_field",
/// "random_normal_6", "random_normal_10", "random_dense_6", "random_dense_10".
/// Throws std::invalid_argument for another name.
BehaviorScene behavior_scene(const std::string& name);
/// The names behavior_scene knows.
std::vector<std::string> behavior_scene_names();

}  // namespace footfall
