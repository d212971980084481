// Reading a rig: the glTF document (tinygltf), its rest pose, the bones the
// profile names, the legs' geometry and the clips.
#include "footfall/animate/rig.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <utility>
#include <stdexcept>

#include "animate/accessor_data.hpp"
#include "animate/clips.hpp"
#include "animate/gltf_checks.hpp"
#include "animate/rig_data.hpp"
#include "footfall/animate/bone_map.hpp"
#include "util/quoted.hpp"

namespace footfall {

namespace {

using animate::Mat4;
using animate::RigData;
using animate::to_z_up;
using detail::user_text;

constexpr double kStandingDrop = 0.5;  // of the leg's length at least, from the hip joints down to the ankles
constexpr double kPoleAhead = 0.5;  // [m] knee poles in front of the knees, as the add-on's

// Images are carried over as they are, never decoded.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0) image->image.assign(bytes, bytes + size);  // a data URI's
  return true;
}

// A model tinygltf read (`ok`), or the reason it could not, naming `name`.
tinygltf::Model checked(bool ok, tinygltf::Model model, const std::string& error, const std::string& name) {
  if (!ok) {
    const std::string first = error.substr(0, error.find('\n'));
    throw std::invalid_argument(name + ": not a glTF file this Footfall can read: " +
                                user_text(first.empty() ? "no reason given" : first));
  }
  for (const std::string& extension : model.extensionsRequired) {
    throw std::invalid_argument(name + ": needs the glTF extension " + user_text(extension) +
                                ", which Footfall cannot carry into a crowd");
  }
  return model;
}

bool is_file(const std::string& path, void*) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

bool read_file(std::vector<unsigned char>* out, std::string* error, const std::string& path, void*) {
  std::ifstream in(path, std::ios::binary);
  if (!is_file(path, nullptr) || !in) {
    if (error) *error += "cannot read the file " + path + "\n";
    return false;
  }
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

// The files a .gltf names beside it are read as they are named: a URI naming
// a folder or a device is refused, and nothing is expanded or written.
tinygltf::FsCallbacks files_beside() {
  return {is_file, [](const std::string& path, void*) { return path; }, read_file,
          [](std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
            if (error) *error += "writing files is not allowed\n";
            return false;
          },
          nullptr};
}

// Bytes read from memory stand alone: buffers and images are data URIs or
// the .glb's own chunk, never files that happen to be near.
tinygltf::FsCallbacks no_files() {
  tinygltf::FsCallbacks callbacks = files_beside();
  callbacks.FileExists = [](const std::string&, void*) { return false; };
  callbacks.ReadWholeFile = [](std::vector<unsigned char>*, std::string* error, const std::string& path, void*) {
    if (error) *error += "a rig read from memory cannot name the file " + path + "\n";
    return false;
  };
  return callbacks;
}

tinygltf::Model read_model(const std::string& path) {
  std::error_code missing;
  if (!std::filesystem::is_regular_file(path, missing))
    throw std::invalid_argument(user_text(path) + ": no such file");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  loader.SetFsCallbacks(files_beside());
  tinygltf::Model model;
  std::string error, warning;
  const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                         : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  return checked(ok, std::move(model), error, path);
}

tinygltf::Model parse_model(const std::string& bytes, const std::string& name) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  loader.SetFsCallbacks(no_files());
  tinygltf::Model model;
  std::string error, warning;
  const bool ok =
      bytes.compare(0, 4, "glTF") == 0
          ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                        static_cast<unsigned int>(bytes.size()))
          : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()), "");
  return checked(ok, std::move(model), error, name);
}

Mat4 local_matrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return animate::from_columns(node.matrix.data());
  animate::Trs trs;
  if (node.translation.size() == 3) trs.translation = {node.translation[0], node.translation[1], node.translation[2]};
  if (node.rotation.size() == 4)
    trs.rotation = animate::normalized({node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]});
  if (node.scale.size() == 3) trs.scale = {node.scale[0], node.scale[1], node.scale[2]};
  return animate::to_matrix(trs);
}

