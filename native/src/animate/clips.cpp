#include "animate/clips.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "animate/accessor_data.hpp"
#include "footfall/animate/gait_cycle.hpp"
#include "footfall/model/geometry.hpp"

namespace footfall::animate {

namespace {

const double kConvention = GaitCycle{}.strike;  // the right heel strike of a procedural clip
constexpr int kCycleSamples = 64;     // poses sampled over a clip to find its cycle
constexpr double kSwing = 0.3490658503988659;  // 20 deg: the procedural arm swing each way
constexpr int kProceduralKeys = 8;    // keys per procedural cycle

Track::Interpolation interpolation_of(const std::string& name) {
  if (name == "STEP") return Track::kStep;
  if (name == "CUBICSPLINE") return Track::kCubic;
  return Track::kLinear;
}

void index_tracks(Clip& clip, std::size_t nodes) {
  clip.track_of.assign(nodes, {-1, -1, -1});
  for (std::size_t i = 0; i < clip.tracks.size(); ++i)
    clip.track_of[clip.tracks[i].node][clip.tracks[i].path] = static_cast<int>(i);
}

// The value of a track at time t (components 3 or 4).
std::array<double, 4> evaluate(const Track& track, double t) {
  const int n = track.path == Track::kRotation ? 4 : 3;
  const int per_key = track.interpolation == Track::kCubic ? 3 * n : n;
  const int offset = track.interpolation == Track::kCubic ? n : 0;  // the value, between the tangents
  const std::vector<double>& times = track.times;
  const auto value = [&](std::size_t k) { return &track.values[k * per_key + offset]; };
  std::array<double, 4> out{0, 0, 0, 1};
  const auto set = [&](const double* v) { std::copy(v, v + n, out.begin()); };
  if (t <= times.front() || times.size() == 1) {
    set(value(0));
    return out;
  }
  if (t >= times.back()) {
    set(value(times.size() - 1));
    return out;
  }
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const double span = times[k + 1] - times[k];
  const double w = (t - times[k]) / span;
  if (track.interpolation == Track::kStep) {
    set(value(k));
    return out;
  }
  if (track.interpolation == Track::kCubic) {
    const double w2 = w * w, w3 = w2 * w;
    const double* p0 = value(k);
    const double* m0 = &track.values[k * per_key + 2 * n];        // out-tangent of key k
    const double* p1 = value(k + 1);
    const double* m1 = &track.values[(k + 1) * per_key];          // in-tangent of key k + 1
    for (int c = 0; c < n; ++c)
      out[c] = (2 * w3 - 3 * w2 + 1) * p0[c] + (w3 - 2 * w2 + w) * span * m0[c] +
               (-2 * w3 + 3 * w2) * p1[c] + (w3 - w2) * span * m1[c];
    if (n == 4) {
      const Quat q = normalized({out[3], out[0], out[1], out[2]});
      out = {q.x, q.y, q.z, q.w};
    }
    return out;
  }
  const double* a = value(k);
  const double* b = value(k + 1);
  if (n == 4) {
    const Quat q = slerp({a[3], a[0], a[1], a[2]}, {b[3], b[0], b[1], b[2]}, w);
    return {q.x, q.y, q.z, q.w};
  }
  for (int c = 0; c < n; ++c) out[c] = (1 - w) * a[c] + w * b[c];
  return out;
}

// World positions (Z up) of `nodes` at time t of the clip.
std::vector<Vec3> pose_positions(const RigData& rig, const Clip& clip, double t,
                                 const std::vector<int>& nodes) {
  std::vector<Mat4> world(rig.parent.size());
  std::vector<char> done(rig.parent.size(), 0);
  const auto world_of = [&](int node, const auto& self) -> const Mat4& {
    if (!done[node]) {
      const Mat4 local = to_matrix(sample(clip, node, rig.rest_trs[node], t));
      world[node] = rig.parent[node] < 0 ? local : self(rig.parent[node], self) * local;
      done[node] = 1;
    }
    return world[node];
  };
  std::vector<Vec3> out;
  for (int node : nodes) out.push_back(to_z_up(world_of(node, world_of).translation()));
  return out;
}

// The clip's cycle and right heel strike: where the right foot is furthest
// ahead of the left; for a clip whose feet keep still, where the left hand
// is furthest ahead of the right (arms swing against the legs).
void find_cycle(const RigData& rig, Clip& clip, double duration) {
  const Vec3 forward{std::cos(rig.forward_yaw), std::sin(rig.forward_yaw), 0.0};
  const std::vector<int> nodes{rig.legs[0].foot, rig.legs[1].foot, rig.hands[0], rig.hands[1]};
  std::vector<double> feet(kCycleSamples), hands(kCycleSamples);
  for (int i = 0; i < kCycleSamples; ++i) {
    const auto p = pose_positions(rig, clip, clip.start + duration * i / kCycleSamples, nodes);
    feet[i] = dot(p[1] - p[0], forward);
    hands[i] = dot(p[2] - p[3], forward);
  }
  const double leg = 0.5 * (rig.legs[0].upper + rig.legs[0].lower + rig.legs[1].upper + rig.legs[1].lower);
  const GaitCycle found = find_gait_cycle(feet, hands, leg);
  clip.cycle = duration / found.cycles;
  clip.strike = found.strike;
  clip.feet_step = found.source == "feet";
}

}  // namespace

Clip clip_from_animation(const RigData& rig, int index) {
  const tinygltf::Animation& animation = rig.model.animations[index];
  Clip clip;
  clip.source = animation.name.empty() ? "animations[" + std::to_string(index) + "]" : animation.name;
  double first = 1e300, last = -1e300;
  for (const tinygltf::AnimationChannel& channel : animation.channels) {
    Track track;
    if (channel.target_path == "translation") track.path = Track::kTranslation;
    else if (channel.target_path == "rotation") track.path = Track::kRotation;
    else if (channel.target_path == "scale") track.path = Track::kScale;
    else continue;  // morph weights: not a bone's
    const std::string where = "animation '" + animation.name + "'";
    if (channel.target_node < 0 || channel.target_node >= static_cast<int>(rig.parent.size()))
      throw std::invalid_argument(where + ": a channel targets no node");
    if (channel.sampler < 0 || channel.sampler >= static_cast<int>(animation.samplers.size()))
      throw std::invalid_argument(where + ": a channel has no sampler");
    const tinygltf::AnimationSampler& sampler = animation.samplers[channel.sampler];
    track.node = channel.target_node;
    track.interpolation = interpolation_of(sampler.interpolation);
    track.times = accessor_values(rig.model, sampler.input);
    track.values = accessor_values(rig.model, sampler.output);
    const std::size_t per_key = (track.path == Track::kRotation ? 4 : 3) * (track.interpolation == Track::kCubic ? 3 : 1);
    if (track.times.empty() || track.values.size() != track.times.size() * per_key ||
        !std::is_sorted(track.times.begin(), track.times.end()))
      throw std::invalid_argument(where + ": a sampler's keys and values do not match");
    const auto finite = [](const std::vector<double>& xs) {
      return std::all_of(xs.begin(), xs.end(), [](double x) { return std::isfinite(x); });
    };
    if (!finite(track.times) || !finite(track.values))
      throw std::invalid_argument(where + ": a sampler has a key time or value that is not a finite number");
    first = std::min(first, track.times.front());
    last = std::max(last, track.times.back());
    clip.tracks.push_back(std::move(track));
  }
  index_tracks(clip, rig.parent.size());
  if (clip.tracks.empty() || last <= first) {
    clip.start = 0;
    clip.cycle = 1;
    clip.strike = kConvention;
    return clip;
  }
  clip.start = first;
  find_cycle(rig, clip, last - first);
  return clip;
}

Clip procedural_clip(const RigData& rig, const std::string& behavior) {
  Clip clip;
  clip.source = "procedural";
  clip.cycle = behavior == "idle" ? 2.0 : 1.0;
  clip.strike = kConvention;
  const Vec3 forward{std::cos(rig.forward_yaw), std::sin(rig.forward_yaw), 0.0};
  const Vec3 right{forward.y, -forward.x, 0.0};  // turning about it swings a hanging arm forward
  for (int side = 0; side < 2; ++side) {
    const int arm = rig.upper_arms[side];
    const int child = rig.forearms[side];
    const double sign = side == 0 ? 1.0 : -1.0;
    const Mat4& world = rig.rest_world[arm];
    const Vec3 along = normalized(to_z_up(rig.rest_world[child].translation() - world.translation()));
    Track track;
    track.node = arm;
    track.path = Track::kRotation;
    for (int k = 0; k <= kProceduralKeys; ++k) {
      const double phase = static_cast<double>(k) / kProceduralKeys;
      Quat turn;  // in the world, Z up
      if (behavior == "walk") {
        // The left arm forward at a quarter cycle, the right arm opposite.
        turn = axis_angle(right, sign * kSwing * std::sin(2 * kPi * phase));
      } else if (behavior == "arms_in") {
        const Vec3 down{0, 0, -1};
        const Vec3 axis = cross(along, down);
        if (length(axis) > 1e-9) turn = axis_angle(normalized(axis), std::acos(std::clamp(dot(along, down), -1.0, 1.0)));
      }
      // The same turn in glTF's frame, then seen from the arm's rest: the
      // local rotation that turns the arm by it with its parents at rest.
      const Vec3 axis_y_up = to_y_up({turn.x, turn.y, turn.z});
      const Quat turn_y_up{turn.w, axis_y_up.x, axis_y_up.y, axis_y_up.z};
      const Quat rest_world = decompose(world).rotation;
      const Quat local = rig.rest_trs[arm].rotation * (Quat{rest_world.w, -rest_world.x, -rest_world.y, -rest_world.z} * turn_y_up * rest_world);
      track.times.push_back(phase * clip.cycle);
      for (double v : {local.x, local.y, local.z, local.w}) track.values.push_back(v);
    }
    clip.tracks.push_back(std::move(track));
  }
  index_tracks(clip, rig.parent.size());
  return clip;
}

Trs sample(const Clip& clip, int node, const Trs& rest, double t) {
  Trs pose = rest;
  const std::array<int, 3>& tracks = clip.track_of[node];
  if (tracks[Track::kTranslation] >= 0) {
    const auto v = evaluate(clip.tracks[tracks[Track::kTranslation]], t);
    pose.translation = {v[0], v[1], v[2]};
  }
  if (tracks[Track::kRotation] >= 0) {
    const auto v = evaluate(clip.tracks[tracks[Track::kRotation]], t);
    pose.rotation = normalized({v[3], v[0], v[1], v[2]});
  }
  if (tracks[Track::kScale] >= 0) {
    const auto v = evaluate(clip.tracks[tracks[Track::kScale]], t);
    pose.scale = {v[0], v[1], v[2]};
  }
  return pose;
}

}  // namespace footfall::animate
