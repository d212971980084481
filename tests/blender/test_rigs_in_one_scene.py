"""Blender background test: two rigs of different sizes in one scene. The
scene's rig (the panel's choice) animates and sizes most agents; an agent
whose 'footfall_rig' names the other walks with a character sized from that
one, and is animated with it, its feet on the plan.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_rigs_in_one_scene.py
"""

import json
import math
import os
import pathlib
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402
import numpy  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from foot_contact import FootRest  # noqa: E402
from harness import check, run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-rigs-"))
RIG = ROOT / "rigs" / "footfall_humanoid.glb"
SMALL = 0.8  # the second rig's scale


def operator_error(operator, **options):
    try:
        operator(**options)
    except RuntimeError as error:
        return str(error)
    raise AssertionError(f"{operator.idname()} did not fail")


def scene_with_two_rigs():
    """The project's rig ('tall', the scene's rig), and a copy of it scaled
    0.8 ('small'), both imported with Footfall; three agents in a corridor,
    'kid' animated with the small rig, 'bob' with overrides of its own."""
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "first rig refused")
    tall = bpy.context.scene.footfall_rig
    tall.name = "tall"
    if "bool" not in numpy.__dict__:
        numpy.bool = bool  # Debian's Blender 3.4 importer
    bpy.ops.import_scene.gltf(filepath=str(RIG))
    (small,) = [o for o in bpy.data.objects if o.type == "ARMATURE" and o is not tall]
    small.name = "small"
    small.scale = (SMALL, SMALL, SMALL)
    bpy.context.view_layer.update()
    check(bpy.ops.footfall.import_rig(armature="small") == {"FINISHED"}, "second rig refused")
    check(bpy.context.scene.footfall_rig == small, "the rig imported last is not the scene's")
    bpy.context.scene.footfall_rig = tall
    walls = [{"polygon": [[-1, y0], [9, y0], [9, y0 + 0.3], [-1, y0 + 0.3]], "height": 2.0} for y0 in (1.5, -1.8)]
    scenario = {"format": "footfall-scenario", "version": 1, "obstacles": walls, "agents": [
        {"name": "ann", "position": [0, 0.6], "goals": [[8, 0.6]]},
        {"name": "kid", "position": [8, -0.2], "goals": [[0, -0.2]]},
        {"name": "bob", "position": [0, -1.0], "goals": [[8, -1.0]], "character": {"max_step_length": 0.7}}]}
    path = TMP / "corridor.json"
    path.write_text(json.dumps(scenario))
    check(bpy.ops.footfall.load_scenario(filepath=str(path)) == {"FINISHED"}, "the scenario did not load")
    bpy.data.objects["kid"]["footfall_rig"] = "small"
    return tall, small


def stored_plan():
    from footfall.bridge import plan_store

    return plan_store.load_plan()


def test_each_agent_walks_with_its_own_rig():
    from footfall.bridge import rig_import

    tall, small = scene_with_two_rigs()
    check(json.loads(bpy.data.objects["bob"]["footfall_character"]) == {"max_step_length": 0.7},
          "the agent's own character was not kept in the scene")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    plan = stored_plan()
    agents = {a.name: a for a in plan.agents}
    hips = {rig.name: rig_import.profile_of(rig).dimensions["hip_height"] for rig in (tall, small)}
    check(abs(hips["small"] / hips["tall"] - SMALL) < 1e-3, f"rig sizes: {hips}")
    check(agents["ann"].character is None, "the scene's rig's agent has a character of its own")
    check(abs(plan.character.com_height - 1.05 * hips["tall"]) < 1e-6, f"planned for {plan.character.com_height}")
    check(abs(agents["kid"].character.com_height - 1.05 * hips["small"]) < 1e-6,
          f"kid planned as {agents['kid'].character.com_height} m")
    check(agents["bob"].character.left.max_step_length == 0.7, "bob's own override was lost")
    longest = {name: max(math.dist(s.com_start, s.com_end) for s in a.footsteps) for name, a in agents.items()}
    print(f"longest strides: {longest}")
    check(longest["kid"] < longest["ann"], f"the small rig's agent strides as far: {longest}")

    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    rig_of = {"ann": tall, "kid": small, "bob": tall}
    feet = {(rig.name, side): FootRest(rig, rig_import.profile_of(rig), side)
            for rig in (tall, small) for side in ("left", "right")}
    worst, stance = 0.0, 0
    for frame in range(scene.frame_start, scene.frame_end + 1, 2):
        scene.frame_set(frame)
        t = (frame - scene.frame_start) / fps
        from footfall.core import native

        ff = native.load()
        for name, agent in agents.items():
            armature = bpy.data.objects[name].evaluated_get(bpy.context.evaluated_depsgraph_get())
            for side, pose in zip(("left", "right"), ff.feet_at(agent, t)):
                if pose.planted:
                    worst = max(worst, feet[rig_of[name].name, side].error(armature, pose))
                    stance += 1
    print(f"{stance} stance samples, feet at most {worst * 1000:.2f} mm off the plan")
    check(stance > 100 and worst <= 0.002, f"feet {worst * 1000:.2f} mm off the plan")
    kid_hips = bpy.data.objects["kid"].data.bones[rig_import.profile_of(small).bones["hips"]].head_local.z
    check(abs(kid_hips - hips["small"]) < 0.05, f"kid's instance has its hips at {kid_hips:.3f} m")


