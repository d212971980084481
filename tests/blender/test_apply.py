"""Blender background test: footfall.apply animates rig instances that walk
exactly on the plan.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_apply.py
"""

import json
import math
import os
import pathlib
import sys
import tempfile

import addon_utils
import bpy

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-apply-"))
RIG = ROOT / "rigs" / "footfall_humanoid.glb"


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def fresh_scene_with_rig():
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "rig import failed")


def doorway_plan(ff):
    """Three agents through a 1.2 m doorway, planned with the rig's parameters, as a plan file."""
    from footfall.bridge import rig_import
    from footfall.core import character, scenario as sc

    (rig,) = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    c, p = character.derive_parameters(rig_import.profile_of(rig).dimensions)
    walls = [sc.ObstacleInput(o.polygon, o.height) for o in ff.wall_with_door(4.0, 1.2)]
    agents = [sc.AgentInput("ann", (0, 0.2), [(8, 0.1)]), sc.AgentInput("bob", (-1.5, -0.4), [(8, -0.2)]),
              sc.AgentInput("cy", (-3, 0.5), [(7, 0.3)])]
    plan = sc.plan(sc.scenario_document(sc.ScenarioInput(agents, walls, c, p)))
    check(all(a.status == ff.AgentStatus.REACHED for a in plan.agents), "not every agent reached")
    path = TMP / "doorway-plan.json"
    ff.write_plan_file(plan, str(path))
    return plan, path


def evaluated(name):
    return bpy.data.objects[name].evaluated_get(bpy.context.evaluated_depsgraph_get())


def test_feet_and_pelvis_follow_the_plan():
    from footfall.core import native
    from footfall.bridge import rig_import

    ff = native.load()
    fresh_scene_with_rig()
    plan, path = doorway_plan(ff)
    check(bpy.ops.footfall.apply(plan_filepath=str(path)) == {"FINISHED"}, "apply failed")
    (rig,) = [o for o in bpy.data.objects if o.type == "ARMATURE" and rig_import.PROFILE_PROPERTY in o]
    profile = rig_import.profile_of(rig)
    ankle_z = {side: rig.data.bones[profile.bones[side]["foot"]].head_local.z for side in ("left", "right")}
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    worst_foot, worst_pelvis, stance_frames = 0.0, 0.0, 0
    for frame in range(scene.frame_start, scene.frame_end + 1):
        scene.frame_set(frame)
        t = (frame - scene.frame_start) / fps
        for agent in plan.agents:
            armature = evaluated(agent.name)
            world = armature.matrix_world
            feet = ff.feet_at(agent, t)
            for side, pose in zip(("left", "right"), feet):
                if not pose.planted:
                    continue
                stance_frames += 1
                head = world @ armature.pose.bones[profile.bones[side]["foot"]].head
                planned = (pose.position[0], pose.position[1], ankle_z[side])
                worst_foot = max(worst_foot, math.dist(tuple(head), planned))
            hips = world @ armature.pose.bones[profile.bones["hips"]].head
            worst_pelvis = max(worst_pelvis, math.dist(hips.xy, ff.com_at(agent, t).position))
    print(f"stance samples {stance_frames}, worst foot error {worst_foot * 1000:.2f} mm, "
          f"worst pelvis error {worst_pelvis * 100:.2f} cm")
    check(stance_frames > 300, f"only {stance_frames} stance samples")
    check(worst_foot <= 0.002, f"a planted foot is {worst_foot * 1000:.2f} mm off the plan")
    check(worst_pelvis <= 0.02, f"the pelvis is {worst_pelvis * 100:.2f} cm off the COM")


def main():
    tests = [test_feet_and_pelvis_follow_the_plan]
    failed = 0
    for test in tests:
        try:
            test()
            print(f"PASS {test.__name__}")
        except Exception as error:  # report every test, then fail the run
            failed += 1
            import traceback
            traceback.print_exc()
            print(f"FAIL {test.__name__}: {error!r}")
    print(f"{len(tests) - failed} passed, {failed} failed")
    if failed:
        sys.exit(1)


main()
