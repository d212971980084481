# SPDX-License-Identifier: GPL-3.0-or-later
"""Animating one rig instance per agent from a plan.

Each instance is a copy of the imported rig's armature (its own data) with the
rig's meshes linked. IK controls live inside the armature itself (Blender's
glTF exporter mishandles constraints that target other objects): a foot target
per side, a duplicate of the foot bone's rest that the foot copies its
rotation from and the shin's IK reaches for, and a knee pole. One action per
agent keys, at every frame, the hips on the planned COM path and the foot
targets on the planned feet; the upper body plays the rig's clips as NLA
strips, one per section of the path (clip_timing).

Every planned foot position is the point on the ground under the ankle with
the foot flat; the foot rolls heel to toe about it (core/foot_roll.py), and
the toe bends as the heel rises. On a plan's ground the core says where each
sole goes (on its tread, along its slope, lifted over nosings), how high the
body rides and how far it leans (footfall._native.ground_motion).
"""

import functools
import math
import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Callable, Dict, Generator, List, NamedTuple, Optional, Set, Tuple

import bpy
import numpy
from mathutils import Matrix, Vector

from ..core import clip_timing, foot_roll, native
from ..core.rig_profile import STAIR_CLIPS
from . import action_curves, procedural_clips, rig_clips
from .rig_import import foot_skin, profile_of

IK_FOOT = "footfall_ik_foot.{}"
POLE = "footfall_pole.{}"
CONTROL_PREFIXES = (IK_FOOT.format(""), POLE.format(""))  # bones that only drive the others
SIDES = (("left", "L"), ("right", "R"))
CROWD_COLLECTION = "Footfall Crowd"
LOCOMOTION_OF = "footfall_locomotion_of"  # on an instance's locomotion action: the instance
POLE_AHEAD = 0.5  # [m] knee poles in front of the knees
REACH = 0.995  # share of the leg's length the hips may stretch it to (a locked knee snaps)
BLEND_SECONDS = 0.25  # cross-fade between the clips of two sections
UPPER_BODY_TRACK = "Footfall upper body"  # the NLA tracks of the sections' clips: "... idle", "... A", ...
LOOK_AHEAD_TRACK = "Footfall look ahead"
# How near the keys' curves pass to the motion sampled at every frame (keys_to_keep; a crowd
# keyed at every frame was 34 million keys): [m], and per quaternion component.
KEY_TOLERANCE = (5e-4, 5e-4)
POLE_TOLERANCE = (5e-3, 5e-4)  # a knee pole half a metre ahead only aims the knee
# The look-ahead's turns of the chest and head: about 0.2 degrees (the hips and
# the toes stay at KEY_TOLERANCE: the legs' reach and the toes' contact hang on them).
LOOK_TOLERANCE = (2e-3, 2e-3)
INFLUENCE_TOLERANCE = 2e-3  # of a walking clip's strip
SWING_LOOSENESS = 3.0  # a foot in the air, moving fast, is keyed within 1.5 mm
# A foot on the ground (planted, or lifted less than GROUNDED_LIFT) within an
# eighth of a millimetre: rolling on its ball, the keys' errors would add up
# to a millimetre's slide of the toes.
PLANTED_LOOSENESS = 0.25
GROUNDED_LIFT = 0.005  # [m]
_THREADS = ThreadPoolExecutor(max_workers=os.cpu_count() or 1, thread_name_prefix="footfall keys")
LINEAR, HANDLE_FREE = 1, 0  # KeyframePoint.interpolation and handle type values for foreach_set


@dataclass
class Leg:
    foot: str
    shin: str
    thigh: str
    toe: str
    foot_rest: Matrix  # armature space
    pole_rest: Matrix
    toe_rest: Matrix
    thigh_head: Vector
    ankle: Vector
    knee: Vector
    length: float  # hip to knee to ankle
    shape: foot_roll.FootShape  # the foot seen from the side, for its roll
    foot_length: float  # heel to toe tip along the ground


@dataclass
class RigRest:
    """The rig's rest pose as the animation needs it."""

    hips: str
    hips_rest: Matrix
    forward_yaw: float  # the rig's facing in the rest pose [rad]
    chest: str
    head: str
    legs: Dict[str, Leg] = field(default_factory=dict)


def _pole_angle(thigh, shin, pole: Vector) -> float:
    """The IK pole angle that leaves the knee where it is at rest."""
    axis = shin.tail_local - thigh.head_local
    normal = axis.cross(pole - thigh.head_local)
    projected = normal.cross(thigh.tail_local - thigh.head_local)
    x_axis = thigh.matrix_local.to_3x3().col[0]
    angle = x_axis.angle(projected)
    return -angle if (thigh.tail_local - thigh.head_local).dot(x_axis.cross(projected)) > 0 else angle


