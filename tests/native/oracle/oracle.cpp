#include "oracle/oracle.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace footfall::testing {

double distance_to_polygon(const std::vector<Vec2>& polygon, Vec2 p) {
  // Winding number for inside (the library uses the crossing rule).
  int winding = 0;
  double nearest = INFINITY;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
    if (a.y <= p.y && b.y > p.y && side > 0) ++winding;
    if (a.y > p.y && b.y <= p.y && side < 0) --winding;
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double len2 = ex * ex + ey * ey;
    const double t =
        len2 > 0 ? std::clamp(((p.x - a.x) * ex + (p.y - a.y) * ey) / len2, 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, std::hypot(p.x - (a.x + t * ex), p.y - (a.y + t * ey)));
  }
  return winding != 0 ? 0.0 : nearest;
}

std::string first_contact(const AgentPlan& plan, const CharacterParams& character,
                          const std::vector<Obstacle>& obstacles, double dt) {
  const double end = plan.end_time();
  for (double t = 0.0; t <= end + 1e-9; t += dt) {
    const std::vector<Circle> circles = collision_circles(plan, character, t);
    for (size_t c = 0; c < circles.size(); ++c) {
      if (c == 1 || c == 2) continue;  // the shoulders
      for (size_t o = 0; o < obstacles.size(); ++o) {
        const double gap =
            distance_to_polygon(obstacles[o].polygon, circles[c].center) - circles[c].radius;
        if (gap < 0.0) {
          std::ostringstream out;
          out << plan.name << ": circle " << c << " (" << circles[c].center.x << ", "
              << circles[c].center.y << ") overlaps obstacle " << o << " by " << -gap
              << " m at t = " << t;
          return out.str();
        }
      }
    }
  }
  return {};
}

}  // namespace footfall::testing
