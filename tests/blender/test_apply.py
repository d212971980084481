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


def glb_json(path):
    """The JSON chunk of a .glb file."""
    import struct

    data = pathlib.Path(path).read_bytes()
    length, kind = struct.unpack_from("<I4s", data, 12)
    check(kind == b"JSON", "not a GLB file")
    return json.loads(data[20:20 + length])


def feet_now(names, profile):
    """World positions of every agent's foot bones at the current frame."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    result = {}
    for name in names:
        armature = bpy.data.objects[name].evaluated_get(depsgraph)
        for side in ("left", "right"):
            bone = profile.bones[side]["foot"]
            result[(name, side)] = armature.matrix_world @ armature.pose.bones[bone].head
    return result


def test_export_validates_and_reimports():
    import subprocess

    from footfall.bridge import rig_import
    from footfall.core import native

    ff = native.load()
    fresh_scene_with_rig()
    plan, path = doorway_plan(ff)
    check(bpy.ops.footfall.apply(plan_filepath=str(path)) == {"FINISHED"}, "apply failed")
    (rig,) = [o for o in bpy.data.objects if o.type == "ARMATURE" and rig_import.PROFILE_PROPERTY in o]
    profile = rig_import.profile_of(rig)
    names = [agent.name for agent in plan.agents]
    scene = bpy.context.scene
    probe_frames = [scene.frame_start + 12, (scene.frame_start + scene.frame_end) // 2, scene.frame_end - 5]
    expected = {}
    for frame in probe_frames:
        scene.frame_set(frame)
        expected[frame] = feet_now(names, profile)
    objects_before = sorted(o.name for o in bpy.data.objects)

    out = TMP / "crowd.glb"
    check(bpy.ops.footfall.export_gltf(filepath=str(out)) == {"FINISHED"}, "export failed")
    check(sorted(o.name for o in bpy.data.objects) == objects_before, "the export changed the scene")
    check(not pathlib.Path(str(out) + ".partial.glb").exists(), "a partial file was left")
    validator = ROOT / "tests" / "gltf" / "validate.mjs"
    run = subprocess.run(["node", str(validator), str(out)], capture_output=True, text=True)
    report = json.loads(run.stdout)["issues"]
    print(f"validator: {report['numErrors']} errors, {report['numWarnings']} warnings")
    check(run.returncode == 0 and report["numErrors"] == 0, f"the validator found errors: {run.stdout[:2000]}")
    gltf = glb_json(out)
    check(sorted(a["name"] for a in gltf["animations"]) == sorted(names), [a["name"] for a in gltf["animations"]])

    bpy.ops.wm.read_homefile(use_empty=True)
    import numpy

    if "bool" not in numpy.__dict__:
        numpy.bool = bool  # Debian's Blender 3.4 importer
    bpy.ops.import_scene.gltf(filepath=str(out))
    for name in names:
        data = bpy.data.objects[name].animation_data
        if data.action is None:  # the importer may leave the animation on an NLA track
            data.action = data.nla_tracks[0].strips[0].action
        for track in data.nla_tracks:
            track.mute = True
    worst = 0.0
    for frame, feet in expected.items():
        bpy.context.scene.frame_set(frame)
        for key, position in feet_now(names, profile).items():
            worst = max(worst, (position - feet[key]).length)
    print(f"re-imported feet: worst {worst * 1000:.2f} mm off")
    check(worst <= 0.005, f"re-imported feet are {worst * 1000:.2f} mm off")


def main():
    tests = [test_feet_and_pelvis_follow_the_plan, test_export_validates_and_reimports]
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
