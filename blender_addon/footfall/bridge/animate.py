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

Every planned foot position is the point on the ground under the ankle; the
ankle stays at its rest height while the foot is planted.
"""

import bisect
import math
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional

import bpy
from mathutils import Matrix, Quaternion, Vector

from ..core import clip_timing
from . import procedural_clips
from .rig_import import profile_of

IK_FOOT = "footfall_ik_foot.{}"
POLE = "footfall_pole.{}"
SIDES = (("left", "L"), ("right", "R"))
CROWD_COLLECTION = "Footfall Crowd"
POLE_AHEAD = 0.5  # [m] knee poles in front of the knees
REACH = 0.995  # share of the leg's length the hips may stretch it to (a locked knee snaps)
BLEND_SECONDS = 0.25  # cross-fade between the clips of two sections


@dataclass
class _Leg:
    foot: str
    shin: str
    thigh: str
    foot_rest: Matrix  # armature space
    pole_rest: Matrix
    thigh_head: Vector
    ankle: Vector
    knee: Vector
    length: float  # hip to knee to ankle


@dataclass
class RigRest:
    """The rig's rest pose as the animation needs it."""

    hips: str
    hips_rest: Matrix
    forward_yaw: float  # the rig's facing in the rest pose [rad]
    legs: Dict[str, _Leg] = field(default_factory=dict)


def _yaw(angle: float) -> Matrix:
    return Matrix.Rotation(angle, 4, "Z")


def _rotation(matrix: Matrix) -> Matrix:
    return matrix.to_3x3().to_4x4()


def _pole_angle(thigh, shin, pole: Vector) -> float:
    """The IK pole angle that leaves the knee where it is at rest."""
    axis = shin.tail_local - thigh.head_local
    normal = axis.cross(pole - thigh.head_local)
    projected = normal.cross(thigh.tail_local - thigh.head_local)
    x_axis = thigh.matrix_local.to_3x3().col[0]
    angle = x_axis.angle(projected)
    return -angle if (thigh.tail_local - thigh.head_local).dot(x_axis.cross(projected)) < 0 else angle


def _forward_yaw(data, bones) -> float:
    forward = Vector((0.0, 0.0))
    for side, _suffix in SIDES:
        foot = data.bones[bones[side]["foot"]]
        forward += (foot.tail_local - foot.head_local).xy
    return math.atan2(forward.y, forward.x)


def _template(rig, profile) -> bpy.types.Armature:
    """A copy of the rig's armature with the IK foot targets and knee poles added."""
    data = rig.data.copy()
    holder = bpy.data.objects.new("footfall template", data)
    bpy.context.scene.collection.objects.link(holder)
    previous = bpy.context.view_layer.objects.active
    bpy.context.view_layer.objects.active = holder
    try:
        bpy.ops.object.mode_set(mode="EDIT")
        forward = Vector((math.cos(_forward_yaw(data, profile.bones)), math.sin(_forward_yaw(data, profile.bones)), 0))
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


def rig_rest(data, profile) -> RigRest:
    """Rest geometry of a template armature (one with the IK bones)."""
    bones = profile.bones
    rest = RigRest(bones["hips"], data.bones[bones["hips"]].matrix_local.copy(), _forward_yaw(data, bones))
    for side, suffix in SIDES:
        limb = bones[side]
        thigh, shin, foot = (data.bones[limb[r]] for r in ("thigh", "shin", "foot"))
        rest.legs[side] = _Leg(
            foot=limb["foot"], shin=limb["shin"], thigh=limb["thigh"],
            foot_rest=foot.matrix_local.copy(),
            pole_rest=data.bones[POLE.format(suffix)].matrix_local.copy(),
            thigh_head=thigh.head_local.copy(), ankle=foot.head_local.copy(), knee=shin.head_local.copy(),
            length=(shin.head_local - thigh.head_local).length + (foot.head_local - shin.head_local).length,
        )
    return rest


