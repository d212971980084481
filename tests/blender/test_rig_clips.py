"""Blender background test: a rig's own walk clip, unnamed and with root
motion, is found by its feet, played without its root motion, and phased
to the plan's steps by its own heel strike.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_rig_clips.py
"""

import math
import os
import pathlib
import sys

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, run  # noqa: E402
from mathutils import Matrix, Vector  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
RIG = ROOT / "rigs" / "footfall_humanoid.glb"
TAKE = "Take 001"
STRIKE = 0.6  # where in its cycle the clip's right heel strikes
CYCLE = 32  # frames
SIDE_AXIS = Vector((1.0, 0.0, 0.0))  # the rig faces -Y: turning about +X swings a hanging limb back


def _key_turn(action, bone, frame, angle):
    """Keys `bone` turned by `angle` about the rig's side axis, its parents at rest."""
    from footfall.bridge import action_curves

    rest = bone.matrix_local.to_3x3()
    quaternion = (rest.inverted() @ Matrix.Rotation(angle, 3, SIDE_AXIS) @ rest).to_quaternion()
    for i in range(4):
        curve = action_curves.curve(action, f'pose.bones["{bone.name}"].rotation_quaternion', i, bone.name)
        curve.keyframe_points.insert(frame, quaternion[i], options={"FAST"})


def _key_location(action, bone, frame, offset):
    """Keys `bone` moved by `offset` (armature space)."""
    from footfall.bridge import action_curves

    local = bone.matrix_local.to_3x3().inverted() @ offset
    for i in range(3):
        curve = action_curves.curve(action, f'pose.bones["{bone.name}"].location', i, bone.name)
        curve.keyframe_points.insert(frame, local[i], options={"FAST"})


def rig_with_a_take():
    """The project's rig as a file's armature would come: a root bone above
    the hips, no clip named walk, and an unnamed walk ('Take 001') that
    carries the rig forward 1.2 m a cycle on its root, right heel strike at
    STRIKE, arms swinging against the legs. Returns the armature."""
    from footfall.bridge import rig_import

    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "rig import failed")
    (rig,) = rig_import.imported_rigs()
    del rig[rig_import.PROFILE_PROPERTY]
    profile = rig_import.rig_profile.load(str(RIG.with_suffix(".json")))
    for action in [a for a in bpy.data.actions if a.name.startswith("walk")]:
        bpy.data.actions.remove(action)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode="EDIT")
    root = rig.data.edit_bones.new("root")
    root.head, root.tail = (0.0, 0.0, 0.0), (0.0, 0.2, 0.0)
    rig.data.edit_bones[profile.bones["hips"]].parent = root
    bpy.ops.object.mode_set(mode="OBJECT")

    action = bpy.data.actions.new(TAKE)
    bones = rig.data.bones
    for k in range(CYCLE + 1):
        frame, wave = 1 + k, math.cos(2 * math.pi * (k / CYCLE - STRIKE))
        _key_location(action, bones["root"], frame, Vector((0.0, -1.2 * k / CYCLE, 0.02 * wave)))
        for side, sign in (("right", 1.0), ("left", -1.0)):
            _key_turn(action, bones[profile.bones[side]["thigh"]], frame, -sign * 0.4 * wave)
            _key_turn(action, bones[profile.bones[side]["upper_arm"]], frame, sign * 0.3 * wave)
    rig.animation_data_create()
    return rig


def test_an_unnamed_walk_is_found_by_its_feet():
    from footfall.bridge import rig_import

    rig = rig_with_a_take()
    imported = rig_import.import_rig(armature=rig.name)
    check(imported.profile.clips["walk"] == TAKE, f"walk clip: {imported.profile.clips}")
    (note,) = [n for n in imported.notes if n.startswith("walk:")]
    print(note)
    check("right heel strike at 60 %" in note and "from its feet" in note and "root motion is left out" in note, note)
    check(imported.profile.clips["arms_in"] is not None, f"the named clips: {imported.profile.clips}")


