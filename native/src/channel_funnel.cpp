// Footfall — the funnel algorithm with circles at the corners (the "simple
// stupid funnel" over corners of radius r, Demyen's and Kallmann's extension).
#include "channel_funnel.hpp"

#include <cmath>
#include <optional>

namespace footfall {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A point the path wraps around: obstacle on the path's left (+1), right
/// (-1), or a bare point (start and goal, radius 0).
struct Corner {
  Vec2 center;
  double radius = 0.0;
  int side = 0;
  bool same(const Corner& o) const { return center == o.center && side == o.side; }
};

/// Direction and touch points of the line leaving `a` and arriving at `b`
/// that keeps each corner on its side; false if none exists.
bool tangent(const Corner& a, const Corner& b, Vec2& from, Vec2& to) {
  const Vec2 d = b.center - a.center;
  const double k = b.side * b.radius - a.side * a.radius;  // offset of b's touch point vs a's
  const double dd = dot(d, d);
  if (dd <= k * k || dd == 0.0) return false;
  const double run = std::sqrt(dd - k * k);
  const Vec2 dir = Vec2{run * d.x + k * d.y, run * d.y - k * d.x} * (1.0 / dd);
  const Vec2 left = perp(dir);  // each centre = touch point + side * radius * left
  from = a.center - a.side * a.radius * left;
  to = b.center - b.side * b.radius * left;
  return true;
}

Vec2 direction(const Corner& a, const Corner& b, bool& ok) {
  Vec2 from, to;
  ok = tangent(a, b, from, to) && ok;
  return to - from;
}

/// Appends the arc around `c` from touch point `p0` to `p1`, as the
/// circumscribed polygon, then `p1`.
void append_arc(const Corner& c, Vec2 p0, Vec2 p1, double tolerance, std::vector<Vec2>& out) {
  const double a0 = angle_of(p0 - c.center), a1 = angle_of(p1 - c.center);
  double sweep = c.side * (a1 - a0);  // left corners turn counter-clockwise
  while (sweep < 0) sweep += 2 * kPi;
  while (sweep >= 2 * kPi) sweep -= 2 * kPi;
  const double max_step = 2 * std::acos(c.radius / (c.radius + tolerance));
  const int n = static_cast<int>(std::ceil(sweep / max_step));
  if (n > 0 && sweep > 1e-12) {
    const double step = sweep / n, reach = c.radius / std::cos(step / 2);
    for (int k = 0; k < n; ++k)
      out.push_back(c.center + reach * unit(a0 + c.side * (k + 0.5) * step));
  }
  out.push_back(p1);
}

/// True if the way from `apex` to `target` (the tangent that keeps both on
/// their sides) passes `c` on the wrong side or nearer than its radius,
/// within the way's span.
bool blocks(const Corner& c, const Corner& apex, const Corner& target) {
  Vec2 from, to;
  if (!tangent(apex, target, from, to)) return true;
  const Vec2 way = to - from;
  const double len2 = dot(way, way);
  const double t = len2 > 0 ? dot(c.center - from, way) / len2 : 0.0;
  if (t <= 0 || t >= 1) return distance_to_segment(c.center, from, to) < c.radius;
  const double beside = c.side * cross(way, c.center - from) / std::sqrt(len2);  // > 0: its side
  return beside < c.radius;
}

/// Removes corners the path would wrap the wrong way round (a left corner
/// turned clockwise, or more than half a turn): with circles, two corners on
/// opposite sides can cross the funnel before a later, tighter corner of the
/// same side shows that the path bends there instead. What stays is taut,
/// every corner turned its own way.
void drop_wrong_turns(std::vector<Corner>& corners) {
  for (std::size_t k = 1; k + 1 < corners.size();) {
    bool ok = true;
    const Vec2 in = direction(corners[k - 1], corners[k], ok);
    const Vec2 out = direction(corners[k], corners[k + 1], ok);
    const double turn = corners[k].side * cross(in, out);
    if (ok && (turn > 0 || (turn == 0 && dot(in, out) > 0))) {
      ++k;
      continue;
    }
    if (!ok) return;  // no tangent at all: the funnel reports the channel too narrow
    corners.erase(corners.begin() + static_cast<long>(k));
    k = std::max<std::size_t>(1, k - 1);
  }
}

}  // namespace