def _forward_yaw(data, bones) -> float:
    forward = rig_clips.feet_forward(data, bones)
    return math.atan2(forward[1], forward[0])


class TransformError(ValueError):
    """A rig whose world transform an armature cannot take on (a shear)."""


def _world_rest_matrix(rig) -> Matrix:
    """The rig's world transform (its object's and its parents'), which the
    template's bones take on: the instances stand at identity, so that their
    armature space is the world the plan is in."""
    world = rig.matrix_world.copy()
    axes = [world.col[i].xyz for i in range(3)]
    lengths = [axis.length for axis in axes]
    if min(lengths) <= 0.0:
        raise TransformError(f"rig '{rig.name}': its world transform flattens it (a scale of 0)")
    for i in range(3):
        for j in range(i + 1, 3):
            if abs(axes[i].dot(axes[j])) > 1e-4 * lengths[i] * lengths[j]:
                raise TransformError(f"rig '{rig.name}': its world transform shears it (a non-uniform "
                                     "scale under a rotation, in its object or parents); apply the scale first")
    return world


def _template(rig, profile) -> bpy.types.Armature:
    """A copy of the rig's armature in world space (its object and parent
    transforms applied) with the IK foot targets and knee poles added."""
    world = _world_rest_matrix(rig)
    data = rig.data.copy()
    data.transform(world)
    holder = bpy.data.objects.new("footfall template", data)
    bpy.context.scene.collection.objects.link(holder)
    previous = bpy.context.view_layer.objects.active
    bpy.context.view_layer.objects.active = holder
    try:
        bpy.ops.object.mode_set(mode="EDIT")
        yaw = _forward_yaw(data, profile.bones)
        forward = Vector((math.cos(yaw), math.sin(yaw), 0.0))
        for side, suffix in SIDES:
            bones = profile.bones[side]
            foot = data.edit_bones[bones["foot"]]
            target = data.edit_bones.new(IK_FOOT.format(suffix))
            target.head, target.tail, target.roll = foot.head, foot.tail, foot.roll
            target.use_deform = False
            pole = data.edit_bones.new(POLE.format(suffix))
            pole.head = data.edit_bones[bones["shin"]].head + POLE_AHEAD * forward
            pole.tail = pole.head + Vector((0.0, 0.0, 0.1))
            pole.use_deform = False
        bpy.ops.object.mode_set(mode="OBJECT")
    finally:
        bpy.context.view_layer.objects.active = previous
        bpy.data.objects.remove(holder)
    return data


def rig_rest(data, profile, feet=None) -> RigRest:
    """Rest geometry of a template armature (one with the IK bones); `feet`
    (side -> the vertices skinned to its foot and toe: rig_import.foot_skin)
    place the heels and bound the heels' rise."""
    bones = profile.bones
    rest = RigRest(bones["hips"], data.bones[bones["hips"]].matrix_local.copy(), _forward_yaw(data, bones),
                   bones["chest"], bones["head"])
    forward = Vector((math.cos(rest.forward_yaw), math.sin(rest.forward_yaw), 0.0))
    for side, suffix in SIDES:
        limb = bones[side]
        thigh, shin, foot, toe = (data.bones[limb[r]] for r in ("thigh", "shin", "foot", "toe"))
        rest.legs[side] = Leg(
            foot=limb["foot"], shin=limb["shin"], thigh=limb["thigh"], toe=limb["toe"],
            foot_rest=foot.matrix_local.copy(),
            pole_rest=data.bones[POLE.format(suffix)].matrix_local.copy(),
            toe_rest=toe.matrix_local.copy(),
            thigh_head=thigh.head_local.copy(), ankle=foot.head_local.copy(), knee=shin.head_local.copy(),
            length=(shin.head_local - thigh.head_local).length + (foot.head_local - shin.head_local).length,
            shape=foot_roll.foot_shape(foot.head_local, toe.head_local, forward, profile.dimensions["foot_length"],
                                       (feet or {}).get(side, ())),
            foot_length=profile.dimensions["foot_length"],
        )
    return rest


def _instance(name: str, template, rig, collection) -> bpy.types.Object:
    """A new armature with its own copy of the template and the rig's meshes linked."""
    armature = bpy.data.objects.new(name, template.copy())
    armature.data.name = name
    collection.objects.link(armature)
    for mesh in (c for c in rig.children if c.type == "MESH"):
        body = deformed_copy(mesh, armature, collection)
        body.name = f"{name} body"
        body.hide_render = body.hide_viewport = False  # whatever the template's visibility
    return armature