// A transform that is a rotation, a uniform or per-axis scale and a
// translation, without shear or mirror, as poses of its children need.
bool without_shear(const Mat4& m) {
  const animate::Trs trs = animate::decompose(m);
  if (!(trs.scale.x > 0 && trs.scale.y > 0 && trs.scale.z > 0)) return false;
  const Mat4 back = animate::to_matrix(trs);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (std::abs(back.m[r][c] - m.m[r][c]) > 1e-5 * std::max(1.0, std::abs(m.m[r][c]))) return false;
  return true;
}

void read_hierarchy(RigData& rig) {
  const auto& nodes = rig.model.nodes;
  const std::size_t n = nodes.size();
  rig.parent.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    for (int child : nodes[i].children) {
      if (child < 0 || child >= static_cast<int>(n) || rig.parent[child] >= 0)
        throw std::invalid_argument(rig.path + ": nodes[" + std::to_string(i) + "]: a child that is not a node, or has two parents");
      rig.parent[child] = static_cast<int>(i);
    }
  const int scene = rig.model.defaultScene >= 0 ? rig.model.defaultScene : 0;
  if (scene < static_cast<int>(rig.model.scenes.size())) {
    rig.scene_roots = rig.model.scenes[scene].nodes;
  } else {
    for (std::size_t i = 0; i < n; ++i)
      if (rig.parent[i] < 0) rig.scene_roots.push_back(static_cast<int>(i));
  }
  rig.rest_local.resize(n);
  rig.rest_trs.resize(n);
  rig.rest_world.resize(n);
  std::vector<char> placed(n, 0);
  const std::function<void(int, const Mat4&, int)> place = [&](int node, const Mat4& above, int depth) {
    if (depth > static_cast<int>(n) || placed[node])
      throw std::invalid_argument(rig.path + ": the node hierarchy has a cycle");
    placed[node] = 1;
    rig.rest_local[node] = local_matrix(nodes[node]);
    rig.rest_trs[node] = animate::decompose(rig.rest_local[node]);
    rig.rest_world[node] = above * rig.rest_local[node];
    for (int child : nodes[node].children) place(child, rig.rest_world[node], depth + 1);
  };
  for (int root : rig.scene_roots) {
    if (root < 0 || root >= static_cast<int>(n) || rig.parent[root] >= 0)
      throw std::invalid_argument(rig.path + ": the scene lists a node that is not a root");
    place(root, Mat4{}, 0);
  }
  rig.in_scene = placed;
}

// What each joint goes by: its name, or nodes[N] where it has none or shares it.
std::vector<std::string> bone_names(const tinygltf::Model& model, const std::vector<int>& joints) {
  std::map<std::string, int> count;
  for (int joint : joints) ++count[model.nodes[joint].name];
  std::vector<std::string> names(model.nodes.size());
  for (int joint : joints) {
    const std::string& name = model.nodes[joint].name;
    names[joint] = name.empty() || count[name] > 1 ? "nodes[" + std::to_string(joint) + "]" : name;
  }
  return names;
}

// The node of a bone the profile names: one of the skin's joints.
int bone(const RigData& rig, const std::vector<int>& joints, const std::string& name, const std::string& field) {
  int found = -1, same = 0;
  for (int joint : joints) {
    same += rig.model.nodes[joint].name == name ? 1 : 0;
    if (rig.bone_names[joint] == name) found = joint;
  }
  if (same > 1)
    throw std::invalid_argument(rig.path + ": " + field + " = " + user_text(name) +
                                ": two bones have that name (name them nodes[N], by their index)");
  if (found < 0)
    throw std::invalid_argument(rig.path + ": " + field + " = " + user_text(name) + ": the rig has no such bone");
  return found;
}

// A skinned vertex of the rig's body at rest, Z up: the node of the joint
// that moves it most, and its weight on each node.
struct SkinnedVertex {
  int joint = -1;
  Vec3 position;
  std::array<std::pair<int, double>, 4> weights{};
  double weight_on(int node) const {
    double sum = 0;
    for (const auto& [n, w] : weights) sum += n == node ? w : 0.0;
    return sum;
  }
};

