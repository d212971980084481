// Footfall — when two agents' circles count as touching, for the footstep
// search and for the crowd's commit check alike.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// Agents are checked against each other at the instants t = k * kContactDt,
/// in the search, in the crowd's commit check and in `footfall metrics`
/// (20 Hz) alike: a foot lifted and another put down at the same instant
/// touch only then, so a check between the grid's instants would disagree
/// with the others. [s]
constexpr double kContactDt = 0.05;

/// A rest keeps this much room round its torso disc from others standing
/// still: packed tighter, a jam leaves no one room to pivot or step back. [m]
constexpr double kRestRoom = 0.1;

/// The first instant of the contact grid at or after time t (within 1 ns).
inline long first_contact_instant(double t) {
  return static_cast<long>(std::ceil(t / kContactDt - 1e-9));
}

/// How near two agents come at one instant: the smallest gap between a
/// circle of one and a circle of the other (negative where they overlap),
/// outright and with both grown by the padding that covers their travel
/// until the next sample. [m]
///
/// Gaps of kFar or more are taken in as kFar, without a square root (most
/// pairs checked in a crowd): only gaps below a pad decide anything (see
/// touching()), and pads, half the travel between samples, are far smaller.
struct Gap {
  static constexpr double kFar = 0.5;  ///< [m]
  double outright = std::numeric_limits<double>::infinity();
  double padded = std::numeric_limits<double>::infinity();

  /// Takes in the pair (a, b), whose radii are grown by `pad` between samples.
  void add(const Circle& a, const Circle& b, double pad) {
    const Vec2 d = a.center - b.center;
    const double touch = a.radius + b.radius;
    double gap = kFar;
    if (pad >= 0.5 * kFar || dot(d, d) < (touch + kFar) * (touch + kFar))
      gap = std::sqrt(dot(d, d)) - touch;
    outright = std::min(outright, gap);
    padded = std::min(padded, gap - pad);
  }
};

/// True if two agents whose COMs move at `speed_a` and `speed_b` are standing
/// still (swaying on the spot at most). [m/s]
inline bool standing_still(double speed_a, double speed_b) {
  constexpr double kStill = 0.1;  // [m/s]
  return speed_a < kStill && speed_b < kStill;
}

/// True if the pair touches at a sample whose gap is `now`, in a move that
/// began with the outright gap `at_start` (infinite unless both stood still
/// there): an outright overlap always does; coming within the padding does
/// unless the pair comes no nearer than it was at the start. Without the
/// exception, two agents left standing close after a jam could never take a
/// step, each held by the other's padding.
inline bool touching(const Gap& now, double at_start) {
  constexpr double kSlack = 1e-9;  // [m]
  return now.outright < 0 || (now.padded < 0 && now.outright < at_start - kSlack);
}

}  // namespace footfall
