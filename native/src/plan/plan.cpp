#include "footfall/plan/plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace footfall {
namespace {

constexpr double kMaxLift = 0.12;        // [m] swing height of a full stride
constexpr double kLiftPerStride = 0.15;  // swing height per metre of stride

// Index of the step under way at time t: the last one that started at or
// before t (clamped to the first and last). Plans are never empty here.
int step_index(const AgentPlan& plan, double t) {
  const auto& steps = plan.footsteps;
  const auto after =
      std::upper_bound(steps.begin(), steps.end(), t,
                       [](double time, const Footstep& s) { return time < s.start_time; });
  return std::max(0, static_cast<int>(after - steps.begin()) - 1);
}

double smoothstep(double u) { return u * u * (3.0 - 2.0 * u); }

}  // namespace

double ground_at(const AgentPlan& plan, double t) {
  const auto& steps = plan.footsteps;
  if (steps.empty() || t < steps.front().start_time)
    return std::max(plan.start.foot_heights[0], plan.start.foot_heights[1]);
  return steps[step_index(plan, t)].foot_height;
}

ComSample com_at(const AgentPlan& plan, double t) {
  if (plan.footsteps.empty()) return {plan.start.com, {0.0, 0.0}};
  return com_at(plan.footsteps[step_index(plan, t)], t);
}

namespace {

// How far the torso circles reach from the COM. [m]
double torso_reach(const CharacterParams& character) {
  double reach = 0.0;
  for (const Circle& circle : torso_circles({0.0, 0.0}, 0.0, character))
    reach = std::max(reach, length(circle.center) + circle.radius);
  return reach;
}

// How far a planted foot's circle can reach from the COM during `step`: the
// COM stays within its stray of the chord, and a point's distance to a chord
// is greatest at one of its ends. [m]
double foot_reach(const Footstep& step, Vec2 foot, const CharacterParams& character) {
  const double far = std::max(distance(step.com_start, foot), distance(step.com_end, foot));
  return far + com_stray(step) + character.foot_radius;
}

// Standing at the start: the feet where they stand. [m]
double start_feet_reach(const AgentPlan& plan, const CharacterParams& character) {
  double reach = 0.0;
  for (const Vec2& foot : plan.start.feet)
    reach = std::max(reach, distance(plan.start.com, foot) + character.foot_radius);
  return reach;
}

}  // namespace

double top_com_speed(const AgentPlan& plan, double from) {
  double speed = 0.0;
  if (plan.footsteps.empty()) return speed;
  // From the step under way at `from`: a long plan's past costs nothing.
  for (auto step = plan.footsteps.begin() + step_index(plan, from); step != plan.footsteps.end();
       ++step)
    speed = std::max(speed, top_speed(*step));
  return speed;
}

double circle_reach(const AgentPlan& plan, const CharacterParams& shared, double from) {
  const CharacterParams& character = character_of(plan, shared);
  double reach = torso_reach(character);
  const auto& steps = plan.footsteps;
  if (steps.empty() || from < steps.front().start_time)  // standing at the start first
    reach = std::max(reach, start_feet_reach(plan, character));
  if (steps.empty()) return reach;
  // Where each foot was last planted before the step under way.
  std::array<Vec2, 2> last = plan.start.feet;
  const int first = step_index(plan, from);
  std::array<bool, 2> found{false, false};
  for (int i = first - 1; i >= 0 && !(found[0] && found[1]); --i) {
    const int f = static_cast<int>(steps[i].foot);
    if (!found[f]) last[f] = steps[i].foot_position;
    found[f] = true;
  }
  for (auto step = steps.begin() + first; step != steps.end(); ++step) {
    for (const Vec2& foot : {step->foot_position, last[static_cast<int>(other(step->foot))]})
      reach = std::max(reach, foot_reach(*step, foot, character));
    last[static_cast<int>(step->foot)] = step->foot_position;
  }
  return reach;
}