std::vector<SkinnedVertex> skinned_vertices(const RigData& rig) {
  const tinygltf::Skin& skin = rig.model.skins[rig.skin];
  std::vector<Mat4> bind(skin.joints.size());  // joint world at rest times its inverse bind matrix
  const std::vector<double> inverse =
      skin.inverseBindMatrices >= 0 ? animate::accessor_values(rig.model, skin.inverseBindMatrices) : std::vector<double>{};
  for (std::size_t j = 0; j < skin.joints.size(); ++j)
    bind[j] = rig.rest_world[skin.joints[j]] *
              (inverse.size() >= 16 * (j + 1) ? animate::from_columns(&inverse[16 * j]) : Mat4{});
  std::vector<SkinnedVertex> vertices;
  for (std::size_t node = 0; node < rig.model.nodes.size(); ++node) {
    const tinygltf::Node& n = rig.model.nodes[node];
    if (n.skin != rig.skin || n.mesh < 0) continue;
    for (const tinygltf::Primitive& primitive : rig.model.meshes[n.mesh].primitives) {
      const auto position = primitive.attributes.find("POSITION");
      const auto joint = primitive.attributes.find("JOINTS_0");
      const auto weight = primitive.attributes.find("WEIGHTS_0");
      if (position == primitive.attributes.end() || joint == primitive.attributes.end() ||
          weight == primitive.attributes.end())
        continue;
      const auto p = animate::accessor_values(rig.model, position->second);
      const auto j = animate::accessor_values(rig.model, joint->second);
      const auto w = animate::accessor_values(rig.model, weight->second);
      const std::size_t count = std::min({p.size() / 3, j.size() / 4, w.size() / 4});
      for (std::size_t v = 0; v < count; ++v) {
        const std::size_t strongest = static_cast<std::size_t>(std::max_element(&w[4 * v], &w[4 * v + 4]) - &w[4 * v]);
        const auto index = static_cast<std::size_t>(j[4 * v + strongest]);
        if (index >= skin.joints.size()) continue;
        Vec3 world{0, 0, 0};
        SkinnedVertex skinned;
        for (int k = 0; k < 4; ++k) {
          const auto jk = static_cast<std::size_t>(j[4 * v + k]);
          if (w[4 * v + k] <= 0 || jk >= bind.size()) continue;
          world = world + w[4 * v + k] * animate::transform_point(bind[jk], {p[3 * v], p[3 * v + 1], p[3 * v + 2]});
          skinned.weights[k] = {skin.joints[jk], w[4 * v + k]};
        }
        skinned.joint = skin.joints[index];
        skinned.position = to_z_up(world);
        vertices.push_back(skinned);
      }
    }
  }
  return vertices;
}

