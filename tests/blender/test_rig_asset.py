"""Blender background test: the project's humanoid rig asset (rigs/footfall_humanoid.glb)
imports with the bones, hierarchy, clips, skinning and dimensions its rig profile
(rigs/footfall_humanoid.json) promises.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_rig_asset.py
"""

import json
import os
import pathlib
import sys

import numpy

# Debian's Blender 3.4.1 glTF importer uses numpy.bool, which numpy >= 1.24 removed.
numpy.bool = bool

import bpy

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, run  # noqa: E402
from mathutils import Vector

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
from footfall.bridge import action_curves  # noqa: E402

RIGS_DIR = ROOT / "rigs"
PROFILE = json.loads((RIGS_DIR / "footfall_humanoid.json").read_text())
SIDES = {"left": "L", "right": "R"}
LOWER_BODY = {"hips", "thigh", "shin", "foot", "toe"}



def bone_names():
    b = PROFILE["bones"]
    names = {k: b[k] for k in ("hips", "spine", "chest", "neck", "head")}
    for side in SIDES:
        for k, v in b[side].items():
            names[f"{side}.{k}"] = v
    return names


BONES = bone_names()


def expected_parents():
    parents = {"hips": None, "spine": "hips", "chest": "spine", "neck": "chest", "head": "neck"}
    for side in SIDES:
        parents.update({
            f"{side}.upper_arm": "chest", f"{side}.forearm": f"{side}.upper_arm", f"{side}.hand": f"{side}.forearm",
            f"{side}.thigh": "hips", f"{side}.shin": f"{side}.thigh", f"{side}.foot": f"{side}.shin",
            f"{side}.toe": f"{side}.foot",
        })
    return {BONES[k]: (BONES[p] if p else None) for k, p in parents.items()}


_scene = {}


def imported():
    """Import the .glb once into an empty scene; returns (armature, mesh)."""
    if not _scene:
        bpy.ops.wm.read_factory_settings(use_empty=True)
        path = RIGS_DIR / PROFILE["rig"]
        check(path.is_file(), f"missing {path}")
        options = dict(filepath=str(path), bone_heuristic="BLENDER")
        if "disable_bone_shape" in bpy.ops.import_scene.gltf.get_rna_type().properties.keys():
            options["disable_bone_shape"] = True  # no stray Icosphere (Blender 4.x and later)
        bpy.ops.import_scene.gltf(**options)
        objects = list(bpy.context.scene.objects)
        _scene["armatures"] = [o for o in objects if o.type == "ARMATURE"]
        _scene["meshes"] = [o for o in objects if o.type == "MESH"]
        _scene["others"] = [o for o in objects if o.type not in ("ARMATURE", "MESH")]
    check(len(_scene["armatures"]) == 1, f"expected one armature, got {[o.name for o in _scene['armatures']]}")
    check(len(_scene["meshes"]) == 1, f"expected one mesh, got {[o.name for o in _scene['meshes']]}")
    return _scene["armatures"][0], _scene["meshes"][0]


def clip_action(arm, clip):
    """The action the importer made for glTF animation `clip`: it pushes it onto an
    NLA track named after the animation and names the action '<clip>_<armature>'."""
    tracks = [t for t in arm.animation_data.nla_tracks if t.name == clip] if arm.animation_data else []
    actions = {s.action for t in tracks for s in t.strips if s.action}
    actions |= {a for a in bpy.data.actions if a.name in (clip, f"{clip}_{arm.name}")}
    check(len(actions) == 1, f"clip {clip!r}: expected one action, found {sorted(a.name for a in actions)}")
    return actions.pop()


def play(arm, action, frame):
    ad = arm.animation_data
    for track in ad.nla_tracks:
        track.mute = True
    ad.action = action
    bpy.context.scene.frame_set(int(round(frame)))


def rest_pose(arm):
    if arm.animation_data:
        arm.animation_data.action = None
        for track in arm.animation_data.nla_tracks:
            track.mute = True
    for pb in arm.pose.bones:
        pb.matrix_basis.identity()
    bpy.context.scene.frame_set(1)


def group_vertices(mesh, bone, coords, min_weight=0.5):
    index = mesh.vertex_groups[bone].index
    return [coords[v.index] for v in mesh.data.vertices
            if any(g.group == index and g.weight > min_weight for g in v.groups)]


