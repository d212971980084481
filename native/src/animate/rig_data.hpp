// Footfall — what animating a crowd needs of a rig: the glTF document, the
// rest pose, the roles of the bones, the legs' geometry and the clips.
#pragma once

#include <tiny_gltf.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "footfall/animate/foot_roll.hpp"
#include "animate/transform.hpp"

namespace footfall::animate {

/// Points and directions between glTF's frame (Y up) and the plan's (Z up,
/// the ground the XY plane), as Blender converts them.
inline Vec3 to_z_up(Vec3 v) { return {v.x, -v.z, v.y}; }
inline Vec3 to_y_up(Vec3 v) { return {v.x, v.z, -v.y}; }

/// One animated property of one node: keys and values as glTF gives them
/// (CUBICSPLINE: in-tangent, value, out-tangent per key).
struct Track {
  enum Path { kTranslation, kRotation, kScale };
  enum Interpolation { kLinear, kStep, kCubic };
  int node = -1;
  Path path = kRotation;
  Interpolation interpolation = kLinear;
  std::vector<double> times;   ///< [s], increasing
  std::vector<double> values;  ///< components per value: 3, or 4 (x, y, z, w)
};

/// An upper-body clip: a rig's animation, or a procedural one.
struct Clip {
  std::string source;  ///< the animation's name (animations[N] if it has none), or "procedural"
  bool feet_step = false;  ///< its feet show a gait cycle (a walk, not an upper-body clip)
  double start = 0;    ///< [s] of the animation
  double cycle = 1;    ///< [s] of one gait cycle
  double strike = 0.25;  ///< the right heel strike, a fraction of the cycle
  std::vector<Track> tracks;
  /// Per node: its tracks' indices (translation, rotation, scale), -1: none.
  std::vector<std::array<int, 3>> track_of;
};

/// One leg's rest geometry, Z up. [m]
struct Leg {
  int thigh = -1, shin = -1, foot = -1, toe = -1;
  Vec3 hip, knee, ankle;
  double upper = 0, lower = 0;  ///< hip to knee, knee to ankle
  Vec3 pole_ahead;              ///< the knee's pole seen from the ankle
  FootShape shape;
  double foot_length = 0;       ///< heel to toe tip along the ground
};

struct RigData {
  std::string path;
  tinygltf::Model model;
  std::vector<int> parent;         ///< per node, -1 for a root
  std::vector<Mat4> rest_local;    ///< per node, glTF frame
  std::vector<Mat4> rest_world;    ///< per node, glTF frame
  std::vector<Trs> rest_trs;       ///< per node: rest_local as T, R, S
  std::vector<int> scene_roots;    ///< the default scene's root nodes
  std::vector<char> in_scene;      ///< per node: below one of them
  int skin = -1;                   ///< the skin of the rig's body
  /// Per node, the name its bone goes by: the node's, or nodes[N] for a
  /// joint with no name or a name another joint has too.
  std::vector<std::string> bone_names;
  int hips = -1;
  int chest = -1, head = -1;       ///< turned toward the path ahead
  std::array<Leg, 2> legs;         ///< left, right
  std::array<int, 2> upper_arms{}, forearms{}, hands{};  ///< left, right
  double forward_yaw = 0;          ///< the rig's facing at rest, Z up [rad]
  double hip_height = 0;           ///< [m]
  /// The nodes a clip poses: the joints below the hips, legs left out.
  std::vector<int> upper_body;
  std::map<std::string, Clip> clips;  ///< by behaviour
};

/// The local transform that gives node `node` the world transform `world`
/// (glTF frame) under a parent whose world transform is `parent_world`.
inline Mat4 local_under(const Mat4& parent_world, const Mat4& world) {
  return inverse(parent_world) * world;
}

}  // namespace footfall::animate
