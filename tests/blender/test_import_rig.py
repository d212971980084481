"""Blender background test: footfall.import_rig on rigs of several naming
schemes, exported to glTF by this test, and on the project's own rig.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_import_rig.py
"""

import json
import os
import pathlib
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, expect_valid_gltf, run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-rigs-"))

# Rest-pose joints of a 1.8 m humanoid facing -Y (x: left is +x).
TRUNK = [("hips", None, (0, 0, 0.95), (0, 0, 1.05)), ("spine", "hips", (0, 0, 1.05), (0, 0, 1.2)),
         ("chest", "spine", (0, 0, 1.2), (0, 0, 1.45)), ("neck", "chest", (0, 0, 1.45), (0, 0, 1.55)),
         ("head", "neck", (0, 0, 1.55), (0, 0, 1.8))]


def limb_bones(side, x):
    s = 1 if side == "left" else -1
    return [("upper_arm", "chest", (s * 0.19, 0, 1.42), (s * 0.35, 0, 1.2)),
            ("forearm", "upper_arm", (s * 0.35, 0, 1.2), (s * 0.45, 0, 0.98)),
            ("hand", "forearm", (s * 0.45, 0, 0.98), (s * 0.5, 0, 0.88)),
            ("thigh", "hips", (s * x, 0, 0.95), (s * x, 0, 0.5)),
            ("shin", "thigh", (s * x, 0, 0.5), (s * x, 0, 0.09)),
            ("foot", "shin", (s * x, 0, 0.09), (s * x, -0.14, 0.02)),
            ("toe", "foot", (s * x, -0.14, 0.02), (s * x, -0.2, 0.0))]


def build_and_export(name, rename, without=()):
    """A skinned rig whose bones are named by rename(role, side), written as
    TMP/name.glb; the roles in `without` left out."""
    bpy.ops.wm.read_homefile(use_empty=True)
    armature_data = bpy.data.armatures.new(name)
    armature = bpy.data.objects.new(name, armature_data)
    bpy.context.scene.collection.objects.link(armature)
    bpy.context.view_layer.objects.active = armature
    bpy.ops.object.mode_set(mode="EDIT")
    names = {}
    specs = [(r, None, p, h, t) for r, p, h, t in TRUNK]
    for side in ("left", "right"):
        specs += [(r, side, p, h, t) for r, p, h, t in limb_bones(side, 0.1) if r not in without]
    for role, side, parent, head, tail in specs:
        bone = armature_data.edit_bones.new(rename(role, side))
        bone.head, bone.tail = head, tail
        names[(role, side)] = bone.name
        if parent:
            parent_side = side if parent in ("upper_arm", "forearm", "thigh", "shin", "foot") else None
            bone.parent = armature_data.edit_bones[names[(parent, parent_side)]]
    bpy.ops.object.mode_set(mode="OBJECT")
    bpy.ops.mesh.primitive_cube_add(size=0.3, location=(0, 0, 1.2))
    body = bpy.context.active_object
    group = body.vertex_groups.new(name=names[("hips", None)])
    group.add(range(len(body.data.vertices)), 1.0, "REPLACE")
    body.parent = armature
    body.modifiers.new("Armature", "ARMATURE").object = armature
    path = TMP / f"{name}.glb"
    bpy.ops.export_scene.gltf(filepath=str(path), export_format="GLB", export_skins=True)
    return path


def fresh_scene():
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)


def inventory():
    kinds = ("objects", "meshes", "armatures", "actions", "materials", "images", "collections")
    return {kind: sorted(b.name for b in getattr(bpy.data, kind)) for kind in kinds}



def imported_profile():
    from footfall.bridge import rig_import

    (armature,) = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    return rig_import.profile_of(armature)


def mixamo_name(role, side):
    table = {"hips": "Hips", "spine": "Spine", "chest": "Spine2", "neck": "Neck", "head": "Head", "upper_arm": "Arm",
             "forearm": "ForeArm", "hand": "Hand", "thigh": "UpLeg", "shin": "Leg", "foot": "Foot", "toe": "ToeBase"}
    return "mixamorig:" + ("" if side is None else side.title()) + table[role]


