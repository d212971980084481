# SPDX-License-Identifier: GPL-3.0-or-later
"""A rig's own actions as behaviour clips: which actions are the rig's,
which one plays which behaviour, its gait cycle (core/clip_cycle), and the
copy Apply plays, with the root motion left out.

The rig's actions themselves are never changed: Apply plays copies.
"""

import dataclasses
import math
import re
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence

import bpy
import numpy

from ..core import clip_cycle
from ..core.rig_profile import CLIP_ROLES, STAIR_CLIPS
from . import action_curves

SAMPLES = 64  # per clip, to find its cycle
CLIP_OF = "footfall_clip_of"  # on Apply's copies: the action copied
_CHANNEL = re.compile(r'^pose\.bones\["((?:[^"\\]|\\.)*)"\]\.(\w+)$')
# Names that say which behaviour an action plays, after an exact match and
# the importer's "NAME_Object" suffix.
_NAME_PATTERNS = {
    "walk": re.compile(r"walk", re.IGNORECASE),
    "arms_in": re.compile(r"arms?[ _.-]?in\b", re.IGNORECASE),
    "side_step": re.compile(r"side[ _.-]?step|strafe", re.IGNORECASE),
    "idle": re.compile(r"idle", re.IGNORECASE),
    "stairs_up": re.compile(r"(stairs?|steps?)[ _.-]?up|up[ _.-]?(the[ _.-]?)?stairs|ascend", re.IGNORECASE),
    "stairs_down": re.compile(r"(stairs?|steps?)[ _.-]?down|down[ _.-]?(the[ _.-]?)?stairs|descend",
                              re.IGNORECASE),
}


class ClipError(ValueError):
    """A clip named for a rig is missing or unusable; the message names it."""


@dataclass(frozen=True)
class Clip:
    """An action to play for a behaviour: frames first..last hold
    `cycle.cycles` gait cycles."""

    action: bpy.types.Action
    first: float
    last: float
    cycle: clip_cycle.ClipCycle

    @property
    def cycle_frames(self) -> float:
        return (self.last - self.first) / self.cycle.cycles


def _channels(action) -> Dict[str, Dict[str, Dict[int, bpy.types.FCurve]]]:
    """The action's pose-bone F-curves: bone -> property -> index -> curve."""
    found: Dict[str, Dict[str, Dict[int, bpy.types.FCurve]]] = {}
    for curve in action_curves.curves(action):
        match = _CHANNEL.match(curve.data_path)
        if match:
            bone = re.sub(r"\\(.)", r"\1", match.group(1))
            found.setdefault(bone, {}).setdefault(match.group(2), {})[curve.array_index] = curve
    return found


def actions_of(armature) -> List[bpy.types.Action]:
    """The actions in the file that animate the armature's bones (most of
    whose bone channels name its bones), but for Footfall's own (clip copies,
    procedural clips, an applied crowd's locomotion: properties "footfall_...")."""
    names = set(armature.data.bones.keys())
    result = []
    for action in bpy.data.actions:
        if any(key.startswith("footfall_") for key in action.keys()):
            continue
        bones = _channels(action)
        if bones and 2 * sum(b in names for b in bones) >= len(bones):
            result.append(action)
    return result


def _frame_range(action):
    """The action's frames; a pose keyed on one frame spans one."""
    first, last = action.frame_range
    return float(first), max(float(last), float(first) + 1.0)


def _values(curves: Dict[int, bpy.types.FCurve], size: int, default: Sequence[float], frames) -> numpy.ndarray:
    values = numpy.tile(numpy.array(default, dtype=float), (len(frames), 1))
    for index, curve in curves.items():
        if index < size:
            values[:, index] = [curve.evaluate(f) for f in frames]
    return values


def _bases(rig, channels, bones: Sequence[str], frames) -> Dict[str, numpy.ndarray]:
    """Each bone's pose basis at the frames, from the action's channels."""
    bases = {}
    for name in bones:
        props = channels.get(name)
        if not props:
            continue
        location = _values(props.get("location", {}), 3, (0, 0, 0), frames)
        scale = _values(props.get("scale", {}), 3, (1, 1, 1), frames)
        mode = rig.pose.bones[name].rotation_mode if name in rig.pose.bones else "QUATERNION"
        if "rotation_quaternion" in props or ("rotation_euler" not in props and "rotation_axis_angle" not in props):
            rotation = clip_cycle.quaternion_matrices(_values(props.get("rotation_quaternion", {}), 4, (1, 0, 0, 0), frames))
        elif "rotation_euler" in props:
            order = mode if mode in ("XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX") else "XYZ"
            rotation = clip_cycle.euler_matrices(_values(props["rotation_euler"], 3, (0, 0, 0), frames), order)
        else:
            angle_axis = _values(props["rotation_axis_angle"], 4, (0, 0, 1, 0), frames)
            half = 0.5 * angle_axis[:, 0:1]
            axis = angle_axis[:, 1:] / numpy.maximum(numpy.linalg.norm(angle_axis[:, 1:], axis=1, keepdims=True), 1e-12)
            rotation = clip_cycle.quaternion_matrices(numpy.hstack((numpy.cos(half), numpy.sin(half) * axis)))
        bases[name] = clip_cycle.basis_matrices(location, rotation, scale)
    return bases


