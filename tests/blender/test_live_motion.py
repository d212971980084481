"""Blender background test: footfall.apply(live=True) poses the crowd from its
plan at each frame, as the keyed crowd moves, with a fraction of the keys,
and goes on doing so in the file saved and opened again.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_live_motion.py
"""

import contextlib
import io
import os
import pathlib
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from foot_contact import plan_errors  # noqa: E402
from harness import check, run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-live-"))
RIG = ROOT / "rigs" / "footfall_humanoid.glb"
FEET = ("foot.L", "foot.R", "toe.L", "toe.R")  # the project rig's


def fresh_scene_with_rig():
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "rig import failed")


def demo_planned():
    """The README's demo in a fresh scene with the project's rig, planned: (ff, plan)."""
    from footfall.bridge import plan_store, scene_build
    from footfall.core import native
    from footfall.core.scenario import document_of

    ff = native.load()
    fresh_scene_with_rig()
    scene_build.build(bpy.context.scene, document_of(ff.demo_scenario()), "demo")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    return ff, plan_store.load_plan()


def demo_applied_live():
    """The demo planned and applied live."""
    demo_planned()
    check(bpy.ops.footfall.apply(live=True) == {"FINISHED"}, "live apply failed")


def crowd_bones(frames):
    """Every crowd bone's head in the world at each of `frames`: {(frame, agent, bone): position}."""
    from footfall.bridge import animate

    scene = bpy.context.scene
    heads = {}
    for frame in frames:
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        for armature in animate.crowd_armatures():
            posed = armature.evaluated_get(depsgraph)
            for bone in posed.pose.bones:
                heads[(frame, armature.name, bone.name)] = (posed.matrix_world @ bone.head).copy()
    return heads


def farthest(after, before, keys=None) -> float:
    """How far apart the positions of `after` and `before` come, over `keys` (all of `before`'s)."""
    return max((after[key] - before[key]).length for key in (before if keys is None else keys))


def saved_and_opened(name: str) -> None:
    """Saves the file as `name` in TMP and opens it again, as an animator would."""
    path = TMP / name
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.wm.open_mainfile(filepath=str(path))


def key_count() -> int:
    """Keys in every action and NLA strip of the file."""
    from footfall.bridge import action_curves

    keys = sum(len(curve.keyframe_points) for action in bpy.data.actions for curve in action_curves.curves(action))
    return keys + sum(len(curve.keyframe_points) for obj in bpy.data.objects if obj.animation_data
                      for track in obj.animation_data.nla_tracks for strip in track.strips
                      for curve in strip.fcurves)


def imported_rig():
    from footfall.bridge import rig_import

    (rig,) = rig_import.imported_rigs()
    return rig, rig_import.profile_of(rig)


def frames_across():
    scene = bpy.context.scene
    return list(range(scene.frame_start, scene.frame_end + 1, 7))


def test_a_live_crowd_moves_as_the_keyed_one():
    from footfall.bridge import animate, live_motion

    ff, plan = demo_planned()
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "keyed apply failed")
    keyed, keyed_keys = crowd_bones(frames_across()), key_count()
    check(bpy.ops.footfall.apply(live=True) == {"FINISHED"}, "live apply failed")
    live, live_keys = crowd_bones(frames_across()), key_count()
    check(live.keys() == keyed.keys(), "the live crowd has other agents or bones")
    off = {key: (live[key] - keyed[key]).length for key in keyed}
    feet = max(d for key, d in off.items() if key[2] in FEET)
    every = max(off.values())
    print(f"live against keyed: feet {feet * 1000:.2f} mm, every bone {every * 1000:.2f} mm; "
          f"keys {keyed_keys} keyed, {live_keys} live")
    # The keys pass within 1.5 mm of the motion sampled at every frame (the knees follow within about 9 mm).
    check(feet <= 0.003, f"a live foot is {feet * 1000:.2f} mm from the keyed one")
    check(every <= 0.015, f"a live bone is {every * 1000:.2f} mm from the keyed one")
    check(live_keys < keyed_keys / 3, f"{live_keys} keys live against {keyed_keys} keyed")
    armatures = live_motion.live_armatures()
    check(len(armatures) == len(plan.agents), f"{len(armatures)} live armatures for {len(plan.agents)} agents")
    check(all(action.name.endswith("look ahead") for a in armatures for action in animate.own_actions(a)),
          "a live armature has a locomotion action")
    worst_foot, worst_pelvis, _ = plan_errors(ff, plan, *imported_rig())
    check(worst_foot <= 0.002, f"a live planted foot is {worst_foot * 1000:.2f} mm off the plan")
    check(worst_pelvis <= 0.02, f"the live pelvis is {worst_pelvis * 100:.2f} cm off the COM")


def test_a_live_crowd_plays_the_same_in_the_file_opened_again():
    from footfall.bridge import live_motion

    demo_applied_live()
    before = crowd_bones(frames_across())
    saved_and_opened("live.blend")
    check(live_motion.PLAN_TEXT in bpy.data.texts, "the crowd's plan was not saved")
    after = crowd_bones(frames_across())
    worst = farthest(after, before)
    check(worst <= 1e-5, f"opened again, a bone is {worst * 1000:.3f} mm from where it was")