def deformed_copy(mesh, armature, collection) -> bpy.types.Object:
    """A copy of `mesh` (data linked, vertex groups and modifiers copied)
    parented to and deformed by `armature`, in `collection`, where the mesh
    is in the world (the armature's bones are in world space, _template)."""
    body = mesh.copy()
    world = mesh.matrix_world.copy()
    body.parent = armature
    body.matrix_parent_inverse = armature.matrix_world.inverted()
    body.matrix_basis = world
    for modifier in body.modifiers:
        if modifier.type == "ARMATURE":
            modifier.object = armature
    collection.objects.link(body)
    return body


def _add_controls(armature, rest: RigRest) -> None:
    """The shins reach for the foot targets (IK with a knee pole); the feet
    copy their rotation. The bones keyed by quaternion turn by quaternion."""
    armature.pose.bones[rest.hips].rotation_mode = "QUATERNION"
    for side, suffix in SIDES:
        leg = rest.legs[side]
        armature.pose.bones[leg.toe].rotation_mode = "QUATERNION"
        ik = armature.pose.bones[leg.shin].constraints.new("IK")
        ik.target, ik.subtarget = armature, IK_FOOT.format(suffix)
        ik.pole_target, ik.pole_subtarget = armature, POLE.format(suffix)
        ik.pole_angle = _pole_angle(armature.data.bones[leg.thigh], armature.data.bones[leg.shin], leg.pole_rest.to_translation())
        ik.chain_count = 2
        copy = armature.pose.bones[leg.foot].constraints.new("COPY_ROTATION")
        copy.target, copy.subtarget = armature, IK_FOOT.format(suffix)


def _quaternion_product(a, b):
    """Row-wise products of (n, 4) quaternions (w, x, y, z)."""
    aw, ax, ay, az = a.T
    bw, bx, by, bz = b.T
    return numpy.column_stack((aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                               aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw))


def _turns(rest: Matrix, axis, angles):
    """Pose quaternions of a bone (parents at rest) turning it by `angles`
    about the armature-space `axis`: about R^T axis in the bone's frame."""
    local = numpy.array(rest.to_3x3()).T @ numpy.asarray(axis, dtype=float)
    half = 0.5 * angles
    return numpy.column_stack((numpy.cos(half), numpy.outer(numpy.sin(half), local)))


def _tilts(rest: Matrix, normals):
    """Pose quaternions of an unparented bone turning it by the shortest turn
    from the up direction to each of `normals` (n, 3): a sole laid along the
    ground's slope."""
    axes = numpy.cross([0.0, 0.0, 1.0], normals)
    sines = numpy.linalg.norm(axes, axis=1)
    units = axes / numpy.where(sines > 0.0, sines, 1.0)[:, None]
    half = 0.5 * numpy.arctan2(sines, normals[:, 2])
    local = units @ numpy.array(rest.to_3x3())  # rows: R^T axis
    return numpy.column_stack((numpy.cos(half), numpy.sin(half)[:, None] * local))


def _tilted(quaternions, vectors):
    """`vectors` (n, 3) turned by the unit `quaternions` (n, 4; w, x, y, z)."""
    w, axes = quaternions[:, :1], quaternions[:, 1:]
    twice = 2.0 * numpy.cross(axes, vectors)
    return vectors + w * twice + numpy.cross(axes, twice)


def _pose_arrays(rest: Matrix, positions, yaws=None):
    """Pose-bone location (and quaternion) arrays, one row per frame, that put
    an unparented bone's head at `positions` turned by `yaws` about world Z.

    With rest = T(h) R, the pose basis is T(R^T (p - h)) and the rotation by
    the yaw about R^T z."""
    rotation = numpy.array(rest.to_3x3())
    head = numpy.array(rest.to_translation())
    locations = (positions - head) @ rotation  # rows: R^T (p - h)
    if yaws is None:
        return locations, None
    axis = rotation[2]  # R^T z
    half = 0.5 * yaws
    quaternions = numpy.column_stack((numpy.cos(half), numpy.outer(numpy.sin(half), axis)))
    return locations, quaternions


class Keyed(NamedTuple):
    """A bone's motion sampled at every frame, to key: location and
    quaternion arrays (one row per frame; None: not keyed), how near the keys
    must stay to them ([m], per quaternion component), and where that may be
    looser (a factor per frame)."""

    locations: Optional[numpy.ndarray]
    quaternions: Optional[numpy.ndarray]
    tolerance: Tuple[float, float] = KEY_TOLERANCE
    looseness: Optional[numpy.ndarray] = None


def _write_action(armature, name: str, frames, channels: Dict[str, Keyed]) -> bpy.types.Action:
    """A new active action keying each bone's motion in `channels`."""
    action = bpy.data.actions.new(name)
    action[LOCOMOTION_OF] = armature.name  # not a clip of the rig (rig_clips.actions_of)
    _key_channels(action, frames, channels)
    action_curves.assign(armature, action)
    return action