PlanBounds::PlanBounds(const AgentPlan& plan, const CharacterParams& shared) {
  const CharacterParams& character = character_of(plan, shared);
  const auto& steps = plan.footsteps;
  const double torso = torso_reach(character);
  start_.reach = std::max(torso, start_feet_reach(plan, character));
  start_.com_box = {plan.start.com, plan.start.com};
  // Each step's own terms first, going forward (the foot that stays planted
  // through it was put down earlier), then the maxima going back.
  suffix_.resize(steps.size());
  starts_.resize(steps.size());
  std::array<Vec2, 2> last = plan.start.feet;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const Footstep& step = steps[i];
    starts_[i] = step.start_time;
    From& own = suffix_[i];
    own.top_speed = top_speed(step);
    own.reach = torso;
    for (const Vec2& foot : {step.foot_position, last[static_cast<int>(other(step.foot))]})
      own.reach = std::max(own.reach, foot_reach(step, foot, character));
    last[static_cast<int>(step.foot)] = step.foot_position;
    own.com_box = {step.com_start, step.com_start};
    own.com_box.take_in(step.com_end);
    // com_at rounds: a step that stays put may place its COM an ulp aside.
    const double size = std::max({std::fabs(own.com_box.min.x), std::fabs(own.com_box.min.y),
                                  std::fabs(own.com_box.max.x), std::fabs(own.com_box.max.y), 1.0});
    const double grow = com_stray(step) + 8.0 * std::numeric_limits<double>::epsilon() * size;
    own.com_box = {own.com_box.min - Vec2{grow, grow}, own.com_box.max + Vec2{grow, grow}};
  }
  for (std::size_t i = steps.size(); i-- > 1;) {
    const From& later = suffix_[i];
    From& here = suffix_[i - 1];
    here.top_speed = std::max(here.top_speed, later.top_speed);
    here.reach = std::max(here.reach, later.reach);
    here.com_box.take_in(later.com_box);
  }
  if (!suffix_.empty()) suffix_.front().com_box.take_in(plan.start.com);  // before it
}

PlanBounds::From PlanBounds::from(double from) const {
  if (suffix_.empty()) return start_;
  // The step under way, as step_index finds it.
  const auto after = std::upper_bound(starts_.begin(), starts_.end(), from);
  const auto index = std::max<std::ptrdiff_t>(0, after - starts_.begin() - 1);
  From bounds = suffix_[static_cast<std::size_t>(index)];
  if (from < starts_.front()) bounds.reach = std::max(bounds.reach, start_.reach);
  return bounds;
}

std::size_t droppable_steps(const AgentPlan& plan, double from) {
  const auto& steps = plan.footsteps;
  if (steps.empty() || from < steps.front().start_time) return 0;
  std::array<bool, 2> found{false, false};
  for (int i = step_index(plan, from) - 1; i >= 0; --i) {
    found[static_cast<int>(steps[i].foot)] = true;
    if (found[0] && found[1]) return static_cast<std::size_t>(i);
  }
  return 0;
}

void drop_steps(AgentPlan& plan, std::size_t count, std::vector<Footstep>& past) {
  const auto end = plan.footsteps.begin() + static_cast<std::ptrdiff_t>(count);
  for (auto step = plan.footsteps.begin(); step != end; ++step)
    plan.start = state_after(plan.start, *step);
  past.insert(past.end(), plan.footsteps.begin(), end);
  plan.footsteps.erase(plan.footsteps.begin(), end);
}

double facing_at(const AgentPlan& plan, double t) {
  if (plan.footsteps.empty() || t < plan.footsteps.front().start_time) return plan.start.facing;
  return plan.footsteps[step_index(plan, t)].phi;
}

double swing_lift(double stride, double u) {
  return std::min(kMaxLift, kLiftPerStride * stride) * std::sin(kPi * std::clamp(u, 0.0, 1.0));
}

