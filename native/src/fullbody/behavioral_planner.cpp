// Footfall — Algorithms 1 and 2 of the behavioural path planner, with the
// choices the paper leaves open made as docs/full-body.md describes.
#include "footfall/fullbody/behavioral_planner.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "footfall/fullbody/body_sweep.hpp"
#include "footfall/model/polyline.hpp"

namespace footfall {

const char* to_string(BehaviorPathStatus status) {
  switch (status) {
    case BehaviorPathStatus::kFound:
      return "found";
    case BehaviorPathStatus::kHorizon:
      return "horizon";
    case BehaviorPathStatus::kTimeLimit:
      return "time_limit";
    case BehaviorPathStatus::kNoPath:
      return "no_path";
    case BehaviorPathStatus::kStartBlocked:
      return "start_blocked";
    case BehaviorPathStatus::kGoalBlocked:
      return "goal_blocked";
    case BehaviorPathStatus::kOutside:
      return "outside";
  }
  return "?";
}

namespace {

/// A query inserts at most this many point obstacles: each bends the path a
/// little, and a place no behaviour passes could take them without end.
constexpr int kMaxPointObstacles = 64;
/// A contact this close to the last one, at the same obstacle, is the same:
/// the point obstacle before it did not move the path there. [m]
constexpr double kSameContact = 0.01;
/// Lengths closer than this are the same place. [m]
constexpr double kSamePlace = 1e-9;

using Clock = std::chrono::steady_clock;

// One run of Algorithm 1; owns the point obstacles it inserts.
class Query {
 public:
  Query(NavMesh& mesh, const CollisionScene& scene, const BodyModel& body,
        const PlannerParams& params)
      : mesh_(mesh),
        scene_(scene),
        body_(body),
        params_(params),
        deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(params.behavior_time_limit))),
        c1_(body.clearance(Behavior::kSideStep)),
        walk_reach_(body.step_duration(Behavior::kWalk) * body.speed(Behavior::kWalk)) {}
  ~Query() {
    for (const PointObstacle& point : points_) mesh_.remove(point.id);
  }
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;

  BehaviorPath run(Vec2 from, Vec2 to);

 private:
  PathResult find(double radius, Vec2 a, Vec2 b) {
    ++result_.path_queries;
    PathQuery query;
    query.from = a;
    query.to = b;
    query.radius = radius;
    return mesh_.find_path(query);
  }
  BodyCollision test(Behavior behavior, const Polyline& path, double from, double to,
                     double start_time = 0) {
    return sweep_body(scene_, body_, behavior, path, from, to, start_time, params_.pose_rate,
                      result_.poses_tested);
  }
  // FINDPATH(c1) again around a contact `along` the current path: from a
  // step before it to two walking cycles past it, the rest of the path kept
  // (a local repair: detours are short, l_t at most, and a query is dearer
  // the farther it goes); from the start to the goal where the window's
  // ends are blocked.
  PathResult find_around(const Polyline& current, double along);
  // Walking along `path` from `from` (a step boundary) to its end.
  BodyCollision test_walk(const Polyline& path, double from) {
    return test(Behavior::kWalk, path, from, path.length(), from / body_.speed(Behavior::kWalk));
  }
  // The last walking step boundary at or before `along`. [m]
  double walk_boundary(double along) const {
    return std::floor(along / walk_reach_ + 1e-9) * walk_reach_;
  }
  // A point obstacle between the contact's floor projection and the root.
  void insert_point(const BodyCollision& hit) {
    const Vec2 contact = ground(hit.contact.point);
    const Vec2 at = contact + params_.point_obstacle_fraction * (hit.root - contact);
    points_.push_back({mesh_.add_point(at), at});
    ++result_.point_obstacles;
  }
  void remove_last_point() {
    mesh_.remove(points_.back().id);
    points_.pop_back();
  }
  // Takes out the point obstacles within `radius` of `place`; true if any.
  bool remove_points_near(Vec2 place, double radius);
  // Appends a section, merged into the last if it has the same behaviour
  // and the merged one passes.
  void append(Behavior behavior, double clearance, std::vector<Vec2> points);
  // FURTHEST: how far along `path` walking goes before the step that hits.
  double furthest(const BodyCollision& hit) const;
  // CLOSEST: the nearest step boundary past `q` up to which `behavior` passes
  // and after which walking can go on for a step (or to the end); if
  // `behavior` meets something else past `beyond` (where walking failed),
  // the last boundary before it; false if it fails before `beyond`.
  bool closest(const Polyline& path, double q, double beyond, Behavior behavior, double& r);
  // Switches to `behavior` at `q` along `current`, trying first the way on
  // with the behaviour's own clearance (centred in tall passages), then
  // `current` itself; on success appends the walk up to q and the
  // behaviour's section, and leaves in `current` the rest of the way.
  bool switch_to(Behavior behavior, Polyline& current, double q, double beyond, Vec2 goal);
  std::string blocked_at(const BodyCollision& hit) const;

