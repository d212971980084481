// Footfall — a scenario's characters, its shared one and the agents' own,
// each with the planner that walks it and what that planner needs.
#pragma once

#include <map>
#include <memory>
#include <optional>

#include "footfall/crowd/scenario.hpp"
#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/fullbody/step_body_test.hpp"
#include "footfall/planner/planner.hpp"

namespace footfall::detail {

/// One planner per character object (the scenario's, and each distinct
/// AgentSpec::character): its obstacles at the character's body height, its
/// body model, with a `scene` its full-body step test, and the footstep
/// planner. An agent's own character walks the scenario's gaits scaled to
/// it: speeds by its preferred speed over the scenario's, durations by its
/// preferred step duration over the scenario's (a smaller character takes
/// shorter, quicker steps). With `ground`, its planners plant every foot on
/// it. `scenario`, `scene` and `ground` must outlive it.
class CharacterPlanners {
 public:
  CharacterPlanners(const Scenario& scenario, const CollisionScene* scene,
                    const Ground* ground = nullptr);

  /// What agent `agent` walks with.
  const CharacterParams& character(const AgentSpec& agent) const;
  const FootstepPlanner& planner(const AgentSpec& agent) const { return entry(agent).planner; }
  const ObstacleMap& obstacles(const AgentSpec& agent) const { return entry(agent).obstacles; }
  const BodyModel& body(const AgentSpec& agent) const { return entry(agent).body; }

 private:
  struct Entry {
    Entry(const CharacterParams& character, const Scenario& scenario, const CollisionScene* scene,
          const Ground* ground);
    PlannerParams params;
    ObstacleMap obstacles;
    BodyModel body;
    std::optional<StepBodyTest> body_test;
    FootstepPlanner planner;
  };
  const Entry& entry(const AgentSpec& agent) const;

  const Scenario* scenario_;
  std::map<const CharacterParams*, std::unique_ptr<const Entry>> entries_;
};

}  // namespace footfall::detail