def _instance(name: str, template, rig, rest: RigRest, collection) -> bpy.types.Object:
    armature = bpy.data.objects.new(name, template.copy())
    armature.data.name = name
    collection.objects.link(armature)
    for mesh in (c for c in rig.children if c.type == "MESH"):
        body = mesh.copy()  # mesh data linked, vertex groups and modifiers copied
        body.name = f"{name} body"
        body.hide_render = body.hide_viewport = False  # whatever the template's visibility
        body.parent = armature
        for modifier in body.modifiers:
            if modifier.type == "ARMATURE":
                modifier.object = armature
        collection.objects.link(body)
    bpy.context.view_layer.update()  # a new armature object gets its pose here
    for side, suffix in SIDES:
        leg = rest.legs[side]
        ik = armature.pose.bones[leg.shin].constraints.new("IK")
        ik.target, ik.subtarget = armature, IK_FOOT.format(suffix)
        ik.pole_target, ik.pole_subtarget = armature, POLE.format(suffix)
        ik.pole_angle = _pole_angle(armature.data.bones[leg.thigh], armature.data.bones[leg.shin], leg.pole_rest.to_translation())
        ik.chain_count = 2
        copy = armature.pose.bones[leg.foot].constraints.new("COPY_ROTATION")
        copy.target, copy.subtarget = armature, IK_FOOT.format(suffix)
    return armature


class _Channels:
    """Per-frame values of pose-bone channels, written as keyframes in bulk."""

    def __init__(self):
        self.values: Dict[tuple, List[float]] = {}
        self.last_quaternion: Dict[str, Quaternion] = {}

    def pose(self, bone: str, rest: Matrix, target: Matrix, rotate: bool = True):
        """Keys the bone so that its armature-space matrix is `target`."""
        basis = rest.inverted() @ target
        location = basis.to_translation()
        for i in range(3):
            self.values.setdefault((f'pose.bones["{bone}"].location', i), []).append(location[i])
        if rotate:
            quaternion = basis.to_quaternion()
            last = self.last_quaternion.get(bone)
            if last is not None and last.dot(quaternion) < 0:  # the shorter way round
                quaternion.negate()
            self.last_quaternion[bone] = quaternion
            for i in range(4):
                self.values.setdefault((f'pose.bones["{bone}"].rotation_quaternion', i), []).append(quaternion[i])

    def write(self, armature, name: str, frames: List[float]) -> bpy.types.Action:
        action = bpy.data.actions.new(name)
        armature.animation_data_create().action = action
        for (path, index), values in self.values.items():
            curve = action.fcurves.new(path, index=index, action_group=path.split('"')[1])
            curve.keyframe_points.add(len(frames))
            curve.keyframe_points.foreach_set("co", [x for pair in zip(frames, values) for x in pair])
            curve.update()
        return action


def _facing(feet, step) -> float:
    """The body's facing: between the feet; in a side step, across the step's
    direction of travel, on the side the feet point to."""
    between = math.atan2(sum(math.sin(f.orientation) for f in feet), sum(math.cos(f.orientation) for f in feet))
    if step is None or step.behavior.name != "SIDE_STEP":
        return between
    travel = math.atan2(step.com_end[1] - step.com_start[1], step.com_end[0] - step.com_start[0])
    across = (travel + math.pi / 2, travel - math.pi / 2)
    return min(across, key=lambda a: abs(math.remainder(a - between, 2 * math.pi)))


def _locomotion(ff, agent, rest: RigRest, frames: List[float], frame_offset: float, fps: float) -> _Channels:
    """Hips on the COM path, foot targets on the feet, poles ahead of the knees."""
    channels = _Channels()
    hips_rotation = _rotation(rest.hips_rest)
    hips_z = rest.hips_rest.to_translation().z
    steps = agent.footsteps
    starts = [step.start_time for step in steps]
    for frame in frames:
        t = (frame - frame_offset) / fps
        com = ff.com_at(agent, t).position
        feet = ff.feet_at(agent, t)
        index = bisect.bisect_right(starts, t) - 1
        turn = _yaw(_facing(feet, steps[index] if index >= 0 else None) - rest.forward_yaw)
        # The hips as high as at rest, but low enough for both legs to reach.
        height = hips_z
        ankles = {}
        for (side, _suffix), foot in zip(SIDES, feet):
            leg = rest.legs[side]
            ankles[side] = Vector((foot.position[0], foot.position[1], leg.ankle.z + foot.lift))
            hip_offset = turn @ (leg.thigh_head - rest.hips_rest.to_translation())
            horizontal = (Vector(com) + hip_offset.xy - ankles[side].xy).length
            reach = REACH * leg.length
            rise = math.sqrt(max(reach * reach - horizontal * horizontal, 0.0))
            height = min(height, ankles[side].z + rise - hip_offset.z)
        channels.pose(rest.hips, rest.hips_rest, Matrix.Translation((com[0], com[1], height)) @ turn @ hips_rotation)
        for (side, suffix), foot in zip(SIDES, feet):
            leg = rest.legs[side]
            foot_turn = _yaw(foot.orientation - rest.forward_yaw)
            channels.pose(IK_FOOT.format(suffix), leg.foot_rest,
                          Matrix.Translation(ankles[side]) @ foot_turn @ _rotation(leg.foot_rest))
            knee = (foot_turn @ (leg.knee - leg.ankle)) + ankles[side]
            ahead = foot_turn @ (leg.pole_rest.to_translation() - leg.knee)
            channels.pose(POLE.format(suffix), leg.pole_rest,
                          Matrix.Translation(knee + ahead) @ _rotation(leg.pole_rest), rotate=False)
    return channels