def odd_name(role, side):
    """Names detection cannot read: the toes are 'Digit'."""
    base = "Digit" if role == "toe" else role
    return base if side is None else f"{base}_{side[0].upper()}"


def test_mixamo_rig_is_detected():
    path = build_and_export("mixamo", mixamo_name)
    fresh_scene()
    check(bpy.ops.footfall.import_rig(filepath=str(path)) == {"FINISHED"}, "import failed")
    profile = imported_profile()
    check(profile.bones["left"]["shin"] == "mixamorig:LeftLeg", profile.bones)
    check(profile.bones["chest"] == "mixamorig:Spine2", profile.bones)
    check(abs(profile.dimensions["hip_height"] - 0.95) < 1e-3, profile.dimensions)
    check(abs(profile.dimensions["leg_length"] - 0.86) < 1e-3, profile.dimensions)
    check(all(clip is None for clip in profile.clips.values()), profile.clips)


def test_unmappable_rig_lists_bones_and_changes_nothing():
    path = build_and_export("odd", odd_name, without=("toe",))
    fresh_scene()
    bpy.ops.mesh.primitive_uv_sphere_add()  # something of the user's, which must survive
    before = inventory()
    try:
        bpy.ops.footfall.import_rig(filepath=str(path))
        raise AssertionError("no error")
    except RuntimeError as error:
        message = str(error)
    check("left.toe, right.toe" in message, message)
    check("Its bones: " in message and "foot_L" in message, f"the bones it holds are not listed: {message}")
    check("profile JSON beside the file" in message and "Footfall panel" in message, message)
    check(inventory() == before, f"scene changed: {inventory()} vs {before}")


def test_bones_of_no_naming_scheme_are_found_from_the_skeleton():
    """Bones named Bone.000 to Bone.018 in no order of role: the map comes from
    the hierarchy and the rest pose, bone by bone, and the message says so."""
    import random

    roles = [(r, None) for r, *_ in TRUNK] + [(r, s) for s in ("left", "right") for r, *_ in limb_bones(s, 0.1)]
    order = list(roles)
    random.Random(5).shuffle(order)
    names = {role: f"Bone.{i:03d}" for i, role in enumerate(order)}
    path = build_and_export("nameless", lambda role, side: names[(role, side)])
    fresh_scene()
    check(bpy.ops.footfall.import_rig(filepath=str(path)) == {"FINISHED"}, "import failed")
    profile = imported_profile()
    for (role, side), name in names.items():
        found = profile.bones[role] if side is None else profile.bones[side][role]
        check(found == name, f"{side or ''} {role}: {found}, not {name}")


def test_rigs_are_read_from_gltf_and_fbx_files_only():
    fresh_scene()
    blend = TMP / "scene.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(blend), copy=True)
    before = inventory()
    try:
        bpy.ops.footfall.import_rig(filepath=str(blend))
        raise AssertionError("no error")
    except RuntimeError as error:
        check("reads glTF (.glb, .gltf) and FBX (.fbx) files" in str(error) and "armature=" in str(error), str(error))
    check(inventory() == before, "the refused import changed the scene")


def test_an_fbx_rig_is_imported_and_kept_out_of_renders():
    build_and_export("mixamo_fbx", mixamo_name)
    path = TMP / "mixamo.fbx"
    bpy.ops.export_scene.fbx(filepath=str(path), add_leaf_bones=False)
    fresh_scene()
    check(bpy.ops.footfall.import_rig(filepath=str(path)) == {"FINISHED"}, "FBX import failed")
    profile = imported_profile()
    check(profile.bones["left"]["shin"] == "mixamorig:LeftLeg", profile.bones)
    check(abs(profile.dimensions["hip_height"] - 0.95) < 1e-3, profile.dimensions)
    (armature,) = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    check(all(o.hide_render for o in (armature, *armature.children)), "the template rig would be rendered")