void read_legs(RigData& rig, const RigProfile& profile) {
  Vec3 forward{0, 0, 0};
  for (int side = 0; side < 2; ++side) {
    const animate::Leg& leg = rig.legs[side];
    forward = forward + (to_z_up(rig.rest_world[leg.toe].translation()) - to_z_up(rig.rest_world[leg.foot].translation()));
  }
  forward.z = 0;
  if (length(forward) < 1e-9)
    throw std::invalid_argument(rig.path + ": the feet point straight up or down at rest: the rig's facing is unclear");
  forward = animate::normalized(forward);
  rig.forward_yaw = std::atan2(forward.y, forward.x);
  const std::vector<SkinnedVertex> vertices = skinned_vertices(rig);
  double hips = 0;
  for (int side = 0; side < 2; ++side) {
    animate::Leg& leg = rig.legs[side];
    leg.hip = to_z_up(rig.rest_world[leg.thigh].translation());
    leg.knee = to_z_up(rig.rest_world[leg.shin].translation());
    leg.ankle = to_z_up(rig.rest_world[leg.foot].translation());
    const Vec3 ball = to_z_up(rig.rest_world[leg.toe].translation());
    leg.upper = length(leg.knee - leg.hip);
    leg.lower = length(leg.ankle - leg.knee);
    leg.pole_ahead = (leg.knee + kPoleAhead * forward) - leg.ankle;
    const auto found = profile.dimensions.find("foot_length");
    const double foot_length = leg.foot_length = found != profile.dimensions.end() ? found->second : length(ball - leg.ankle) / (1 - animate::kHeelShare);
    double heel = 0;
    std::vector<animate::SoleVertex> skin;
    for (const SkinnedVertex& v : vertices) {
      if (v.joint == leg.foot || v.joint == leg.toe) heel = std::max(heel, -dot(v.position - leg.ankle, forward));
      const double on_foot = v.weight_on(leg.foot), on_toe = v.weight_on(leg.toe);
      if (on_foot + on_toe > 0)
        skin.push_back({dot(v.position - leg.ankle, forward), v.position.z, on_foot, on_toe});
    }
    leg.shape = {leg.ankle.z, heel > 0 ? heel : animate::kHeelShare * foot_length, dot(ball - leg.ankle, forward),
                 ball.z};
    leg.shape.toe_off_limit = animate::steepest_toe_off(leg.shape, skin);
    hips += 0.5 * leg.hip.z;
    // Standing legs hang nearly straight down; a rig lying down (modelled Z
    // up and exported without turning it) would walk on its side.
    if (leg.hip.z - leg.ankle.z < kStandingDrop * (leg.upper + leg.lower))
      throw std::invalid_argument(rig.path + ": the rig does not stand upright at rest (the ankles are not below the "
                                  "hips): lying down, or turned as if glTF were Z up");
  }
  rig.hip_height = hips;
  if (!(rig.hip_height > 0))
    throw std::invalid_argument(rig.path + ": the hip joints are not above the ground (z = 0) at rest: a rig lying down or below the floor");
}

// A rig with no walk so named walks with the one animation whose feet step
// (Mixamo's "mixamo.com", a glTF's only animation) of those no other
// behaviour takes (`used`), as Import Rig takes it; else a procedural walk.
animate::Clip only_stepping_clip(const RigData& rig, const std::set<int>& used) {
  std::vector<animate::Clip> stepping;
  for (std::size_t i = 0; i < rig.model.animations.size(); ++i) {
    if (used.count(static_cast<int>(i)) > 0) continue;
    animate::Clip clip = animate::clip_from_animation(rig, static_cast<int>(i));
    if (clip.feet_step) stepping.push_back(std::move(clip));
  }
  return stepping.size() == 1 ? std::move(stepping[0]) : animate::procedural_clip(rig, "walk");
}

void read_clips(RigData& rig, const RigProfile& profile) {
  const auto& animations = rig.model.animations;
  const auto find = [&](const std::string& name, bool exact) {
    for (std::size_t i = 0; i < animations.size(); ++i) {
      std::string a = animations[i].name, b = name;
      if (!exact) {
        std::transform(a.begin(), a.end(), a.begin(), [](unsigned char c) { return std::tolower(c); });
        std::transform(b.begin(), b.end(), b.begin(), [](unsigned char c) { return std::tolower(c); });
      }
      if (a == b) return static_cast<int>(i);
    }
    return -1;
  };
  const auto named_index = [&](const char* behavior) {
    const auto named = profile.clips.find(behavior);
    if (named == profile.clips.end()) return find(behavior, false);
    const int index = find(named->second, true);
    if (index < 0) {
      std::string names;
      for (const auto& a : animations) names += (names.empty() ? "" : ", ") + user_text(a.name);
      throw std::invalid_argument(rig.path + ": clips." + behavior + " = " + user_text(named->second) +
                                  ": the rig has no such animation (it has: " + (names.empty() ? "none" : names) + ")");
    }
    return index;
  };
  std::map<std::string, int> named;  // each behaviour's animation, where it has one
  std::set<int> used;
  for (const char* behavior : kClipBehaviors) named[behavior] = named_index(behavior);
  for (const char* behavior : kStairClips) named[behavior] = named_index(behavior);
  for (const auto& [behavior, index] : named)
    if (index >= 0) used.insert(index);
  for (const auto& [behavior, index] : named) {
    if (index >= 0)
      rig.clips[behavior] = animate::clip_from_animation(rig, index);
    else if (behavior == "walk")
      rig.clips[behavior] = only_stepping_clip(rig, used);
    else if (std::find(std::begin(kClipBehaviors), std::end(kClipBehaviors), behavior) !=
             std::end(kClipBehaviors))
      rig.clips[behavior] = animate::procedural_clip(rig, behavior);
  }
}

