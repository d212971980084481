# SPDX-License-Identifier: GPL-3.0-or-later
"""Live motion: a crowd posed from its plan at each frame, instead of keyed.

Keyed in full, a crowd's locomotion is most of its .blend (docs/notes/
blender-workflow.md). Applied live, what animate keys in an agent's
locomotion action (the hips, the foot targets, the toes, the knee poles) is
not keyed: a frame-change handler sets those bones from the motion sampled
at every frame of the Apply, held in memory. The plan the crowd plays is kept
packed in the Text "footfall_crowd_plan", and each live armature says in its
property "footfall_live" which agent it plays and how (its rest as JSON, its
frames, frame rate and speed), so that after the file is opened again the first
frame change samples the motion anew. The clips' strips, their influence,
the look-ahead and the leaving stay keyed.

Only Blender with the add-on plays it: elsewhere (a render farm without it,
an exporter other than Footfall's) the crowd stands still. Keyed Apply is
for those.
"""

import json
import uuid
from dataclasses import astuple
from typing import Dict

import bpy
import numpy
from bpy.app.handlers import persistent
from mathutils import Matrix, Vector

from ..core import foot_roll, native
from . import animate, plan_store

LIVE = "footfall_live"  # a live armature's property (a group): what poses it
PLAN_TEXT = "footfall_crowd_plan"  # the plan the live crowd plays, packed as plan_store packs
REVISION = "footfall_revision"  # the Text's property: new at every store


class LiveMotionError(ValueError):
    """A live armature whose plan or agent is gone; the message names it."""


class _Motion:
    """One armature's locomotion at every frame from `first`: a row per
    frame of the driven bones' locations, then their quaternions."""

    PATHS = (("location", 3, "locations"), ("rotation_quaternion", 4, "quaternions"))  # and Keyed's field

    def __init__(self, first: int, channels: Dict[str, animate.Keyed]):
        self.first = first
        self.bones = {path: [bone for bone, keyed in channels.items() if getattr(keyed, field) is not None]
                      for path, _, field in self.PATHS}
        # float32: 200 agents for 5,000 frames take some 150 MB.
        self.rows = numpy.hstack([getattr(channels[bone], field) for path, _, field in self.PATHS
                                  for bone in self.bones[path]]).astype(numpy.float32)
        self._places = {}  # bone count -> where the driven values go in such an armature's pose arrays

    def row(self, frame: float) -> numpy.ndarray:
        """The driven values at `frame` (between frames, in between; before
        the first or after the last, held)."""
        at = min(max(frame - self.first, 0.0), len(self.rows) - 1.0)
        below = int(at)
        share = numpy.float32(at - below)
        if share == 0.0:
            return self.rows[below]
        return (1.0 - share) * self.rows[below] + share * self.rows[below + 1]

    def _places_in(self, bones) -> list:
        """Where the driven values go in the pose arrays of an armature with
        these bones (per path: indices into its flat array)."""
        count = len(bones)
        if count not in self._places:
            index = {bone.name: i for i, bone in enumerate(bones)}
            missing = [b for path in self.bones.values() for b in path if b not in index]
            if missing:
                raise LiveMotionError(f"its bone '{missing[0]}' is gone")
            self._places[count] = [numpy.array([width * index[b] + k for b in self.bones[path] for k in range(width)],
                                               dtype=int) for path, width, _ in self.PATHS]
        return self._places[count]

    def pose(self, armature, frame: float) -> None:
        """Poses the armature at `frame`, in bulk; an armature already so posed
        (one standing, or gone) is not touched, which spares Blender its update."""
        bones = armature.pose.bones
        values = self.row(frame)
        arrays, changed, column = [], False, 0
        for (path, width, _), places in zip(self.PATHS, self._places_in(bones)):
            array = numpy.empty(width * len(bones), dtype=numpy.float32)
            bones.foreach_get(path, array)
            wanted = values[column:column + len(places)]
            column += len(places)
            changed = changed or not numpy.array_equal(array[places], wanted)
            array[places] = wanted
            arrays.append((path, array))
        if not changed:
            return
        for path, array in arrays:
            bones.foreach_set(path, array)
        armature.update_tag(refresh={"OBJECT"})  # foreach_set tags nothing; the pose follows its object's update


