# SPDX-License-Identifier: GPL-3.0-or-later
"""The body the full-body planner tests, measured from a rig: its capsules
fitted to the skinned mesh (core/body_capsules), posed by the clips Apply
plays (the rig's own, else the procedural ones) at PHASES phases of a gait
cycle, from the right heel strike (the core's phase 0: the left foot's step
begins), in the planner's travel frame.

Import Rig stores the result on the armature (BODY_PROPERTY); the scenario
gives it to the planner as the character's `behaviors` (core/character).
"""

import json
from typing import Dict, List, Optional, Tuple

import bpy
import numpy

from ..core import body_capsules
from ..core.body_capsules import LIMB_JOINTS, Role
from . import procedural_clips, rig_clips

PHASES = 32
BODY_PROPERTY = "footfall_body"
PLANNED_BEHAVIORS = ("walk", "arms_in", "side_step")


def _bone(bones: Dict[str, object], role: Role) -> str:
    return bones[role[0]] if len(role) == 1 else bones[role[0]][role[1]]


def _roles_by_bone(bones: Dict[str, object]) -> Dict[str, Role]:
    roles: Dict[str, Role] = {}
    for key, value in bones.items():
        if isinstance(value, dict):
            roles.update({name: (key, role) for role, name in value.items()})
        else:
            roles[value] = (key,)
    return roles


def _vertices(rig, bones: Dict[str, object]) -> Tuple[numpy.ndarray, List[Optional[Role]]]:
    """Rest positions (world) of the vertices of every mesh the rig deforms,
    and each one's role: that of the bone it is skinned to most, or of that
    bone's nearest mapped ancestor (fingers go with the hand)."""
    by_bone = _roles_by_bone(bones)
    role_of: Dict[str, Optional[Role]] = {}
    for bone in rig.data.bones:
        role_of[bone.name] = next((by_bone[b.name] for b in [bone, *bone.parent_recursive] if b.name in by_bone),
                                  None)
    points, roles = [], []
    for mesh in [o for o in bpy.data.objects if o.type == "MESH" and
                 any(m.type == "ARMATURE" and m.object == rig for m in o.modifiers)]:
        group_roles = [role_of.get(group.name) for group in mesh.vertex_groups]
        world = numpy.array(mesh.matrix_world)
        for vertex in mesh.data.vertices:
            strongest = max(vertex.groups, key=lambda g: g.weight, default=None)
            if strongest is None or strongest.weight <= 0 or strongest.group >= len(group_roles):
                continue
            points.append(world[:3, :3] @ numpy.array(vertex.co) + world[:3, 3])
            roles.append(group_roles[strongest.group])
    return numpy.array(points).reshape(-1, 3), roles


def _clip(rig, profile, behavior: str) -> rig_clips.Clip:
    return rig_clips.own_clip(rig, profile, behavior) or procedural_clips.clip(behavior, rig, profile)


def measure(rig, profile) -> Tuple[dict, Dict[str, str]]:
    """{"height": the top of the mesh above the ground [m], "poses":
    {behaviour: [pose: {limb: [ax, ay, az, bx, by, bz, radius]}]}}, and the
    limbs that took the built-in body's radius, each with why
    (body_capsules.rest_capsules)."""
    bones = profile.bones
    world = numpy.array(rig.matrix_world)
    data = rig.data

    def joint(role: Role, end: str) -> numpy.ndarray:
        bone = data.bones[_bone(bones, role)]
        local = bone.head_local if end == "head" else bone.tail_local
        return world[:3, :3] @ numpy.array(local) + world[:3, 3]

    joints = {j: joint(*j) for ends in LIMB_JOINTS.values() for j in ends}
    vertices, roles = _vertices(rig, bones)
    capsules, fallbacks = body_capsules.rest_capsules(joints, body_capsules.limb_points(vertices, roles, joints),
                                                      profile.dimensions["leg_length"])
    names = sorted({_bone(bones, r) for c in capsules.values() for r in (c.bone_a, c.bone_b)} | {bones["hips"]})
    # Each capsule end in its bone's rest frame (world scale and placement included).
    rest = {name: world @ numpy.array(data.bones[name].matrix_local) for name in names}
    ends = {limb: [numpy.linalg.inv(rest[_bone(bones, role)]) @ numpy.append(point, 1.0)
                   for role, point in ((c.bone_a, c.a), (c.bone_b, c.b))] for limb, c in capsules.items()}
    facing = world[:3, :3] @ rig_clips.feet_forward(data, bones)
    motions = {}
    for behavior in PLANNED_BEHAVIORS:
        clip = _clip(rig, profile, behavior)
        phases = (clip.cycle.strike + numpy.arange(PHASES) / PHASES) % 1.0
        posed = rig_clips.posed(rig, clip.action, bones, names, clip.first + phases * clip.cycle_frames)
        poses = []
        for k in range(PHASES):
            placed = {name: world @ posed[name][k] for name in names}
            frame = body_capsules.travel_frame(placed[bones["hips"]][:3, 3], facing, behavior == "side_step")
            pose = {}
            for limb, (a, b) in ends.items():
                c = capsules[limb]
                pa = (frame @ placed[_bone(bones, c.bone_a)] @ a)[:3]
                pb = (frame @ placed[_bone(bones, c.bone_b)] @ b)[:3]
                pose[limb] = [round(float(v), 4) for v in (*pa, *pb)] + [round(c.radius, 4)]
            poses.append(pose)
        motions[behavior] = poses
    height = float(vertices[:, 2].max()) if len(vertices) else float(joints[("head",), "tail"][2])
    return {"height": round(height, 4), "poses": motions}, fallbacks


def _fallback_notes(fallbacks: Dict[str, str]) -> List[str]:
    """A note naming the limbs that took the built-in body's radius, and why."""
    if not fallbacks:
        return []
    by_why: Dict[str, List[str]] = {}
    for limb, why in fallbacks.items():
        by_why.setdefault(why, []).append(limb)
    limbs = "; ".join(f"{', '.join(names)} ({why})" for why, names in by_why.items())
    return [f"body: the built-in body's radius, scaled to the rig's leg length, for the limbs its mesh gives "
            f"nothing usable: {limbs}"]


def measured(rig, profile) -> Tuple[Optional[dict], List[str]]:
    """The rig's body and notes for the user (which limbs took the built-in
    body's radius); None (and why) where its motions do not narrow from walk
    to arms in to side step: the planner needs that order, and then tests the
    built-in body."""
    body, fallbacks = measure(rig, profile)
    notes = _fallback_notes(fallbacks)
    extents = {b: body_capsules.lateral_extent(body["poses"][b]) for b in PLANNED_BEHAVIORS}
    widths = ", ".join(f"{b} {extents[b]:.2f} m" for b in reversed(PLANNED_BEHAVIORS))
    if not extents["side_step"] < extents["arms_in"] < extents["walk"]:
        return None, notes + [f"body: its clips do not narrow from walk to arms in to side step (across the way: "
                              f"{widths}); the planner tests the built-in body"]
    return body, notes + [f"body measured from its mesh and clips (across the way: {widths})"]


def body_of(rig) -> Optional[dict]:
    """The body stored on an imported rig; None for a rig whose clips gave
    none (measured), or imported before Footfall measured bodies: it plans
    with the built-in body."""
    text = rig.get(BODY_PROPERTY)
    return json.loads(text) if text else None
