// Footfall — the funnel algorithm with circles at the corners (the "simple
// stupid funnel" over corners of radius r, Demyen's and Kallmann's extension).
#include "channel_funnel.hpp"

#include <algorithm>
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
  int portal = -1;  ///< Index of the portal it ends (the goal: the portal count).
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

/// Where the path meets corner k's circle (`in`) and leaves it (`out`).
struct Touch {
  Vec2 in, out;
};

/// The touch points of the path through `corners`; false if two corners
/// leave no straight way between them.
bool touch_points(const std::vector<Corner>& corners, std::vector<Touch>& touches) {
  touches.assign(corners.size(), {});
  touches.front().in = corners.front().center;
  touches.back().out = corners.back().center;
  for (std::size_t k = 0; k + 1 < corners.size(); ++k)
    if (!tangent(corners[k], corners[k + 1], touches[k].out, touches[k + 1].in)) return false;
  return true;
}

/// The polyline of tangents and arcs (arcs on their circumscribed polygons).
std::vector<Vec2> trace(const std::vector<Corner>& corners, const std::vector<Touch>& touches,
                        double tolerance) {
  std::vector<Vec2> points{corners.front().center};
  for (std::size_t k = 1; k < corners.size(); ++k) {
    if (k > 1) append_arc(corners[k - 1], touches[k - 1].in, touches[k - 1].out, tolerance, points);
    points.push_back(touches[k].in);
  }
  return points;
}

/// How near the arc of `c` from `in` to `out` comes to `p`, if the nearest
/// point lies inside the arc (the tangents cover its ends).
std::optional<double> arc_distance(const Corner& c, const Touch& t, Vec2 p) {
  if (c.radius == 0.0) return std::nullopt;
  const Vec2 a = t.in - c.center, b = t.out - c.center, v = p - c.center;
  // Inside the sweep from a to b, turning c.side's way (less than a full turn).
  const bool inside = c.side * cross(a, b) >= 0
                          ? c.side * cross(a, v) >= 0 && c.side * cross(v, b) >= 0
                          : !(c.side * cross(b, v) > 0 && c.side * cross(v, a) > 0);
  if (!inside) return std::nullopt;
  return std::fabs(length(v) - c.radius);
}

/// The first portal end (2 i for portal i's left, 2 i + 1 for its right)
/// that the path passes nearer than `radius` or on the wrong side. A portal
/// end is checked against the tangent that crosses its portal and the arcs
/// at both ends of that tangent.
std::optional<std::size_t> first_missed_end(const std::vector<Portal>& portals, double radius,
                                             const std::vector<Corner>& corners,
                                             const std::vector<Touch>& touches) {
  constexpr double kSlack = 1e-9;
  std::size_t k = 0;  // corners[k] is the last corner at or before the portal
  for (std::size_t i = 0; i < portals.size(); ++i) {
    while (k + 2 < corners.size() && corners[k + 1].portal <= static_cast<int>(i)) ++k;
    const Vec2 from = touches[k].out, to = touches[k + 1].in;
    for (int side : {+1, -1}) {
      const Vec2 end = side > 0 ? portals[i].left : portals[i].right;
      if ((corners[k].center == end && corners[k].side == side) ||
          (corners[k + 1].center == end && corners[k + 1].side == side)) {
        continue;  // wrapped: exactly at the radius
      }
      double gap = distance_to_segment(end, from, to);
      for (std::size_t j : {k, k + 1})
        if (const std::optional<double> d = arc_distance(corners[j], touches[j], end)) gap = std::min(gap, *d);
      const Vec2 way = to - from;
      const double along = dot(end - from, way);
      const bool wrong_side = along > 0 && along < dot(way, way) && side * cross(way, end - from) < 0;
      if (wrong_side || gap < radius - kSlack) return 2 * i + (side > 0 ? 0 : 1);
    }
  }
  return std::nullopt;
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
    return i < n ? Corner{portals[i].left, radius, +1, i} : Corner{goal, 0.0, 0, n};
  };
  auto right_of = [&](int i) {
    return i < n ? Corner{portals[i].right, radius, -1, i} : Corner{goal, 0.0, 0, n};
  };
  std::vector<Corner> corners{{start, 0.0, 0}};
  Corner apex = corners.front(), left = apex, right = apex;
  int apex_index = -1, left_index = -1, right_index = -1;
  bool ok = true;
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
      } else {
        // Crossed: the left corner comes first, unless the new right one
        // stands in the way to it (with circles, either may).
        wrap(blocks(new_right, apex, left) ? -1 : +1, blocks(new_right, apex, left) ? i : left_index);
        continue;
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
      } else {
        wrap(blocks(new_left, apex, right) ? +1 : -1, blocks(new_left, apex, right) ? i : right_index);
        continue;
      }
    }
    if (!ok) {
      result.failed_portal = std::min(i, n - 1);
      return result;
    }
  }
  corners.push_back({goal, 0.0, 0, n});
  // The funnel's corners are a first guess; a portal end the path still
  // passes too near or on the wrong side joins them, until none does.
  for (int round = 0;; ++round) {
    drop_wrong_turns(corners);
    std::vector<Touch> touches;
    if (!touch_points(corners, touches) || round > n + 4) {
      result.failed_portal = n > 0 ? n - 1 : 0;
      return result;
    }
    const std::optional<std::size_t> missing = first_missed_end(portals, radius, corners, touches);
    if (!missing) {
      result.points = trace(corners, touches, tolerance);
      break;
    }
    const Corner end = *missing % 2 == 0 ? left_of(static_cast<int>(*missing / 2))
                                         : right_of(static_cast<int>(*missing / 2));
    const auto after = std::find_if(corners.begin(), corners.end(),
                                    [&](const Corner& c) { return c.portal > end.portal; });
    corners.insert(after, end);
  }
  result.ok = true;
  return result;
}

}  // namespace footfall