def _chain(data, name: str) -> List[str]:
    bone = data.bones[name]
    return [bone.name] + [b.name for b in bone.parent_recursive]


def feet_forward(data, bones: Dict[str, object]) -> numpy.ndarray:
    """Where the rig faces at rest, in its armature space: the sum of its
    feet's directions (heel to toe; not of unit length)."""
    forward = numpy.zeros(3)
    for side in ("left", "right"):
        foot = data.bones[bones[side]["foot"]]
        forward += numpy.array(foot.tail_local - foot.head_local)
    return forward


def find_cycle(rig, action, bones: Dict[str, object]) -> clip_cycle.ClipCycle:
    """The gait cycle of `action` played on `rig`, whose bone map is `bones`."""
    data = rig.data
    first, last = _frame_range(action)
    frames = first + (last - first) * numpy.arange(SAMPLES) / SAMPLES
    ends = {(side, role): bones[side][role] for side in ("left", "right") for role in ("foot", "hand")}
    needed = sorted({b for name in ends.values() for b in _chain(data, name)})
    rests = {b.name: clip_cycle.BoneRest(b.name, b.parent.name if b.parent else None, numpy.array(b.matrix_local))
             for b in data.bones}
    heads = clip_cycle.pose_heads(rests, _bases(rig, _channels(action), needed, frames), list(ends.values()),
                                  SAMPLES)
    leg_length = sum(0.5 * (data.bones[leg["foot"]].head_local - data.bones[leg["thigh"]].head_local).length
                     for leg in (bones["left"], bones["right"]))
    forward = feet_forward(data, bones)
    forward[2] = 0.0  # armature space: the rig's own up, as at rest
    forward /= max(numpy.linalg.norm(forward), 1e-12)
    return clip_cycle.find_cycle(forward, leg_length, heads[ends["left", "foot"]], heads[ends["right", "foot"]],
                                 heads[ends["left", "hand"]], heads[ends["right", "hand"]])


def root_motion(rig, action, bones: Dict[str, object]) -> List[bpy.types.FCurve]:
    """The curves that move the whole rig rather than pose it: the object's
    own, any bone's this rig does not have, every channel of the bones above
    the hips and the hips' location. The plan places and turns the body."""
    data = rig.data
    hips = data.bones[bones["hips"]]
    above = {b.name for b in hips.parent_recursive}
    moving = []
    for curve in action_curves.curves(action):
        match = _CHANNEL.match(curve.data_path)
        bone = re.sub(r"\\(.)", r"\1", match.group(1)) if match else None
        if bone is None or bone not in data.bones or bone in above or \
                (bone == hips.name and match.group(2) == "location"):
            moving.append(curve)
    return moving


def posed(rig, action, bones: Dict[str, object], names: Sequence[str], frames) -> Dict[str, numpy.ndarray]:
    """Armature-space matrices (len(frames), 4, 4) of the bones `names` as
    Apply plays `action` at the frames: without its root motion."""
    moving = {(c.data_path, c.array_index) for c in root_motion(rig, action, bones)}
    channels: Dict[str, Dict[str, Dict[int, bpy.types.FCurve]]] = {}
    for bone, props in _channels(action).items():
        for prop, curves in props.items():
            for index, curve in curves.items():
                if (curve.data_path, curve.array_index) not in moving:
                    channels.setdefault(bone, {}).setdefault(prop, {})[index] = curve
    needed = sorted({b for name in names for b in _chain(rig.data, name)})
    rests = {b.name: clip_cycle.BoneRest(b.name, b.parent.name if b.parent else None, numpy.array(b.matrix_local))
             for b in rig.data.bones}
    return clip_cycle.pose_matrices(rests, _bases(rig, channels, needed, frames), names, len(frames))


def _playable_copy(rig, action, bones, behavior: str) -> bpy.types.Action:
    """A copy of the rig's action without its root motion, its bone
    locations in metres (the rig's world scale)."""
    copy = action.copy()
    copy.name = f"footfall {behavior} from {action.name}"
    copy[CLIP_OF] = action.name
    copy.use_fake_user = False
    for curve in root_motion(rig, copy, bones):
        action_curves.remove(copy, curve)
    scale = abs(rig.matrix_world.to_3x3().determinant()) ** (1.0 / 3.0)
    if not math.isclose(scale, 1.0):
        for curve in action_curves.curves(copy):
            if curve.data_path.endswith(".location"):
                for key in curve.keyframe_points:
                    for point in (key.co, key.handle_left, key.handle_right):
                        point[1] *= scale
    return copy