// The skin of the rig's body: the one holding the profile's hips, else the
// one with the most joints; its joints must be nodes of the scene.
int body_skin(const RigData& rig, const RigProfile& profile) {
  const auto& skins = rig.model.skins;
  const auto hips = profile.bones.find("hips");
  int chosen = -1;
  for (std::size_t s = 0; s < skins.size(); ++s) {
    const bool has_hips = hips != profile.bones.end() &&
        std::any_of(skins[s].joints.begin(), skins[s].joints.end(), [&](int joint) {
          return joint >= 0 && joint < static_cast<int>(rig.model.nodes.size()) && rig.model.nodes[joint].name == hips->second;
        });
    if (hips != profile.bones.end() ? has_hips && chosen < 0
                                    : chosen < 0 || skins[s].joints.size() > skins[chosen].joints.size())
      chosen = static_cast<int>(s);
  }
  if (chosen < 0)
    throw std::invalid_argument(rig.path + (hips != profile.bones.end()
                                                ? ": no skin has the bone " + user_text(hips->second) + " (bones.hips)"
                                                : std::string(": no skin")) +
                                ": the rig needs a skinned mesh on a skeleton");
  for (int joint : skins[chosen].joints)
    if (joint < 0 || joint >= static_cast<int>(rig.model.nodes.size()) || !rig.in_scene[joint])
      throw std::invalid_argument(rig.path + ": skins[" + std::to_string(chosen) +
                                  "]: a joint that is not a node of the rig's scene");
  return chosen;
}

// The joints as bones for detection: heads where the joints are at rest,
// tails at their child joints' heads (their mean, for several), a leaf's
// half its parent's length on along it, as Blender's importer guesses.
std::vector<RigBone> skeleton(const RigData& rig, const std::vector<int>& joints) {
  std::map<int, int> parent_joint;  // joint -> nearest ancestor joint
  for (int joint : joints)
    for (int up = rig.parent[joint]; up >= 0; up = rig.parent[up])
      if (std::find(joints.begin(), joints.end(), up) != joints.end()) {
        parent_joint[joint] = up;
        break;
      }
  const auto head = [&](int joint) { return to_z_up(rig.rest_world[joint].translation()); };
  std::vector<RigBone> bones;
  for (int joint : joints) {
    RigBone bone;
    bone.name = rig.bone_names[joint];
    const auto parent = parent_joint.find(joint);
    if (parent != parent_joint.end()) bone.parent = rig.bone_names[parent->second];
    bone.head = head(joint);
    Vec3 sum{0, 0, 0};
    int children = 0;
    for (const auto& [child, above] : parent_joint)
      if (above == joint) {
        sum = sum + head(child);
        ++children;
      }
    if (children > 0)
      bone.tail = (1.0 / children) * sum;
    else if (parent != parent_joint.end())
      bone.tail = *bone.head + 0.5 * (*bone.head - head(parent->second));
    else
      bone.tail = *bone.head + Vec3{0, 0, 0.1};
    bones.push_back(std::move(bone));
  }
  return bones;
}

// Every role's bone: the profile's, the others detected.
std::map<std::string, std::string> bone_roles(const RigData& rig, const std::vector<int>& joints,
                                              const RigProfile& profile) {
  const std::vector<RigBone> bones = skeleton(rig, joints);
  const BoneDetection found = detect_bones(bones, profile.bones);
  if (found.missing.empty()) return found.roles;
  std::string missing, names;
  for (const std::string& role : found.missing) missing += (missing.empty() ? "" : ", ") + role;
  for (std::size_t i = 0; i < bones.size() && i < 200; ++i) names += (i ? ", " : "") + user_text(bones[i].name);
  throw std::invalid_argument(rig.path + ": could not find these bones: " + missing + " (its bones: " + names +
                              "); name them in a rig profile (docs/rig-profile.md)");
}

}  // namespace