def test_a_rigify_metarig_in_the_scene_is_used_as_it_is():
    """Blender's own human metarig (Rigify), made in the scene: its neck and
    head are spine.004 and spine.006."""
    fresh_scene()
    addon_utils.enable("rigify", default_set=True, handle_error=None)
    bpy.ops.object.armature_human_metarig_add()
    metarig = bpy.context.active_object
    check(bpy.ops.footfall.import_rig(armature=metarig.name) == {"FINISHED"}, "the metarig was refused")
    profile = imported_profile()
    check((profile.bones["neck"], profile.bones["head"]) == ("spine.004", "spine.006"), profile.bones)
    check((profile.bones["hips"], profile.bones["left"]["foot"]) == ("spine", "foot.L"), profile.bones)
    check(0.8 < profile.dimensions["hip_height"] < 1.2, profile.dimensions)


def test_panel_fields_complete_the_map():
    path = build_and_export("odd_fields", odd_name)
    fresh_scene()
    fields = bpy.context.scene.footfall_bone_map
    fields.left_toe, fields.right_toe = "Digit_L", "Digit_R"
    check(bpy.ops.footfall.import_rig(filepath=str(path)) == {"FINISHED"}, "import failed")
    check(imported_profile().bones["right"]["toe"] == "Digit_R", "toe not mapped")


def test_profile_beside_the_file_completes_the_map():
    path = build_and_export("odd_profile", odd_name)
    path.with_suffix(".json").write_text(json.dumps(
        {"format": "footfall-rig-profile", "version": 1, "bones": {"left": {"toe": "Digit_L"}, "right": {"toe": "Digit_R"}}}))
    fresh_scene()
    check(bpy.ops.footfall.import_rig(filepath=str(path)) == {"FINISHED"}, "import failed")
    check(imported_profile().bones["left"]["toe"] == "Digit_L", "toe not mapped")


def test_project_rig_matches_its_profile():
    rig = ROOT / "rigs" / "footfall_humanoid.glb"
    fresh_scene()
    check(bpy.ops.footfall.import_rig(filepath=str(rig)) == {"FINISHED"}, "import failed")
    profile = imported_profile()
    stored = json.loads(rig.with_suffix(".json").read_text())
    for key, value in stored["dimensions"].items():
        check(abs(profile.dimensions[key] - value) < 1e-3, f"{key}: measured {profile.dimensions[key]}, profile {value}")
    check(all(profile.clips[b] for b in ("walk", "arms_in", "side_step", "idle")), profile.clips)
    check(profile.bones == stored["bones"], profile.bones)


def test_the_planners_body_is_measured_from_the_rig():
    """Import Rig stores the body the planner tests: 32 poses of 14 capsules
    per behaviour, the walking hands swinging ahead and behind, the side
    step's toes across the way; a rig whose clips do not narrow from walk to
    arms in to side step is told so, and plans with the built-in body."""
    import shutil

    from footfall.bridge import rig_body, rig_import

    project = ROOT / "rigs" / "footfall_humanoid.glb"
    fresh_scene()
    imported = rig_import.import_rig(str(project))
    body = rig_body.body_of(imported.armature)
    check(body is not None and any("body measured" in note for note in imported.notes), imported.notes)
    check(not any("built-in body" in note for note in imported.notes), "a limb of the project's rig has no capsule")
    check(sorted(body["poses"]) == ["arms_in", "side_step", "walk"], sorted(body["poses"]))
    check(all(len(poses) == rig_body.PHASES and all(len(pose) == 14 and all(c[6] > 0 for c in pose.values())
                                                    for pose in poses) for poses in body["poses"].values()),
          "a pose without its 14 capsules")
    hands = [max(pose["forearm_left"][0], pose["forearm_left"][3]) for pose in body["poses"]["walk"]]
    check(max(hands) > 0.15 and min(hands) < 0.05, f"the left hand swings from {min(hands):.2f} to {max(hands):.2f} m")
    toes = [pose["foot_left"][4] - pose["foot_left"][1] for pose in body["poses"]["side_step"]]
    check(min(toes) > 0.1, "side-stepping, the feet do not point across the way")
    check(1.7 < body["height"] < 1.9, f"height {body['height']}")

    odd = TMP / "narrow.glb"
    shutil.copy(project, odd)
    profile = json.loads(project.with_suffix(".json").read_text())
    profile["clips"]["arms_in"] = "walk"  # arms "held in" as wide as walking
    odd.with_suffix(".json").write_text(json.dumps(profile))
    fresh_scene()
    imported = rig_import.import_rig(str(odd))
    check(rig_body.body_of(imported.armature) is None, "a body whose behaviours do not narrow was stored")
    check(any("do not narrow" in note for note in imported.notes), imported.notes)


