// Footfall — the parameter structs and obstacles read from and written to
// JSON (io/param_json.hpp).
#include "io/param_json.hpp"

#include <algorithm>
#include <iterator>
#include <type_traits>

#include "footfall/model/footstep.hpp"
#include "model/param_checks.hpp"

namespace footfall {
namespace detail {

namespace {

template <class S>
bool read_field(const Json& value, const std::string& key, const std::string& path, S& target);

// Reads every key of the object `json` into `target`, by S's table; a key
// that is no field of S goes to unknown(key, value, path) (by default: refused).
template <class S, class Unknown>
void read_struct(const Json& json, const std::string& path, S& target, Unknown unknown) {
  if (!json.is_object()) fail(path, "expected an object, got " + type_name(json));
  for (auto it = json.begin(); it != json.end(); ++it) {
    const std::string field = child(path, it.key());
    if (!read_field(it.value(), it.key(), field, target)) unknown(it.key(), it.value(), field);
  }
}

template <class S>
void read_struct(const Json& json, const std::string& path, S& target) {
  read_struct(json, path, target, [](const std::string&, const Json&, const std::string& field) {
    fail(field, "unknown field");
  });
}

// One table entry read from `value`, if its name is `key`.
template <class S>
struct FieldReader {
  const Json& value;
  const std::string& key;
  const std::string& path;
  S& target;
  bool found = false;

  void operator()(const ScalarParam<S, double>& field) {
    if (claim(field.name)) target.*field.member = number(value, path);
  }
  void operator()(const ScalarParam<S, int>& field) {
    if (!claim(field.name)) return;
    const long long whole = integer(value, path);
    check_range(target, static_cast<double>(whole), field.range, path);  // before narrowing
    target.*field.member = static_cast<int>(whole);
  }
  template <class N>
  void operator()(const NestedParam<S, N>& field) {
    if (claim(field.name)) read_struct(value, path, target.*field.member);
  }
  void operator()(const NumberListParam<S>& field) {
    if (!claim(field.name)) return;
    std::vector<double>& list = target.*field.member;
    list.clear();
    const Json& items = array(value, path);
    for (std::size_t i = 0; i < items.size(); ++i) list.push_back(number(items[i], item(path, i)));
  }
  template <class E>
  void operator()(const StructListParam<S, E>& field) {
    if (!claim(field.name)) return;
    std::vector<E>& list = target.*field.member;
    list.clear();
    const Json& items = array(value, path);
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string item_path = item(path, i);
      E element;
      read_struct(items[i], item_path, element);
      // Every field of an item is given: an item is a whole, not an override.
      for_each_param<E>([&](const auto& f) { require(items[i], item_path, f.name); });
      list.push_back(element);
    }
  }

