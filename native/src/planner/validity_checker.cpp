#include "footfall/planner/validity_checker.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "footfall/fullbody/step_body_test.hpp"
#include "footfall/plan/section_lookup.hpp"
#include "footfall/ground/ground.hpp"
#include "model/contact.hpp"
#include "planner/validity_impl.hpp"

namespace footfall {
namespace {

// A disc that holds the torso throughout the step, grown by `margin`: the
// whole step's COM lies within half the chord plus its stray of the chord's
// midpoint.
Circle sweep_bound(const Footstep& step, const CharacterParams& character, double margin) {
  const double chord = distance(step.com_start, step.com_end);
  return {0.5 * (step.com_start + step.com_end),
          0.5 * chord + com_stray(step) + 0.5 * character.torso_width + margin};
}

// `others` sampled from time `from` on, for a check outside a search (which
// keeps its own samples for all its steps).
detail::SampledAgents& sampled(const MovingObstacles& others, const CharacterParams& character,
                               double from) {
  thread_local detail::SampledAgents samples;
  samples.reset(others, character, from);
  return samples;
}

// A character standing at a state, checked against other agents' plans from
// the state's time on, with room to turn on the spot, as room_to_turn() asks
// of static obstacles: two agents resting face to face a few centimetres
// apart could never step again, every turn swinging a shoulder into the other.
class StandingCheck {
 public:
  StandingCheck(const FootstepState& state, const CharacterParams& character)
      : com_(state.com),
        ground_(std::max(state.foot_heights[0], state.foot_heights[1])),
        headroom_(character.body_height),
        mine_{Circle{state.com, 0.5 * character.torso_width},
              Circle{state.feet[0], character.foot_radius},
              Circle{state.feet[1], character.foot_radius}},
        first_(first_contact_instant(state.time)) {
    extent_ = mine_.front().radius + kRestRoom;
    for (const Circle& circle : mine_)
      extent_ = std::max(extent_, distance(circle.center, com_) + circle.radius);
  }

  // True if it touches agent j of `others` (sampled from the state's time).
  bool touches(detail::SampledAgents& others, std::size_t j) const {
    // After its plan ends, the other stands too: the first instant from then
    // on is the last that can differ.
    const long last = std::max(first_, first_contact_instant(others.plan(j).end_time()));
    const double span = static_cast<double>(last - first_) * kContactDt;
    const PlanBounds::From& bounds = others.bounds(j);
    const double near = extent_ + bounds.reach + 0.5 * bounds.top_speed * kContactDt;
    if (squared_distance(bounds.com_box, {com_, com_}) > near * near) return false;
    if (distance(others.at(j, first_).com, com_) > near + bounds.top_speed * span) return false;
    double start_gap = std::numeric_limits<double>::infinity();  // see touching()
    for (long k = first_; k <= last; ++k) {
      const detail::AgentWhere& them = others.at(j, k);
      if (!them.present) break;  // gone for good
      if (distance(them.com, com_) > near || levels_apart(them.ground, ground_, headroom_))
        continue;
      const detail::AgentShape& shape = others.shape(j, k);
      const double pad = 0.5 * them.speed * kContactDt;
      if (k != first_ && distance(them.com, com_) - extent_ - shape.extent - pad > 0.0) continue;
      // Room kept from those standing still (the torso disc only).
      const double room = standing_still(0.0, them.speed) ? kRestRoom : 0.0;
      Gap gap;
      for (int i = 0; i < shape.count; ++i)
        for (std::size_t m = 0; m < mine_.size(); ++m) {
          Circle circle = mine_[m];
          if (m == 0) circle.radius += room;
          gap.add(circle, shape.circles[i], pad);
        }
      if (k == first_ && standing_still(0.0, them.speed)) start_gap = gap.outright;
      if (touching(gap, start_gap)) return true;
    }
    return false;
  }