class RecordingOperator:
    """Stands in for an operator instance in a direct call of its `execute`:
    the properties it reads, and the reports it makes."""

    def __init__(self, **properties):
        self.__dict__.update(properties)
        self.reports = []

    def report(self, levels, message):
        self.reports.append((levels, message))


def project_rig_in_scene(scale=1.0):
    """The project's rig as Blender's glTF importer makes it in a fresh
    scene (not imported with Footfall), its armature object scaled by `scale`."""
    import numpy

    fresh_scene()
    if "bool" not in numpy.__dict__:
        numpy.bool = bool  # Debian's Blender 3.4 importer
    bpy.ops.import_scene.gltf(filepath=str(ROOT / "rigs" / "footfall_humanoid.glb"))
    (armature,) = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    armature.scale = (scale, scale, scale)
    bpy.context.view_layer.update()
    return armature


def scene_state():
    """The data-blocks, every object's and the scene's custom properties
    (not those an add-on registers, stored once read), and the scene's rig."""
    properties = {o.name: {k: str(o[k]) for k in o.keys() if k not in o.bl_rna.properties}
                  for o in [*bpy.data.objects, bpy.context.scene]}
    return inventory(), properties, bpy.context.scene.footfall_rig


def plan_and_apply(agents):
    """Plans the agents (scenario file entries) with the scene's rig; checks
    that every one reaches its goal, and applies."""
    from footfall.bridge import plan_store

    scenario = TMP / "agents.json"
    scenario.write_text(json.dumps({"format": "footfall-scenario", "version": 1, "agents": agents}))
    check(bpy.ops.footfall.load_scenario(filepath=str(scenario)) == {"FINISHED"}, "load failed")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    plan = json.loads(plan_store.load())
    check(all(agent["status"] == "reached" for agent in plan["agents"]), [a["status"] for a in plan["agents"]])
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")


def skin_to(mesh, bone, other, keep):
    """Moves the weights of `bone`'s vertex group to `other`'s, except on
    the `keep` vertices skinned most to `bone` that are lowest (nearest the
    elbow, for an upper arm)."""
    group, target = mesh.vertex_groups[bone], mesh.vertex_groups[other]
    own = sorted((v for v in mesh.data.vertices if max(v.groups, key=lambda g: g.weight).group == group.index),
                 key=lambda v: v.co.z)
    kept = {v.index for v in own[:keep]}
    for vertex in mesh.data.vertices:
        weight = next((g.weight for g in vertex.groups if g.group == group.index), 0.0)
        if weight > 0 and vertex.index not in kept:
            target.add([vertex.index], weight, "ADD")
            group.remove([vertex.index])