namespace {

FootPose planted(Vec2 position, double orientation, double ground) {
  FootPose foot;
  foot.position = position;
  foot.orientation = orientation;
  foot.ground = foot.swing_to_ground = ground;
  return foot;
}

// `from` moved toward the planted pose `to` by the fraction u of a swing.
FootPose swing(const FootPose& from, const Footstep& to, double u) {
  const double s = smoothstep(std::clamp(u, 0.0, 1.0));
  const double stride = distance(from.position, to.foot_position);
  FootPose foot;
  foot.position = from.position + s * (to.foot_position - from.position);
  foot.orientation =
      wrap_angle(from.orientation + s * wrap_angle(to.foot_orientation - from.orientation));
  foot.lift = swing_lift(stride, u);
  foot.planted = stride == 0.0 && to.foot_orientation == from.orientation;
  foot.ground = from.ground;
  foot.swing_to_ground = to.foot_height;
  foot.swing_from = from.position;
  foot.swing_to = to.foot_position;
  foot.swing_from_orientation = from.orientation;
  foot.swing_to_orientation = to.foot_orientation;
  foot.swing_phase = std::clamp(u, 0.0, 1.0);
  return foot;
}

// The feet before any step: where they stand.
std::array<FootPose, 2> standing_feet(const AgentPlan& plan) {
  std::array<FootPose, 2> feet;
  for (int f = 0; f < 2; ++f)
    feet[f] = planted(plan.start.feet[f], plan.start.facing, plan.start.foot_heights[f]);
  return feet;
}

// The feet at time t during step k (step_index), t not before the first step.
std::array<FootPose, 2> feet_during(const AgentPlan& plan, int k, double t) {
  std::array<FootPose, 2> feet = standing_feet(plan);
  const auto& steps = plan.footsteps;
  // Where each foot was last planted before step k: found walking back, so a
  // long plan costs no more than a short one.
  std::array<bool, 2> found{false, false};
  for (int i = k - 1; i >= 0 && !(found[0] && found[1]); --i) {
    const int f = static_cast<int>(steps[i].foot);
    if (found[f]) continue;
    feet[f] = planted(steps[i].foot_position, steps[i].foot_orientation, steps[i].foot_height);
    found[f] = true;
  }
  const Footstep& step = steps[k];
  const int stepping = static_cast<int>(step.foot);
  const int other_foot = static_cast<int>(other(step.foot));
  const FootPose before = feet[stepping];
  // A start's foot stays as it was put down (its own orientation is chosen
  // again when a crowd's plan is complete; the pose must not change with it).
  feet[stepping] = step.kind == StepKind::kStart
                       ? planted(before.position, before.orientation, before.ground)
                       : planted(step.foot_position, step.foot_orientation, step.foot_height);
  // One that leaves walks on off its last step: the other foot swings a
  // stride on (two COM chords), as the COM travels beyond the planted foot.
  const bool walks_off = k + 1 == static_cast<int>(steps.size()) && plan.leaves &&
                         step.kind == StepKind::kWalk;
  Footstep walk_on = step;
  if (walks_off) {
    walk_on.foot = other(step.foot);
    walk_on.foot_position = feet[other_foot].position + 2.0 * (step.com_end - step.com_start);
  }
  if (t >= step.end_time) {
    if (walks_off) feet[other_foot] = swing(feet[other_foot], walk_on, 1.0);  // landing as it goes
    return feet;
  }
  // A foot lands at its step's start, having swung during the step before,
  // which the other foot took. The planner puts a start before a walk whose
  // foot had no such step; a step that still has none (a pivot or a side step
  // as the first step, or a plan file of an older planner) swings its foot in
  // a lead-in at the start of its own step, the other foot still planted.
  double stance_start = step.start_time;
  const bool swung_in = k > 0 && steps[k - 1].foot != step.foot;
  // To a nanometre and a nanoradian: the orientations chosen over a whole
  // plan may differ from the standing one in the last bit.
  const bool moves = distance(before.position, step.foot_position) > 1e-9 ||
                     std::fabs(wrap_angle(before.orientation - step.foot_orientation)) > 1e-9;
  if (!swung_in && moves && step.kind != StepKind::kStart) {
    const double lead = set_off_lead(step);
    if (t < step.start_time + lead) {
      feet[stepping] = swing(before, step, (t - step.start_time) / lead);
      return feet;
    }
    stance_start += lead;
  }
  // Meanwhile the other foot swings to where the next step plants it.
  const double u = (t - stance_start) / (step.end_time - stance_start);
  if (k + 1 < static_cast<int>(steps.size()) && steps[k + 1].foot == other(step.foot) &&
      steps[k + 1].kind != StepKind::kStart) {  // a start's foot stays put
    feet[other_foot] = swing(feet[other_foot], steps[k + 1], u);
  } else if (walks_off) {
    feet[other_foot] = swing(feet[other_foot], walk_on, u);
  }
  return feet;
}

}  // namespace

