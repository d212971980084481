// Footfall — the funnel algorithm with circles at the corners (the "simple
// stupid funnel" over corners of radius r, Demyen's and Kallmann's extension).
#include "navmesh/channel_funnel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace footfall {
namespace {

/// Rounding allowance for an arc reaching out of its fan. [rad]
constexpr double kArcSlack = 1e-12;

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
/// circumscribed polygon with steps of at most `max_step` radians, then `p1`.
void append_arc(const Corner& c, Vec2 p0, Vec2 p1, double max_step, std::vector<Vec2>& out) {
  const double a0 = angle_of(p0 - c.center), a1 = angle_of(p1 - c.center);
  double sweep = c.side * (a1 - a0);  // left corners turn counter-clockwise
  while (sweep < 0) sweep += 2 * kPi;
  while (sweep >= 2 * kPi) sweep -= 2 * kPi;
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

/// True if the segment `from` -> `to` passes portal end `end` as it must:
/// at least `radius` away, and on the end's `side` (+1: the walker's left)
/// wherever it is abeam of the segment, its ends included (an end level
/// with where the segment starts, on the wrong side, is passed wrongly).
bool passes_end(Vec2 end, int side, Vec2 from, Vec2 to, double radius) {
  constexpr double kSlack = 1e-9;
  const Vec2 way = to - from;
  const double along = dot(end - from, way);
  const bool wrong_side = along >= 0 && along <= dot(way, way) && side * cross(way, end - from) < 0;
  return !wrong_side && distance_to_segment(end, from, to) >= radius - kSlack;
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

/// The polyline of tangents and arcs (arcs on their circumscribed polygons,
/// every corner's circle of `radius`, at most `tolerance` outside it).
std::vector<Vec2> trace(const std::vector<Corner>& corners, const std::vector<Touch>& touches,
                        double radius, double tolerance) {
  // The step that keeps the polygon's vertices within tolerance of the circle.
  const double max_step = 2 * std::acos(radius / (radius + tolerance));
  std::vector<Vec2> points{corners.front().center};
  for (std::size_t k = 1; k < corners.size(); ++k) {
    if (k > 1) append_arc(corners[k - 1], touches[k - 1].in, touches[k - 1].out, max_step, points);
    points.push_back(touches[k].in);
  }
  return points;
}

/// The tangent (from corner j to corner j + 1) on which the path crosses
/// `portal`, which lies between corners k and k + 1; none if it crosses on
/// an arc. Where neither corner ends the portal, that is tangent k. A corner
/// that ends it is taken to cross it on its arc; with `strict_ends`, only
/// if no tangent beside it crosses the portal (a corner ending a fan of
/// portals may leave the last of them, or meet the first, on a tangent).
std::optional<std::size_t> crossing_tangent(const Portal& portal,
                                            const std::vector<Corner>& corners,
                                            const std::vector<Touch>& touches, std::size_t k,
                                            bool strict_ends) {
  auto ends = [&](const Corner& c) {
    return (c.side > 0 && c.center == portal.left) || (c.side < 0 && c.center == portal.right);
  };
  const bool at_this = ends(corners[k]), at_next = ends(corners[k + 1]);
  if (!at_this && !at_next) return k;
  if (!strict_ends) return std::nullopt;
  auto crosses = [&](std::size_t j) {
    return segments_cross(touches[j].out, touches[j + 1].in, portal.left, portal.right);
  };
  if (crosses(k)) return k;
  if (at_this && k > 0 && crosses(k - 1)) return k - 1;
  if (at_next && k + 2 < corners.size() && crosses(k + 1)) return k + 1;
  return std::nullopt;
}

/// A portal end the path passes nearer than `radius` or on the wrong side:
/// 2 i for portal i's left, 2 i + 1 for its right, and the index in the
/// corners where it belongs (after the tangent that passed it).
struct MissedEnd {
  std::size_t end;
  std::size_t at;
};

/// The first portal end that the path passes nearer than `radius` or on the
/// wrong side, checked on the tangent that crosses its portal
/// (crossing_tangent).
std::optional<MissedEnd> first_missed_end(const std::vector<Portal>& portals, double radius,
                                          const std::vector<Corner>& corners,
                                          const std::vector<Touch>& touches, bool strict_ends) {
  std::size_t k = 0;  // corners[k] is the last corner at or before the portal
  for (std::size_t i = 0; i < portals.size(); ++i) {
    while (k + 2 < corners.size() && corners[k + 1].portal <= static_cast<int>(i)) ++k;
    const std::optional<std::size_t> j =
        crossing_tangent(portals[i], corners, touches, k, strict_ends);
    if (!j) continue;
    for (int side : {+1, -1}) {
      const Vec2 end = side > 0 ? portals[i].left : portals[i].right;
      auto is_end = [&](const Corner& c) { return c.side == side && c.center == end; };
      if (is_end(corners[*j]) || is_end(corners[*j + 1])) continue;
      if (!passes_end(end, side, touches[*j].out, touches[*j + 1].in, radius))
        return MissedEnd{2 * i + (side > 0 ? 0 : 1), *j + 1};
    }
  }
  return std::nullopt;
}

/// Angle from `from` to `to` turning `side`'s way (+1 counter-clockwise), in [0, 2 pi).
double sweep(int side, double from, double to) {
  double a = side * (to - from);
  while (a < 0) a += 2 * kPi;
  while (a >= 2 * kPi) a -= 2 * kPi;
  return a;
}

/// The channel's fan of triangles around corner `c`: it runs through the
/// portals that end at the corner, from the vertex before them to the vertex
/// after them (the start or the goal at the channel's ends, whose directions
/// lie inside the end triangles' fans).
std::pair<Vec2, Vec2> fan_ends(const Corner& c, Vec2 start, Vec2 goal,
                               const std::vector<Portal>& portals) {
  const int n = static_cast<int>(portals.size());
  auto end_of = [&](int i) { return c.side > 0 ? portals[i].left : portals[i].right; };
  int first = c.portal, last = c.portal;
  while (first > 0 && end_of(first - 1) == c.center) --first;
  while (last + 1 < n && end_of(last + 1) == c.center) ++last;
  return {first > 0 ? end_of(first - 1) : start, last + 1 < n ? end_of(last + 1) : goal};
}

/// How far the arc of corner `c`, from touch point `in` to `out`, reaches
/// beyond its fan (<= 0 if it stays inside).
double arc_excess(const Corner& c, Vec2 in, Vec2 out, Vec2 start, Vec2 goal,
                  const std::vector<Portal>& portals) {
  const auto [before, after] = fan_ends(c, start, goal, portals);
  const double lo = angle_of(before - c.center);
  double fan = sweep(c.side, lo, angle_of(after - c.center));
  if (fan == 0.0) fan = 2 * kPi;  // round the tip of a wall: in on one face, out on the other
  const double arc_start = sweep(c.side, lo, angle_of(in - c.center));
  const double arc = sweep(c.side, angle_of(in - c.center), angle_of(out - c.center));
  return arc_start + arc - fan;
}

/// A stand-in for the angle of `v` turning `side`'s way from the x axis, in
/// [0, 4): it grows with the angle, and costs a division where atan2 costs
/// some hundred instructions. NaN for the zero vector.
double diamond_angle(Vec2 v, int side) {
  const double x = v.x, y = side * v.y;
  if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (y - x);
  return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

/// True if the arc of `c` from `in` to `out` lies inside its fan with room
/// to spare (1e-9 of a turn): then arc_excess is surely negative, without
/// its four atan2. False when in doubt (near a fan end, a fan of nearly a
/// full turn, a nearly empty arc), where arc_excess must decide.
bool arc_clearly_in_fan(const Corner& c, Vec2 in, Vec2 out, Vec2 start, Vec2 goal,
                        const std::vector<Portal>& portals) {
  constexpr double kRoom = 1e-9;  // diamond angle units, each at least a radian's worth
  const auto [before, after] = fan_ends(c, start, goal, portals);
  const double lo = diamond_angle(before - c.center, c.side);
  auto turn = [&](Vec2 p) {
    const double t = diamond_angle(p - c.center, c.side) - lo;
    return t < 0 ? t + 4 : t;
  };
  const double to_in = turn(in), to_out = turn(out), fan = turn(after);
  return to_in > kRoom && to_out > to_in + kRoom && fan > to_out + kRoom && fan < 4 - kRoom;
}

/// The same for the arc between the tangents from `prev` and to `next`
/// (infinite-ish, 2 pi, where either tangent does not exist).
double arc_excess(const Corner& prev, const Corner& c, const Corner& next, Vec2 start, Vec2 goal,
                  const std::vector<Portal>& portals) {
  Vec2 from, in, out, to;
  if (!tangent(prev, c, from, in) || !tangent(c, next, out, to)) return 2 * kPi;
  return arc_excess(c, in, out, start, goal, portals);
}

/// The corner whose arc reaches farthest out of its fan, if any does: with
/// circles, two corners on opposite sides can cross the funnel before a
/// later, tighter corner of the same side shows that the path bends there
/// instead, and the path would loop round the first one.
std::optional<std::size_t> worst_wrap(const std::vector<Corner>& corners,
                                      const std::vector<Touch>& touches, Vec2 start, Vec2 goal,
                                      const std::vector<Portal>& portals) {
  std::optional<std::size_t> worst;
  double most = kArcSlack;
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    if (corners[k].radius == 0.0 ||
        arc_clearly_in_fan(corners[k], touches[k].in, touches[k].out, start, goal, portals))
      continue;
    const double excess =
        arc_excess(corners[k], touches[k].in, touches[k].out, start, goal, portals);
    if (excess > most) {
      most = excess;
      worst = k;
    }
  }
  return worst;
}

/// True if the tangent from `a` to `b` crosses portals [first, last] as a
/// disc's centre may: every portal end other than the two corners lies on
/// its own side of it and at least `radius` from it.
bool crosses_cleanly(const Corner& a, const Corner& b, const std::vector<Portal>& portals,
                     int first, int last, double radius) {
  Vec2 from, to;
  if (!tangent(a, b, from, to)) return false;
  for (int i = std::max(first, 0); i <= last && i < static_cast<int>(portals.size()); ++i)
    for (int side : {+1, -1}) {
      const Vec2 end = side > 0 ? portals[i].left : portals[i].right;
      const auto is = [&](const Corner& c) { return c.side == side && c.center == end; };
      if (!is(a) && !is(b) && !passes_end(end, side, from, to, radius)) return false;
    }
  return true;
}

/// The length of the arc round `c` from where the tangent from `in` touches
/// it to where the tangent to `out` leaves it.
double arc_length(const Corner& in, const Corner& c, const Corner& out) {
  if (c.radius == 0.0) return 0.0;
  Vec2 from, touch_in, touch_out, to;
  tangent(in, c, from, touch_in);
  tangent(c, out, touch_out, to);
  return c.radius * sweep(c.side, angle_of(touch_in - c.center), angle_of(touch_out - c.center));
}

/// The shortest path through the channel by dynamic programming over every
/// portal end as a possible corner: exact for any channel, but cubic in its
/// length, so only the fallback for channels the funnel's repairs cannot
/// settle. A corner's arc must stay in its fan, as the funnel's repairs
/// demand: the link test sees only the portal ends abeam of a tangent, so in
/// a channel that winds round an obstacle an arc swinging through the
/// obstacle could hand over to a tangent that skips the loop with no portal
/// end abeam. Empty if no disc of `radius` gets through.
std::vector<Corner> shortest_corners(Vec2 start, Vec2 goal, const std::vector<Portal>& portals,
                                     double radius) {
  const int n = static_cast<int>(portals.size());
  std::vector<Corner> nodes{{start, 0.0, 0, -1}};
  for (int i = 0; i < n; ++i) {
    nodes.push_back({portals[i].left, radius, +1, i});
    nodes.push_back({portals[i].right, radius, -1, i});
  }
  nodes.push_back({goal, 0.0, 0, n});
  const int count = static_cast<int>(nodes.size());
  constexpr double kUnreached = std::numeric_limits<double>::infinity();
  // reach[b][a]: shortest way from the start to where the tangent from a
  // touches b; a later corner of the same circle is the same corner.
  std::vector<std::vector<double>> reach(count, std::vector<double>(count, kUnreached));
  std::vector<std::vector<int>> before(count, std::vector<int>(count, -1));
  auto link = [&](int a, int b) {
    return !nodes[a].same(nodes[b]) && crosses_cleanly(nodes[a], nodes[b], portals, nodes[a].portal,
                                                       std::min(nodes[b].portal, n - 1), radius);
  };
  auto span = [&](int a, int b) {
    Vec2 from, to;
    tangent(nodes[a], nodes[b], from, to);
    return distance(from, to);
  };
  for (int b = 1; b < count; ++b)
    if (link(0, b)) reach[b][0] = span(0, b);
  std::vector<char> links(count);
  for (int b = 1; b + 1 < count; ++b) {
    if (std::all_of(reach[b].begin(), reach[b].end(), [&](double r) { return r == kUnreached; }))
      continue;
    for (int c = b + 1; c < count; ++c) links[c] = nodes[c].portal != nodes[b].portal && link(b, c);
    for (int a = 0; a < b; ++a) {
      if (reach[b][a] == kUnreached) continue;
      for (int c = b + 1; c < count; ++c) {
        if (!links[c]) continue;
        if (nodes[b].radius > 0 &&
            arc_excess(nodes[a], nodes[b], nodes[c], start, goal, portals) > kArcSlack)
          continue;
        const double total = reach[b][a] + arc_length(nodes[a], nodes[b], nodes[c]) + span(b, c);
        if (total < reach[c][b]) {
          reach[c][b] = total;
          before[c][b] = a;
        }
      }
    }
  }
  const int last = count - 1;
  int b = static_cast<int>(std::min_element(reach[last].begin(), reach[last].end()) -
                           reach[last].begin());
  if (reach[last][b] == kUnreached) return {};
  std::vector<Corner> out{nodes[last]};
  for (int c = last; b >= 0;) {
    out.push_back(nodes[b]);
    const int a = before[c][b];
    c = b;
    b = a;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace

FunnelPath funnel(Vec2 start, Vec2 goal, const std::vector<Portal>& portals, double radius,
                  double tolerance, bool strict_ends) {
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
  // From the apex towards left and right, while they differ from it; kept for
  // the next portal, which shares a corner with this one where they are a
  // triangle's edges.
  Vec2 left_dir, right_dir;
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
    } else if (const Vec2 to_new_right =
                   right.same(new_right) ? right_dir : direction(apex, new_right, ok);
               right.same(apex) || right.same(new_right) || cross(right_dir, to_new_right) >= 0) {
      if (left.same(apex) || cross(left_dir, to_new_right) <= 0) {
        right = new_right;
        right_index = i;
        right_dir = to_new_right;
      } else {
        // Crossed: the left corner comes first, unless the new right one
        // stands in the way to it (with circles, either may).
        const bool in_the_way = blocks(new_right, apex, left);
        wrap(in_the_way ? -1 : +1, in_the_way ? i : left_index);
        continue;
      }
    }
    if (new_left.same(apex)) {
      left = new_left;
      left_index = i;
    } else if (const Vec2 to_new_left =
                   left.same(new_left) ? left_dir : direction(apex, new_left, ok);
               left.same(apex) || left.same(new_left) || cross(left_dir, to_new_left) <= 0) {
      if (right.same(apex) || cross(right_dir, to_new_left) >= 0) {
        left = new_left;
        left_index = i;
        left_dir = to_new_left;
      } else {
        const bool in_the_way = blocks(new_left, apex, right);
        wrap(in_the_way ? +1 : -1, in_the_way ? i : right_index);
        continue;
      }
    }
    if (!ok) break;
  }
  corners.push_back({goal, 0.0, 0, n});
  // The funnel's corners are a first guess; a portal end the path still
  // passes too near or on the wrong side joins them, until none does. The
  // rare channel where that goes round in circles (two corners that cross
  // the funnel with a wall's end between them) gets the exact, slow answer.
  std::vector<Touch> touches;
  for (int round = 0; ok; ++round) {
    if (!touch_points(corners, touches) || round > 2 * n + 4) {
      ok = false;
      break;
    }
    if (const std::optional<MissedEnd> missing =
            first_missed_end(portals, radius, corners, touches, strict_ends)) {
      const int i = static_cast<int>(missing->end / 2);
      // Corners stay in portal order: one that ends portal i and passed
      // the end on its way in or out now counts as wrapped at portal i.
      for (std::size_t c = 0; c < corners.size(); ++c)
        corners[c].portal =
            c < missing->at ? std::min(corners[c].portal, i) : std::max(corners[c].portal, i);
      corners.insert(corners.begin() + static_cast<long>(missing->at),
                     missing->end % 2 == 0 ? left_of(i) : right_of(i));
      continue;
    }
    if (const std::optional<std::size_t> loose =
            worst_wrap(corners, touches, start, goal, portals)) {
      corners.erase(corners.begin() + static_cast<long>(*loose));
      continue;
    }
    break;
  }
  if (!ok) {
    corners = shortest_corners(start, goal, portals, radius);
    if (corners.empty() || !touch_points(corners, touches)) {
      result.failed_portal = n > 0 ? n - 1 : 0;
      return result;
    }
  }
  result.points = trace(corners, touches, radius, tolerance);
  result.ok = true;
  return result;
}

}  // namespace footfall