def _key_channels(action, frames, channels: Dict[str, Keyed]) -> None:
    """Keys each bone's motion with the keys whose curves (Bezier; straight
    in Blender 3.4) pass within its tolerance of every frame's sample and
    through those that stand still."""
    cubic = _free_handles_set_in_bulk()
    # Each component on its own: a hip's height kinked at every step would
    # otherwise key its smooth glide forward as often.
    motions = [(bone, path, index, numpy.ascontiguousarray(values[:, index]), tolerance,
                [] if keyed.looseness is None else keyed.looseness)
               for bone, keyed in channels.items()
               for path, values, tolerance in zip(("location", "rotation_quaternion"),
                                                  (keyed.locations, keyed.quaternions), keyed.tolerance)
               if values is not None
               for index in range(values.shape[1])]
    thin = native.load().keys_to_keep
    # The core thins them on every core at once; Blender's data is written from this thread only.
    thinned = _THREADS.map(lambda m: thin(frames, m[3], [m[4]], cubic=cubic, scale=m[5]), motions)
    for (bone, path, index, values, _, _), (kept, slopes) in zip(motions, thinned):
        curve = action_curves.curve(action, f'pose.bones["{bone}"].{path}', index, bone)
        _write_keys(curve.keyframe_points, frames[kept], values[kept], slopes[:, 0], _handle_reach(frames[kept]))
        curve.update()


def _handle_reach(at):
    """Bezier handles a third of the way to the neighbouring keys (before,
    after), along the slope: each segment is then the cubic keys_to_keep
    checked; None where keys are straight (Blender 3.4)."""
    if not _free_handles_set_in_bulk():
        return None
    return numpy.diff(at, prepend=at[0] - 1.0) / 3.0, numpy.diff(at, append=at[-1] + 1.0) / 3.0


def _pairs(x, y) -> numpy.ndarray:
    pairs = numpy.empty((len(x), 2))
    pairs[:, 0], pairs[:, 1] = x, y
    return pairs.ravel()


def _write_keys(points, at, value, slope, reach) -> None:
    """Adds keys at frames `at`: Bezier ones with free handles `reach`
    (before, after) frames away along `slope`, or with reach None straight ones."""
    points.add(len(at))
    points.foreach_set("co", _pairs(at, value))
    if reach is None:
        points.foreach_set("interpolation", numpy.full(len(at), LINEAR))
        return
    before, after = reach
    free = numpy.full(len(at), HANDLE_FREE)  # new keys are Bezier with automatic handles: free them
    points.foreach_set("handle_left_type", free)
    points.foreach_set("handle_right_type", free)
    points.foreach_set("handle_left", _pairs(at - before, value - slope * before))
    points.foreach_set("handle_right", _pairs(at + after, value + slope * after))


@functools.lru_cache(maxsize=None)
def _free_handles_set_in_bulk() -> bool:
    """Whether this Blender sets keys' handle types with foreach_set (3.4
    leaves them automatic, which would bend the curves keys_to_keep checked:
    there the keys are straight, and more)."""
    action = bpy.data.actions.new("footfall handle check")
    try:
        points = action_curves.curve(action, "location", 0, "check").keyframe_points
        points.add(1)
        points.foreach_set("handle_left_type", [HANDLE_FREE])
        return points[0].handle_left_type == "FREE"
    finally:
        bpy.data.actions.remove(action)


def _step_arrays(ff, steps) -> foot_roll.Steps:
    start = numpy.array([s.start_time for s in steps])
    end = numpy.array([s.end_time for s in steps])
    chord = numpy.array([math.dist(s.com_start, s.com_end) for s in steps])
    heights = numpy.array([s.foot_height for s in steps])
    stair = numpy.zeros(len(steps), dtype=bool)
    stair[1:] = numpy.abs(numpy.diff(heights)) > foot_roll.STAIR_RISE
    return foot_roll.Steps(start, end, numpy.array([0 if s.foot == ff.Foot.LEFT else 1 for s in steps]),
                           numpy.array([s.kind != ff.StepKind.SIDE_STEP for s in steps], dtype=bool) & ~stair,
                           chord / numpy.maximum(end - start, 1e-9))


class Terrain(NamedTuple):
    """A plan's ground, for its agents' motion: the core's index of it, and
    the character the plan was made for (an agent's own wins)."""

    ground: object  # footfall._native.Ground
    character: object  # footfall._native.CharacterParams


def terrain_of(ff, plan) -> Optional[Terrain]:
    """The plan's Terrain, or None on the flat (its feet and body as planned)."""
    return Terrain(ff.Ground(plan.ground), plan.character) if plan.ground else None


