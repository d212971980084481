#include "footfall/model/params.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "footfall/model/geometry.hpp"

namespace footfall {
namespace {

// Checks lo <(=) value <(=) hi; `open_low` / `open_high` exclude the bound.
void check_range(double value, const std::string& field, double lo, double hi, bool open_low,
                 bool open_high) {
  const bool ok = std::isfinite(value) && (open_low ? value > lo : value >= lo) &&
                  (open_high ? value < hi : value <= hi);
  if (ok) return;
  std::ostringstream message;
  message.precision(10);
  message << field << ": must be in " << (open_low ? "(" : "[") << lo << ", " << hi
          << (open_high ? ")" : "]") << ", got " << value;
  throw std::invalid_argument(message.str());
}

void check_closed(double value, const std::string& field, double lo, double hi) {
  check_range(value, field, lo, hi, false, false);
}
void check_open_low(double value, const std::string& field, double lo, double hi) {
  check_range(value, field, lo, hi, true, false);
}

void validate(const FootLimits& limits, const std::string& path) {
  check_open_low(limits.min_step_duration, path + ".min_step_duration", 0.0, 5.0);
  check_closed(limits.max_step_duration, path + ".max_step_duration", limits.min_step_duration,
               5.0);
  check_open_low(limits.min_step_length, path + ".min_step_length", 0.0, 3.0);
  check_closed(limits.max_step_length, path + ".max_step_length", limits.min_step_length, 3.0);
  check_open_low(limits.min_speed, path + ".min_speed", 0.0, 10.0);
  check_closed(limits.max_speed, path + ".max_speed", limits.min_speed, 10.0);
}

}  // namespace

void validate(const CharacterParams& p, const std::string& path) {
  check_closed(p.com_height, path + ".com_height", 0.2, 3.0);
  check_open_low(p.mass, path + ".mass", 0.0, 500.0);
  check_closed(p.energy_rate, path + ".energy_rate", 0.0, 1e5);
  check_closed(p.curvature_weight, path + ".curvature_weight", 0.0, 1.0);
  check_open_low(p.foot_offset, path + ".foot_offset", 0.0, 0.5);
  check_open_low(p.torso_width, path + ".torso_width", 0.0, 1.5);
  check_open_low(p.torso_radius, path + ".torso_radius", 0.0, p.torso_width / 2);
  check_open_low(p.shoulder_radius, path + ".shoulder_radius", 0.0, p.torso_width / 2);
  check_open_low(p.foot_radius, path + ".foot_radius", 0.0, 0.5);
  check_open_low(p.preferred_speed, path + ".preferred_speed", 0.0, 10.0);
  check_open_low(p.preferred_step_duration, path + ".preferred_step_duration", 0.0, 5.0);
  check_open_low(p.max_foot_turn, path + ".max_foot_turn", 0.0, kPi);
  validate(p.left, path + ".left");
  validate(p.right, path + ".right");
}

void validate(const PlannerParams& p, const std::string& path) {
  check_closed(p.max_expansions, path + ".max_expansions", 1, 1000000);
  check_closed(p.stall_expansions, path + ".stall_expansions", 0, 1000000);
  check_closed(p.heuristic_weight, path + ".heuristic_weight", 1.0, 10.0);
  check_open_low(p.goal_tolerance, path + ".goal_tolerance", 0.0, 10.0);
  check_closed(p.local_goal_distance, path + ".local_goal_distance", 1.0, 1000.0);
  if (!(p.goal_tolerance < p.local_goal_distance)) {
    throw std::invalid_argument(path + ".goal_tolerance: must be less than local_goal_distance (" +
                                std::to_string(p.local_goal_distance) + ")");
  }
  check_open_low(p.max_time, path + ".max_time", 0.0, 100000.0);
  check_open_low(p.stop_duration, path + ".stop_duration", 0.0, 5.0);
  check_closed(p.collision_sample_spacing, path + ".collision_sample_spacing", 0.005, 0.05);
  check_open_low(p.min_progress, path + ".min_progress", 0.0, 10.0);
  if (p.gaits.empty() || p.gaits.size() > 16) {
    throw std::invalid_argument(path + ".gaits: must hold 1 to 16 gaits, got " +
                                std::to_string(p.gaits.size()));
  }
  for (size_t i = 0; i < p.gaits.size(); ++i) {
    const std::string item = path + ".gaits[" + std::to_string(i) + "]";
    check_open_low(p.gaits[i].speed, item + ".speed", 0.0, 10.0);
    check_open_low(p.gaits[i].duration, item + ".duration", 0.0, 5.0);
  }
  if (p.turn_angles.empty() || p.turn_angles.size() > 32) {
    throw std::invalid_argument(path + ".turn_angles: must hold 1 to 32 angles, got " +
                                std::to_string(p.turn_angles.size()));
  }
  for (size_t i = 0; i < p.turn_angles.size(); ++i) {
    check_range(p.turn_angles[i], path + ".turn_angles[" + std::to_string(i) + "]", 0.0, kPi / 2,
                true, true);
  }
}

}  // namespace footfall
