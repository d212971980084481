# SPDX-License-Identifier: GPL-3.0-or-later
"""Upper-body clips for rigs that have none for a behaviour: an arm swing
for walking, arms held against the body for tight passages, a still upper
body for side steps and idle. Built from the bone map and the rest pose, so
they suit any mapped humanoid."""

import math

import bpy
from mathutils import Matrix, Vector

from ..core import clip_cycle
from . import action_curves, rig_clips

CYCLE_FRAMES = {"walk": 24, "arms_in": 24, "side_step": 24, "idle": 48}
SWING = math.radians(20)  # arm swing each way while walking
SAMPLES = 8  # keys per cycle
PROCEDURAL_FOR = "footfall_procedural_for"  # the rig a procedural clip was made for
PROCEDURAL_BEHAVIOR = "footfall_procedural_behavior"


def _key(action, bone: str, frame: float, quaternion) -> None:
    path = f'pose.bones["{bone}"].rotation_quaternion'
    for i in range(4):
        curve = action_curves.curve(action, path, i, bone)
        curve.keyframe_points.insert(frame, quaternion[i], options={"FAST"})


def _basis(rest: Matrix, world_rotation: Matrix):
    """The pose rotation of a bone (parents at rest) turning it by `world_rotation`."""
    rest3 = rest.to_3x3()
    return (rest3.inverted() @ world_rotation @ rest3).to_quaternion()


def make(behavior: str, armature, profile) -> bpy.types.Action:
    """A cyclic upper-body action for `behavior` on `armature`'s bones,
    named 'footfall procedural BEHAVIOR for ARMATURE'; made once per rig
    (the property PROCEDURAL_FOR names the rig: a long name is cut short)."""
    for action in bpy.data.actions:
        if action.get(PROCEDURAL_FOR) == armature.name and action.get(PROCEDURAL_BEHAVIOR) == behavior:
            return action
    action = bpy.data.actions.new(f"footfall procedural {behavior} for {armature.name}")
    action[PROCEDURAL_FOR], action[PROCEDURAL_BEHAVIOR] = armature.name, behavior
    cycle = CYCLE_FRAMES[behavior]
    bones = armature.data.bones
    forward = rig_clips.feet_forward(armature.data, profile.bones)
    forward = Vector((forward[0], forward[1], 0.0)).normalized()
    right = Vector((forward.y, -forward.x, 0.0))  # turning about it swings a hanging arm forward
    for side, sign in (("left", 1.0), ("right", -1.0)):
        bone = bones[profile.bones[side]["upper_arm"]]
        rest = bone.matrix_local
        arm = (bone.tail_local - bone.head_local).normalized()
        for k in range(SAMPLES + 1):
            phase = k / SAMPLES
            if behavior == "walk":
                # Left arm forward at a quarter cycle, the right arm opposite.
                turn = Matrix.Rotation(sign * SWING * math.sin(2 * math.pi * phase), 3, right)
            elif behavior == "arms_in":
                turn = arm.rotation_difference(Vector((0.0, 0.0, -1.0))).to_matrix()
            else:
                turn = Matrix.Identity(3)
            _key(action, bone.name, 1 + phase * cycle, _basis(rest, turn))
    return action


def clip(behavior: str, armature, profile) -> rig_clips.Clip:
    """The procedural action for `behavior` as a clip of one cycle, timed by
    the convention (the left arm forward at the right heel strike)."""
    action = make(behavior, armature, profile)
    first, last = action.curve_frame_range
    return rig_clips.Clip(action, first, last, clip_cycle.ClipCycle(1, clip_cycle.CONVENTION, "convention"))
