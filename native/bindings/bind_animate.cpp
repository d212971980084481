// Rigs and the animated crowd as glTF: footfall._native.detect_bones,
// split_side, foot_roll, upper_body, keys_to_keep, find_gait_cycle, animate_gltf.
#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "footfall/animate/bone_map.hpp"
#include "footfall/animate/crowd_gltf.hpp"
#include "footfall/animate/foot_roll.hpp"
#include "footfall/animate/gait_cycle.hpp"
#include "footfall/animate/ground_follow.hpp"
#include "footfall/animate/key_thinning.hpp"
#include "footfall/animate/upper_body.hpp"

#include <algorithm>
#include <array>
#include <optional>

namespace footfall::bindings {

namespace py = pybind11;

namespace {

std::optional<Vec3> point_or_none(const py::handle& value) {
  if (value.is_none()) return std::nullopt;
  const auto xyz = value.cast<std::array<double, 3>>();
  return Vec3{xyz[0], xyz[1], xyz[2]};
}

}  // namespace

void bind_animate(py::module_& m) {
  py::dict amplitudes;
  amplitudes["heel_strike"] = animate::kHeelStrike;
  amplitudes["toe_off"] = animate::kToeOff;
  amplitudes["heel_share"] = animate::kHeelShare;
  amplitudes["stair_rise"] = animate::kStairRise;
  m.attr("FOOT_ROLL") = amplitudes;
  m.def(
      "detect_bones",
      [](const py::sequence& bones, const std::map<std::string, std::string>& given) {
        std::vector<RigBone> rig;
        for (const py::handle item : bones) {
          const auto fields = item.cast<py::sequence>();
          if (fields.size() != 4)
            throw std::invalid_argument("a bone is (name, parent or None, head or None, tail or None)");
          RigBone bone;
          bone.name = fields[0].cast<std::string>();
          if (!fields[1].is_none()) bone.parent = fields[1].cast<std::string>();
          bone.head = point_or_none(fields[2]);
          bone.tail = point_or_none(fields[3]);
          rig.push_back(std::move(bone));
        }
        const BoneDetection found = detect_bones(rig, given);
        return py::make_tuple(found.roles, found.missing);
      },
      py::arg("bones"), py::arg("given") = std::map<std::string, std::string>{},
      "A humanoid's bones by role: `bones` are (name, parent or None, rest head (x, y, z) or "
      "None, rest tail or None), Z up; `given` role -> bone for roles already chosen (\"hips\", "
      "\"left.thigh\", ...). Returns (role -> bone, the roles not found).");
  m.def(
      "foot_roll",
      [](const py::array_t<double>& times, const py::array_t<bool>& planted, int side,
         const py::array_t<double>& start, const py::array_t<double>& end, const py::array_t<int>& foot,
         const py::array_t<bool>& forward, const py::array_t<double>& speed, std::array<double, 5> shape,
         double full_speed, bool leaves) {
        const auto n = static_cast<std::size_t>(start.size());
        if (static_cast<std::size_t>(end.size()) != n || static_cast<std::size_t>(foot.size()) != n ||
            static_cast<std::size_t>(forward.size()) != n || static_cast<std::size_t>(speed.size()) != n)
          throw std::invalid_argument("the steps' arrays differ in length");
        if (planted.size() != times.size()) throw std::invalid_argument("times and planted differ in length");
        std::vector<animate::RollStep> steps(n);
        for (std::size_t i = 0; i < n; ++i)
          steps[i] = {start.at(i), end.at(i), foot.at(i), forward.at(i), speed.at(i)};
        const animate::FootRoller roller(std::move(steps), full_speed, leaves);
        const animate::FootShape foot_shape{shape[0], shape[1], shape[2], shape[3], shape[4]};
        const auto count = times.size();
        py::array_t<double> pitch(count), ahead(count), up(count);
        for (py::ssize_t i = 0; i < count; ++i) {
          const animate::FootRoll r = roller.at(times.at(i), side, planted.at(i), foot_shape);
          pitch.mutable_at(i) = r.pitch;
          ahead.mutable_at(i) = r.forward;
          up.mutable_at(i) = r.up;
        }
        return py::make_tuple(pitch, ahead, up);
      },
      py::arg("times"), py::arg("planted"), py::arg("side"), py::arg("start"), py::arg("end"), py::arg("foot"),
      py::arg("forward"), py::arg("speed"), py::arg("shape"), py::arg("full_speed"), py::arg("leaves") = false,
      "Heel-toe roll of foot `side` (0 left) at `times`, planted or not: (pitch, forward, up) arrays. "
      "Steps as arrays (start, end, foot, forward, speed); shape (ankle_height, heel_back, ball_ahead, "
      "ball_height, toe_off_limit).");
  m.def(
      "steepest_toe_off",
      [](std::array<double, 4> shape, const py::array_t<double>& skin) {
        if (skin.ndim() != 2 || skin.shape(1) != 4)
          throw std::invalid_argument("the skin is an array of (ahead, height, foot weight, toe weight) rows");
        std::vector<animate::SoleVertex> vertices(static_cast<std::size_t>(skin.shape(0)));
        for (py::ssize_t i = 0; i < skin.shape(0); ++i)
          vertices[static_cast<std::size_t>(i)] = {skin.at(i, 0), skin.at(i, 1), skin.at(i, 2), skin.at(i, 3)};
        return animate::steepest_toe_off({shape[0], shape[1], shape[2], shape[3]}, vertices);
      },
      py::arg("shape"), py::arg("skin"),
      "The most a foot's heel may rise in a stance [rad]: shape (ankle_height, heel_back, ball_ahead, "
      "ball_height) and the foot's skin at rest, rows of (ahead of the ankle, height, weight on the foot "
      "bone, on the toe bone) [m].");
  py::dict shares;
  shares["chest"] = animate::kChestLook;
  shares["head"] = animate::kHeadLook;
  m.attr("LOOK_SHARES") = shares;
  m.def(
      "upper_body",
      [](const AgentPlan& agent, const py::array_t<double>& times, double full_speed) {
        const animate::UpperBodyFollower follower(agent, full_speed);
        const auto count = times.size();
        py::array_t<double> facing(count), swing(count), look(count), twist(count);
        for (py::ssize_t i = 0; i < count; ++i) {
          const double t = times.at(i);
          facing.mutable_at(i) = animate::body_facing(agent, t);
          swing.mutable_at(i) = follower.swing_at(t);
          look.mutable_at(i) = follower.look_at(t);
          twist.mutable_at(i) = follower.twist_at(t);
        }
        return py::make_tuple(facing, swing, look, twist);
      },
      py::arg("agent"), py::arg("times"), py::arg("full_speed"),
      "How the upper body follows an agent's plan at `times` [s]: (facing, swing, look, twist) arrays: "
      "the body's facing [rad], the share of the walking clip's amplitude, the look angle [rad] the "
      "chest and head turn by (LOOK_SHARES of it each, the head on top of the chest), and the chest's "
      "twist [rad] to the heading the planner tested (on top of its look).");
  m.def(
      "ground_motion",
      [](const AgentPlan& agent, const CharacterParams& character, const Ground& ground,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& times,
         double heel_back, double toe_ahead, double width) {
        const animate::GroundFollower follower(agent, character, ground, {heel_back, toe_ahead, width});
        const py::ssize_t count = times.size();
        py::array_t<double> soles({count, py::ssize_t{2}, py::ssize_t{3}});
        py::array_t<double> headings({count, py::ssize_t{2}});
        py::array_t<double> normals({count, py::ssize_t{2}, py::ssize_t{3}});
        py::array_t<double> body(count), lean(count);
        auto s = soles.mutable_unchecked<3>();
        auto h = headings.mutable_unchecked<2>();
        auto n = normals.mutable_unchecked<3>();
        auto b = body.mutable_unchecked<1>();
        auto l = lean.mutable_unchecked<1>();
        const double* t = times.data();
        {
          py::gil_scoped_release release;
          for (py::ssize_t i = 0; i < count; ++i) {
            const std::array<FootPose, 2> feet = feet_at(agent, t[i]);
            for (py::ssize_t side = 0; side < 2; ++side) {
              const animate::FootOnGround foot = follower.foot(feet[static_cast<std::size_t>(side)]);
              const std::array<double, 3> sole{foot.sole.x, foot.sole.y, foot.sole.z};
              const std::array<double, 3> normal{foot.normal.x, foot.normal.y, foot.normal.z};
              for (py::ssize_t k = 0; k < 3; ++k) {
                s(i, side, k) = sole[static_cast<std::size_t>(k)];
                n(i, side, k) = normal[static_cast<std::size_t>(k)];
              }
              h(i, side) = foot.heading;
            }
            b(i) = follower.body_height(feet);
            l(i) = follower.lean(t[i]);
          }
        }
        return py::make_tuple(soles, headings, normals, body, lean);
      },
      py::arg("agent"), py::arg("character"), py::arg("ground"), py::arg("times"), py::arg("heel_back"),
      py::arg("toe_ahead"), py::arg("width"),
      "How the agent's motion follows the ground at `times` [s] (animate/ground_follow.hpp), for a foot "
      "`heel_back` behind and `toe_ahead` of the point under its ankle and `width` wide [m]: (soles "
      "(n, 2, 3): each foot's point under the ankle, lifted clear of the ground while it swings; "
      "headings (n, 2) [rad]; normals (n, 2, 3) of the soles' planes; body (n,): the ground's height "
      "the body rides over [m]; lean (n,): the upper body's lean into a climb [rad, forward "
      "positive]), feet [left, right].");
  m.def(
      "keys_to_keep",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& times,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& values,
         const std::vector<double>& tolerance, bool cubic, const std::vector<double>& scale) {
        if (times.ndim() != 1 || values.ndim() < 1 || values.ndim() > 2 || values.shape(0) != times.shape(0))
          throw std::invalid_argument("keys_to_keep: times must be (n,) and values (n,) or (n, channels)");
        const std::vector<double> t(times.data(), times.data() + times.size());
        const std::vector<double> v(values.data(), values.data() + values.size());
        std::vector<double> tol = tolerance;
        const auto channels = static_cast<std::size_t>(values.ndim() == 2 ? values.shape(1) : 1);
        if (tol.size() == 1) tol.assign(channels, tolerance[0]);
        if (tol.size() != channels)
          throw std::invalid_argument("keys_to_keep: one tolerance, or one per channel");
        animate::ThinnedKeys keys;
        {
          py::gil_scoped_release release;  // so that callers may thin several motions at once
          keys = animate::keys_to_keep(t, v, tol, cubic ? animate::KeyCurve::kCubic : animate::KeyCurve::kLinear,
                                       scale);
        }
        const auto kept_count = static_cast<py::ssize_t>(keys.kept.size());
        py::array_t<std::int64_t> kept(kept_count);
        for (py::ssize_t i = 0; i < kept_count; ++i) kept.mutable_at(i) = static_cast<std::int64_t>(keys.kept[i]);
        py::array_t<double> slopes({kept_count, static_cast<py::ssize_t>(channels)});
        std::copy(keys.slopes.begin(), keys.slopes.end(), slopes.mutable_data());
        return py::make_tuple(kept, slopes);
      },
      py::arg("times"), py::arg("values"), py::arg("tolerance"), py::arg("cubic") = true,
      py::arg("scale") = std::vector<double>{},
      "(kept, slopes): the indices of the samples to key (the first and the last among them) and "
      "their slopes (kept, channels), so that cubic Hermite curves between them (Bezier keys with "
      "handles a third of the way along the slopes), or with cubic=False straight lines, pass "
      "within `tolerance` (one number, or one per channel; times `scale[i]` at sample i, if given) "
      "of every sample, and through those that stand still: `times` (n,) increasing, `values` (n,) "
      "or (n, channels).");
  m.def(
      "find_gait_cycle",
      [](const std::vector<double>& feet, const std::vector<double>& hands, double leg_length) {
        const animate::GaitCycle found = animate::find_gait_cycle(feet, hands, leg_length);
        return py::make_tuple(found.cycles, found.strike, found.source);
      },
      py::arg("feet"), py::arg("hands"), py::arg("leg_length"),
      "(cycles, strike, source) of a clip sampled evenly over its range (its end left out): `feet` "
      "the right foot's lead over the left along the facing, `hands` the left hand's over the right.");
  m.def("stair_climbs", &animate::stair_climbs, py::arg("agent"),
        "Per footstep of the agent's plan: 1 where it climbs a stair, -1 where it goes down one, "
        "0 elsewhere (a rig's stair clips play there).");
  m.def("split_side", &split_side, py::arg("name"),
        "(side, base name) of a bone name: side 'left', 'right' or '' for the trunk.");
  m.def(
      "animate_gltf",
      [](const Plan& plan, const std::string& rig_path, const std::string& out_path, double fps,
         const std::string& profile_path) {
        CrowdGltfSummary summary;
        {
          py::gil_scoped_release release;
          const Rig rig = Rig::load(rig_path, rig_profile_for(rig_path, profile_path));
          CrowdGltfOptions options;
          options.fps = fps;
          summary = write_crowd_gltf(plan, rig, out_path, options);
        }
        py::dict result;
        result["agents"] = summary.agents;
        result["frames"] = summary.frames;
        result["bytes"] = summary.bytes;
        result["clips"] = summary.clips;
        return result;
      },
      py::arg("plan"), py::arg("rig_path"), py::arg("out_path"), py::arg("fps") = 24.0,
      py::arg("profile_path") = "",
      "Animates every agent of `plan` on the rig (.glb or .gltf; its profile beside it, "
      "RIG.json, if any, unless `profile_path` is given; bones it does not name are detected) and writes one animated .glb to `out_path`, "
      "`fps` keys a second. Returns {agents, frames, bytes, clips}. ValueError names what is "
      "wrong (the rig, its profile, an agent planned for another size); no file is left then.");
}

}  // namespace footfall::bindings
