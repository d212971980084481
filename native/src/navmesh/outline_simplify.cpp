#include "navmesh/outline_simplify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>

namespace footfall {

namespace {

int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double o = cross(b - a, c - a);
  return (o > 0) - (o < 0);
}

bool on_segment(Vec2 p, Vec2 a, Vec2 b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Closed segments [p, q] and [a, b] share a point.
bool segments_meet(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  const int o1 = orientation(p, q, a), o2 = orientation(p, q, b), o3 = orientation(a, b, p),
            o4 = orientation(a, b, q);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, p, q)) || (o2 == 0 && on_segment(b, p, q)) ||
         (o3 == 0 && on_segment(p, a, b)) || (o4 == 0 && on_segment(q, a, b));
}

// The closed triangle (a, b, c), either winding, holds p.
bool in_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const int o1 = orientation(a, b, p), o2 = orientation(b, c, p), o3 = orientation(c, a, p);
  return !((o1 < 0 || o2 < 0 || o3 < 0) && (o1 > 0 || o2 > 0 || o3 > 0));
}

bool segment_meets_triangle(Vec2 p, Vec2 q, Vec2 a, Vec2 b, Vec2 c) {
  if (segments_meet(p, q, a, b) || segments_meet(p, q, b, c) || segments_meet(p, q, c, a)) return true;
  // Otherwise only wholly inside; a flat triangle is its sides.
  return orientation(a, b, c) != 0 && in_triangle(p, a, b, c);
}

// One step of the simplification.
enum class Step { kDropReflex, kExtendEdges };

struct Candidate {
  double cost;
  Step step;
  int vertex;  // the reflex vertex, or the first of the short edge
  bool operator>(const Candidate& o) const { return cost > o.cost; }
};

class Simplifier {
 public:
  Simplifier(const std::vector<Vec2>& ccw, double tolerance)
      : pos_(ccw), tolerance_(tolerance), count_(static_cast<int>(ccw.size())) {
    const int n = count_;
    prev_.resize(n);
    next_.resize(n);
    for (int i = 0; i < n; ++i) {
      prev_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
    }
    alive_.assign(n, 1);
    drift_.assign(n, 0.0);
    seen_.assign(n, 0);
    // Cells about as large as an edge: a short edge's test reads a few.
    Vec2 low = pos_[0], high = pos_[0];
    double total = 0;
    for (int i = 0; i < n; ++i) {
      low = {std::min(low.x, pos_[i].x), std::min(low.y, pos_[i].y)};
      high = {std::max(high.x, pos_[i].x), std::max(high.y, pos_[i].y)};
      total += distance(pos_[i], pos_[next_[i]]);
    }
    origin_ = low;
    cell_ = std::max({total / n, tolerance_, 1e-6 * std::max(high.x - low.x, high.y - low.y)});
    for (int i = 0; i < n; ++i) file_edge(i);
    for (int i = 0; i < n; ++i) offer(i);
  }

  std::vector<Vec2> run() {
    while (!queue_.empty() && count_ > 3) {
      const Candidate c = queue_.top();
      queue_.pop();
      if (c.cost > tolerance_) break;
      if (!alive_[c.vertex]) continue;
      Vec2 meet;
      const double now = cost(c.step, c.vertex, meet);
      if (now != c.cost) {  // the outline changed since it was offered
        if (now <= tolerance_) queue_.push({now, c.step, c.vertex});
        continue;
      }
      if (c.step == Step::kDropReflex ? !drop_reflex(c.vertex) : !extend_edges(c.vertex, meet)) continue;
    }
    std::vector<Vec2> out;
    int start = 0;
    while (!alive_[start]) ++start;
    int i = start;
    do {
      out.push_back(pos_[i]);
      i = next_[i];
    } while (i != start);
    return out;
  }

 private:
  static constexpr double kNever = std::numeric_limits<double>::infinity();

  bool reflex(int i) const { return cross(pos_[i] - pos_[prev_[i]], pos_[next_[i]] - pos_[i]) <= 0; }

  // How far outside the original outline a step leaves the new edges (kNever
  // if the step does not apply); `meet` gets where the extended edges meet.
  double cost(Step step, int i, Vec2& meet) const {
    const int a = prev_[i], b = next_[i];
    if (step == Step::kDropReflex) {
      if (!reflex(i)) return kNever;
      const double notch = distance_to_segment(pos_[i], pos_[a], pos_[b]);
      return std::max(drift_[a], drift_[i]) + notch;
    }
    const int c = next_[b];
    if (reflex(i) || reflex(b) || c == a) return kNever;
    const Vec2 d1 = pos_[i] - pos_[a], d2 = pos_[b] - pos_[c];
    const double denominator = cross(d1, d2);
    if (denominator == 0) return kNever;
    const double s = cross(pos_[b] - pos_[i], d2) / denominator;
    const double t = cross(pos_[b] - pos_[i], d1) / denominator;
    if (!(s > 0) || !(t > 0)) return kNever;
    meet = pos_[i] + s * d1;
    const double corner = drift_[i] + distance_to_segment(meet, pos_[i], pos_[b]);
    return std::max({drift_[a], drift_[b], corner});
  }