def motion_of(ff, agent, rest: RigRest, frames, fps: float, speed: float, terrain: Optional[Terrain] = None):
    """The agent's motion at `frames` (the first is the plan's time 0; after
    its plan the agent holds its last pose), for an agent walking at `speed`
    (on `terrain`, its plan's ground): the locomotion's channels (bone ->
    Keyed), and the walking clips' swing, the look-ahead, the chest's twist
    (ff.upper_body) and the upper body's lean into a climb."""
    times = numpy.minimum((frames - frames[0]) / fps, agent.end_time())
    facing, swing, look, twist = ff.upper_body(agent, times, speed)
    on_ground = None
    if terrain is not None:
        leg = rest.legs["left"]  # the rig's left foot for both, as the core's writer
        on_ground = ff.ground_motion(agent, agent.character or terrain.character, terrain.ground, times,
                                     agent.scale * leg.shape.heel_back,
                                     agent.scale * (leg.foot_length - leg.shape.heel_back),
                                     (agent.character or terrain.character).sole_width)
    lean = numpy.zeros(len(times)) if on_ground is None else on_ground[4]
    return _locomotion(ff, agent, rest, times, facing, speed, on_ground), swing, look, twist, lean


def _locomotion(ff, agent, rest: RigRest, times, facing, full_speed: float, on_ground=None):
    """Channels of the hips on the COM path, the foot targets on the feet
    (rolling heel to toe: foot_roll, the toes bending as the heels rise) and
    the poles ahead of the knees, at `times` (clamped to the plan's end: after
    its plan the agent holds its last pose; one that leaves is hidden then,
    _key_leaving); `facing` is the body's there (ff.upper_body); `on_ground`:
    ff.ground_motion's arrays on a plan's ground, else None."""
    count = len(times)
    com, feet_xy, feet_yaw, lift, planted = ff.sample_motion(agent, times)
    body = numpy.zeros(count)
    if on_ground is not None:
        soles, feet_yaw, normals, body, _ = on_ground
    # In the rig's own size: the instance object scales it to the plan's (agent.scale).
    com, feet_xy, lift, body = com / agent.scale, feet_xy / agent.scale, lift / agent.scale, body / agent.scale
    step_arrays = _step_arrays(ff, agent.footsteps)
    lateral = numpy.cross([math.cos(rest.forward_yaw), math.sin(rest.forward_yaw), 0.0], [0.0, 0.0, 1.0])
    body_yaw = numpy.unwrap(facing) - rest.forward_yaw
    hips_head = numpy.array(rest.hips_rest.to_translation())
    cos, sin = numpy.cos(body_yaw), numpy.sin(body_yaw)
    # The hips as high as at rest over the ground, but low enough for both legs to reach.
    height = hips_head[2] + body
    channels = {}
    for side, (name, suffix) in enumerate(SIDES):
        leg = rest.legs[name]
        pitch, forward, up = foot_roll.roll(times, planted[:, side], side, step_arrays, leg.shape, full_speed,
                                            agent.leaves)
        offsets = numpy.column_stack((forward * numpy.cos(feet_yaw[:, side]),
                                      forward * numpy.sin(feet_yaw[:, side]), up))
        if on_ground is None:
            flat = numpy.column_stack((feet_xy[:, side], leg.ankle.z + lift[:, side]))
            ankles = flat + offsets
        else:
            # The ankle over the sole, and rolled, along the sole's slope.
            tilts = _tilts(Matrix.Identity(4), normals[:, side])
            flat = soles[:, side] / agent.scale + _tilted(tilts, numpy.tile([0.0, 0.0, leg.ankle.z], (count, 1)))
            ankles = flat + _tilted(tilts, offsets)
        offset = numpy.array(leg.thigh_head) - hips_head
        hip_xy = com + numpy.column_stack((cos * offset[0] - sin * offset[1], sin * offset[0] + cos * offset[1]))
        horizontal = numpy.linalg.norm(hip_xy - ankles[:, :2], axis=1)
        rise = numpy.sqrt(numpy.maximum((REACH * leg.length) ** 2 - horizontal ** 2, 0.0))
        height = numpy.minimum(height, ankles[:, 2] + rise - offset[2])
        foot_yaw = numpy.unwrap(feet_yaw[:, side]) - rest.forward_yaw
        locations, yawed = _pose_arrays(leg.foot_rest, ankles, foot_yaw)
        # Pitched about the rest's side axis first, then turned to the foot's yaw (and tilted along the ground).
        grounded = planted[:, side] | (lift[:, side] < GROUNDED_LIFT)
        looseness = numpy.where(grounded, PLANTED_LOOSENESS, SWING_LOOSENESS)
        turned = _quaternion_product(yawed, _turns(leg.foot_rest, lateral, pitch))
        if on_ground is not None:
            turned = _quaternion_product(_tilts(leg.foot_rest, normals[:, side]), turned)
        channels[IK_FOOT.format(suffix)] = Keyed(locations, turned, looseness=looseness)
        channels[leg.toe] = Keyed(None, _turns(leg.toe_rest, lateral, -numpy.minimum(pitch, 0.0)),
                                  looseness=looseness)
        ahead = numpy.array(leg.pole_rest.to_translation() - leg.ankle)  # the pole, seen from the ankle
        poles = flat + numpy.column_stack((numpy.cos(foot_yaw) * ahead[0] - numpy.sin(foot_yaw) * ahead[1],
                                             numpy.sin(foot_yaw) * ahead[0] + numpy.cos(foot_yaw) * ahead[1],
                                             numpy.full(count, ahead[2])))
        channels[POLE.format(suffix)] = Keyed(*_pose_arrays(leg.pole_rest, poles), tolerance=POLE_TOLERANCE)
    channels[rest.hips] = Keyed(*_pose_arrays(rest.hips_rest, numpy.column_stack((com, height)), body_yaw))
    return channels


