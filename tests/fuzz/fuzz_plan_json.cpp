// Fuzz target: plan JSON (either version), read or refused with
// std::invalid_argument; a plan read is evaluated as the add-on and
// `footfall metrics` do (at 1 Hz, so that a long valid plan stays quick), and
// written again and read back it must write the same text: nothing the file
// holds is lost or changed on the way (a throw here is a finding too).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "footfall/io/plan_file.hpp"
#include "footfall/plan/metrics.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  footfall::Plan plan;
  try {
    plan = footfall::parse_plan(std::string(reinterpret_cast<const char*>(data), size),
                                "fuzz.json");
  } catch (const std::invalid_argument&) {
    return 0;
  }
  for (const footfall::AgentPlan& agent : plan.agents) {
    for (const double t : {0.0, 0.5 * agent.end_time(), agent.end_time() + 1.0}) {
      footfall::com_at(agent, t);
      footfall::feet_at(agent, t);
      footfall::collision_circles(agent, plan.character, t);
    }
  }
  const std::string text = footfall::plan_to_json(plan);
  if (footfall::plan_to_json(footfall::parse_plan(text, "again.json")) != text) __builtin_trap();
  try {
    footfall::measure_plan(plan, 1.0);
  } catch (const std::invalid_argument&) {  // obstacles that an ObstacleMap refuses
  }
  return 0;
}