 private:
  bool claim(const char* name) {
    if (found || key != name) return false;
    found = true;
    return true;
  }
};

template <class S>
bool read_field(const Json& value, const std::string& key, const std::string& path, S& target) {
  FieldReader<S> reader{value, key, path, target};
  for_each_param<S>([&](const auto& field) { reader(field); });
  return reader.found;
}

// Every number and nested struct of `source`, by the table's names.
template <class S>
Json struct_to_json(const S& source) {
  Json json = Json::object();
  for_each_param<S>([&](const auto& field) {
    using Field = std::decay_t<decltype(field)>;
    if constexpr (std::is_same_v<Field, ScalarParam<S, double>> ||
                  std::is_same_v<Field, ScalarParam<S, int>>) {
      json[field.name] = source.*field.member;
    } else if constexpr (std::is_same_v<Field, NumberListParam<S>>) {
      json[field.name] = source.*field.member;
    } else if constexpr (std::is_same_v<Field, NestedParam<S, FootLimits>>) {
      json[field.name] = struct_to_json(source.*field.member);
    } else {
      Json items = Json::array();
      for (const auto& element : source.*field.member) items.push_back(struct_to_json(element));
      json[field.name] = items;
    }
  });
  return json;
}

}  // namespace

namespace {

constexpr Behavior kBehaviors[] = {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep};

// One pose: every limb by name, as [ax, ay, az, bx, by, bz, radius].
BodyPose read_pose(const Json& json, const std::string& path) {
  if (!json.is_object()) fail(path, "expected an object of limbs, got " + type_name(json));
  std::vector<std::string> limbs;
  for (int limb = 0; limb < kLimbCount; ++limb) limbs.push_back(to_string(static_cast<Limb>(limb)));
  for (auto it = json.begin(); it != json.end(); ++it)
    if (std::find(limbs.begin(), limbs.end(), it.key()) == limbs.end())
      fail(child(path, it.key()), "unknown limb");
  BodyPose pose;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const std::string at = child(path, limbs[limb]);
    const Json& c = array(require(json, path, limbs[limb].c_str()), at);
    if (c.size() != 7) fail(at, "expected [ax, ay, az, bx, by, bz, radius], got " +
                                    std::to_string(c.size()) + " items");
    double v[7];
    for (int k = 0; k < 7; ++k) v[k] = number(c[k], item(at, k));
    pose[limb] = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
  }
  return pose;
}

void read_motions(const Json& json, const std::string& path, CharacterParams& params) {
  if (!json.is_object()) fail(path, "expected an object, got " + type_name(json));
  for (auto it = json.begin(); it != json.end(); ++it) {
    const std::string at = child(path, it.key());
    const Behavior* behavior = std::find_if(std::begin(kBehaviors), std::end(kBehaviors),
                                            [&](Behavior b) { return it.key() == to_string(b); });
    if (behavior == std::end(kBehaviors)) fail(at, "unknown behaviour (walk, arms_in, side_step)");
    expect_object(it.value(), at, {"cycle_duration", "speed", "poses"});
    BehaviorMotion motion;
    motion.cycle_duration =
        number(require(it.value(), at, "cycle_duration"), child(at, "cycle_duration"));
    motion.speed = number(require(it.value(), at, "speed"), child(at, "speed"));
    const std::string poses_path = child(at, "poses");
    const Json& poses = array(require(it.value(), at, "poses"), poses_path);
    for (std::size_t i = 0; i < poses.size(); ++i)
      motion.poses.push_back(read_pose(poses[i], item(poses_path, i)));
    params.motions[static_cast<int>(*behavior)] = std::move(motion);
  }
}

Json motions_to_json(const CharacterParams& params) {
  Json json = Json::object();
  for (const Behavior behavior : kBehaviors) {
    const BehaviorMotion& motion = params.motions[static_cast<int>(behavior)];
    if (motion.empty()) continue;
    Json poses = Json::array();
    for (const BodyPose& pose : motion.poses) {
      Json limbs = Json::object();
      for (int limb = 0; limb < kLimbCount; ++limb) {
        const Capsule& c = pose[limb];
        limbs[to_string(static_cast<Limb>(limb))] = {c.a.x, c.a.y, c.a.z, c.b.x, c.b.y, c.b.z, c.radius};
      }
      poses.push_back(std::move(limbs));
    }
    json[to_string(behavior)] = {
        {"cycle_duration", motion.cycle_duration}, {"speed", motion.speed}, {"poses", poses}};
  }
  return json;
}

}  // namespace

void read_character(const Json& json, const std::string& path, CharacterParams& params) {
  // A flat foot-limit key sets both feet; "behaviors" holds sampled motions.
  read_struct(json, path, params, [&](const std::string& key, const Json& value,
                                      const std::string& field) {
    if (key == "behaviors") return read_motions(value, field, params);
    if (!read_field(value, key, field, params.left)) fail(field, "unknown field");
    read_field(value, key, field, params.right);
  });
  // Per-foot objects win over flat keys, whatever their order in the file.
  for (const char* side : {"left", "right"})
    if (json.contains(side))
      read_struct(json[side], child(path, side), side[0] == 'l' ? params.left : params.right);
}

void read_planner(const Json& json, const std::string& path, PlannerParams& params) {
  read_struct(json, path, params);
}