std::array<FootPose, 2> feet_at(const AgentPlan& plan, double t) {
  if (plan.footsteps.empty() || t < plan.footsteps.front().start_time) return standing_feet(plan);
  return feet_during(plan, step_index(plan, t), t);
}

namespace {

// collision_circles at time t, with the step under way (k, step_index's) known.
int circles_during(const AgentPlan& plan, int k, const CharacterParams& shared, double t,
                   std::array<Circle, 5>& out) {
  if (!present_at(plan, t)) return 0;
  const CharacterParams& character = character_of(plan, shared);
  // What com_at, facing_at and feet_at give, from the one step.
  const auto& steps = plan.footsteps;
  const bool started = !steps.empty() && t >= steps.front().start_time;
  const Vec2 com = steps.empty() ? plan.start.com : com_at(steps[k], t).position;
  const Footstep* step = started ? &steps[k] : nullptr;
  const auto torso = step ? torso_circles(com, step->phi, character, 0.0, torso_width_of(*step))
                          : torso_circles(com, plan.start.facing, character);
  int count = 0;
  for (const Circle& circle : torso) out[count++] = circle;
  for (const FootPose& foot : started ? feet_during(plan, k, t) : standing_feet(plan)) {
    if (foot.planted) out[count++] = {foot.position, character.foot_radius};
  }
  return count;
}

}  // namespace

int collision_circles(const AgentPlan& plan, const CharacterParams& character, double t,
                      std::array<Circle, 5>& out) {
  return circles_during(plan, plan.footsteps.empty() ? 0 : step_index(plan, t), character, t, out);
}

int PlanWalk::step(double t) {
  // As step_index: the last step that started at or before t (or the first);
  // searched for only when the last one found cannot lead to it. Steps are
  // in the order of their start times, so from one that started at or before
  // t the answer lies ahead.
  const auto& steps = plan_->footsteps;
  if (step_ < 0 || step_ >= static_cast<int>(steps.size()) || steps[step_].start_time > t)
    return step_ = step_index(*plan_, t);
  while (step_ + 1 < static_cast<int>(steps.size()) && steps[step_ + 1].start_time <= t) ++step_;
  return step_;
}

ComSample PlanWalk::com_at(double t) {
  if (plan_->footsteps.empty()) return {plan_->start.com, {0.0, 0.0}};
  return footfall::com_at(plan_->footsteps[step(t)], t);
}

int PlanWalk::collision_circles(const CharacterParams& character, double t,
                                std::array<Circle, 5>& out) {
  return circles_during(*plan_, plan_->footsteps.empty() ? 0 : step(t), character, t, out);
}

std::vector<Circle> collision_circles(const AgentPlan& plan, const CharacterParams& character,
                                      double t) {
  std::array<Circle, 5> circles;
  const int count = collision_circles(plan, character, t, circles);
  return {circles.begin(), circles.begin() + count};
}

}  // namespace footfall