def test_a_rig_whose_mesh_gives_its_upper_arms_nothing_plans_applies_and_exports():
    """The project's rig, its right upper arm skinned with the chest (no
    vertex of its own) and its left one keeping one vertex (a capsule of
    radius 0, which Plan refused: 'character.behaviors.walk.poses[0]
    .upper_arm_left: radius must be in (0, 1] m'): Import Rig says that both
    take the built-in body's radius, scaled to the rig, and the rig plans,
    applies and exports a valid glTF."""
    from footfall.bridge import rig_body
    from footfall.core import body_capsules
    from footfall.ui.operators import FOOTFALL_OT_import_rig

    armature = project_rig_in_scene()
    (mesh,) = [o for o in bpy.data.objects if o.type == "MESH" and o.parent == armature]  # 4.x adds a bone shape
    skin_to(mesh, "upper_arm.R", "chest", keep=0)
    skin_to(mesh, "upper_arm.L", "chest", keep=1)

    importer = RecordingOperator(filepath="", armature=armature.name)
    check(FOOTFALL_OT_import_rig.execute(importer, bpy.context) == {"FINISHED"}, importer.reports)
    notes = [message for levels, message in importer.reports if levels == {"INFO"} and "built-in body" in message]
    check(len(notes) == 1 and notes[0].endswith(": upper_arm_left (its vertices give a radius of 0 m); "
                                                "upper_arm_right (no vertices of its own)"), importer.reports)
    body = rig_body.body_of(armature)
    check(body is not None, f"no body stored: {importer.reports}")
    leg_length = imported_profile().dimensions["leg_length"]
    for limb in ("upper_arm_left", "upper_arm_right"):
        radius = body["poses"]["walk"][0][limb][6]
        check(radius == round(body_capsules.builtin_radius(limb, leg_length), 4), f"{limb}: radius {radius}")

    plan_and_apply([{"name": "ann", "position": [0, 0], "goals": [[5, 0]]},
                    {"name": "bob", "position": [5, 0.3], "goals": [[0, 0.3]]}])
    out = TMP / "armless.glb"
    check(bpy.ops.footfall.export_gltf(filepath=str(out)) == {"FINISHED"}, "export failed")
    expect_valid_gltf(out)


def test_a_rig_too_tall_or_too_small_to_plan_is_refused_and_changes_nothing():
    """The project's rig scaled 2 (3.6 m tall: Plan failed on 'character.body_height
    must be in [0.5, 3]') and 0.2 (0.36 m, its centre of mass under the core's
    0.2 m): Import Rig, from the scene or from a file, refuses it naming the rig,
    the measurement and the limit, and the scene stays as it was."""
    for scale, name, expected in (
            (2.0, "giant", "is 3.60 m tall; Footfall plans bodies from 0.5 to 3 m tall: scale the rig"),
            (0.2, "dwarf", "is 0.36 m tall; its hip height of 0.19 m gives a centre of mass Footfall cannot plan "
                           "(character.com_height: must be in [0.2, 3], got 0.19")):
        armature = project_rig_in_scene(scale)
        armature.name = name
        path = TMP / f"{name}.glb"
        bpy.ops.export_scene.gltf(filepath=str(path), export_format="GLB")
        for source, options in ((name, {"armature": name}), (path.name, {"filepath": str(path)})):
            if "filepath" in options:
                fresh_scene()
                bpy.ops.mesh.primitive_uv_sphere_add()  # something of the user's, which must survive
            before = scene_state()
            try:
                bpy.ops.footfall.import_rig(**options)
                raise AssertionError(f"{source}: imported")
            except RuntimeError as error:
                message = str(error)
            check(f"rig '{source}' {expected}" in message, message)
            check(scene_state() == before, f"{source}: the refused import changed the scene: {scene_state()}")


def test_a_rig_near_the_limits_imports_plans_and_applies():
    """The project's rig scaled 1.6 (2.9 m tall) and 0.3 (0.54 m): Import Rig
    takes it, and it plans and applies."""
    for scale in (1.6, 0.3):
        armature = project_rig_in_scene(scale)
        check(bpy.ops.footfall.import_rig(armature=armature.name) == {"FINISHED"}, f"x{scale}: import failed")
        plan_and_apply([{"name": "ann", "position": [0, 0], "goals": [[6, 0]]}])