  NavMesh& mesh_;
  const CollisionScene& scene_;
  const BodyModel& body_;
  const PlannerParams& params_;
  Clock::time_point deadline_;
  double c1_;
  double walk_reach_;  // a walking step's travel: "near" for point obstacles [m]
  struct PointObstacle {
    int id;
    Vec2 at;
  };
  std::vector<PointObstacle> points_;
  BehaviorPath result_;
};

void Query::append(Behavior behavior, double clearance, std::vector<Vec2> points) {
  const double length = polyline_length(points);
  if (length <= kSamePlace) return;
  auto& sections = result_.sections;
  if (!sections.empty() && sections.back().behavior == behavior) {
    // One section if the motion passes the two in one go (its phase runs on
    // across the join), else two.
    std::vector<Vec2> joined = sections.back().points;
    joined.insert(joined.end(), points.begin() + 1, points.end());
    const Polyline whole(joined);
    if (!test(behavior, whole, 0, whole.length()).hit) {
      BehaviorSection& last = sections.back();
      last.points = std::move(joined);
      last.length += length;
      last.clearance = std::min(last.clearance, clearance);
      return;
    }
  }
  sections.push_back({behavior, clearance, std::move(points), length});
}

PathResult Query::find_around(const Polyline& current, double along) {
  const double a = std::max(0.0, walk_boundary(along) - walk_reach_);
  const double b = std::min(current.length(), along + 4 * walk_reach_);
  PathResult window = find(c1_, current.point_at(a), current.point_at(b));
  if (window.status == PathStatus::kStartBlocked || window.status == PathStatus::kGoalBlocked)
    return find(c1_, current.points().front(), current.points().back());
  if (window.status != PathStatus::kFound) return window;
  PathResult whole;
  whole.status = PathStatus::kFound;
  whole.points = current.between(0, a);
  whole.points.insert(whole.points.end(), window.points.begin() + 1, window.points.end());
  const std::vector<Vec2> rest = current.between(b, current.length());
  whole.points.insert(whole.points.end(), rest.begin() + 1, rest.end());
  whole.length = polyline_length(whole.points);
  return whole;
}

// How far two paths from the same start run over the same points. [m]
double common_prefix(const Polyline& a, const Polyline& b) {
  const auto& p = a.points();
  const auto& q = b.points();
  double along = 0;
  for (std::size_t k = 1; k < std::min(p.size(), q.size()) && p[k] == q[k]; ++k)
    along += distance(p[k - 1], p[k]);
  return along;
}

bool Query::remove_points_near(Vec2 place, double radius) {
  const auto near = [&](const PointObstacle& p) { return distance(p.at, place) <= radius; };
  bool any = false;
  for (const PointObstacle& p : points_) {
    if (!near(p)) continue;
    mesh_.remove(p.id);
    any = true;
  }
  points_.erase(std::remove_if(points_.begin(), points_.end(), near), points_.end());
  return any;
}

double Query::furthest(const BodyCollision& hit) const {
  // The last boundary strictly before the contact: a contact at a boundary
  // belongs to the step that ends there.
  const double step = body_.step_duration(Behavior::kWalk);
  const double steps = std::max(0.0, std::ceil(hit.time / step) - 1);
  return std::min(hit.along, steps * step * body_.speed(Behavior::kWalk));
}

bool Query::closest(const Polyline& path, double q, double beyond, Behavior behavior,
                    double& r) {
  const double step = body_.step_duration(behavior);
  const double stride = step * body_.speed(behavior);
  const double walk_step = body_.step_duration(Behavior::kWalk) * body_.speed(Behavior::kWalk);
  const double end = path.length();
  double at = q;
  for (long long k = 1; at < end - kSamePlace; ++k) {
    const double next = std::min(q + static_cast<double>(k) * stride, end);
    if (test(behavior, path, at, next, static_cast<double>(k - 1) * step).hit) {
      // Past the place walking failed, the section may end before this new
      // contact: the next round handles it as it handled the first.
      if (at <= beyond + kSamePlace) return false;
      r = at;
      return true;
    }
    if (next >= end - kSamePlace ||
        !test(Behavior::kWalk, path, next, std::min(next + walk_step, end)).hit) {
      r = next;
      return true;
    }
    at = next;
  }
  r = end;
  return true;
}

bool Query::switch_to(Behavior behavior, Polyline& current, double q, double beyond,
                      Vec2 goal) {
  const Vec2 from = current.point_at(q);
  const double clearance = body_.clearance(behavior);
  const PathResult own = find(clearance, from, goal);
  double r = 0;
  if (own.status == PathStatus::kFound &&
      own.length <= current.length() - q + params_.detour_limit) {
    Polyline path(own.points);
    if (closest(path, 0, beyond - q, behavior, r)) {
      append(Behavior::kWalk, c1_, current.between(0, q));
      append(behavior, clearance, path.between(0, r));
      current = Polyline(path.between(r, path.length()));
      return true;
    }
  }
  if (!closest(current, q, beyond, behavior, r)) return false;
  append(Behavior::kWalk, c1_, current.between(0, q));
  append(behavior, c1_, current.between(q, r));
  current = Polyline(current.between(r, current.length()));
  return true;
}

