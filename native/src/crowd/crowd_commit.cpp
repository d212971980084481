// Footfall — committing the crowd's new plans (crowd_commit.hpp).
#include "crowd/crowd_commit.hpp"

#include <algorithm>

namespace footfall::crowd {

namespace {

/// A wait of `duration` for walker w standing where its plan ends, in the
/// posture its last step holds: every other plan was checked against it
/// standing so past that end. Nothing moves, so nothing is checked (labelled
/// anew, a wait could stand side-on where its rest stood arms in, and fail).
/// On ground the foot keeps its height and orientations too: turned to the
/// facing, a sole on a tread may reach over its nosing or into the riser
/// behind.
StepResult stand_on(const Walker& w, const ValidityChecker& checks, double duration) {
  const FootstepAction wait_there{StepKind::kStop, other(w.state.last_foot), w.state.facing, 0.0,
                                  duration};
  StepResult wait = create_footstep(w.state, wait_there, checks.character());
  if (!w.plan.footsteps.empty()) wait.step.behavior = w.plan.footsteps.back().behavior;
  if (checks.on_ground()) {
    const int foot = static_cast<int>(wait.step.foot);
    wait.step.foot_height = wait.state.foot_heights[foot] = w.state.foot_heights[foot];
    wait.step.orientation_interval = wait.state.foot_orientation[foot] =
        w.state.foot_orientation[foot];
    wait.step.foot_orientation = w.state.foot_orientation[foot].inner;
  }
  return wait;
}

}  // namespace

void rest_until(Walker& w, const FootstepPlanner& planner, double t) {
  if (w.resting > 0) {
    w.state = w.rested;
    w.resting = 0;
  }
  const std::optional<WholeBody> following = planner.whole_body(w.following());
  bool waited = false;
  while (w.state.time < t) {
    const double duration = std::min(t - w.state.time, kMaxWait);
    const StepResult wait = w.state.standing()
                                ? stand_on(w, planner.validity(), duration)
                                : planner.validity().stop_step(w.state, duration, {},
                                                               following ? &*following : nullptr);
    if (!wait.valid()) break;
    w.plan.footsteps.push_back(wait.step);
    w.state = wait.state;
    waited = true;
  }
  if (waited) {
    w.bounds = std::make_shared<const PlanBounds>(w.plan, planner.character());
    w.samples = nullptr;
    ++w.version;
  }
}

void progress(Walker& w, double way_left, const FootstepPlanner& planner) {
  if (w.first_way == 0.0) w.first_way = way_left;
  if (way_left < w.best_way - planner.params().min_progress) {
    w.best_way = way_left;
    w.improved_at = w.state.time;
  }
}

Proposal propose(const std::vector<Walker>& walkers, std::size_t i, const Attempt& a,
                 const FootstepPlanner& planner, std::vector<std::size_t> close,
                 const Snapshot& now) {
  const Walker& w = walkers[i];
  Proposal p;
  p.close = std::move(close);
  p.steps = a.steps;
  p.rested = a.end;
  // One that leaves at its last goal walks on through it; the others come to rest.
  p.leaving = leaves_now(w, a.reached);
  if (!p.leaving) {
    p.steps.insert(p.steps.end(), a.rest.steps.begin(), a.rest.steps.end());
    p.rested = a.rest.state;
  }
  if (a.steps.empty()) return p;
  AgentPlan plan;
  plan.character = w.plan.character;
  plan.leaves = p.leaving;
  plan.start = w.plan.start;
  const std::size_t kept = w.plan.footsteps.size() - w.resting;
  plan.footsteps.assign(w.plan.footsteps.begin(), w.plan.footsteps.begin() + kept);
  plan.footsteps.insert(plan.footsteps.end(), p.steps.begin(), p.steps.end());
  // During the last kept step the free foot swings toward the next step's
  // foot (feet_at): that step's circles change with the new steps too.
  const double from = kept > 0 ? plan.footsteps[kept - 1].start_time : a.steps.front().start_time;
  p.trial = detail::Trial(std::move(plan), from, planner.character());
  // A new place to rest needs room among everyone, seen or not.
  p.new_place = !p.leaving && distance(p.rested.com, rest_of(w).com) > kSamePlace;
  const bool bounded = p.trial.from() >= now.bounds_from;
  for (const std::size_t j : p.close) p.versions.push_back(walkers[j].version);
  for (const std::size_t j : p.close)
    p.hits.push_back(
        !(bounded && p.trial.apart(now.bounds[j])) &&
        p.trial.touches(walkers[j].plan, *walkers[j].bounds, walkers[j].samples.get()));
  p.no_room.assign(p.close.size(), 0);
  if (p.new_place) {
    const std::vector<char> clear =
        planner.validity().stands_clear_of_each(p.rested, plans_of(walkers, p.close));
    for (std::size_t c = 0; c < clear.size(); ++c) p.no_room[c] = !clear[c];
  }
  return p;
}

int refusal(const std::vector<Walker>& walkers, Proposal& p, const FootstepPlanner& planner) {
  if (p.trial.plan().footsteps.empty()) return -1;
  const auto changed = [&](std::size_t c) { return walkers[p.close[c]].version != p.versions[c]; };
  for (std::size_t c = 0; c < p.close.size(); ++c) {
    const Walker& other = walkers[p.close[c]];
    if (changed(c) ? p.trial.touches(other.plan, *other.bounds, other.samples.get()) : p.hits[c])
      return static_cast<int>(c);
  }
  if (!p.new_place) return -1;
  for (std::size_t c = 0; c < p.close.size(); ++c) {
    if (changed(c) ? !planner.validity().stands_clear(p.rested, {obstacle_of(walkers[p.close[c]])})
                   : p.no_room[c])
      return static_cast<int>(c);
  }
  return -1;
}

void commit(std::vector<Walker>& walkers, std::size_t i, const Attempt& a, Proposal& p, int refused,
            const FootstepPlanner& planner, double t) {
  Walker& w = walkers[i];
  if (a.searched) {
    ++w.plan.searches;
    w.plan.nodes_generated += a.nodes_generated;
    w.plan.nodes_expanded += a.nodes_expanded;
  }
  if (refused >= 0) {
    if (std::find(w.noticed.begin(), w.noticed.end(), p.close[refused]) == w.noticed.end())
      w.noticed.push_back(p.close[refused]);
    w.news_at = t;
  }
  if (a.steps.empty() || refused >= 0) {
    rest_until(w, planner, t);
    w.retry_at = t + kRetryAfter * (1 << std::min(w.failures++, kMaxBackoff));
    if (!(a.reached && a.steps.empty())) {  // at the goal already, or waiting
      progress(w, w.best_way, planner);
      return;
    }
  } else {
    // Waiting on where it stands is no news to the others.
    if (!std::all_of(p.steps.begin(), p.steps.end(),
                     [&](const Footstep& step) { return still(step, w.state.facing); }))
      w.committed_at = t;
    w.failures = 0;
    // Those noticed stay in mind while they are near.
    const Vec2 here = com_at(w.plan, t).position;
    w.noticed.erase(std::remove_if(w.noticed.begin(), w.noticed.end(),
                                   [&](std::size_t j) {
                                     return distance(com_at(walkers[j].plan, t).position, here) >
                                            kNoticeDistance;
                                   }),
                    w.noticed.end());
    w.samples = std::make_shared<const PlanSamples>(p.trial.take_samples());
    w.plan.footsteps = std::move(p.trial.plan().footsteps);
    w.bounds = std::make_shared<const PlanBounds>(std::move(p.trial.bounds()));
    ++w.version;
    w.resting = p.steps.size() - a.steps.size();
    w.state = a.end;
    w.rested = p.rested;
  }
  if (!a.reached) {
    progress(w, a.way_left, planner);
    return;
  }
  ++w.plan.goals_reached;
  if (++w.goal == w.spec->goals.size()) {
    w.plan.status = AgentStatus::kReached;
    w.plan.leaves = w.spec->leave_at_goal;
    ++w.version;
    w.samples = nullptr;  // taken before it could leave at its goal
    w.done = true;
    return;
  }
  w.first_way = 0.0;
  w.best_way = std::numeric_limits<double>::infinity();
  // It stands at the goal for its wait (facing as asked, once it has
  // turned); its patience starts when it walks on.
  w.start_at = std::max(w.start_at, (a.turned ? w.rested.time : w.state.time) + w.spec->goal_wait);
  w.improved_at = std::max(w.state.time, w.start_at);
  w.roomy = false;
  w.stuck_times = 0;
}

}  // namespace footfall::crowd