def test_an_agent_scaled_past_what_footfall_plans_is_named_and_changes_nothing():
    """Issue 49: the project's rig scaled 1.6 (2.9 m tall) imports, but an
    agent of footfall_scale 1.1 on it stands 3.2 m tall, which the core
    refused as 'agents[0].character.body_height'. Plan now refuses it naming
    the agent, its rig, both heights, the scale and the limits, and changes
    nothing; at the scale the message offers it plans. Randomize Agents
    refuses a size range that reaches past 3 m on the rig, and draws one
    within it."""
    import math

    from footfall.bridge import plan_store, rig_body

    armature = project_rig_in_scene(1.6)
    armature.name = "giant"
    check(bpy.ops.footfall.import_rig(armature="giant") == {"FINISHED"}, "the giant was not imported")
    height = rig_body.body_of(armature)["height"]
    check(2.75 < height < 3.0, f"the giant is {height} m tall")
    scenario = TMP / "walker.json"
    scenario.write_text(json.dumps({"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 3], "goals": [[6, 3]]},
        {"name": "walker", "position": [0, 0], "goals": [[6, 0]], "scale": 1.1}]}))
    check(bpy.ops.footfall.load_scenario(filepath=str(scenario)) == {"FINISHED"}, "load failed")
    walker = bpy.data.objects["walker"]
    walker.name = "Walker.003"  # the message names the object, as the user sees it, not the agent's name
    walker["footfall_agent_name"] = "walker"
    within = math.floor(100 * 3.0 / height) / 100

    before = scene_state()
    try:
        bpy.ops.footfall.plan()
        raise AssertionError("a 3.2 m agent was planned")
    except RuntimeError as error:
        message = str(error)
    check(f"agent 'Walker.003': its rig 'giant' ({height:.2f} m) at scale 1.10 is {1.1 * height:.2f} m tall; "
          f"Footfall plans bodies from 0.5 to 3 m: lower its scale to {within:.2f} or less" in message, message)
    check("body_height" not in message, message)
    check(scene_state() == before and plan_store.TEXT_NAME not in bpy.data.texts,
          f"the refused Plan changed the scene: {scene_state()}")

    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj == walker)
    try:
        bpy.ops.footfall.randomize_agents(scale_min=1.0, scale_max=1.2)
        raise AssertionError("sizes up to 1.2 drawn for a 2.9 m rig")
    except RuntimeError as error:
        message = str(error)
    check(f"Size range 1-1.2: at 1.2, rig 'giant' is {1.2 * height:.2f} m tall; Footfall plans bodies from 0.5 "
          "to 3 m tall: narrow the size range" in message, message)
    check(scene_state() == before, f"the refused Randomize changed the scene: {scene_state()}")
    check(bpy.ops.footfall.randomize_agents(scale_min=1.0, scale_max=within) == {"FINISHED"}, "randomize failed")
    check(1.0 <= walker["footfall_scale"] <= within, walker["footfall_scale"])

    walker["footfall_scale"] = within
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "the agent at a scale within the range did not plan")
    plan = json.loads(plan_store.load())
    check(all(agent["status"] == "reached" for agent in plan["agents"]), [a["status"] for a in plan["agents"]])
    (planned,) = [agent for agent in plan["agents"] if agent["name"] == "walker"]
    check(planned["scale"] == within, planned.get("scale"))

run([test_mixamo_rig_is_detected, test_bones_of_no_naming_scheme_are_found_from_the_skeleton,
     test_rigs_are_read_from_gltf_and_fbx_files_only, test_an_fbx_rig_is_imported_and_kept_out_of_renders,
     test_a_rigify_metarig_in_the_scene_is_used_as_it_is, test_unmappable_rig_lists_bones_and_changes_nothing,
     test_panel_fields_complete_the_map, test_profile_beside_the_file_completes_the_map,
     test_project_rig_matches_its_profile, test_the_planners_body_is_measured_from_the_rig,
     test_a_rig_whose_mesh_gives_its_upper_arms_nothing_plans_applies_and_exports,
     test_a_rig_too_tall_or_too_small_to_plan_is_refused_and_changes_nothing,
     test_a_rig_near_the_limits_imports_plans_and_applies,
     test_an_agent_scaled_past_what_footfall_plans_is_named_and_changes_nothing])