def crowd_armatures() -> List[bpy.types.Object]:
    """The armatures that footfall.apply made."""
    collection = bpy.data.collections.get(CROWD_COLLECTION)
    return [o for o in collection.objects if o.type == "ARMATURE"] if collection else []


def own_actions(obj) -> List[bpy.types.Action]:
    """The actions Apply made for an instance: its locomotion and look-ahead
    (the clips its strips play are the rig's, shared)."""
    animation = obj.animation_data
    if animation is None:
        return []
    found = [animation.action] if animation.action else []
    found += [strip.action for track in animation.nla_tracks for strip in track.strips
              if strip.action is not None and LOCOMOTION_OF in strip.action]
    return found


def _key_leaving(armature, agent, frame_offset: float, fps: float) -> None:
    """An agent that leaves at its goal is shown up to its leave time and
    hidden, in viewports and renders, from the first frame after it."""
    if not agent.leaves:
        return
    gone = math.floor(frame_offset + agent.end_time() * fps) + 1
    for obj in (armature, *armature.children):
        for prop in ("hide_viewport", "hide_render"):
            for frame, hidden in ((frame_offset, False), (gone, True)):
                setattr(obj, prop, hidden)
                obj.keyframe_insert(prop, frame=frame)
            setattr(obj, prop, False)


def _make_cyclic(clip: rig_clips.Clip) -> None:
    """Loops the clip, and spans it twice: a strip plays a one-cycle window
    that may start anywhere in the first cycle, and NLA strips hold an
    action's last value past its frame range instead of letting the Cycles
    modifier go on."""
    for curve in action_curves.curves(clip.action):
        if not any(m.type == "CYCLES" for m in curve.modifiers):
            curve.modifiers.new("CYCLES")
    clip.action.use_frame_range = True
    clip.action.frame_start, clip.action.frame_end = clip.first, clip.last + (clip.last - clip.first)


