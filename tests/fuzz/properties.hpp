// The properties the fuzz targets check of what they read, beyond not
// crashing: a violation aborts with what was violated, which libFuzzer
// reports as a finding.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "animate/agent_motion.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/model/param_table.hpp"
#include "io/param_json.hpp"

namespace footfall::fuzz {

/// Aborts, naming `property`, unless it `holds`.
inline void require(bool holds, const char* property) {
  if (holds) return;
  std::fprintf(stderr, "fuzz: property violated: %s\n", property);
  std::abort();
}

template <class S>
bool same_params(const S& a, const S& b);

template <class S, class T>
bool same_field(const ScalarParam<S, T>& field, const S& a, const S& b) {
  return a.*field.member == b.*field.member;
}
template <class S>
bool same_field(const NumberListParam<S>& field, const S& a, const S& b) {
  return a.*field.member == b.*field.member;
}
template <class S, class N>
bool same_field(const NestedParam<S, N>& field, const S& a, const S& b) {
  return same_params(a.*field.member, b.*field.member);
}
template <class S, class E>
bool same_field(const StructListParam<S, E>& field, const S& a, const S& b) {
  return std::equal((a.*field.member).begin(), (a.*field.member).end(), (b.*field.member).begin(),
                    (b.*field.member).end(), same_params<E>);
}

/// True if every field of S's parameter table is the same in `a` and `b`.
template <class S>
bool same_params(const S& a, const S& b) {
  bool same = true;
  for_each_param<S>([&](const auto& field) { same = same && same_field(field, a, b); });
  return same;
}

/// True if `a` and `b` are the same character: every parameter, and the
/// behaviours' motions (as the files write them).
inline bool same_character(const CharacterParams& a, const CharacterParams& b) {
  return detail::character_to_json(a) == detail::character_to_json(b);
}

inline bool same_obstacle(const Obstacle& a, const Obstacle& b) {
  const auto same_vertex = [](Vec3 p, Vec3 q) { return p.x == q.x && p.y == q.y && p.z == q.z; };
  return a.polygon == b.polygon && a.height == b.height && a.base == b.base &&
         std::equal(a.mesh.vertices.begin(), a.mesh.vertices.end(), b.mesh.vertices.begin(),
                    b.mesh.vertices.end(), same_vertex) &&
         a.mesh.triangles == b.mesh.triangles;
}

/// Agents as the readers make them (`sections` are the planner's, not read).
inline bool same_agent(const AgentSpec& a, const AgentSpec& b) {
  const bool same_own_character = a.character == nullptr || b.character == nullptr
                                      ? a.character == b.character
                                      : same_character(*a.character, *b.character);
  return a.name == b.name && a.position == b.position && a.facing == b.facing &&
         a.goals == b.goals && a.leave_at_goal == b.leave_at_goal && same_own_character &&
         a.time_limit == b.time_limit && a.start_delay == b.start_delay &&
         a.goal_wait == b.goal_wait && a.end_facing == b.end_facing &&
         a.goal_facings == b.goal_facings && a.scale == b.scale && a.height == b.height &&
         a.goal_heights == b.goal_heights;
}

/// True if `a` and `b` hold the same obstacles, agents and parameters, to the bit.
inline bool same_scenario(const Scenario& a, const Scenario& b) {
  return std::equal(a.obstacles.begin(), a.obstacles.end(), b.obstacles.begin(), b.obstacles.end(),
                    same_obstacle) &&
         std::equal(a.ground.begin(), a.ground.end(), b.ground.begin(), b.ground.end(),
                    same_obstacle) &&
         std::equal(a.agents.begin(), a.agents.end(), b.agents.begin(), b.agents.end(),
                    same_agent) &&
         same_character(a.character, b.character) && same_params(a.planner, b.planner);
}

/// Aborts unless every bone of a posed rig, at every frame, has a finite
/// translation and scale and a finite rotation of unit length (to 1e-6).
inline void require_sound_pose(const animate::AgentMotion& motion) {
  const auto finite = [](Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  for (const std::vector<animate::Trs>& frames : motion.frames) {
    for (const animate::Trs& bone : frames) {
      const animate::Quat& q = bone.rotation;
      const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
      require(std::isfinite(norm) && std::fabs(norm - 1.0) <= 1e-6,
              "a posed bone's rotation is finite and of unit length");
      require(finite(bone.translation) && finite(bone.scale),
              "a posed bone's translation and scale are finite");
    }
  }
}

}  // namespace footfall::fuzz
