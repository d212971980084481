// Footfall — landmarks for the path search's heuristic: their choice, their
// distances, the lower bounds drawn from them (navmesh_landmarks.hpp says
// why they hold), and when a mesh builds them.
#include "navmesh_landmarks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace footfall {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Landmarks per radius: each costs one search of the whole mesh to build
/// and one look-up per search node that turns.
constexpr std::size_t kLandmarkCount = 8;
/// Radii a mesh keeps landmarks for at once (the oldest goes first).
constexpr std::size_t kLandmarkRadii = 4;

Vec2 centroid_of(Face f) {
  return (1.0 / 3.0) *
         (to_vec(f->vertex(0)->point()) + to_vec(f->vertex(1)->point()) + to_vec(f->vertex(2)->point()));
}

/// Keeps the least length reported per vertex and per face, for one landmark.
class Column : public SearchReport {
 public:
  Column(const std::unordered_map<Vertex, std::size_t>& vertex_row, double* near_vertex,
         const std::unordered_map<Face, std::size_t>& face_row, double* to_centroid, std::size_t stride)
      : vertex_row_(vertex_row), face_row_(face_row), near_vertex_(near_vertex),
        to_centroid_(to_centroid), stride_(stride) {}
  void gate_end(Vertex v, double length) override { keep(vertex_row_, near_vertex_, v, length); }
  void centroid(Face f, double length) override { keep(face_row_, to_centroid_, f, length); }

 private:
  template <class Handle>
  void keep(const std::unordered_map<Handle, std::size_t>& rows, double* column, Handle h, double length) {
    const auto found = rows.find(h);
    if (found == rows.end()) return;
    double& slot = column[found->second * stride_];
    slot = std::min(slot, length);
  }
  const std::unordered_map<Vertex, std::size_t>& vertex_row_;
  const std::unordered_map<Face, std::size_t>& face_row_;
  double* near_vertex_;
  double* to_centroid_;
  std::size_t stride_;
};

}  // namespace

std::shared_ptr<const Landmarks> Landmarks::build(const NavMeshState& mesh, double radius) {
  auto out = std::make_shared<Landmarks>();
  out->radius_ = radius;
  // Vertices with a walkable face around them can be landmarks.
  std::vector<Vertex> candidates;
  for (Vertex v : mesh.cdt.finite_vertex_handles()) {
    out->vertex_row_.emplace(v, out->vertex_row_.size());
    auto faces = mesh.cdt.incident_faces(v), end = faces;
    bool walkable = false;
    do walkable = walkable || mesh.walkable(faces); while (++faces != end);
    if (walkable) candidates.push_back(v);
  }
  for (Face f : mesh.cdt.finite_face_handles())
    if (mesh.walkable(f)) out->face_row_.emplace(f, out->face_row_.size());
  if (out->face_row_.empty()) return out;
  out->count_ = kLandmarkCount;
  out->near_vertex_.assign(out->vertex_row_.size() * kLandmarkCount, kInf);
  out->to_centroid_.assign(out->face_row_.size() * kLandmarkCount, kInf);
  // The first landmark is the centroid of the largest walkable face (open
  // ground, not a pocket between obstacles); each next one the centroid of
  // a walkable face at the vertex farthest from those before it (by the
  // least distance from any of them, among the vertices they reach).
  std::vector<double> nearest(candidates.size(), kInf);
  Face face;
  double largest = -1.0;
  for (const auto& [f, row] : out->face_row_) {
    const Vec2 a = to_vec(f->vertex(0)->point());
    const double area = cross(to_vec(f->vertex(1)->point()) - a, to_vec(f->vertex(2)->point()) - a);
    if (area > largest) {
      largest = area;
      face = f;
    }
  }
  for (std::size_t k = 0; k < kLandmarkCount; ++k) {
    Column column(out->vertex_row_, out->near_vertex_.data() + k, out->face_row_,
                  out->to_centroid_.data() + k, kLandmarkCount);
    out->work_ += search_everywhere(mesh, face, centroid_of(face), radius, column);
    double farthest = -1.0;
    Vertex next;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const double d = out->near_vertex_[out->vertex_row_.at(candidates[i]) * kLandmarkCount + k];
      nearest[i] = std::min(nearest[i], d);
      if (nearest[i] < kInf && nearest[i] > farthest) {
        farthest = nearest[i];
        next = candidates[i];
      }
    }
    if (next == Vertex()) break;  // nothing reached: the rest would repeat this one
    auto faces = mesh.cdt.incident_faces(next);
    while (!mesh.walkable(faces)) ++faces;
    face = faces;
  }
  return out;
}

