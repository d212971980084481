// Footfall — a planner per character of a scenario (character_planners.hpp).
#include "crowd/character_planners.hpp"

#include <stdexcept>

#include "util/field_path.hpp"

namespace footfall::detail {

namespace {

PlannerParams scaled_to(const CharacterParams& character, const Scenario& scenario) {
  PlannerParams params = scenario.planner;
  if (&character == &scenario.character) return params;
  const double speed = character.preferred_speed / scenario.character.preferred_speed;
  const double duration = character.preferred_step_duration / scenario.character.preferred_step_duration;
  for (Gait& gait : params.gaits) {
    gait.speed *= speed;
    gait.duration *= duration;
  }
  return params;
}

const Ground& ground_or_none(const Ground* ground) {
  static const Ground none;
  return ground != nullptr ? *ground : none;
}

}  // namespace

CharacterPlanners::Entry::Entry(const CharacterParams& character, const Scenario& scenario,
                                const CollisionScene* scene, const Ground* ground)
    : params(scaled_to(character, scenario)),
      obstacles(scenario.obstacles,
                cut_heights(ground_or_none(ground), scenario.obstacles, character.body_height)),
      body(character),
      body_test(scene ? std::optional<StepBodyTest>(std::in_place, *scene, body,
                                                     scenario.planner.pose_rate)
                      : std::nullopt),
      planner(character, params, obstacles, body_test ? &*body_test : nullptr, ground) {}

CharacterPlanners::CharacterPlanners(const Scenario& scenario, const CollisionScene* scene,
                                     const Ground* ground)
    : scenario_(&scenario) {
  entries_.emplace(&scenario.character,
                   std::make_unique<const Entry>(scenario.character, scenario, scene, ground));
  for (std::size_t i = 0; i < scenario.agents.size(); ++i) {
    const AgentSpec& agent = scenario.agents[i];
    if (!agent.character || entries_.count(agent.character.get()) > 0) continue;
    try {
      entries_.emplace(agent.character.get(),
                       std::make_unique<const Entry>(*agent.character, scenario, scene, ground));
    } catch (const std::invalid_argument& error) {
      // The planner names the field as the scenario's ("character.preferred_speed").
      throw std::invalid_argument(item("agents", i) + "." + error.what());
    }
  }
}

const CharacterParams& CharacterPlanners::character(const AgentSpec& agent) const {
  return agent.character ? *agent.character : scenario_->character;
}

const CharacterPlanners::Entry& CharacterPlanners::entry(const AgentSpec& agent) const {
  return *entries_.at(&character(agent));
}

}  // namespace footfall::detail