def _upper_body(armature, agent, clips: Dict[str, rig_clips.Clip], fps: float, frame_offset: float,
                frames, swing) -> None:
    """Over a base track playing "idle" throughout, one NLA strip per
    section, on two alternating tracks that cross-fade; a strip that overlaps
    the one before on its track (sections shorter than the blends, as a
    crowd's short waits make) goes on a free track above. A walking strip's
    influence, keyed at `frames`, is also `swing` there, the share of the
    clip's amplitude (ff.upper_body)."""
    climbs = native.load().stair_climbs(agent)
    steps = [clip_timing.Step(s.start_time, s.end_time, s.foot.name.lower(), s.kind.name.lower(),
                              s.behavior.name.lower(), climb) for s, climb in zip(agent.footsteps, climbs)]
    sections = clip_timing.sections(steps, clips.keys())
    last_frame = frames[-1]
    tracks, ends = [], []  # NLA tracks, and the frame where each one's last strip ends

    def add_track(name: str):
        tracks.append(armature.animation_data.nla_tracks.new())
        tracks[-1].name = f"{UPPER_BODY_TRACK} {name}"
        ends.append(-math.inf)

    def track_for(i: int, start: float) -> int:
        """Strip i's track: A or B by turns, else the lowest free one above A, else a new one."""
        # Blender first places the strip at the whole frame below its start.
        k = next((k for k in [1 + i % 2, *range(2, len(tracks))] if ends[k] <= math.floor(start)), None)
        if k is None:
            add_track(chr(ord("A") + len(tracks) - 1))
            k = len(tracks) - 1
        return k

    add_track("idle")
    idle = clips["idle"]
    base = tracks[0].strips.new("idle", int(frame_offset), idle.action)
    base.action_frame_start, base.action_frame_end = idle.first, idle.first + idle.cycle_frames
    base.repeat = max((last_frame - frame_offset) / idle.cycle_frames, 1e-3)
    base.extrapolation = "HOLD_FORWARD"
    add_track("A")
    add_track("B")
    fades = clip_timing.cross_fades(sections, BLEND_SECONDS)
    for i, section in enumerate(sections):
        clip = clips[section.behavior]
        # Neighbouring strips overlap by the cross-fade; the last plays to the scene's end.
        lead, tail = fades[i]
        if i == len(sections) - 1:
            tail = (last_frame - frame_offset) / fps - section.end
        timing = clip_timing.strip_timing(section, clip.first, clip.first + clip.cycle_frames, fps, frame_offset,
                                          lead, max(tail, 0.0), clip.cycle.strike)
        k = track_for(i, timing.frame_start)
        strip = tracks[k].strips.new(f"{section.behavior} {i}", int(timing.frame_start), clip.action)
        strip.name = f"{section.behavior} {i}"  # Blender 3.4 names a new strip after its action
        # The start first: Blender 3.4 moves only the start; scale and repeat then set the end.
        strip.frame_start = timing.frame_start
        strip.action_frame_start, strip.action_frame_end = timing.action_frame_start, timing.action_frame_end
        strip.scale, strip.repeat = timing.scale, timing.repeat
        ends[k] = strip.frame_end  # as Blender holds it (single precision: 187 can end at 187.0000153)
        last = i == len(sections) - 1
        strip.extrapolation = "HOLD_FORWARD" if last else "NOTHING"
        # Strips above track A fade in and out over what is below; the last
        # one holds to the scene's end, faded in only (faded out, the arms
        # would drop to idle at the last frame).
        blend_in = blend_out = 0.0
        if k > 1:
            strip.use_auto_blend = False
            blend_in = min(BLEND_SECONDS * fps, 0.5 * (strip.frame_end - strip.frame_start))
            blend_out = 0.0 if last else blend_in
            strip.blend_in, strip.blend_out = blend_in, blend_out
        if clip_timing.walking(section.behavior):
            # Keyed, the influence replaces the fades: they are keyed into it.
            fade = clip_timing.fade(frames, strip.frame_start, strip.frame_end, blend_in, blend_out)
            _key_influence(strip, frames, fade * swing)


def _key_influence(strip, frames, influence) -> None:
    """Keys the strip's influence over the frames it plays, within
    INFLUENCE_TOLERANCE of its value at each."""
    strip.use_animated_influence = True
    curve = strip.fcurves.find("influence")
    curve.keyframe_points.clear()
    inside = (frames >= math.floor(strip.frame_start)) & (frames <= math.ceil(strip.frame_end))
    at, values = frames[inside], influence[inside]
    kept, slopes = native.load().keys_to_keep(at, values, [INFLUENCE_TOLERANCE], cubic=_free_handles_set_in_bulk())
    _write_keys(curve.keyframe_points, at[kept], values[kept], slopes[:, 0], _handle_reach(at[kept]))
    curve.update()


def _look_ahead(ff, armature, agent_name: str, rest: RigRest, frames, look, twist, lean) -> None:
    """A top NLA track that turns the chest and head by shares of the `look`
    angle at the frames (ff.upper_body), the chest also by its `twist`,
    about the world's up, and leans the chest forward by `lean` (on ground,
    into a climb), combined with (turning on top of) the clips below.
    Bones not turned by quaternion are left as the clips pose them."""
    turns = {"chest": ff.LOOK_SHARES["chest"] * look + twist, "head": ff.LOOK_SHARES["head"] * look}
    lateral = (math.sin(rest.forward_yaw), -math.cos(rest.forward_yaw), 0.0)  # the rig's right at rest
    action = bpy.data.actions.new(f"{agent_name} look ahead")
    action[LOCOMOTION_OF] = armature.name
    channels = {}
    for role, bone in (("chest", rest.chest), ("head", rest.head)):
        if armature.pose.bones[bone].rotation_mode != "QUATERNION":
            continue
        matrix = armature.data.bones[bone].matrix_local
        turned = _turns(matrix, (0.0, 0.0, 1.0), turns[role])
        if role == "chest" and numpy.any(lean != 0.0):
            turned = _quaternion_product(turned, _turns(matrix, lateral, -lean))
        channels[bone] = Keyed(None, turned, tolerance=LOOK_TOLERANCE)
    if not channels:
        bpy.data.actions.remove(action)
        return
    _key_channels(action, frames, channels)
    track = armature.animation_data.nla_tracks.new()
    track.name = LOOK_AHEAD_TRACK
    strip = track.strips.new("look ahead", int(frames[0]), action)
    strip.blend_type = "COMBINE"
    strip.extrapolation = "HOLD_FORWARD"