def deformed_coords(mesh):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh.evaluated_get(depsgraph)
    data = evaluated.to_mesh()
    coords = [evaluated.matrix_world @ v.co for v in data.vertices]
    evaluated.to_mesh_clear()
    return coords


def centroid(points):
    return sum(points, Vector()) / len(points)


# ---------------------------------------------------------------------------
def test_profile_format():
    check(PROFILE["format"] == "footfall-rig-profile" and PROFILE["version"] == 1, "wrong profile format/version")
    check(PROFILE["facing"] == "-Y", f"facing {PROFILE['facing']}")
    check(set(PROFILE["clips"]) == {"walk", "arms_in", "side_step", "idle"}, f"clips {PROFILE['clips']}")
    check(set(PROFILE["dimensions"]) == {"hip_height", "leg_length", "shoulder_width", "foot_length"},
          f"dimensions {PROFILE['dimensions']}")


def test_one_armature_with_every_profile_bone():
    arm, _ = imported()
    check(not _scene["others"], f"unexpected objects {[o.name for o in _scene['others']]}")
    missing = sorted(set(BONES.values()) - set(arm.data.bones.keys()))
    check(not missing, f"bones missing: {missing}")


def test_bone_hierarchy():
    arm, _ = imported()
    for bone, parent in expected_parents().items():
        actual = arm.data.bones[bone].parent
        check((actual.name if actual else None) == parent, f"{bone}: parent {actual and actual.name}, expected {parent}")


def test_every_vertex_is_skinned():
    arm, mesh = imported()
    check(mesh.parent == arm, f"mesh parent is {mesh.parent}")
    mods = [m for m in mesh.modifiers if m.type == "ARMATURE"]
    check(len(mods) == 1 and mods[0].object == arm, "mesh has no Armature modifier on the armature")
    groups = {g.index: g.name for g in mesh.vertex_groups}
    check(set(groups.values()) <= set(arm.data.bones.keys()), f"vertex groups not named like bones: {groups}")
    unweighted = [v.index for v in mesh.data.vertices if sum(g.weight for g in v.groups) < 0.99]
    check(not unweighted, f"{len(unweighted)} of {len(mesh.data.vertices)} vertices lack full skin weights")
    tris = sum(len(p.vertices) - 2 for p in mesh.data.polygons)
    check(tris < 5000, f"{tris} triangles")
    check(len(mesh.data.materials) >= 1, "no material")


def test_every_clip_exists_loops_and_keys_only_the_upper_body():
    arm, _ = imported()
    lower = {BONES[k] for k in LOWER_BODY if k in BONES}
    lower |= {BONES[f"{s}.{k}"] for s in SIDES for k in LOWER_BODY if f"{s}.{k}" in BONES}
    lengths = {"walk": 24, "arms_in": 24, "side_step": 24, "idle": 48}  # frames at 24 fps
    for clip, name in PROFILE["clips"].items():
        action = clip_action(arm, name)
        keyed = {fc.data_path.split('"')[1] for fc in action_curves.curves(action) if fc.data_path.startswith("pose.bones")}
        check(keyed and not (keyed & lower), f"{clip}: keys {sorted(keyed)}")
        start, end = action.frame_range
        check(abs((end - start) - lengths[clip]) < 0.01, f"{clip}: frames {start}-{end}")
        play(arm, action, start)
        first = {pb.name: pb.matrix.copy() for pb in arm.pose.bones}
        play(arm, action, end)
        for pb in arm.pose.bones:
            check(all(abs(a - b) < 1e-4 for ra, rb in zip(first[pb.name], pb.matrix) for a, b in zip(ra, rb)),
                  f"{clip}: {pb.name} differs between frames {start} and {end} (not a seamless loop)")
    rest_pose(arm)


def test_walk_swings_the_arms():
    arm, _ = imported()
    action = clip_action(arm, PROFILE["clips"]["walk"])
    start, end = action.frame_range
    hand = arm.pose.bones[BONES["left.hand"]]
    positions = []
    for fraction in (0.25, 0.75):
        play(arm, action, start + fraction * (end - start))
        positions.append(arm.matrix_world @ hand.head)
    rest_pose(arm)
    forward = -(positions[0].y - positions[1].y)  # facing -Y: forward is -Y
    check(forward > 0.10, f"left hand is only {forward:.3f} m further forward at 1/4 than at 3/4 cycle")


