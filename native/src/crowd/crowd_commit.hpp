// Footfall — committing the crowd's new plans (crowd_planner.cpp). A new plan is
// committed only if it keeps clear of every other agent's plan, rest
// included, seen or not; otherwise the agent waits where its rest leaves it.
// The check against the plans of the view the search read is made on the
// threads, with the search (propose()); only the plans changed since (by a
// commit, or a wait) are checked again, in the agents' order (refusal()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "crowd/crowd_walker.hpp"
#include "crowd/trial.hpp"

namespace footfall::crowd {

/// Lets the agent's provisional rest happen (it is no longer provisional),
/// and if it would then stand before time `t`, has it stand until `t` (in
/// waits of kMaxWait at most: one woken after long stuck waits many): the
/// next steps start now, not in the past.
void rest_until(Walker& w, const FootstepPlanner& planner, double t);

/// Notes the way left, and when it last shortened by min_progress.
void progress(Walker& w, double way_left, const FootstepPlanner& planner);

/// An attempt as it would stand in its agent's plan, and what the commit
/// check finds against each agent near, in the view its search read. Made for every
/// due agent at once (on the workers): in the agents' order, only the plans
/// changed since need checking again (refusal()).
struct Proposal {
  std::vector<Footstep> steps;          ///< The attempt's steps, then (unless it leaves) its rest.
  FootstepState rested;                 ///< Where they leave the agent.
  bool leaving = false;                 ///< It walks on through its last goal.
  detail::Trial trial;                  ///< The plan with them in place of the old rest.
  bool new_place = false;               ///< It rests somewhere new: it needs room there.
  std::vector<std::size_t> close;       ///< The agents near (near()).
  std::vector<char> hits;               ///< Per close: the trial touches its plan.
  std::vector<char> no_room;            ///< Per close: no room to rest beside it (new_place).
  std::vector<std::uint64_t> versions;  ///< Per close: the version of the plan checked.
};

/// The trial that agent i's attempt makes, and its check against the plans
/// of the agents `close` as they stand now.
Proposal propose(const std::vector<Walker>& walkers, std::size_t i, const Attempt& a,
                 const FootstepPlanner& planner, std::vector<std::size_t> close,
                 const Snapshot& now);

/// The index in p.close of the agent the trial is refused for: the first it
/// touches, else (resting somewhere new) the first it has no room beside;
/// -1 if none. The plans changed since the proposal was made are checked anew.
int refusal(const std::vector<Walker>& walkers, Proposal& p, const FootstepPlanner& planner);

/// Adds the attempt's steps and a provisional rest after them to agent i's
/// plan, in place of its old rest, unless the proposal was refused (for
/// p.close[refused]); then the old rest happens and the agent waits there.
/// Then goals reached and progress.
void commit(std::vector<Walker>& walkers, std::size_t i, const Attempt& a, Proposal& p, int refused,
            const FootstepPlanner& planner, double t);

}  // namespace footfall::crowd