def _drop_driven(action, bones) -> None:
    """Removes the clip's curves of what the locomotion drives (the hips'
    location and turn, the toes' turn): keyed, the locomotion action
    replaces them anyway; live, the clip would undo the live pose."""
    driven = {f'pose.bones["{bones["hips"]}"].location', f'pose.bones["{bones["hips"]}"].rotation_quaternion',
              *(f'pose.bones["{bones[side]["toe"]}"].rotation_quaternion' for side, _ in SIDES)}
    for curve in [c for c in action_curves.curves(action) if c.data_path in driven]:
        action_curves.remove(action, curve)


def clips_of(rig, profile) -> Dict[str, rig_clips.Clip]:
    """The clip per behaviour, cyclic: the rig's own (copies without root
    motion or what the locomotion drives), procedural ones where it has none
    (but for stairs: there the walk plays)."""
    clips = {}
    for behavior in profile.clips:
        clip = rig_clips.playable(rig, profile, behavior)
        if clip is None and behavior in STAIR_CLIPS:
            continue  # the walk plays on stairs
        if clip is None:
            clip = procedural_clips.clip(behavior, rig, profile)
        else:
            _drop_driven(clip.action, profile.bones)
        _make_cyclic(clip)
        clips[behavior] = clip
    return clips


@dataclass
class _Character:
    """What Apply makes once per rig: the template armature, its rest, its clips."""

    rig: bpy.types.Object
    template: bpy.types.Armature
    rest: RigRest
    clips: Dict[str, rig_clips.Clip]


def _character(rig) -> _Character:
    profile = profile_of(rig)
    template = _template(rig, profile)
    rest = rig_rest(template, profile, foot_skin(rig, profile.bones))
    return _Character(rig, template, rest, clips_of(rig, profile))


def applying(ff, plan, rigs: Dict[str, bpy.types.Object], scene, only: Optional[Set[str]] = None,
             drive: Optional[Callable] = None) -> Generator[float, None, List[bpy.types.Object]]:
    """Animates one instance of each agent's rig (`rigs`: agent name -> rig)
    per agent of `plan` (of those named in `only`, if given), one agent at a
    time: yields the share done after each; returns the armatures. Stopped
    part way, it leaves what it made so far (the caller removes it).

    The locomotion (motion_of's channels) is keyed in an action per agent,
    or with `drive` given handed to it instead, as drive(armature, agent
    name, rest, frames, fps, preferred speed, channels) (live_motion).

    Frame `scene.frame_start` is time 0; the scene's frame range is extended to
    the end of the longest plan.
    """
    fps = scene.render.fps / scene.render.fps_base
    frame_offset = float(scene.frame_start)
    end_time = max((agent.end_time() for agent in plan.agents), default=0.0)
    last_frame = frame_offset + math.ceil(end_time * fps)
    frames = numpy.arange(int(frame_offset), int(last_frame) + 1, dtype=float)
    collection = bpy.data.collections.get(CROWD_COLLECTION) or bpy.data.collections.new(CROWD_COLLECTION)
    if collection.name not in scene.collection.children:
        scene.collection.children.link(collection)
    characters: Dict[str, _Character] = {}
    for rig in rigs.values():
        if rig.name not in characters:
            characters[rig.name] = _character(rig)
    agents = [agent for agent in plan.agents if only is None or agent.name in only]
    terrain = terrain_of(ff, plan)
    cast = [characters[rigs[agent.name].name] for agent in agents]
    armatures = [_instance(agent.name, c.template, c.rig, collection) for agent, c in zip(agents, cast)]
    for agent, armature in zip(agents, armatures):
        armature.scale = (agent.scale,) * 3  # after its meshes: they follow it
    bpy.context.view_layer.update()  # new armature objects get their poses here, all at once
    for i, (agent, armature, character) in enumerate(zip(agents, armatures, cast)):
        _add_controls(armature, character.rest)
        speed = (agent.character or plan.character).preferred_speed
        channels, swing, look, twist, lean = motion_of(ff, agent, character.rest, frames, fps, speed, terrain)
        if drive is None:
            _write_action(armature, f"{agent.name} locomotion", frames, channels)
        else:
            armature.animation_data_create()
            drive(armature, agent.name, character.rest, frames, fps, speed, channels)
        _upper_body(armature, agent, character.clips, fps, frame_offset, frames, swing)
        _look_ahead(ff, armature, agent.name, character.rest, frames, look, twist, lean)
        _key_leaving(armature, agent, frame_offset, fps)
        yield (i + 1) / len(agents)
    for character in characters.values():
        bpy.data.armatures.remove(character.template)
    scene.frame_end = max(scene.frame_end, int(last_frame))
    return armatures
