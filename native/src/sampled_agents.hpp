// Footfall — other agents' plans sampled at the instants of the contact grid,
// each sample computed once per search, however many candidate steps read it.
// A search checks hundreds of candidate steps against the same few plans at
// the same instants; sampling a plan (its COM, its feet, its circles) cost
// most of a crowd's planning time before this cache.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "footfall/planner.hpp"

namespace footfall::detail {

/// One other agent at one instant of the contact grid.
struct AgentSample {
  bool present = false;  ///< Not yet gone (an agent that leaves at its goal).
  Vec2 com;
  double speed = 0.0;  ///< COM speed. [m/s]
  int count = 0;       ///< Circles held: torso, and planted feet (after with_circles).
  std::array<Circle, 5> circles;
  double extent = 0.0;  ///< How far the circles reach from the COM. [m]
};

class SampledAgents {
 public:
  /// Starts over for `others` (which must outlive the samples taken), whose
  /// instants of interest begin at time `from`. Earlier samples are forgotten.
  void reset(const MovingObstacles& others, const CharacterParams& character, double from);
  std::size_t size() const { return others_->size(); }
  const AgentPlan& plan(std::size_t j) const { return *(*others_)[j]; }
  /// Agent j at instant k (t = k * kContactDt): presence, COM and speed.
  const AgentSample& at(std::size_t j, long k);
  /// The same, with its circles.
  const AgentSample& with_circles(std::size_t j, long k);
  /// The fastest agent j's COM moves in its plan: the largest speed at
  /// either end of one of its steps. [m/s]
  double top_speed(std::size_t j);

 private:
  struct Entry {
    std::uint64_t sampled = 0;  ///< The reset that filled `sample` (0: never).
    std::uint64_t circled = 0;  ///< The reset that filled its circles.
    AgentSample sample;
  };
  Entry& entry(std::size_t j, long k);

  const MovingObstacles* others_ = nullptr;
  const CharacterParams* character_ = nullptr;
  long first_ = 0;           ///< The instant of rows_[0].
  std::uint64_t stamp_ = 0;  ///< Counts resets.
  std::vector<std::vector<Entry>> rows_;  ///< rows_[k - first_][j]
  std::vector<std::pair<std::uint64_t, double>> top_speed_;  ///< (reset, speed) per agent
};

}  // namespace footfall::detail