std::string Query::blocked_at(const BodyCollision& hit) const {
  std::ostringstream message;
  message.precision(4);
  message << "no behaviour passes at (" << hit.root.x << ", " << hit.root.y << "): the "
          << to_string(static_cast<Limb>(hit.contact.limb)) << " meets obstacles["
          << hit.contact.obstacle << "]";
  return message.str();
}

BehaviorPath Query::run(Vec2 from, Vec2 to) {
  const PathResult first = find(c1_, from, to);
  switch (first.status) {
    case PathStatus::kFound:
      break;
    case PathStatus::kNoPath:
      result_.status = BehaviorPathStatus::kNoPath;
      result_.reason = "no path with side-stepping's clearance c1";
      return result_;
    case PathStatus::kStartBlocked:
      result_.status = BehaviorPathStatus::kStartBlocked;
      return result_;
    case PathStatus::kGoalBlocked:
      result_.status = BehaviorPathStatus::kGoalBlocked;
      return result_;
    case PathStatus::kOutside:
      result_.status = BehaviorPathStatus::kOutside;
      return result_;
  }
  Polyline current(first.points);
  BehaviorPathStatus done = BehaviorPathStatus::kFound;
  if (current.length() > params_.behavior_horizon) {
    current = Polyline(current.between(0, params_.behavior_horizon));
    done = BehaviorPathStatus::kHorizon;
  }
  const Vec2 goal = current.points().back();
  // Walking is tested from `resume` on (a step boundary up to which the
  // current path is known to pass); a detour is measured against `stretch`,
  // the length of the way from where the current walking stretch started.
  double resume = 0, stretch = current.length();
  BodyCollision last_hit;
  const auto replace = [&](std::vector<Vec2> points, double hit_along) {
    Polyline next(std::move(points));
    resume = walk_boundary(std::min(common_prefix(current, next), hit_along));
    current = std::move(next);
  };
  while (current.length() > kSamePlace) {
    if (Clock::now() > deadline_) {
      append(Behavior::kSideStep, c1_, current.points());
      done = BehaviorPathStatus::kTimeLimit;
      break;
    }
    BodyCollision hit = test_walk(current, resume);
    if (!hit.hit) {
      append(Behavior::kWalk, c1_, current.points());
      break;
    }
    // Bend the path around the contact.
    PathResult detour;
    const bool unmoved = hit.contact.obstacle == last_hit.contact.obstacle &&
                         distance(hit.root, last_hit.root) < kSameContact;
    last_hit = hit;
    if (!unmoved && result_.point_obstacles < kMaxPointObstacles) {
      insert_point(hit);
      detour = find_around(current, hit.along);
      if (detour.status == PathStatus::kFound &&
          detour.length - stretch <= params_.detour_limit) {
        replace(std::move(detour.points), hit.along);
        continue;
      }
      remove_last_point();
    }
    // Too long. The point obstacles near here were tries at this same narrow
    // place, and would push the path against its sides: out with them.
    if (remove_points_near(hit.root, walk_reach_)) {
      PathResult again = find_around(current, hit.along);
      if (again.status == PathStatus::kFound) {
        replace(std::move(again.points), hit.along);
        hit = test_walk(current, resume);
        if (!hit.hit) continue;
      }
    }
    // Walk as far as walking goes, then the most preferred behaviour that
    // passes, back to walking where it can.
    const double q = furthest(hit);
    if (switch_to(Behavior::kArmsIn, current, q, hit.along, goal) ||
        switch_to(Behavior::kSideStep, current, q, hit.along, goal)) {
      resume = 0;
      stretch = current.length();
      continue;
    }
    // No behaviour passes here: a detour of any length beats none.
    if (!unmoved && result_.point_obstacles < kMaxPointObstacles) {
      insert_point(hit);
      detour = find_around(current, hit.along);
      if (detour.status == PathStatus::kFound) {
        replace(std::move(detour.points), hit.along);
        continue;
      }
    }
    result_.sections.clear();
    result_.status = BehaviorPathStatus::kNoPath;
    result_.reason = blocked_at(hit);
    return result_;
  }
  result_.status = done;
  for (const BehaviorSection& section : result_.sections) result_.length += section.length;
  return result_;
}

}  // namespace

BehavioralPlanner::BehavioralPlanner(NavMesh& mesh, const CollisionScene& scene,
                                     const BodyModel& body, const PlannerParams& params)
    : mesh_(mesh), scene_(scene), body_(body), params_(params) {
  validate(params_);
}

BehaviorPath BehavioralPlanner::plan(Vec2 from, Vec2 to) {
  BehaviorPath path = Query(mesh_, scene_, body_, params_).run(from, to);
  // Measured once the point obstacles are gone: on the scene's own mesh.
  if (!path.sections.empty()) path.min_clearance = std::numeric_limits<double>::infinity();
  for (const BehaviorSection& section : path.sections)
    for (std::size_t k = 1; k < section.points.size(); ++k)
      path.min_clearance = std::min(
          path.min_clearance, mesh_.clearance_between(section.points[k - 1], section.points[k]));
  return path;
}

}  // namespace footfall