def test_arms_in_keeps_the_hands_at_the_torso():
    """Each hand (centroid of its vertices) stays within 15 cm of the torso's side: the
    vertical line at the torso's widest point below the armpits (x = +-half width, y = its centre)."""
    arm, mesh = imported()
    rest_pose(arm)
    rest = deformed_coords(mesh)
    armpit = (arm.matrix_world @ arm.data.bones[BONES["left.upper_arm"]].head_local).z - 0.08
    torso = [p for b in ("hips", "spine", "chest") for p in group_vertices(mesh, BONES[b], rest) if p.z < armpit]
    half_width = max(abs(p.x) for p in torso)
    centre_y = (max(p.y for p in torso) + min(p.y for p in torso)) / 2
    action = clip_action(arm, PROFILE["clips"]["arms_in"])
    start, end = (int(round(f)) for f in action.frame_range)
    worst = (0.0, None)
    for frame in range(start, end + 1):
        play(arm, action, frame)
        coords = deformed_coords(mesh)
        for side in SIDES:
            c = centroid(group_vertices(mesh, BONES[f"{side}.hand"], coords))
            distance = Vector((abs(c.x) - half_width, c.y - centre_y)).length
            worst = max(worst, (distance, f"{side} hand at frame {frame} {tuple(round(v, 3) for v in c)}"), key=lambda w: w[0])
    rest_pose(arm)
    print(f"arms_in: torso half width {half_width:.3f} m, worst hand distance {worst[0]:.3f} m ({worst[1]})")
    check(worst[0] < 0.15, f"the {worst[1]} is {worst[0]:.3f} m from the torso's side in arms_in")


def test_dimensions_match_the_rest_pose():
    arm, mesh = imported()
    rest_pose(arm)
    mw = arm.matrix_world
    head = lambda key: mw @ arm.data.bones[BONES[key]].head_local
    flat = lambda v: Vector((v.x, v.y))
    rest = deformed_coords(mesh)
    hip_h, leg, foot = [], [], []
    for side in SIDES:
        hip, knee, ankle = head(f"{side}.thigh"), head(f"{side}.shin"), head(f"{side}.foot")
        hip_h.append(hip.z)
        leg.append((hip - knee).length + (knee - ankle).length)
        # glTF stores joints, not bone tails, and the importer gives a leaf bone (toe) its
        # parent's length; so the toe bone's tail is taken where the script built it: at the
        # tip of the toe mesh, the toe.* vertices' furthest reach along the foot's ground axis.
        a, ball = flat(ankle), flat(head(f"{side}.toe"))
        ahead = (ball - a).normalized()
        check(ahead.y < -0.9, f"{side} foot does not point to -Y: {ahead}")
        tip = max((flat(p) - a).dot(ahead) for p in group_vertices(mesh, BONES[f"{side}.toe"], rest))
        heel = max(0.0, max(-(flat(p) - a).dot(ahead) for p in group_vertices(mesh, BONES[f"{side}.foot"], rest)))
        foot.append(tip + heel)
    measured = {
        "hip_height": sum(hip_h) / 2,
        "leg_length": sum(leg) / 2,
        "shoulder_width": (head("left.upper_arm") - head("right.upper_arm")).length,
        "foot_length": sum(foot) / 2,
    }
    print("measured dimensions:", {k: round(v, 4) for k, v in measured.items()})
    for key, value in measured.items():
        check(abs(PROFILE["dimensions"][key] - value) <= 0.001, f"{key}: profile {PROFILE['dimensions'][key]}, measured {value:.4f}")
    check(min(p.z for p in rest) > -0.001 and min(p.z for p in rest) < 0.005, "feet are not on the ground")
    height = max(p.z for p in rest)
    check(1.7 < height < 1.9, f"height {height:.3f} m")



run([
        test_profile_format,
        test_one_armature_with_every_profile_bone,
        test_bone_hierarchy,
        test_every_vertex_is_skinned,
        test_every_clip_exists_loops_and_keys_only_the_upper_body,
        test_walk_swings_the_arms,
        test_arms_in_keeps_the_hands_at_the_torso,
        test_dimensions_match_the_rest_pose,
    ])
