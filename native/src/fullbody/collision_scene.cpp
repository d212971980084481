// Footfall — capsules against the scene's triangles.
#include "footfall/fullbody/collision_scene.hpp"

#include <cmath>

#include "fullbody/capsule_triangle.hpp"
#include "fullbody/collision_tree.hpp"
#include "fullbody/prism_surface.hpp"

namespace footfall {
namespace {

std::vector<SceneTriangle> surfaces(const std::vector<Obstacle>& obstacles) {
  std::vector<SceneTriangle> result;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const Obstacle& obstacle = obstacles[i];
    validate(obstacle, "obstacles[" + std::to_string(i) + "]");
    const int index = static_cast<int>(i);
    if (obstacle.is_mesh()) {
      const auto& v = obstacle.mesh.vertices;
      for (const auto& t : obstacle.mesh.triangles)
        result.push_back({{v[t[0]], v[t[1]], v[t[2]]}, index, {}, 0.0, {}});
    } else {
      for (const auto& corners : detail::prism_surface(obstacle)) result.push_back({corners, index, {}, 0.0, {}});
    }
  }
  return result;
}

Box3 box_of(const Capsule& capsule) {
  Box3 box;
  box.take_in(capsule.a);
  box.take_in(capsule.b);
  const Vec3 r{capsule.radius, capsule.radius, capsule.radius};
  box.min = box.min - r;
  box.max = box.max + r;
  return box;
}

// Keeps in `best` the deeper of it and `capsule`'s contact with `t`; true
// if `t` is within reach.
bool take_contact(const SceneTriangle& t, const Capsule& capsule, Contact& best,
                  double& best_squared) {
  if (!t.box.meets(box_of(capsule))) return false;
  // Both ends farther than the radius on one side of the plane: no contact.
  const double da = dot(t.normal, capsule.a) - t.offset, db = dot(t.normal, capsule.b) - t.offset;
  if ((da > capsule.radius && db > capsule.radius) ||
      (da < -capsule.radius && db < -capsule.radius))
    return false;
  const auto d = detail::segment_triangle_distance(capsule.a, capsule.b, t.corners[0],
                                                   t.corners[1], t.corners[2]);
  // Touching counts: a limb grazing a wall is a collision.
  if (d.squared > best_squared || (best.limb >= 0 && d.squared == best_squared)) return false;
  best_squared = d.squared;
  best.limb = 0;
  best.point = d.on_segment;
  best.depth = capsule.radius - std::sqrt(d.squared);
  best.obstacle = t.obstacle;
  return true;
}

// The deepest contact of `capsule` with the scene; with `any`, the first found.
Contact capsule_contact(const CollisionTree& tree, const Capsule& capsule, bool any) {
  Contact best;
  double best_squared = capsule.radius * capsule.radius;
  tree.visit(box_of(capsule), [&](const SceneTriangle& t) {
    return take_contact(t, capsule, best, best_squared) && any;
  });
  return best;
}

}  // namespace

CollisionScene::CollisionScene(const std::vector<Obstacle>& obstacles)
    : tree_(std::make_unique<CollisionTree>(surfaces(obstacles))) {}
CollisionScene::~CollisionScene() = default;
CollisionScene::CollisionScene(CollisionScene&&) noexcept = default;
CollisionScene& CollisionScene::operator=(CollisionScene&&) noexcept = default;

std::size_t CollisionScene::triangle_count() const { return tree_->triangles.size(); }

bool CollisionScene::near(Vec3 lo, Vec3 hi) const {
  Box3 box;
  box.take_in(lo);
  box.take_in(hi);
  return tree_->visit(box, [](const SceneTriangle&) { return true; });
}

Contact CollisionScene::test(const Capsule& capsule) const {
  return capsule_contact(*tree_, capsule, false);
}

Contact CollisionScene::test(const BodyPose& pose, const GroundPlacement& placement,
                             bool deepest) const {
  if (tree_->nodes.empty()) return {};
  std::array<Capsule, kLimbCount> placed;
  Box3 body;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    placed[limb] = placement.apply(pose[limb]);
    body.take_in(box_of(placed[limb]));
  }
  // The triangles near the body, found once for all its limbs.
  thread_local std::vector<const SceneTriangle*> near;
  near.clear();
  tree_->visit(body, [&](const SceneTriangle& t) {
    near.push_back(&t);
    return false;
  });
  Contact result;
  for (int limb = 0; limb < kLimbCount && !near.empty(); ++limb) {
    Contact contact;
    double best_squared = placed[limb].radius * placed[limb].radius;
    for (const SceneTriangle* t : near)
      if (take_contact(*t, placed[limb], contact, best_squared) && !deepest) break;
    if (!contact) continue;
    contact.limb = limb;
    if (!deepest) return contact;
    if (!result || contact.depth > result.depth) result = contact;
  }
  return result;
}

}  // namespace footfall