_motions: Dict[str, _Motion] = {}  # by the "id" in an armature's LIVE property
_failed = set()  # ids whose motion could not be made: said once, not at every frame
_crowd_plan = (None, None, None)  # (the Text's revision, the core's reading of it, its terrain)


def drive(armature, agent: str, rest: animate.RigRest, frames, fps: float, speed: float, channels) -> None:
    """animate.applying's `drive`: poses `armature` live from `channels`
    (sampled at `frames`) and records how to sample them again."""
    key = uuid.uuid4().hex
    armature[LIVE] = {"id": key, "agent": agent, "first": int(frames[0]), "count": len(frames), "fps": fps,
                      "speed": speed, "rest": json.dumps(_rest_to_dict(rest))}
    _motions[key] = _Motion(int(frames[0]), channels)
    _motions[key].pose(armature, bpy.context.scene.frame_current)


def store_plan(packed: str) -> None:
    """Keeps `packed` (plan_store.pack) as the plan the live crowd plays."""
    block = bpy.data.texts.get(PLAN_TEXT) or bpy.data.texts.new(PLAN_TEXT)
    block.from_string(packed)
    block[REVISION] = uuid.uuid4().hex


def live_armatures():
    """The crowd's armatures posed live."""
    return [obj for obj in animate.crowd_armatures() if LIVE in obj]


def crowd_state() -> str:
    """How the crowd is animated, for the panel ("" without a crowd)."""
    armatures = animate.crowd_armatures()
    if not armatures:
        return ""
    live = sum(LIVE in obj for obj in armatures)
    if live == len(armatures):
        return f"Crowd: {live} agents live (posed from the plan at each frame)"
    return f"Crowd: {len(armatures) - live} agents keyed" + (f", {live} live" if live else "")


def _forget_gone() -> list:
    """Forgets the motion of armatures gone (it holds a few MB each); returns
    the live armatures."""
    live = live_armatures()
    kept = {obj[LIVE].get("id") for obj in live}
    for key in [k for k in _motions if k not in kept]:
        del _motions[key]
    return live


def tidy() -> None:
    """Forgets the motion of armatures gone, and the crowd's plan once no
    armature plays it live."""
    if not _forget_gone() and PLAN_TEXT in bpy.data.texts:
        bpy.data.texts.remove(bpy.data.texts[PLAN_TEXT])


def _plan():
    """The crowd's plan and its terrain (animate.terrain_of), read once a revision of its Text."""
    global _crowd_plan
    block = bpy.data.texts.get(PLAN_TEXT)
    if block is None:
        raise LiveMotionError(f"the Text '{PLAN_TEXT}' with the plan the crowd plays is gone: Apply again")
    if _crowd_plan[0] != block.get(REVISION) or _crowd_plan[1] is None:
        try:
            plan = native.load().parse_plan(plan_store.unpack(block.as_string()), PLAN_TEXT)
        except ValueError as error:
            raise LiveMotionError(f"{error}: Apply again") from error
        _crowd_plan = (block.get(REVISION), plan, animate.terrain_of(native.load(), plan))
    return _crowd_plan[1], _crowd_plan[2]


