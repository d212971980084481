#include "animate/agent_motion.hpp"

#include <algorithm>
#include <cmath>

#include "animate/clips.hpp"
#include "animate/section_timing.hpp"
#include "footfall/animate/ground_follow.hpp"
#include "footfall/animate/upper_body.hpp"
#include "footfall/model/geometry.hpp"

namespace footfall::animate {

namespace {

constexpr double kReach = 0.995;  // share of the leg's length the hips may stretch it to (a locked knee snaps)

// glTF's frame (Y up) as seen from the plan's (Z up), and back.
Mat4 y_up_to_z_up() {
  Mat4 c;
  c.m[1] = {0, 0, -1, 0};
  c.m[2] = {0, 1, 0, 0};
  return c;
}

// A rigid motion of the plan's world (Z up) expressed in glTF's frame.
Mat4 in_gltf(const Mat4& motion) {
  static const Mat4 c = y_up_to_z_up();
  static const Mat4 c_inverse = inverse(c);
  return c_inverse * motion * c;
}

Mat4 turn_about_z(double yaw) { return rotation(axis_angle({0, 0, 1}, yaw)); }

// The shortest turn taking the up direction to `normal` (a sole's plane).
Quat tilt_to(Vec3 normal) {
  const Vec3 axis = cross({0, 0, 1}, normal);
  const double sine = length(axis);
  if (sine == 0.0) return {};
  return axis_angle((1.0 / sine) * axis, std::atan2(sine, normal.z));
}

// The rotation taking the frame (a, b) to (c, d): each pair a direction and a
// second one off it (the knee's plane), orthonormalised.
Mat4 frame_turn(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const auto frame = [](Vec3 x, Vec3 y) {
    x = normalized(x);
    y = normalized(y - dot(y, x) * x);
    const Vec3 z = cross(x, y);
    Mat4 f;
    f.m[0] = {x.x, y.x, z.x, 0};
    f.m[1] = {x.y, y.y, z.y, 0};
    f.m[2] = {x.z, y.z, z.z, 0};
    return f;
  };
  const Mat4 from = frame(a, b);
  Mat4 from_t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) from_t.m[i][j] = from.m[j][i];
  return frame(c, d) * from_t;
}

// The angle nearest `previous` that equals `angle` modulo a turn.
double unwrapped(double angle, double previous) {
  return angle + 2 * kPi * std::round((previous - angle) / (2 * kPi));
}

// A node's pose from the clips playing over its rest, bottom up, as Blender's
// NLA mixes them: each channel a clip keys, value by value (quaternion
// components too) by the clip's influence; a channel it does not key is left
// as the tracks below give it.
Trs layered(const std::vector<ClipLayer>& layers, int node, const Trs& rest) {
  Trs pose = rest;
  for (const ClipLayer& layer : layers) {
    const Trs clip = sample(*layer.clip, node, rest, layer.time);
    const auto& keyed = layer.clip->track_of[node];
    const double w = layer.influence;
    if (keyed[Track::kTranslation] >= 0) pose.translation = (1 - w) * pose.translation + w * clip.translation;
    if (keyed[Track::kRotation] >= 0) {
      const Quat& p = pose.rotation;
      const Quat& q = clip.rotation;
      pose.rotation = {(1 - w) * p.w + w * q.w, (1 - w) * p.x + w * q.x, (1 - w) * p.y + w * q.y,
                       (1 - w) * p.z + w * q.z};
    }
    if (keyed[Track::kScale] >= 0) pose.scale = (1 - w) * pose.scale + w * clip.scale;
  }
  pose.rotation = normalized(pose.rotation);
  return pose;
}

// Keeps a node's rest translation and scale, with the rotation of `local`:
// the skeleton stays rigid whatever the IK asked of it.
Trs rotated_rest(const Trs& rest, const Mat4& local) {
  Trs trs = rest;
  trs.rotation = decompose(local).rotation;
  return trs;
}

}  // namespace