namespace {

TriangleMesh read_mesh(const Json& json, const std::string& path) {
  expect_object(json, path, {"vertices", "triangles"});
  TriangleMesh mesh;
  const std::string vertices_path = child(path, "vertices");
  const Json& vertices = array(require(json, path, "vertices"), vertices_path);
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const std::string at = item(vertices_path, k);
    const Json& xyz = array(vertices[k], at);
    if (xyz.size() != 3) fail(at, "expected [x, y, z], got " + std::to_string(xyz.size()) + " items");
    mesh.vertices.push_back(
        {number(xyz[0], item(at, 0)), number(xyz[1], item(at, 1)), number(xyz[2], item(at, 2))});
  }
  const std::string triangles_path = child(path, "triangles");
  const Json& triangles = array(require(json, path, "triangles"), triangles_path);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::string at = item(triangles_path, t);
    const Json& ijk = array(triangles[t], at);
    if (ijk.size() != 3) fail(at, "expected [i, j, k], got " + std::to_string(ijk.size()) + " items");
    std::array<int, 3> triangle{};
    for (int c = 0; c < 3; ++c) {
      const long long index = integer(ijk[c], item(at, c));
      if (index < 0 || index >= static_cast<long long>(vertices.size()))
        fail(item(at, c), "vertex index " + std::to_string(index) + " is not in [0, " +
                              std::to_string(vertices.size()) + ")");
      triangle[c] = static_cast<int>(index);
    }
    mesh.triangles.push_back(triangle);
  }
  if (mesh.triangles.empty()) fail(triangles_path, "needs at least one triangle");
  return mesh;
}

}  // namespace

namespace {

// Prisms and meshes, as obstacles and ground (`ground`) give them: a
// ground's prism must give its height, and its base defaults to min(0,
// height) where an obstacle's is 0.
std::vector<Obstacle> read_shapes(const Json& json, const std::string& name, bool ground) {
  std::vector<Obstacle> result;
  const Json& shapes = array(json, name);
  for (size_t i = 0; i < shapes.size(); ++i) {
    const std::string path = item(name, i);
    expect_object(shapes[i], path, {"polygon", "height", "base", "mesh"});
    Obstacle shape;
    if (shapes[i].contains("mesh")) {
      for (const char* prism_field : {"polygon", "height", "base"})
        if (shapes[i].contains(prism_field))
          fail(child(path, prism_field), "not with \"mesh\": a mesh gives its own shape");
      shape.mesh = read_mesh(shapes[i]["mesh"], child(path, "mesh"));
      result.push_back(std::move(shape));
      continue;
    }
    const std::string polygon_path = child(path, "polygon");
    const Json& polygon = array(require(shapes[i], path, "polygon"), polygon_path);
    for (size_t k = 0; k < polygon.size(); ++k)
      shape.polygon.push_back(point(polygon[k], item(polygon_path, k)));
    if (shapes[i].contains("height") || ground)
      shape.height = number(require(shapes[i], path, "height"), child(path, "height"));
    shape.base = shapes[i].contains("base") ? number(shapes[i]["base"], child(path, "base"))
                 : ground                   ? std::min(0.0, shape.height)
                                            : 0.0;
    result.push_back(std::move(shape));
  }
  return result;
}

}  // namespace

std::vector<Obstacle> read_obstacles(const Json& json) {
  return read_shapes(json, "obstacles", false);
}

std::vector<Obstacle> read_ground(const Json& json) {
  return read_shapes(json, "ground", true);
}

Json obstacle_to_json(const Obstacle& obstacle) {
  if (obstacle.is_mesh()) {
    Json vertices = Json::array(), triangles = Json::array();
    for (const Vec3 v : obstacle.mesh.vertices) vertices.push_back({v.x, v.y, v.z});
    for (const auto& t : obstacle.mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
    return {{"mesh", {{"vertices", std::move(vertices)}, {"triangles", std::move(triangles)}}}};
  }
  Json polygon = Json::array();
  for (const Vec2 p : obstacle.polygon) polygon.push_back(to_json(p));
  Json json{{"polygon", std::move(polygon)}, {"height", obstacle.height}};
  if (obstacle.base != 0.0) json["base"] = obstacle.base;  // a prism from the ground says nothing
  return json;
}

Json character_to_json(const CharacterParams& params, bool ground) {
  Json json = struct_to_json(params);
  if (!ground)
    for (const char* field : kGroundCharacterFields) json.erase(field);
  Json motions = motions_to_json(params);
  if (!motions.empty()) json["behaviors"] = std::move(motions);
  return json;
}

}  // namespace detail

}  // namespace footfall