def _make_cyclic(action) -> None:
    for curve in action.fcurves:
        if not any(m.type == "CYCLES" for m in curve.modifiers):
            curve.modifiers.new("CYCLES")


def _upper_body(armature, agent, clips: Dict[str, bpy.types.Action], fps: float, frame_offset: float,
                last_frame: float) -> None:
    """One NLA strip per section, on two alternating tracks that cross-fade."""
    steps = [clip_timing.Step(s.start_time, s.end_time, s.foot.name.lower(), s.kind.name.lower(),
                              s.behavior.name.lower()) for s in agent.footsteps]
    sections = clip_timing.sections(steps)
    tracks = [armature.animation_data.nla_tracks.new() for _ in range(2)]
    for track, label in zip(tracks, ("A", "B")):
        track.name = f"Footfall upper body {label}"
    for i, section in enumerate(sections):
        action = clips[section.behavior]
        first, last = action.frame_range
        # Neighbouring strips overlap by the blend time; the last plays to the scene's end.
        lead = BLEND_SECONDS if i > 0 else 0.0
        tail = BLEND_SECONDS if i < len(sections) - 1 else (last_frame - frame_offset) / fps - section.end
        timing = clip_timing.strip_timing(section, first, last, fps, frame_offset, lead, max(tail, 0.0))
        strip = tracks[i % 2].strips.new(f"{section.behavior} {i}", int(timing.frame_start), action)
        # The start first: Blender 3.4 moves only the start; scale and repeat then set the end.
        strip.frame_start = timing.frame_start
        strip.action_frame_start, strip.action_frame_end = timing.action_frame_start, timing.action_frame_end
        strip.scale, strip.repeat = timing.scale, timing.repeat
        strip.extrapolation = "NOTHING" if i < len(sections) - 1 else "HOLD_FORWARD"
        # The upper track fades in and out over the lower one.
        if i % 2:
            strip.use_auto_blend = False
            strip.blend_in = strip.blend_out = min(BLEND_SECONDS * fps, 0.5 * (strip.frame_end - strip.frame_start))


def clips_of(armature, profile) -> Dict[str, bpy.types.Action]:
    """The rig's clip per behaviour, cyclic; procedural ones where it has none."""
    clips = {}
    for behavior, name in profile.clips.items():
        action = bpy.data.actions.get(name) if name else None
        clips[behavior] = action or procedural_clips.make(behavior, armature, profile)
        _make_cyclic(clips[behavior])
    return clips


def apply_plan(ff, plan, rig, scene, progress: Optional[Callable[[float], None]] = None) -> List[bpy.types.Object]:
    """Animates one instance of `rig` per agent of `plan`; returns the armatures.

    Frame `scene.frame_start` is time 0; the scene's frame range is extended to
    the end of the longest plan.
    """
    profile = profile_of(rig)
    fps = scene.render.fps / scene.render.fps_base
    frame_offset = float(scene.frame_start)
    end_time = max((agent.end_time() for agent in plan.agents), default=0.0)
    last_frame = frame_offset + math.ceil(end_time * fps)
    frames = [float(f) for f in range(int(frame_offset), int(last_frame) + 1)]
    collection = bpy.data.collections.get(CROWD_COLLECTION) or bpy.data.collections.new(CROWD_COLLECTION)
    if collection.name not in scene.collection.children:
        scene.collection.children.link(collection)
    template = _template(rig, profile)
    rest = rig_rest(template, profile)
    clips = clips_of(rig, profile)
    armatures = []
    for i, agent in enumerate(plan.agents):
        armature = _instance(agent.name, template, rig, rest, collection)
        _locomotion(ff, agent, rest, frames, frame_offset, fps).write(armature, f"{agent.name} locomotion", frames)
        _upper_body(armature, agent, clips, fps, frame_offset, last_frame)
        armatures.append(armature)
        if progress:
            progress((i + 1) / len(plan.agents))
    bpy.data.armatures.remove(template)
    scene.frame_end = max(scene.frame_end, int(last_frame))
    return armatures
