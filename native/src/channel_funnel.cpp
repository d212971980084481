// Footfall — the funnel algorithm with circles at the corners (the "simple
// stupid funnel" over corners of radius r, Demyen's and Kallmann's extension).
#include "channel_funnel.hpp"

#include <cmath>

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
  int left_index = -1, right_index = -1;
  bool ok = true;
  for (int i = 0; i <= n; ++i) {
    const Corner new_left = left_of(i), new_right = right_of(i);
    // Tighten the right side, or let it cross the left: the left corner becomes the apex.
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
        corners.push_back(left);
        apex = right = left;
        i = right_index = left_index;
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
        corners.push_back(right);
        apex = left = right;
        i = left_index = right_index;
        continue;
      }
    }
    if (!ok) {
      result.failed_portal = std::min(i, n - 1);
      return result;
    }
  }
  corners.push_back({goal, 0.0, 0});
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