FunnelPath funnel(Vec2 start, Vec2 goal, const std::vector<Portal>& portals, double radius,
                  double tolerance) {
  FunnelPath result;
  const int n = static_cast<int>(portals.size());
  auto left_of = [&](int i) {
    return i < n ? Corner{portals[i].left, radius, +1} : Corner{goal, 0.0, 0};
  };
  auto right_of = [&](int i) {
    return i < n ? Corner{portals[i].right, radius, -1} : Corner{goal, 0.0, 0};
  };
  std::vector<Corner> corners{{start, 0.0, 0}};
  Corner apex = corners.front(), left = apex, right = apex;
  int apex_index = -1, left_index = -1, right_index = -1;
  bool ok = true;
  // The corner on one side (+1 left, -1 right) that the way to the goal must
  // wrap, or none. The funnel's side corner, tested against its tangent line,
  // can lie beyond a goal that stops short of it; then an earlier corner of
  // that side, or none, is the one that blocks the way.
  auto blocking = [&](int side) -> std::optional<int> {
    std::optional<int> best;
    Vec2 best_direction;
    for (int k = apex_index + 1; k < n; ++k) {
      const Corner c = side > 0 ? left_of(k) : right_of(k);
      if (c.same(apex) || !blocks(c, apex, {goal, 0.0, 0})) continue;
      const Vec2 d = direction(apex, c, ok);
      if (!best || side * cross(best_direction, d) < 0) {
        best = k;
        best_direction = d;
      }
    }
    return best;
  };
  for (int i = 0; i <= n; ++i) {
    const Corner new_left = left_of(i), new_right = right_of(i);
    // Makes the corner of `side` at portal `k` the apex; the scan goes on
    // after it, or at it again when it is this portal's (for its other end).
    auto wrap = [&](int side, int k) {
      apex = side > 0 ? left_of(k) : right_of(k);
      corners.push_back(apex);
      left = right = apex;
      apex_index = left_index = right_index = k;
      i = k == i ? k - 1 : k;
    };
    // Tighten the right side, or let it cross the left: a left corner becomes the apex.
    if (new_right.same(apex)) {
      right = new_right;
      right_index = i;
    } else if (const Vec2 to_new_right = direction(apex, new_right, ok);
               right.same(apex) || right.same(new_right) ||
               cross(direction(apex, right, ok), to_new_right) >= 0) {
      if (left.same(apex) || cross(direction(apex, left, ok), to_new_right) <= 0) {
        right = new_right;
        right_index = i;
      } else if (i < n) {
        // Crossed: the left corner comes first, unless the new right one
        // stands in the way to it (with circles, either may).
        wrap(blocks(new_right, apex, left) ? -1 : +1, blocks(new_right, apex, left) ? i : left_index);
        continue;
      } else if (const std::optional<int> k = blocking(+1)) {
        wrap(+1, *k);
        continue;
      } else {
        break;  // the goal is in plain view
      }
    }
    if (new_left.same(apex)) {
      left = new_left;
      left_index = i;
    } else if (const Vec2 to_new_left = direction(apex, new_left, ok);
               left.same(apex) || left.same(new_left) ||
               cross(direction(apex, left, ok), to_new_left) <= 0) {
      if (right.same(apex) || cross(direction(apex, right, ok), to_new_left) >= 0) {
        left = new_left;
        left_index = i;
      } else if (i < n) {
        wrap(blocks(new_left, apex, right) ? +1 : -1, blocks(new_left, apex, right) ? i : right_index);
        continue;
      } else if (const std::optional<int> k = blocking(-1)) {
        wrap(-1, *k);
        continue;
      } else {
        break;
      }
    }
    if (!ok) {
      result.failed_portal = std::min(i, n - 1);
      return result;
    }
  }
  corners.push_back({goal, 0.0, 0});
  drop_wrong_turns(corners);
  result.points.push_back(start);
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    Vec2 from, to;
    if (!tangent(corners[k], corners[k + 1], from, to)) {
      result.failed_portal = n > 0 ? n - 1 : 0;
      return result;
    }
    if (k > 0) append_arc(corners[k], result.points.back(), from, tolerance, result.points);
    result.points.push_back(to);
  }
  result.ok = true;
  return result;
}

}  // namespace footfall