def _motion(armature, key: str) -> _Motion:
    """The motion of `armature` (its `key`), sampled anew from the crowd's
    plan if not held."""
    if key in _motions:
        return _motions[key]
    live = armature[LIVE]
    try:
        name, first, count, fps, speed = (live[k] for k in ("agent", "first", "count", "fps", "speed"))
        rest = _rest_from_dict(json.loads(live["rest"]))
    except (KeyError, TypeError, ValueError) as error:
        raise LiveMotionError(f"its property '{LIVE}' is damaged ({error!r}): Apply again") from error
    plan, terrain = _plan()
    agent = next((a for a in plan.agents if a.name == name), None)
    if agent is None:
        raise LiveMotionError(f"the crowd's plan has no agent '{name}': Apply again")
    frames = numpy.arange(first, first + count, dtype=float)
    _motions[key] = _Motion(first, animate.motion_of(native.load(), agent, rest, frames, fps, speed, terrain)[0])
    return _motions[key]


def pose_crowd(scene) -> None:
    """Poses every live armature at the scene's frame; one that cannot be
    posed stands, and the console says why, once."""
    frame = scene.frame_current + scene.frame_subframe
    for armature in live_armatures():
        key = armature[LIVE].get("id")
        if key in _failed:
            continue
        try:
            if key is None:
                raise LiveMotionError(f"its property '{LIVE}' is damaged (no id): Apply again")
            _motion(armature, key).pose(armature, frame)
        except LiveMotionError as error:
            _failed.add(key)
            print(f"Footfall: '{armature.name}' stands still: {error}")


@persistent
def _on_frame_change(scene, *_) -> None:
    pose_crowd(scene)


@persistent
def _on_load(*_) -> None:
    global _crowd_plan
    _motions.clear()
    _failed.clear()
    _crowd_plan = (None, None, None)


@persistent
def _on_undo(*_) -> None:
    _forget_gone()  # an Apply undone: its crowd's motion goes too


_HANDLERS = (("frame_change_pre", _on_frame_change), ("load_post", _on_load), ("undo_post", _on_undo))


def register() -> None:
    for kind, handler in _HANDLERS:
        getattr(bpy.app.handlers, kind).append(handler)


def unregister() -> None:
    for kind, handler in _HANDLERS:
        handlers = getattr(bpy.app.handlers, kind)
        if handler in handlers:
            handlers.remove(handler)


def _rest_to_dict(rest: animate.RigRest) -> dict:
    legs = {side: {"foot": leg.foot, "shin": leg.shin, "thigh": leg.thigh, "toe": leg.toe,
                   "foot_rest": _rows(leg.foot_rest), "pole_rest": _rows(leg.pole_rest),
                   "toe_rest": _rows(leg.toe_rest), "thigh_head": list(leg.thigh_head),
                   "ankle": list(leg.ankle), "knee": list(leg.knee), "length": leg.length,
                   "shape": list(astuple(leg.shape)), "foot_length": leg.foot_length}
            for side, leg in rest.legs.items()}
    return {"hips": rest.hips, "hips_rest": _rows(rest.hips_rest), "forward_yaw": rest.forward_yaw,
            "chest": rest.chest, "head": rest.head, "legs": legs}


def _rest_from_dict(data: dict) -> animate.RigRest:
    rest = animate.RigRest(data["hips"], Matrix(data["hips_rest"]), data["forward_yaw"], data["chest"],
                           data["head"])
    for side, leg in data["legs"].items():
        rest.legs[side] = animate.Leg(
            foot=leg["foot"], shin=leg["shin"], thigh=leg["thigh"], toe=leg["toe"],
            foot_rest=Matrix(leg["foot_rest"]), pole_rest=Matrix(leg["pole_rest"]),
            toe_rest=Matrix(leg["toe_rest"]), thigh_head=Vector(leg["thigh_head"]), ankle=Vector(leg["ankle"]),
            knee=Vector(leg["knee"]), length=leg["length"], shape=foot_roll.FootShape(*leg["shape"]),
            # Applied before feet walked on ground: a foot as the core guesses one without a profile.
            foot_length=leg.get("foot_length", leg["shape"][1] / foot_roll.HEEL_SHARE))
    return rest


def _rows(matrix: Matrix) -> list:
    return [list(row) for row in matrix]