def own_clip(rig, profile, behavior: str) -> Optional[Clip]:
    """The rig's own action named in its profile for `behavior` (not a
    copy), or None where the profile names none."""
    name = profile.clips.get(behavior)
    if not name:
        return None
    action = bpy.data.actions.get(name)
    if action is None:
        raise ClipError(f"rig '{rig.name}': its {behavior} clip '{name}' is no longer in this file "
                        "(import the rig again, or name another clip in its profile)")
    first, last = _frame_range(action)
    return Clip(action, first, last, find_cycle(rig, action, profile.bones))


def playable(rig, profile, behavior: str) -> Optional[Clip]:
    """The clip Apply plays for `behavior`: a copy of the rig's own, or None."""
    clip = own_clip(rig, profile, behavior)
    if clip is None:
        return None
    return dataclasses.replace(clip, action=_playable_copy(rig, clip.action, profile.bones, behavior))


def remove_unused_copies() -> None:
    """Removes clip copies no strip plays any more (those of a replaced
    crowd), and gives the new copies the names those had (not "NAME.001")."""
    for action in [a for a in bpy.data.actions if CLIP_OF in a and a.users == 0]:
        bpy.data.actions.remove(action)
    for action in [a for a in bpy.data.actions if CLIP_OF in a]:
        base = re.sub(r"\.\d{3,}$", "", action.name)
        if base != action.name and base not in bpy.data.actions:
            action.name = base


def _named(behavior: str, actions) -> Optional[bpy.types.Action]:
    """The action whose name says it plays `behavior`: its exact name, the
    name with the importer's "_Object" suffix, or a name that mentions it."""
    ranked = []
    for action in actions:
        if action.name == behavior:
            rank = 0
        elif action.name.startswith(behavior + "_"):
            rank = 1
        elif _NAME_PATTERNS[behavior].search(action.name):
            rank = 2
        else:
            continue
        ranked.append((rank, len(action.name), action.name, action))
    return min(ranked, key=lambda r: r[:3])[3] if ranked else None


def choose(rig, bones: Dict[str, object], given: Dict[str, Optional[str]], actions, source: str):
    """The clip name per behaviour, and notes for the user. A clip the profile
    names must be one of `actions`; the others are found by name, and a walk
    with no name for it is the one action whose feet step (a Mixamo
    "mixamo.com", a glTF's unnamed animation)."""
    by_name = {a.name: a for a in actions}
    chosen: Dict[str, Optional[bpy.types.Action]] = {}
    for behavior in CLIP_ROLES:
        wanted = given.get(behavior)
        if wanted:
            # The importer may add the object's name to an animation's ("walk_Armature").
            action = by_name.get(wanted) or next((a for a in actions if a.name.startswith(wanted + "_")), None)
            if action is None:
                raise ClipError(f"{source}: clips.{behavior} = '{wanted}': no such animation in the rig "
                                f"(animations: {', '.join(sorted(by_name)) or 'none'})")
            chosen[behavior] = action
        else:
            chosen[behavior] = _named(behavior, actions)
    notes = []
    cycles = {}  # each action's cycle, found once

    def cycle_of(action):
        if action.name not in cycles:
            cycles[action.name] = find_cycle(rig, action, bones)
        return cycles[action.name]

    if chosen["walk"] is None:
        free = [a for a in actions if a not in chosen.values()]
        stepping = [a for a in free if cycle_of(a).source == "feet"]
        if len(stepping) == 1:
            chosen["walk"] = stepping[0]
        elif stepping:
            notes.append(f"several clips step ({', '.join(sorted(a.name for a in stepping))}): name the walk "
                         "in the rig's profile")
    for behavior, action in chosen.items():
        if action is None and behavior in STAIR_CLIPS:
            continue  # the walk plays on stairs
        if action is None:
            notes.append(f"no '{behavior}' clip: a procedural one will be used")
            continue
        cycle = cycle_of(action)
        first, last = _frame_range(action)
        timed = {"feet": f"right heel strike at {100 * cycle.strike:.0f} % of the cycle, from its feet",
                 "hands": f"right heel strike at {100 * cycle.strike:.0f} % of the cycle, from its hands",
                 "convention": "no swing to time it by"}[cycle.source]
        root = "; its root motion is left out" if root_motion(rig, action, bones) else ""
        notes.append(f"{behavior}: the rig's clip '{action.name}' ({cycle.cycles} cycle(s) in "
                     f"{last - first:g} frames; {timed}){root}")
    return {b: (a.name if a else None) for b, a in chosen.items() if a or b not in STAIR_CLIPS}, notes