  void offer(int i) {
    Vec2 meet;
    for (const Step step : {Step::kDropReflex, Step::kExtendEdges}) {
      const double c = cost(step, i, meet);
      if (c <= tolerance_) queue_.push({c, step, i});
    }
  }

  // Offers again the steps of the vertices near i, whose costs it changed.
  void offer_around(int i) {
    int k = i;
    for (int back = 0; back < 2; ++back) k = prev_[k];
    for (int step = 0; step < 5; ++step, k = next_[k]) offer(k);
  }

  bool drop_reflex(int i) {
    const int a = prev_[i], b = next_[i];
    if (touches_others(pos_[a], pos_[i], pos_[b], {a, i})) return false;
    drift_[a] = std::max(drift_[a], drift_[i]) + distance_to_segment(pos_[i], pos_[a], pos_[b]);
    unlink(i);
    file_edge(a);
    offer_around(a);
    return true;
  }

  bool extend_edges(int i, Vec2 meet) {
    const int a = prev_[i], b = next_[i];
    if (touches_others(pos_[i], meet, pos_[b], {a, i, b})) return false;
    const double corner = drift_[i] + distance_to_segment(meet, pos_[i], pos_[b]);
    drift_[a] = std::max(drift_[a], corner);
    drift_[i] = std::max(drift_[b], corner);
    pos_[i] = meet;
    unlink(b);
    file_edge(a);
    file_edge(i);
    offer_around(i);
    return true;
  }

  void unlink(int i) {
    next_[prev_[i]] = next_[i];
    prev_[next_[i]] = prev_[i];
    alive_[i] = 0;
    --count_;
  }

  // True if an edge of the outline other than those starting at `own` meets
  // the closed triangle (p, q, r) anywhere but at a vertex they share.
  bool touches_others(Vec2 p, Vec2 q, Vec2 r, std::initializer_list<int> own) {
    ++stamp_;
    const auto [x0, y0] = cell_of({std::min({p.x, q.x, r.x}), std::min({p.y, q.y, r.y})});
    const auto [x1, y1] = cell_of({std::max({p.x, q.x, r.x}), std::max({p.y, q.y, r.y})});
    for (std::int64_t x = x0 - 1; x <= x1 + 1; ++x)
      for (std::int64_t y = y0 - 1; y <= y1 + 1; ++y) {
        const auto found = cells_.find(key(x, y));
        if (found == cells_.end()) continue;
        for (const int e : found->second) {
          if (!alive_[e] || seen_[e] == stamp_ || std::find(own.begin(), own.end(), e) != own.end()) continue;
          seen_[e] = stamp_;
          Vec2 u = pos_[e], v = pos_[next_[e]];
          // An edge that ends at a corner of the triangle touches it there:
          // only the rest of it counts.
          constexpr double kAway = 1e-9;
          if (u == p || u == q || u == r) u = u + kAway * (v - u);
          if (v == p || v == q || v == r) v = v + kAway * (u - v);
          if (segment_meets_triangle(u, v, p, q, r)) return true;
        }
      }
    return false;
  }

  std::pair<std::int64_t, std::int64_t> cell_of(Vec2 p) const {
    return {static_cast<std::int64_t>(std::floor((p.x - origin_.x) / cell_)),
            static_cast<std::int64_t>(std::floor((p.y - origin_.y) / cell_))};
  }
  static std::int64_t key(std::int64_t x, std::int64_t y) { return x * 0x100000000ll + y; }

  // Files edge i (to next_[i]) under every cell within a quarter cell of it:
  // a query that reads the cells round a region meets every edge crossing it.
  // Entries of edges since replaced stay; they are tested as the edge now is.
  void file_edge(int i) {
    const Vec2 u = pos_[i], v = pos_[next_[i]];
    const int samples = 1 + static_cast<int>(4 * distance(u, v) / cell_);
    std::int64_t last = std::numeric_limits<std::int64_t>::min();
    for (int k = 0; k <= samples; ++k) {
      const auto [x, y] = cell_of(u + (static_cast<double>(k) / samples) * (v - u));
      const std::int64_t here = key(x, y);
      if (here == last) continue;
      last = here;
      auto& cell = cells_[here];
      if (cell.empty() || cell.back() != i) cell.push_back(i);
    }
  }

  std::vector<Vec2> pos_;
  double tolerance_;
  int count_;
  std::vector<int> prev_, next_;
  std::vector<char> alive_;
  std::vector<double> drift_;  ///< per edge (by its first vertex): how far it may lie outside the original
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
  Vec2 origin_;
  double cell_ = 1;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
};

}  // namespace

std::vector<Vec2> simplify_outward(const std::vector<Vec2>& ccw, double tolerance) {
  if (ccw.size() <= 3) return ccw;
  return Simplifier(ccw, tolerance).run();
}

}  // namespace footfall