AgentMotion agent_motion(const RigData& rig, const AgentPlan& plan, const CharacterParams& character,
                         const Ground& ground, const std::vector<double>& times, double fps) {
  AgentMotion motion;
  const std::size_t frames = times.size();
  const auto add = [&](int node) {
    motion.nodes.push_back(node);
    motion.frames.emplace_back(frames);
    return motion.nodes.size() - 1;
  };
  const std::size_t hips_slot = add(rig.hips);
  std::array<std::array<std::size_t, 4>, 2> leg_slots;
  for (int side = 0; side < 2; ++side) {
    const Leg& leg = rig.legs[side];
    leg_slots[side] = {add(leg.thigh), add(leg.shin), add(leg.foot), add(leg.toe)};
  }
  std::vector<std::size_t> upper_slots;
  for (int node : rig.upper_body) upper_slots.push_back(add(node));

  const Vec3 hips_head = to_z_up(rig.rest_world[rig.hips].translation());
  const Mat4 hips_parent = rig.parent[rig.hips] >= 0 ? rig.rest_world[rig.parent[rig.hips]] : Mat4{};
  const Vec3 forward{std::cos(rig.forward_yaw), std::sin(rig.forward_yaw), 0.0};
  const Vec3 lateral = cross(forward, {0, 0, 1});  // the feet pitch about it
  const FootRoller roller(plan, character.preferred_speed);
  const UpperBodyFollower follower(plan, character.preferred_speed);
  // The ground's: in the plan's metres, the rig's left foot for both.
  const FootShape& foot_shape = rig.legs[0].shape;
  const GroundFollower on_ground(plan, character, ground,
                                 {plan.scale * foot_shape.heel_back,
                                  plan.scale * (rig.legs[0].foot_length - foot_shape.heel_back),
                                  character.sole_width});
  // A direction of the plan's world (Z up) as a node's rest frame sees it:
  // the toes bend about the side axis, the chest and head turn about the up.
  const auto at_rest = [&](int node, Vec3 direction) {
    const Quat rest = decompose(rig.rest_world[node]).rotation;
    return rotate({rest.w, -rest.x, -rest.y, -rest.z}, to_y_up(direction));
  };
  const std::array<Vec3, 2> toe_axes{at_rest(rig.legs[0].toe, lateral), at_rest(rig.legs[1].toe, lateral)};
  const Vec3 chest_up = at_rest(rig.chest, {0, 0, 1}), head_up = at_rest(rig.head, {0, 0, 1});
  const Vec3 chest_side = at_rest(rig.chest, lateral);
  const SectionTiming timing(plan, rig.clips, times.empty() ? 0.0 : times.back(), fps);
  double body_yaw = 0, previous_yaw = 0;
  std::array<double, 2> foot_yaw{0, 0}, previous_foot{0, 0};

  for (std::size_t f = 0; f < frames; ++f) {
    const double t = std::min(times[f], plan.end_time());
    // In the rig's own size: the agent's node scales it to the plan's (AgentPlan::scale).
    const Vec2 com = (1.0 / plan.scale) * com_at(plan, t).position;
    const std::array<FootPose, 2> feet = feet_at(plan, t);
    std::array<FootOnGround, 2> soles;
    for (int side = 0; side < 2; ++side) {
      soles[side] = on_ground.foot(feet[side]);
      soles[side].sole = (1.0 / plan.scale) * soles[side].sole;
    }
    body_yaw = body_facing(plan, t) - rig.forward_yaw;
    if (f > 0) body_yaw = unwrapped(body_yaw, previous_yaw);
    previous_yaw = body_yaw;

    // The ankles where the feet roll, and the hips as high as at rest but low
    // enough for both legs to reach.
    std::array<Vec3, 2> ankles, flats;
    std::array<FootRoll, 2> rolls;
    std::array<Quat, 2> tilts;
    double height = hips_head.z + on_ground.body_height(feet) / plan.scale;
    const Mat4 body_turn = turn_about_z(body_yaw);
    for (int side = 0; side < 2; ++side) {
      const Leg& leg = rig.legs[side];
      const FootPose& foot = feet[side];
      const Vec3 sole = soles[side].sole;
      foot_yaw[side] = soles[side].heading - rig.forward_yaw;
      if (f > 0) foot_yaw[side] = unwrapped(foot_yaw[side], previous_foot[side]);
      previous_foot[side] = foot_yaw[side];
      rolls[side] = roller.at(t, side, foot.planted, leg.shape);
      tilts[side] = tilt_to(soles[side].normal);
      // The ankle over the sole, and rolled, along the sole's slope.
      flats[side] = sole + rotate(tilts[side], {0, 0, leg.ankle.z});
      const double heading = soles[side].heading;
      ankles[side] = flats[side] + rotate(tilts[side], {rolls[side].forward * std::cos(heading),
                                                         rolls[side].forward * std::sin(heading),
                                                         rolls[side].up});
      const Vec3 offset = leg.hip - hips_head;
      const Vec3 hip = Vec3{com.x, com.y, 0} + transform_direction(body_turn, {offset.x, offset.y, 0});
      const double horizontal = std::hypot(hip.x - ankles[side].x, hip.y - ankles[side].y);
      const double reach = kReach * (leg.upper + leg.lower);
      const double rise = std::sqrt(std::max(reach * reach - horizontal * horizontal, 0.0));
      height = std::min(height, ankles[side].z + rise - offset.z);
    }

    // The hips: turned by the body's yaw about their head, the head on the COM path.
    const Mat4 body = translation({com.x, com.y, height}) * body_turn * translation(-1.0 * hips_head);
    const Mat4 hips_world = in_gltf(body) * rig.rest_world[rig.hips];
    motion.frames[hips_slot][f] = decompose(local_under(hips_parent, hips_world));

    for (int side = 0; side < 2; ++side) {
      const Leg& leg = rig.legs[side];
      const Vec3 hip = transform_point(body, leg.hip);
      const Mat4 foot_turn = turn_about_z(foot_yaw[side]);
      const Vec3 pole = flats[side] + transform_direction(foot_turn, leg.pole_ahead);
      const Vec3 pole_rest = leg.ankle + leg.pole_ahead;
      // The knee in the plane of hip, ankle and pole, the legs' lengths kept.
      const Vec3 to_ankle = ankles[side] - hip;
      const double longest = leg.upper + leg.lower;
      const double d = std::clamp(length(to_ankle), std::abs(leg.upper - leg.lower) + 1e-6, longest - 1e-9);
      const Vec3 u = normalized(to_ankle);
      const double along = (leg.upper * leg.upper - leg.lower * leg.lower + d * d) / (2 * d);
      const double out = std::sqrt(std::max(leg.upper * leg.upper - along * along, 0.0));
      const Vec3 off = (pole - hip) - dot(pole - hip, u) * u;
      const Vec3 knee = hip + along * u + out * normalized(off);
      const Vec3 ankle = hip + d * u;

      const Mat4 thigh_turn = translation(hip) *
                              frame_turn(leg.knee - leg.hip, pole_rest - leg.hip, knee - hip, pole - hip) *
                              translation(-1.0 * leg.hip);
      const Mat4 shin_turn = translation(knee) *
                             frame_turn(leg.ankle - leg.knee, pole_rest - leg.knee, ankle - knee, pole - knee) *
                             translation(-1.0 * leg.knee);
      const Mat4 foot_motion = translation(ankle) * rotation(tilts[side]) * foot_turn *
                               rotation(axis_angle(lateral, rolls[side].pitch)) * translation(-1.0 * leg.ankle);
      const Mat4 thigh_world = in_gltf(thigh_turn) * rig.rest_world[leg.thigh];
      const Mat4 shin_world = in_gltf(shin_turn) * rig.rest_world[leg.shin];
      const Mat4 foot_world = in_gltf(foot_motion) * rig.rest_world[leg.foot];
      const Mat4 thigh_parent = hips_world * inverse(rig.rest_world[rig.hips]) * rig.rest_world[rig.parent[leg.thigh]];
      motion.frames[leg_slots[side][0]][f] = rotated_rest(rig.rest_trs[leg.thigh], local_under(thigh_parent, thigh_world));
      motion.frames[leg_slots[side][1]][f] = rotated_rest(rig.rest_trs[leg.shin], local_under(thigh_world, shin_world));
      motion.frames[leg_slots[side][2]][f] = rotated_rest(rig.rest_trs[leg.foot], local_under(shin_world, foot_world));
      // The toe bends back as the heel rises, staying flat on the ground.
      Trs toe = rig.rest_trs[leg.toe];
      toe.rotation = toe.rotation * axis_angle(toe_axes[side], -std::min(rolls[side].pitch, 0.0));
      motion.frames[leg_slots[side][3]][f] = toe;
    }

    std::vector<ClipLayer> layers = timing.at(times[f]);
    const double swing = follower.swing_at(t), look = follower.look_at(t), twist = follower.twist_at(t);
    const double lean = on_ground.lean(t);
    for (ClipLayer& layer : layers)
      if (layer.walk) layer.influence *= swing;
    for (std::size_t i = 0; i < upper_slots.size(); ++i) {
      const int node = rig.upper_body[i];
      Trs pose = layered(layers, node, rig.rest_trs[node]);
      // Turned on top of the clips, as the add-on's look-ahead track combines.
      if (node == rig.chest)
        pose.rotation = normalized(pose.rotation * axis_angle(chest_up, kChestLook * look + twist) *
                                   axis_angle(chest_side, -lean));
      if (node == rig.head) pose.rotation = normalized(pose.rotation * axis_angle(head_up, kHeadLook * look));
      motion.frames[upper_slots[i]][f] = pose;
    }
  }
  return motion;
}

}  // namespace footfall::animate
