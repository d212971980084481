// Footfall — polylines by arc length.
#include "footfall/model/polyline.hpp"

#include <algorithm>

namespace footfall {

Polyline::Polyline(std::vector<Vec2> points) : points_(std::move(points)) {
  along_.reserve(points_.size());
  double s = 0;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    if (k > 0) s += distance(points_[k - 1], points_[k]);
    along_.push_back(s);
  }
}

std::size_t Polyline::piece_at(double s) const {
  // The piece [k, k + 1] with along_[k] <= s < along_[k + 1]; the last at the end.
  const auto next = std::upper_bound(along_.begin(), along_.end(), s);
  const std::size_t k = next == along_.begin() ? 0 : static_cast<std::size_t>(next - along_.begin()) - 1;
  return std::min(k, points_.size() >= 2 ? points_.size() - 2 : 0);
}

Vec2 Polyline::point_at(double s) const {
  if (points_.size() < 2) return points_.empty() ? Vec2{} : points_.front();
  const std::size_t k = piece_at(s);
  const double piece = along_[k + 1] - along_[k];
  const double t = piece > 0 ? std::clamp((s - along_[k]) / piece, 0.0, 1.0) : 0.0;
  return points_[k] + t * (points_[k + 1] - points_[k]);
}

double Polyline::heading_at(double s) const {
  if (points_.size() < 2) return 0.0;
  std::size_t k = piece_at(s);
  // Zero-length pieces have no direction: look ahead, then back.
  while (k + 2 < points_.size() && points_[k + 1] == points_[k]) ++k;
  while (k > 0 && points_[k + 1] == points_[k]) --k;
  return angle_of(points_[k + 1] - points_[k]);
}

std::vector<Vec2> Polyline::between(double s0, double s1) const {
  std::vector<Vec2> result{point_at(s0)};
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (along_[k] > s0 && along_[k] < s1) result.push_back(points_[k]);
  result.push_back(point_at(s1));
  return result;
}

}  // namespace footfall
