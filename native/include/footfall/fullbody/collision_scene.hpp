// Footfall — the scene's obstacles in 3-D as triangles under a bounding-volume
// hierarchy, for testing the body's capsules against them.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "footfall/model/body.hpp"
#include "footfall/model/geometry3.hpp"
#include "footfall/model/obstacles.hpp"

namespace footfall {

struct CollisionTree;
struct SceneTriangle;

/// A box in a frame turned about the vertical: x along the frame's heading,
/// y to its left, z up, from the frame's origin. [m]
struct FrameBox {
  Vec3 min{INFINITY, INFINITY, INFINITY};
  Vec3 max{-INFINITY, -INFINITY, -INFINITY};

  void take_in(Vec3 lo, Vec3 hi) {
    min = {std::min(min.x, lo.x), std::min(min.y, lo.y), std::min(min.z, lo.z)};
    max = {std::max(max.x, hi.x), std::max(max.y, hi.y), std::max(max.z, hi.z)};
  }
};

/// The surfaces each limb of a moving body may touch (CollisionScene::
/// near_limbs), so that the sweep's poses are tested against those alone.
class LimbSurfaces {
 public:
  /// True if no limb comes near a surface.
  bool empty() const;

 private:
  friend class CollisionScene;
  std::array<std::vector<const SceneTriangle*>, kLimbCount> near_;
};

/// Where a body pose meets an obstacle.
struct Contact {
  int limb = -1;        ///< The first limb (Limb order) that meets one; -1: none.
  Vec3 point;           ///< The point of that limb's axis nearest the obstacle. [m]
  double depth = 0.0;   ///< How far the capsule reaches into the surface. [m] [>= 0]
  int obstacle = -1;    ///< Index of the obstacle met.

  explicit operator bool() const { return limb >= 0; }
};

/// Every obstacle's surface: prisms as their walls and caps, meshes as given.
/// Immutable after construction; queries may run in parallel.
class CollisionScene {
 public:
  /// Obstacles as a scenario gives them (validated: see validate(Obstacle)).
  explicit CollisionScene(const std::vector<Obstacle>& obstacles);
  ~CollisionScene();
  CollisionScene(CollisionScene&&) noexcept;
  CollisionScene& operator=(CollisionScene&&) noexcept;

  /// The first limb of `pose`, placed by `placement`, whose capsule touches a
  /// surface; with `deepest`, every limb is tested and the deepest contact
  /// returned instead.
  Contact test(const BodyPose& pose, const GroundPlacement& placement, bool deepest = false) const;
  /// Finds for each limb the surfaces that may meet its box (`boxes`, in
  /// the frame at `origin` turned by `heading`). Conservative: a surface
  /// left out cannot touch the limb anywhere in its box (separating axes:
  /// the frame's three and the triangle's normal).
  void near_limbs(Vec2 origin, double heading, const std::array<FrameBox, kLimbCount>& boxes,
                  LimbSurfaces& near) const;
  /// The first limb of `pose`, placed by `placement`, that touches one of
  /// the surfaces `near` found for it (near_limbs of a sweep holding the pose).
  Contact test(const BodyPose& pose, const GroundPlacement& placement,
               const LimbSurfaces& near) const;
  /// The deepest contact of one capsule (in world space) with a surface.
  Contact test(const Capsule& capsule) const;
  /// Number of triangles.
  std::size_t triangle_count() const;

 private:
  std::unique_ptr<CollisionTree> tree_;
};

}  // namespace footfall