LandmarkHeuristic::LandmarkHeuristic(const Landmarks* landmarks, Face goal_face, Vec2 goal)
    : landmarks_(landmarks) {
  if (landmarks_ == nullptr) return;
  const double* upper = landmarks_->to_centroid(goal_face);
  if (upper == nullptr) return;
  // The goal's face is convex: m_r(L, goal) <= m_r(L, centroid) + |centroid, goal|.
  const double rest = distance(centroid_of(goal_face), goal);
  goal_upper_.assign(landmarks_->count(), kInf);
  for (std::size_t k = 0; k < landmarks_->count(); ++k)
    if (upper[k] < kInf) {
      goal_upper_[k] = upper[k] + rest;
      used_.push_back(k);
    }
}

double LandmarkHeuristic::from_face(Face f, Vec2 p) const {
  // A gate end x at corner w of f lies within r of w, and f is convex, so
  // m_r(L, p) >= m_r(L, x) - |x, p| >= near_vertex(w) - r - |w, p|.
  double best = 0.0;
  if (used_.empty()) return best;
  for (int i = 0; i < 3; ++i) {
    const double* lower = landmarks_->near_vertex(f->vertex(i));
    if (lower == nullptr) continue;
    const double slack = landmarks_->radius() + distance(to_vec(f->vertex(i)->point()), p);
    for (const std::size_t k : used_)
      if (lower[k] < kInf) best = std::max(best, lower[k] - slack - goal_upper_[k]);
  }
  return best;
}

double LandmarkHeuristic::from_gate_end(Vertex v) const {
  double best = 0.0;
  if (used_.empty()) return best;
  const double* lower = landmarks_->near_vertex(v);
  if (lower == nullptr) return best;
  for (const std::size_t k : used_)
    if (lower[k] < kInf) best = std::max(best, lower[k] - goal_upper_[k]);
  return best;
}

void NavMeshState::build_landmarks(double radius) const {
  std::lock_guard<std::mutex> lock(landmark_mutex);
  LandmarkSlot& slot = slot_for(radius);
  slot.landmarks = Landmarks::build(*this, radius);
  landmark_cost = slot.landmarks->work();
}

NavMeshState::LandmarkSlot& NavMeshState::slot_for(double radius) const {
  for (LandmarkSlot& slot : landmark_slots)
    if (slot.radius == radius) return slot;
  if (landmark_slots.size() == kLandmarkRadii) landmark_slots.erase(landmark_slots.begin());
  landmark_slots.push_back({radius, nullptr, 0});
  return landmark_slots.back();
}

std::shared_ptr<const Landmarks> NavMeshState::landmarks_for_query(double radius) const {
  std::lock_guard<std::mutex> lock(landmark_mutex);
  LandmarkSlot& slot = slot_for(radius);
  // Until a build has been measured, guess a few nodes per face and landmark.
  const long cost = landmark_cost >= 0 ? landmark_cost
                                       : static_cast<long>(4 * kLandmarkCount * cdt.number_of_faces());
  if (slot.landmarks == nullptr && slot.unguided_work >= cost) {
    slot.landmarks = Landmarks::build(*this, radius);
    landmark_cost = slot.landmarks->work();
  }
  return slot.landmarks;
}

void NavMeshState::add_unguided_work(double radius, long expansions) const {
  std::lock_guard<std::mutex> lock(landmark_mutex);
  slot_for(radius).unguided_work += expansions;
}

void NavMeshState::drop_landmarks() {
  std::lock_guard<std::mutex> lock(landmark_mutex);
  landmark_slots.clear();
}

}  // namespace footfall