def test_the_walk_plays_without_root_motion_phased_by_its_own_strike():
    from footfall.bridge import action_curves, rig_clips, rig_import
    from footfall.core import character, native, scenario as sc

    ff = native.load()
    rig = rig_with_a_take()
    check(bpy.ops.footfall.import_rig(armature=rig.name) == {"FINISHED"}, "the rig was refused")
    profile = rig_import.profile_of(rig)
    c, p = character.derive_parameters(profile.dimensions)
    plan = sc.plan(sc.scenario_document(sc.ScenarioInput([sc.AgentInput("walker", (0, 0), [(7, 0.5)])], [], c, p)))
    path = pathlib.Path(bpy.app.tempdir or "/tmp") / "footfall-rig-clips-plan.json"
    ff.write_plan_file(plan, str(path))
    check(bpy.ops.footfall.apply(plan_filepath=str(path), rig=rig.name) == {"FINISHED"}, "apply failed")

    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    agent = plan.agents[0]
    hips_rest = rig.data.bones[profile.bones["hips"]].matrix_local
    worst_hips, strikes = 0.0, 0
    walks = [s for s in agent.footsteps if s.kind == ff.StepKind.WALK][2:-2]
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        t = (frame - scene.frame_start) / fps
        armature = bpy.data.objects[agent.name].evaluated_get(bpy.context.evaluated_depsgraph_get())
        hips = armature.pose.bones[profile.bones["hips"]]
        worst_hips = max(worst_hips, math.dist((armature.matrix_world @ hips.head).xy, ff.com_at(agent, t).position))
    for step in walks:
        frame = scene.frame_start + step.start_time * fps
        scene.frame_set(int(frame), subframe=frame % 1)
        armature = bpy.data.objects[agent.name].evaluated_get(bpy.context.evaluated_depsgraph_get())
        hips = armature.pose.bones[profile.bones["hips"]]
        body = (armature.matrix_world @ hips.matrix @ hips_rest.inverted()).inverted()
        ahead = {side: -(body @ (armature.matrix_world @ armature.pose.bones[profile.bones[side]["hand"]].tail)).y
                 for side in ("left", "right")}
        leading, other = ("left", "right") if step.foot == ff.Foot.RIGHT else ("right", "left")
        check(ahead[leading] > ahead[other] + 0.05,
              f"at the {step.foot.name.lower()} heel strike at {step.start_time:.2f} s the {leading} hand is not ahead: {ahead}")
        strikes += 1
    print(f"hips at most {worst_hips * 100:.2f} cm off the COM; {strikes} heel strikes checked")
    check(strikes >= 6, f"only {strikes} heel strikes checked")
    check(worst_hips <= 0.02, f"the hips are {worst_hips * 100:.2f} cm off the planned COM: root motion played")
    offered = sorted(a.name for a in rig_clips.actions_of(rig))
    check(TAKE in offered and not any("locomotion" in n or n.startswith("footfall") for n in offered),
          f"the rig's actions after Apply: {offered}")
    take = bpy.data.actions[TAKE]
    check(any(c.data_path == 'pose.bones["root"].location' for c in action_curves.curves(take)) and
          not any(c.modifiers for c in action_curves.curves(take)), "the rig's own action was changed")


def test_a_scaled_rigs_clip_moves_bones_in_metres():
    from footfall.bridge import action_curves, rig_clips, rig_import

    rig = rig_with_a_take()
    chest = rig.data.bones[rig_import.rig_profile.load(str(RIG.with_suffix(".json"))).bones["chest"]]
    _key_location(bpy.data.actions[TAKE], chest, 1, Vector((0.0, 0.0, 5.0)))
    check(bpy.ops.footfall.import_rig(armature=rig.name) == {"FINISHED"}, "the rig was refused")
    rig.scale = (0.01, 0.01, 0.01)
    bpy.context.view_layer.update()
    clip = rig_clips.playable(rig, rig_import.profile_of(rig), "walk")
    moved = [c for c in action_curves.curves(clip.action) if c.data_path == f'pose.bones["{chest.name}"].location']
    check(len(moved) == 3, f"chest location curves: {len(moved)}")
    offset = chest.matrix_local.to_3x3() @ Vector([c.evaluate(1) for c in moved])
    check(abs(offset.z - 0.05) < 1e-5, f"a 5-unit move of a rig scaled 0.01 plays as {offset.z:.4f} m")
    check(not any("root" in c.data_path for c in action_curves.curves(clip.action)), "root motion kept")


run([test_an_unnamed_walk_is_found_by_its_feet, test_the_walk_plays_without_root_motion_phased_by_its_own_strike,
     test_a_scaled_rigs_clip_moves_bones_in_metres])
