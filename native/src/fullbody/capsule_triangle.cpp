// Footfall — segment-triangle distance: zero where the segment pierces the
// triangle, else the least of the ends against the triangle and the segment
// against the three edges (the nearest pair always includes one of these).
#include "fullbody/capsule_triangle.hpp"

#include <algorithm>
#include <cmath>

namespace footfall::detail {
namespace {

// The triangle's point nearest to p, by the Voronoi region p lies in
// (vertex, edge or face), from barycentric coordinates.
Vec3 closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0)) return a;  // degenerate triangle: its edges are tested anyway
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

// Nearest points of segments [p1, q1] and [p2, q2].
void closest_between_segments(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, Vec3& on1, Vec3& on2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 1e-18 && e <= 1e-18) {
    s = t = 0;
  } else if (a <= 1e-18) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 1e-18) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denominator = a * e - b * b;
      s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  on1 = p1 + s * d1;
  on2 = p2 + t * d2;
}

void keep_nearer(SegmentTriangleDistance& best, Vec3 on_segment, Vec3 on_triangle) {
  const Vec3 d = on_segment - on_triangle;
  const double squared = dot(d, d);
  if (squared < best.squared) best = {squared, on_segment, on_triangle};
}

}  // namespace

SegmentTriangleDistance segment_triangle_distance(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  // Pierced: the segment crosses the triangle's plane inside it.
  const Vec3 normal = cross(b - a, c - a);
  const double dp = dot(normal, p - a), dq = dot(normal, q - a);
  if ((dp <= 0 && dq >= 0) || (dp >= 0 && dq <= 0)) {
    if (dp != dq) {
      const Vec3 x = p + (dp / (dp - dq)) * (q - p);
      const double u = dot(normal, cross(b - a, x - a)), v = dot(normal, cross(c - b, x - b)),
                   w = dot(normal, cross(a - c, x - c));
      if (u >= 0 && v >= 0 && w >= 0 && dot(normal, normal) > 0) return {0.0, x, x};
    }
  }
  SegmentTriangleDistance best{INFINITY, p, a};
  keep_nearer(best, p, closest_on_triangle(p, a, b, c));
  keep_nearer(best, q, closest_on_triangle(q, a, b, c));
  const Vec3 corners[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    Vec3 on_segment, on_edge;
    closest_between_segments(p, q, corners[k], corners[(k + 1) % 3], on_segment, on_edge);
    keep_nearer(best, on_segment, on_edge);
  }
  return best;
}

}  // namespace footfall::detail