Rig Rig::load(const std::string& path, const RigProfile& profile) {
  return from_model(read_model(path), path, profile);
}

Rig Rig::parse(const std::string& bytes, const std::string& name, const RigProfile& profile) {
  return from_model(parse_model(bytes, name), name, profile);
}

Rig Rig::from_model(tinygltf::Model model, const std::string& path, const RigProfile& profile) {
  auto rig = std::make_shared<RigData>();
  rig->path = path;
  rig->model = std::move(model);
  animate::check_references(rig->model, path);
  read_hierarchy(*rig);
  rig->skin = body_skin(*rig, profile);
  const std::vector<int>& joints = rig->model.skins[rig->skin].joints;
  rig->bone_names = bone_names(rig->model, joints);
  const std::map<std::string, std::string> roles = bone_roles(*rig, joints, profile);
  const auto node_of = [&](const std::string& role) { return bone(*rig, joints, roles.at(role), "bones." + role); };
  rig->hips = node_of("hips");
  rig->chest = node_of("chest");
  rig->head = node_of("head");
  const char* sides[] = {"left", "right"};
  for (int side = 0; side < 2; ++side) {
    const std::string prefix = std::string(sides[side]) + ".";
    animate::Leg& leg = rig->legs[side];
    leg.thigh = node_of(prefix + "thigh");
    leg.shin = node_of(prefix + "shin");
    leg.foot = node_of(prefix + "foot");
    leg.toe = node_of(prefix + "toe");
    rig->upper_arms[side] = node_of(prefix + "upper_arm");
    rig->forearms[side] = node_of(prefix + "forearm");
    rig->hands[side] = node_of(prefix + "hand");
    // The leg as a chain below the hips, as the IK poses it.
    const std::pair<int, int> links[] = {{leg.shin, leg.thigh}, {leg.foot, leg.shin}, {leg.toe, leg.foot}};
    const char* roles_below[] = {"shin", "foot", "toe"};
    const char* roles_above[] = {"thigh", "shin", "foot"};
    for (int k = 0; k < 3; ++k)
      if (rig->parent[links[k].first] != links[k].second)
        throw std::invalid_argument(path + ": bones." + prefix + roles_below[k] + " = " +
                                    user_text(roles.at(prefix + roles_below[k])) + ": not a child of the " +
                                    roles_above[k]);
    bool below = false;
    for (int up = rig->parent[leg.thigh]; up >= 0 && !below; up = rig->parent[up]) below = up == rig->hips;
    if (!below)
      throw std::invalid_argument(path + ": bones." + prefix + "thigh = " + user_text(roles.at(prefix + "thigh")) +
                                  ": not below the hips");
  }
  for (int joint : joints)
    if (!without_shear(rig->rest_world[joint]))
      throw std::invalid_argument(path + ": bone " + user_text(rig->bone_names[joint]) +
                                  ": its rest transform mirrors or shears it (apply the scale in the modelling tool first)");
  read_legs(*rig, profile);
  // The bones a clip poses: below the hips, the legs left out.
  for (int joint : joints) {
    bool below = false;
    for (int up = rig->parent[joint]; up >= 0 && !below; up = rig->parent[up]) below = up == rig->hips;
    bool leg = false;
    for (const animate::Leg& l : rig->legs) leg = leg || joint == l.thigh || joint == l.shin || joint == l.foot || joint == l.toe;
    if (below && !leg) rig->upper_body.push_back(joint);
  }
  read_clips(*rig, profile);
  Rig result;
  result.data_ = std::move(rig);
  return result;
}

double Rig::hip_height() const { return data_->hip_height; }
const std::string& Rig::path() const { return data_->path; }

std::map<std::string, std::string> Rig::clip_sources() const {
  std::map<std::string, std::string> sources;
  for (const auto& [behavior, clip] : data_->clips) sources[behavior] = clip.source;
  return sources;
}

}  // namespace footfall
