// Footfall — capsules against the scene's triangles.
#include "footfall/fullbody/collision_scene.hpp"

#include <algorithm>
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

// A point of the world in the frame at `origin` whose x axis is `along`.
Vec3 in_frame(Vec3 p, Vec2 origin, Vec2 along) {
  const Vec2 d = ground(p) - origin;
  return {dot(d, along), cross(along, d), p.z};
}

// False if an axis separates `box` from the triangle `q` (in the box's
// frame, with its normal `n` there): the box's three axes and the normal.
bool may_meet(const FrameBox& box, const std::array<Vec3, 3>& q, Vec3 n) {
  const auto apart = [](double a, double b, double c, double lo, double hi) {
    return std::max({a, b, c}) < lo || std::min({a, b, c}) > hi;
  };
  if (apart(q[0].x, q[1].x, q[2].x, box.min.x, box.max.x) ||
      apart(q[0].y, q[1].y, q[2].y, box.min.y, box.max.y) ||
      apart(q[0].z, q[1].z, q[2].z, box.min.z, box.max.z))
    return false;
  const Vec3 centre = 0.5 * (box.min + box.max), half = 0.5 * (box.max - box.min);
  const double reach =
      std::fabs(n.x) * half.x + std::fabs(n.y) * half.y + std::fabs(n.z) * half.z;
  return std::fabs(dot(n, centre - q[0])) <= reach;
}

}  // namespace

bool LimbSurfaces::empty() const {
  for (const auto& surfaces : near_)
    if (!surfaces.empty()) return false;
  return true;
}

CollisionScene::CollisionScene(const std::vector<Obstacle>& obstacles)
    : tree_(std::make_unique<CollisionTree>(surfaces(obstacles))) {}
CollisionScene::~CollisionScene() = default;
CollisionScene::CollisionScene(CollisionScene&&) noexcept = default;
CollisionScene& CollisionScene::operator=(CollisionScene&&) noexcept = default;

std::size_t CollisionScene::triangle_count() const { return tree_->triangles.size(); }

void CollisionScene::near_limbs(Vec2 origin, double heading,
                                const std::array<FrameBox, kLimbCount>& boxes,
                                LimbSurfaces& near) const {
  for (auto& surfaces : near.near_) surfaces.clear();
  // A hair of room, so that rounding in the frame's turn leaves no touching
  // surface out.
  constexpr double kRoom = 1e-9;  // [m]
  const Vec3 room{kRoom, kRoom, kRoom};
  FrameBox all;
  for (const FrameBox& b : boxes) all.take_in(b.min, b.max);
  const Vec2 along = unit(heading), left = perp(along);
  Box3 world;
  for (const double x : {all.min.x, all.max.x})
    for (const double y : {all.min.y, all.max.y}) {
      const Vec2 corner = origin + x * along + y * left;
      world.take_in(Vec3{corner.x, corner.y, all.min.z} - room);
      world.take_in(Vec3{corner.x, corner.y, all.max.z} + room);
    }
  tree_->visit(world, [&](const SceneTriangle& t) {
    const std::array<Vec3, 3> q = {in_frame(t.corners[0], origin, along),
                                   in_frame(t.corners[1], origin, along),
                                   in_frame(t.corners[2], origin, along)};
    const Vec3 n{dot(ground(t.normal), along), cross(along, ground(t.normal)), t.normal.z};
    if (!may_meet({all.min - room, all.max + room}, q, n)) return false;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const FrameBox grown{boxes[limb].min - room, boxes[limb].max + room};
      if (may_meet(grown, q, n)) near.near_[limb].push_back(&t);
    }
    return false;
  });
}

Contact CollisionScene::test(const BodyPose& pose, const GroundPlacement& placement,
                             const LimbSurfaces& near) const {
  // The turn's cosine and sine, found once for every limb.
  const Vec2 along = unit(placement.heading);
  const auto place = [&](Vec3 p) {
    return Vec3{placement.position.x + along.x * p.x - along.y * p.y,
                placement.position.y + along.y * p.x + along.x * p.y, p.z + placement.height};
  };
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (near.near_[limb].empty()) continue;
    const Capsule placed{place(pose[limb].a), place(pose[limb].b), pose[limb].radius};
    Contact contact;
    double best_squared = placed.radius * placed.radius;
    for (const SceneTriangle* t : near.near_[limb])
      if (take_contact(*t, placed, contact, best_squared)) {
        contact.limb = limb;
        return contact;
      }
  }
  return {};
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