def test_a_rig_of_another_size_than_planned_is_refused():
    from footfall.bridge import animate

    scene_with_two_rigs()
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    bpy.data.objects["kid"]["footfall_rig"] = "tall"  # changed after planning
    message = operator_error(bpy.ops.footfall.apply)
    check("Agent 'kid': rig 'tall' stands +25 % off" in message, message)
    check(animate.CROWD_COLLECTION not in bpy.data.collections, "a failed apply made a crowd")
    bpy.data.objects["kid"]["footfall_rig"] = "nobody"
    message = operator_error(bpy.ops.footfall.plan)
    check("Agent 'kid': custom property 'footfall_rig' names 'nobody'" in message, message)
    message = operator_error(bpy.ops.footfall.apply)
    check("Agent 'kid': custom property 'footfall_rig' names 'nobody'" in message, message)
    bpy.data.objects["kid"]["footfall_rig"] = 7
    message = operator_error(bpy.ops.footfall.apply)
    check("Agent 'kid': custom property 'footfall_rig' must be a rig's name, got 7" in message, message)


def test_several_rigs_and_none_chosen_is_an_error():
    scene_with_two_rigs()
    bpy.context.scene.footfall_rig = None
    message = operator_error(bpy.ops.footfall.plan)
    check("Several rigs are imported (small, tall)" in message, message)


def test_an_agents_scale_sizes_its_character_and_its_rig():
    """footfall_scale: the agent walks with the character times its size
    (shorter strides) and its instance is the rig scaled alike, its feet on
    the plan; an agent with its own rig is scaled from that one; a value out
    of range is refused, naming the agent."""
    from footfall.bridge import rig_import

    tall, small = scene_with_two_rigs()
    bpy.data.objects["ann"]["footfall_scale"] = 0.8
    bpy.data.objects["kid"]["footfall_scale"] = 1.2
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    plan = stored_plan()
    agents = {a.name: a for a in plan.agents}
    check((agents["ann"].scale, agents["kid"].scale, agents["bob"].scale) == (0.8, 1.2, 1.0),
          f"scales {[(a.name, a.scale) for a in plan.agents]}")
    hips = {rig.name: rig_import.profile_of(rig).dimensions["hip_height"] for rig in (tall, small)}
    check(abs(agents["ann"].character.com_height - 0.8 * 1.05 * hips["tall"]) < 1e-6, "ann's size")
    check(abs(agents["kid"].character.com_height - 1.2 * 1.05 * hips["small"]) < 1e-6, "kid's size")
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    scales = {name: tuple(round(v, 6) for v in bpy.data.objects[name].scale) for name in agents}
    check(scales == {"ann": (0.8,) * 3, "kid": (1.2,) * 3, "bob": (1.0,) * 3}, f"instance scales {scales}")
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    rig_of = {"ann": tall, "kid": small, "bob": tall}
    feet = {(rig.name, side): FootRest(rig, rig_import.profile_of(rig), side)
            for rig in (tall, small) for side in ("left", "right")}
    from footfall.core import native

    ff = native.load()
    worst, stance = 0.0, 0
    for frame in range(scene.frame_start, scene.frame_end + 1, 2):
        scene.frame_set(frame)
        t = (frame - scene.frame_start) / fps
        for name in ("ann", "kid"):
            armature = bpy.data.objects[name].evaluated_get(bpy.context.evaluated_depsgraph_get())
            for side, pose in zip(("left", "right"), ff.feet_at(agents[name], t)):
                if pose.planted:
                    worst = max(worst, feet[rig_of[name].name, side].error(armature, pose))
                    stance += 1
    print(f"scaled agents: {stance} stance samples, feet at most {worst * 1000:.2f} mm off the plan")
    check(stance > 50 and worst <= 0.002, f"feet {worst * 1000:.2f} mm off the plan")
    bpy.data.objects["ann (agent)"]["footfall_scale"] = 5.0
    message = operator_error(bpy.ops.footfall.plan)
    check("scale: must be in [0.5, 1.6]" in message and "'ann'" in message, message)


run([test_each_agent_walks_with_its_own_rig, test_a_rig_of_another_size_than_planned_is_refused,
     test_several_rigs_and_none_chosen_is_an_error, test_an_agents_scale_sizes_its_character_and_its_rig])