def test_a_live_crowd_without_its_plan_stands_and_says_why():
    from footfall.bridge import live_motion

    demo_applied_live()
    bpy.data.texts.remove(bpy.data.texts[live_motion.PLAN_TEXT])
    saved_and_opened("no-plan.blend")
    frames = frames_across()
    said = io.StringIO()
    with contextlib.redirect_stdout(said):
        first = crowd_bones(frames[:1])
        still = crowd_bones(frames[-1:])  # no error at a frame change
    lines = said.getvalue().splitlines()
    check(len(lines) == len(live_motion.live_armatures()) and all(
        "stands still: the Text 'footfall_crowd_plan' with the plan the crowd plays is gone" in line for line in lines),
        f"said {lines}")
    # The locomotion stands (the clips' strips still play the arms).
    driven = [key for key in first if key[2] == imported_rig()[1].bones["hips"] or key[2].startswith("footfall_")]
    moved = max((still[(frames[-1], *key[1:])] - first[key]).length for key in driven)
    check(moved <= 1e-6, f"an armature without its plan walked {moved:.3f} m")


def test_a_live_apply_after_planning_one_agent_again_keeps_the_others_live():
    from footfall.bridge import animate, live_motion, plan_store, scene_build
    from mathutils import Matrix

    fresh_scene_with_rig()
    scene = bpy.context.scene
    scene_build.build(scene, {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "goals": [[8, 0]]},
        {"name": "bob", "position": [0, 3], "goals": [[8, 3]]}]}, "two")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check(bpy.ops.footfall.apply(live=True) == {"FINISHED"}, "live apply failed")
    crowd = bpy.data.collections[animate.CROWD_COLLECTION]
    bob = crowd.objects["bob"].as_pointer()
    bob_before = crowd_bones(frames_across())
    bpy.data.objects["ann goal 1"].matrix_world = Matrix.Translation((8, 1, 0))
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj.name == "ann goal 1")
    check(bpy.ops.footfall.plan(selected_only=True) == {"FINISHED"}, "plan of the selected failed")
    check(bpy.ops.footfall.apply(live=True) == {"FINISHED"}, "live apply failed")
    check(crowd.objects["bob"].as_pointer() == bob, "bob's rig was made again")
    check(len(live_motion.live_armatures()) == 2, "not both armatures are live")
    saved_and_opened("replanned.blend")
    after = crowd_bones(frames_across())
    bob_moved = farthest(after, bob_before, [key for key in bob_before if key[1] == "bob"])
    check(bob_moved <= 1e-5, f"bob moves {bob_moved * 1000:.3f} mm otherwise after ann was planned again")
    ann_end = [a for a in plan_store.load_plan().agents if a.name == "ann"][0].footsteps[-1].com_end
    scene = bpy.context.scene
    scene.frame_set(scene.frame_end)
    ann = bpy.data.objects["ann"].evaluated_get(bpy.context.evaluated_depsgraph_get())
    hips = ann.matrix_world @ ann.pose.bones[imported_rig()[1].bones["hips"]].head
    check(abs(hips.y - ann_end[1]) < 0.15 and abs(ann_end[1] - 1) < 0.25, f"ann ends at {tuple(hips.xy)}")


def test_a_render_poses_the_live_crowd_at_the_frame_it_renders():
    demo_applied_live()
    scene = bpy.context.scene
    hips = imported_rig()[1].bones["hips"]
    frame = (scene.frame_start + scene.frame_end) // 2
    scene.frame_set(frame)
    expected = {a.name: a.pose.bones[hips].location.copy() for a in live_armatures()}
    scene.frame_set(scene.frame_start)
    rendered = {}

    def record(*_):
        rendered.update({a.name: a.pose.bones[hips].location.copy() for a in live_armatures()})

    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x, scene.render.resolution_y = 64, 36
    scene.render.filepath = str(TMP / "frame-")
    scene.camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(scene.camera)
    scene.frame_start = scene.frame_end = frame
    bpy.app.handlers.render_post.append(record)
    try:
        bpy.ops.render.render(animation=True)
    finally:
        bpy.app.handlers.render_post.remove(record)
    check(rendered.keys() == expected.keys(), f"rendered {sorted(rendered)}, expected {sorted(expected)}")
    worst = farthest(rendered, expected)
    check(worst <= 1e-6, f"a rendered agent's hips are {worst:.3f} from where frame {frame} puts them")


def live_armatures():
    from footfall.bridge import live_motion

    return live_motion.live_armatures()


def test_a_live_apply_stopped_part_way_leaves_the_crowd_as_it_was():
    from footfall.bridge import apply_plan

    demo_applied_live()

    def inventory():
        return {kind: sorted(block.name for block in getattr(bpy.data, kind))
                for kind in ("objects", "armatures", "actions", "texts")}

    before, poses = inventory(), crowd_bones(frames_across())
    job = apply_plan.ApplyJob(bpy.context, live=True)
    check(job.advance() and job.advance(), "the demo has more than two agents")
    job.cancel()
    check(inventory() == before, f"a stopped live Apply changed the scene: {inventory()} against {before}")
    after = crowd_bones(frames_across())
    worst = farthest(after, poses)
    check(worst <= 1e-6, f"after a stopped live Apply a bone is {worst * 1000:.3f} mm from where it was")


def test_a_keyed_apply_replaces_the_live_crowd_and_its_plan():
    from footfall.bridge import live_motion

    demo_applied_live()
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "keyed apply failed")
    check(not live_motion.live_armatures(), "an armature is still posed live")
    check(live_motion.PLAN_TEXT not in bpy.data.texts, "the live crowd's plan was left behind")


run([test_a_live_crowd_moves_as_the_keyed_one, test_a_live_crowd_plays_the_same_in_the_file_opened_again,
     test_a_live_crowd_without_its_plan_stands_and_says_why,
     test_a_live_apply_after_planning_one_agent_again_keeps_the_others_live,
     test_a_render_poses_the_live_crowd_at_the_frame_it_renders,
     test_a_live_apply_stopped_part_way_leaves_the_crowd_as_it_was,
     test_a_keyed_apply_replaces_the_live_crowd_and_its_plan])