 private:
  Vec2 com_;
  double ground_, headroom_;    // where it stands, and its height
  std::array<Circle, 3> mine_;  // the torso disc and the feet
  double extent_ = 0.0;         // how far they reach from the COM, room included
  long first_ = 0;
};

}  // namespace

bool WholeBody::label(Footstep& step) const {
  if (sections == nullptr) return true;
  const Behavior place = sections->along(step);
  if (place == Behavior::kSideStep && step.kind == StepKind::kWalk) return false;
  step.behavior = step.kind == StepKind::kSideStep ? Behavior::kSideStep : place;
  return true;
}

bool WholeBody::passes(Footstep& step, const FootstepState& before) const {
  if (body == nullptr) return true;
  // A split walk's start and rest are posed each in its own way.
  const bool split = splits_on_set_off(step, before);
  const auto hits = [&] {
    if (!split) return body->hits(step);
    const std::array<Footstep, 2> parts = split_set_off(step, before, set_off_lead(step));
    return body->hits(parts[0]) || body->hits(parts[1]);
  };
  if (!hits()) return true;
  if (step.behavior != Behavior::kWalk) return false;
  step.behavior = Behavior::kArmsIn;
  if (!hits()) return true;
  step.behavior = Behavior::kWalk;
  return false;
}

// On ground, also steps as short as a stair's tread (0.25-0.35 m): one
// tread a step, at people's pace on stairs.
constexpr Gait kStairGaits[] = {{0.5, 0.6}, {0.4, 0.65}};

using planner::detail::kPivotTurn;
using planner::detail::kFacingTolerance;
using planner::detail::kSideStepSpeed;

ValidityChecker::ValidityChecker(const CharacterParams& character, const PlannerParams& planner,
                                 const ObstacleMap& obstacles, const Ground* ground)
    : impl_(std::make_unique<const Impl>(character, planner, obstacles, ground)) {}

ValidityChecker::~ValidityChecker() = default;

const CharacterParams& ValidityChecker::character() const { return impl_->character_; }
const PlannerParams& ValidityChecker::params() const { return impl_->params_; }
bool ValidityChecker::collides(const FootstepState& state, const WholeBody* whole) const {
  return impl_->collides(state, whole);
}
bool ValidityChecker::collides(const Footstep& step, const MovingObstacles& others) const {
  return impl_->collides(step, others);
}
Rest ValidityChecker::come_to_rest(const FootstepState& state, const MovingObstacles& others,
                                   const WholeBody* whole) const {
  return impl_->come_to_rest(state, others, whole);
}
Rest ValidityChecker::turn_to(const FootstepState& standing, double facing, const MovingObstacles& others,
                              const WholeBody* whole) const {
  return impl_->turn_to(standing, facing, others, whole);
}
bool ValidityChecker::stands_clear(const FootstepState& state, const MovingObstacles& others) const {
  return impl_->stands_clear(state, others);
}
std::vector<char> ValidityChecker::stands_clear_of_each(const FootstepState& state,
                                                        const MovingObstacles& others) const {
  return impl_->stands_clear_of_each(state, others);
}
std::vector<std::size_t> ValidityChecker::standing_clear(const std::vector<FootstepState>& states,
                                                         const MovingObstacles& others,
                                                         std::size_t at_most) const {
  return impl_->standing_clear(states, others, at_most);
}
bool ValidityChecker::room_to_turn(Vec2 com) const { return impl_->room_to_turn(com); }
bool ValidityChecker::keeps_out(const FootstepState& rested, const KeepOut& keep_out) const {
  return impl_->keeps_out(rested, keep_out);
}
bool ValidityChecker::free_to_set_off(const FootstepState& rested, const WholeBody* whole) const {
  return impl_->free_to_set_off(rested, whole);
}
StepResult ValidityChecker::stop_step(const FootstepState& state, double duration,
                                      const MovingObstacles& others, const WholeBody* whole) const {
  return impl_->stop_step(state, duration, others, whole);
}
StepResult ValidityChecker::stop_step(const FootstepState& state,
                                      const MovingObstacles& others) const {
  return impl_->stop_step(state, others);
}
bool ValidityChecker::hits_obstacles(const Footstep& step) const {
  return impl_->hits_obstacles(step);
}
bool ValidityChecker::off_ground(const Footstep& step, const FootstepState& before) const {
  return impl_->off_ground(step, before);
}
bool ValidityChecker::on_ground() const { return impl_->on_ground(); }
FootstepState ValidityChecker::standing(Vec2 position, double facing,
                                        std::optional<double> height) const {
  if (!impl_->on_ground()) return standing_state(position, facing, impl_->character_);
  return standing_on_ground(*impl_->ground_, impl_->character_, position, facing, height);
}

ValidityChecker::Impl::Impl(const CharacterParams& character, const PlannerParams& planner,
                            const ObstacleMap& obstacles, const Ground* ground)
    : character_(character),
      params_(planner),
      obstacles_(obstacles),
      ground_(ground != nullptr && !ground->empty() ? ground : nullptr) {
  validate(character_);
  validate(params_);
  std::vector<Gait> gaits = params_.gaits;
  if (ground_ != nullptr) gaits.insert(gaits.end(), std::begin(kStairGaits), std::end(kStairGaits));
  for (const Gait& gait : gaits) {
    for (const double turn : params_.turn_angles) {
      TabledAction action{detail::step_shape(gait.speed, gait.duration, turn, character_), {}};
      action.allowed[0] =
          detail::check_limits(action.shape, character_.left) == StepValidity::kValid;
      action.allowed[1] =
          detail::check_limits(action.shape, character_.right) == StepValidity::kValid;
      if (action.allowed[0] || action.allowed[1]) actions_.push_back(action);
    }
  }
  for (const Circle& circle : torso_circles({0.0, 0.0}, 0.0, character_))
    torso_extent_ = std::max(torso_extent_, length(circle.center) + circle.radius);
}

bool ValidityChecker::Impl::collides(const FootstepState& state, const WholeBody* whole) const {
  for (const Vec2& foot : state.feet) {
    if (obstacles_.overlaps({foot, character_.foot_radius})) return true;
  }
  const auto torso = torso_circles(state.com, state.facing, character_);
  const std::size_t circles = whole != nullptr && whole->shoulders_in_3d() ? 1 : torso.size();
  for (std::size_t c = 0; c < circles; ++c)
    if (obstacles_.overlaps(torso[c])) return true;
  return false;
}

bool ValidityChecker::Impl::collides(const Footstep& step, const MovingObstacles& others) const {
  return collides(step, sampled(others, character_, step.start_time), false);
}

bool ValidityChecker::Impl::collides(const Footstep& step, detail::SampledAgents& others,
                               bool from_standing, bool shoulders_in_3d) const {
  // Agents first: in a crowd they turn down most candidate steps.
  return touches_agents(step, others, from_standing) || hits_obstacles(step, shoulders_in_3d);
}

bool ValidityChecker::Impl::hits_obstacles(const Footstep& step, bool shoulders_in_3d) const {
  if (obstacles_.overlaps({step.foot_position, character_.foot_radius})) return true;
  // Samples no further apart along the COM path than `spacing`: the path is
  // never longer than the top speed times the time between samples.
  const double top_speed = footfall::top_speed(step);
  const double spacing = params_.collision_sample_spacing;
  // The circles are grown by half the spacing, the COM's travel to the
  // nearest sample. A step that does not move the COM (a wait, or a pivot,
  // whose shoulders swing within the room to turn its rest kept) needs none:
  // grown, a pivot by a wall it stands 0.3 m from would never be clear.
  const double pad = top_speed > 0.0 ? 0.5 * spacing : 0.0;
  thread_local std::vector<int> near;
  near.clear();
  obstacles_.gather(sweep_bound(step, character_, pad), near);
  if (near.empty()) return false;
  const int samples =
      std::max(1, static_cast<int>(std::ceil(top_speed * step.duration() / spacing)));
  const double dt = step.duration() / samples;
  // The torso keeps its facing through the step: its circles' offsets from
  // the COM are found once.
  const auto torso = torso_circles({0.0, 0.0}, step.phi, character_, pad, step.behavior);
  const std::size_t circles = shoulders_in_3d ? 1 : torso.size();
  for (int i = 0; i <= samples; ++i) {
    const Vec2 com = com_at(step, step.start_time + dt * i).position;
    for (std::size_t c = 0; c < circles; ++c)
      if (obstacles_.first_overlap({com + torso[c].center, torso[c].radius}, near) >= 0)
        return true;
  }
  return false;
}

FootholdFault ValidityChecker::Impl::foothold(const Footstep& step,
                                              const FootstepState& before) const {
  if (ground_ == nullptr) return FootholdFault::kNone;
  const int planted = static_cast<int>(step.foot);
  const auto at = [&](int foot) {
    return Vec3{before.feet[foot].x, before.feet[foot].y, before.foot_heights[foot]};
  };
  return foothold_fault(*ground_, character_, step.foot_position, step.orientation_interval,
                        at(1 - planted), at(planted));
}

double ValidityChecker::Impl::ground_height(Vec2 p, double near) const {
  const std::optional<GroundPoint> under = foothold_level(*ground_, character_, p, near);
  return under ? under->z : 0.0;
}

double ValidityChecker::Impl::ground_cost(const Footstep& step, const FootstepState& before) const {
  if (ground_ == nullptr) return 0.0;
  const double rise = step.foot_height - before.foot_heights[1 - static_cast<int>(step.foot)];
  return terrain_cost(character_.mass, distance(step.com_start, step.com_end), rise);
}

double ValidityChecker::Impl::climb_cost(Vec2 from, double z, Vec2 to) const {
  if (ground_ == nullptr) return 0.0;
  constexpr double kSpacing = 0.5;  // [m]
  const int pieces = std::max(1, static_cast<int>(std::ceil(distance(from, to) / kSpacing)));
  double ascent = 0.0, before = ground_height(from, z);
  for (int k = 1; k <= pieces; ++k) {
    const double here =
        ground_height(from + (static_cast<double>(k) / pieces) * (to - from), before);
    ascent += std::max(0.0, here - before);
    before = here;
  }
  return terrain_cost(character_.mass, 0.0, ascent);
}

bool ValidityChecker::Impl::touches_agents(const Footstep& step, detail::SampledAgents& others,
                                     bool from_standing) const {
  // The contact instants while the step is under way; the one at its end
  // belongs to the next step.
  const long first = first_contact_instant(step.start_time);
  const long last = first_contact_instant(step.end_time) - 1;
  if (others.size() == 0 || last < first) return false;
  // Agents that cannot come near the step at one of its instants are left out
  // before sampling: between the middle instant and the step's ends, a COM
  // moves at most at the top speed of its plan, and its circles reach no
  // farther from it than its plan's circle_reach.
  const long middle = first + (last - first) / 2;
  const double span = static_cast<double>(last - middle) * kContactDt;
  const Circle sweep = sweep_bound(step, character_, 0.0);
  const Circle foot{step.foot_position, character_.foot_radius};
  const double my_reach = std::max(sweep.radius, distance(foot.center, sweep.center) + foot.radius);
  const double my_top_speed = top_speed(step);
  const auto may_come_near = [&](std::size_t j) {
    const PlanBounds::From& bounds = others.bounds(j);
    const double pad = 0.5 * (my_top_speed + bounds.top_speed) * kContactDt;
    const double close = my_reach + bounds.reach + pad;
    // Its COM keeps out of a box: far from that, it needs no sample.
    if (squared_distance(bounds.com_box, {sweep.center, sweep.center}) > close * close)
      return false;
    const double reach = close + bounds.top_speed * span;
    const Vec2 d = others.at(j, middle).com - sweep.center;
    return dot(d, d) <= reach * reach;
  };
  // The character at each instant, sampled when first wanted: COM, speed,
  // torso circles, and how far those and the foot reach from the COM.
  struct Instant {
    bool sampled = false;
    Vec2 com;
    double speed = 0.0;
    std::array<Circle, 3> torso;
    double extent = 0.0;
  };
  thread_local std::vector<Instant> mine;
  mine.assign(static_cast<std::size_t>(last - first + 1), Instant{});
  const auto torso_offsets =
      torso_circles({0.0, 0.0}, step.phi, character_, 0.0, torso_width_of(step));  // as above
  const auto instant = [&](long k) -> const Instant& {
    Instant& sample = mine[static_cast<std::size_t>(k - first)];
    if (!sample.sampled) {
      const ComSample me = com_at(step, static_cast<double>(k) * kContactDt);
      sample = {true, me.position, length(me.velocity), torso_offsets,
                std::max(torso_extent_, distance(foot.center, me.position) + foot.radius)};
      for (Circle& circle : sample.torso) circle.center = me.position + circle.center;
    }
    return sample;
  };
  // A step from standing that starts on an instant starts where the
  // character stood: it stood still there, whatever speed the step sets off at.
  const bool stood_at_first =
      from_standing && std::fabs(static_cast<double>(first) * kContactDt - step.start_time) < 1e-9;
  // True if the character touches agent j at instant k, if j counts then
  // (up to `counted_until`; its circles reach `reach`); the first instant
  // sets `start_gap` (see touching()), which the later ones need.
  const auto touches_at = [&](std::size_t j, long k, double counted_until, double reach,
                              double& start_gap) {
    const detail::AgentWhere& them = others.at(j, k);
    if (!them.present || static_cast<double>(k) * kContactDt > counted_until ||
        levels_apart(them.ground, step.foot_height, character_.body_height))
      return false;
    const Instant& me = instant(k);
    // Both move between instants: the circles are grown by half the travel.
    const double pad = 0.5 * (me.speed + them.speed) * kContactDt;
    const Vec2 between = me.com - them.com;
    const double near = me.extent + reach + pad;
    if (dot(between, between) > near * near) return false;
    const detail::AgentShape& shape = others.shape(j, k);
    // Too far apart for any pair of circles to come within the padding; at
    // the first instant the gap is still wanted for the exception below.
    const double apart = length(between) - me.extent - shape.extent - pad;
    if (k != first && apart > 0.0) return false;
    Gap gap;  // of the torso: the foot is put down clear of everyone, standing close or not
    for (int i = 0; i < shape.count; ++i) {
      const Circle& theirs = shape.circles[i];
      const Vec2 to_foot = foot.center - theirs.center;
      const double foot_touch = foot.radius + theirs.radius + pad;
      if (dot(to_foot, to_foot) <= foot_touch * foot_touch) return true;
      for (const Circle& circle : me.torso) gap.add(circle, theirs, pad);
    }
    if (k == first && standing_still(stood_at_first ? 0.0 : me.speed, them.speed))
      start_gap = gap.outright;
    return touching(gap, start_gap);
  };
  // After the first instant, the last: a step turned down mostly walks into
  // someone as it ends (the one ahead in a queue). Then those between. (One
  // call in one loop, which the compiler inlines.)
  const auto touches = [&](std::size_t j) {
    const double until = others.counted_until(j), reach = others.bounds(j).reach;
    double start_gap = std::numeric_limits<double>::infinity();
    for (long n = 0; n <= last - first; ++n) {
      const long k = n == 0 ? first : n == 1 ? last : first + n - 1;
      if (touches_at(j, k, until, reach, start_gap)) return true;
    }
    return false;
  };
  // The agent that turned down the last step checked is tried first: a
  // search's candidates, siblings and cousins, mostly run into the same one.
  const std::size_t blocker = others.blocker();
  if (blocker < others.size() && may_come_near(blocker) && touches(blocker)) return true;
  for (std::size_t j = 0; j < others.size(); ++j) {
    if (j != blocker && may_come_near(j) && touches(j)) {
      others.turned_down_by(j);
      return true;
    }
  }
  return false;
}

bool ValidityChecker::Impl::step_touches_agents(const Footstep& step, const FootstepState& before,
                                                detail::SampledAgents& others) const {
  if (touches_agents(step, others, before.standing())) return true;
  if (step.kind != StepKind::kStop) return false;
  Footstep held = step;
  held.foot = other(step.foot);
  held.foot_position = before.feet[static_cast<int>(held.foot)];
  return touches_agents(held, others, before.standing());
}

Rest ValidityChecker::Impl::come_to_rest(const FootstepState& state,
                                   const MovingObstacles& others, const WholeBody* whole) const {
  return come_to_rest(state, sampled(others, character_, state.time), whole);
}

Rest ValidityChecker::Impl::come_to_rest(const FootstepState& state,
                                   detail::SampledAgents& others, const WholeBody* whole) const {
  Rest rest{{}, state, false};
  const auto stop = [&] {
    double duration = params_.stop_duration;
    for (int attempt = 0; attempt < 4; ++attempt, duration *= 0.5) {
      const StepResult step = stop_step(rest.state, duration, others, whole);
      if (step.valid()) {
        rest.steps.push_back(step.step);
        rest.state = step.state;
        return true;
      }
    }
    return false;
  };
  rest.complete = (rest.state.standing() || stop()) && stop() && stands_clear(rest.state, others);
  return rest;
}

Rest ValidityChecker::Impl::turn_to(const FootstepState& standing, double facing,
                                    const MovingObstacles& others, const WholeBody* whole) const {
  Rest turned{{}, standing, true};
  detail::SampledAgents& samples = sampled(others, character_, standing.time);
  // Turns of at most kPivotTurn, which each foot can follow from the other,
  // then a stop of each foot so that both point the new way. (Both angles
  // wrapped first: a facing of 1e20 rad would swallow the one subtracted.)
  const double target = wrap_angle(facing);
  int closing = std::fabs(wrap_angle(target - wrap_angle(standing.facing))) > kFacingTolerance ? 2 : 0;
  for (double left = wrap_angle(target - wrap_angle(standing.facing));
       std::fabs(left) > kFacingTolerance || closing-- > 0;
       left = wrap_angle(target - wrap_angle(turned.state.facing))) {
    const double turn = std::clamp(left, -kPivotTurn, kPivotTurn);
    const StepResult pivot = stop_step(turned.state, wrap_angle(turned.state.facing + turn),
                                       params_.stop_duration, samples, whole);
    if (!pivot.valid()) {
      turned.complete = false;
      break;
    }
    turned.steps.push_back(pivot.step);
    turned.state = pivot.state;
  }
  return turned;
}

bool ValidityChecker::Impl::stands_clear(const FootstepState& state,
                                   const MovingObstacles& others) const {
  return stands_clear(state, sampled(others, character_, state.time));
}

bool ValidityChecker::Impl::stands_clear(const FootstepState& state,
                                   detail::SampledAgents& others) const {
  const StandingCheck check(state, character_);
  // As in touches_agents: the agent that turned down the last check first.
  const std::size_t blocker = others.blocker();
  if (blocker < others.size() && check.touches(others, blocker)) return false;
  for (std::size_t j = 0; j < others.size(); ++j) {
    if (j != blocker && check.touches(others, j)) {
      others.turned_down_by(j);
      return false;
    }
  }
  return true;
}

std::vector<char> ValidityChecker::Impl::stands_clear_of_each(const FootstepState& state,
                                                        const MovingObstacles& others) const {
  detail::SampledAgents& samples = sampled(others, character_, state.time);
  const StandingCheck check(state, character_);
  std::vector<char> clear(others.size());
  for (std::size_t j = 0; j < others.size(); ++j) clear[j] = !check.touches(samples, j);
  return clear;
}

std::vector<std::size_t> ValidityChecker::Impl::standing_clear(const std::vector<FootstepState>& states,
                                                         const MovingObstacles& others,
                                                         std::size_t at_most) const {
  std::vector<std::size_t> clear;
  if (states.empty()) return clear;
  detail::SampledAgents& samples = sampled(others, character_, states.front().time);
  for (std::size_t k = 0; k < states.size() && clear.size() < at_most; ++k)
    if (stands_clear(states[k], samples)) clear.push_back(k);
  return clear;
}

bool ValidityChecker::Impl::rests_well(const FootstepState& state, detail::SampledAgents& others,
                                 const KeepOut& keep_out, const WholeBody* whole) const {
  const Rest rest = come_to_rest(state, others, whole);
  return rest.complete && keeps_out(rest.state, keep_out) && free_to_set_off(rest.state, whole);
}

bool ValidityChecker::Impl::room_to_turn(Vec2 com) const {
  return !obstacles_.overlaps({com, 0.5 * character_.torso_width});
}

bool ValidityChecker::Impl::keeps_out(const FootstepState& rested, const KeepOut& keep_out) const {
  if (keep_out.empty()) return true;
  const auto torso = torso_circles(rested.com, rested.facing, character_);
  const std::array<Circle, 5> mine{Circle{rested.feet[0], character_.foot_radius},
                                   Circle{rested.feet[1], character_.foot_radius}, torso[0],
                                   torso[1], torso[2]};
  double reach = 0.0;  // of the circles from the COM, with a margin for rounding
  for (const Circle& circle : mine)
    reach = std::max(reach, distance(circle.center, rested.com) + circle.radius + 1e-9);
  for (const Circle& disc : keep_out) {
    const Vec2 d = disc.center - rested.com;
    if (dot(d, d) >= (reach + disc.radius) * (reach + disc.radius)) continue;  // far from all
    for (const Circle& circle : mine)
      if (distance(circle.center, disc.center) < circle.radius + disc.radius) return false;
  }
  return true;
}

StepResult ValidityChecker::Impl::stop_step(const FootstepState& state, double duration,
                                      const MovingObstacles& others, const WholeBody* whole) const {
  return stop_step(state, duration, sampled(others, character_, state.time), whole);
}

StepResult ValidityChecker::Impl::stop_step(const FootstepState& state, double duration,
                                      detail::SampledAgents& others, const WholeBody* whole) const {
  return stop_step(state, state.facing, duration, others, whole);
}

StepResult ValidityChecker::Impl::stop_step(const FootstepState& state, double facing, double duration,
                                      detail::SampledAgents& others, const WholeBody* whole) const {
  StepResult stop = create_footstep(
      state, {StepKind::kStop, other(state.last_foot), facing, 0.0, duration}, character_);
  if (!stop.valid()) return stop;
  place_on_ground(stop.step, state, stop.state);
  stop.step.cost.terrain = ground_cost(stop.step, state);
  if (whole != nullptr) whole->label(stop.step);  // a stop goes anywhere
  if (step_touches_agents(stop.step, state, others) ||
      blocked(stop.step, state, whole != nullptr && whole->shoulders_in_3d()) ||
      (whole != nullptr && !whole->passes(stop.step, state)))
    stop.validity = StepValidity::kCollides;
  return stop;
}

StepResult ValidityChecker::Impl::stop_step(const FootstepState& state,
                                      const MovingObstacles& others) const {
  return stop_step(state, params_.stop_duration, others, nullptr);
}

StepResult ValidityChecker::Impl::side_step(const FootstepState& standing, double way) const {
  return create_footstep(
      standing,
      {StepKind::kSideStep, other(standing.last_foot), way, kSideStepSpeed, params_.stop_duration},
      character_);
}

bool ValidityChecker::Impl::free_to_set_off(const FootstepState& rested,
                                             const WholeBody* whole) const {
  const bool in_3d = whole != nullptr && whole->shoulders_in_3d();
  if (in_3d ? collides(rested, whole) : !room_to_turn(rested.com)) return false;
  const auto clear = [&](StepResult step, double, const detail::StepShape&) {
    if (!step.valid() || (whole != nullptr && !whole->label(step.step))) return false;
    place_on_ground(step.step, rested, step.state);
    return !blocked(step.step, rested, in_3d) &&
           (whole == nullptr || whole->passes(step.step, rested));
  };
  if (tabled_walks(rested, Foot::kLeft, clear) || tabled_walks(rested, Foot::kRight, clear))
    return true;
  // Or a side step, or a pivot toward a way out (the steps' checks pad the
  // torso, so room to turn alone does not promise one). Not a pivot where
  // the shoulders are judged in 3-D: in a pocket between boxes a standing
  // body may turn where no step leads out.
  const double across = rested.facing + outward_sign(other(rested.last_foot)) * 0.5 * kPi;
  if (clear(side_step(rested, across), 0.0, {})) return true;
  if (in_3d) return false;
  for (const double turn : {kPivotTurn, -kPivotTurn, kMaxPivot, -kMaxPivot}) {
    const StepResult pivot = create_footstep(rested,
                                             {StepKind::kStop, other(rested.last_foot),
                                              rested.facing + turn, 0.0, params_.stop_duration},
                                             character_);
    if (clear(pivot, 0.0, {})) return true;
  }
  return false;
}

}  // namespace footfall
