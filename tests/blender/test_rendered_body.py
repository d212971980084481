"""Blender background test: the body the planner tests is the body Apply
renders. In the paper's door scene, and in its corridor with the gaps sized
to the rig's own clearances, both loaded through load_scenario, the rig's
skinned mesh enters no obstacle by more than 1 cm at any frame
(mathutils.bvhtree), and the NLA strips name each section's behaviour over
its time.

Run: blender -b --factory-startup --python-exit-code 1 --python tests/blender/test_rendered_body.py
"""

import json
import os
import pathlib
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402
import numpy  # noqa: E402
from mathutils import Vector  # noqa: E402
from mathutils.bvhtree import BVHTree  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, evaluated_points, run  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-body-"))
RIG = ROOT / "rigs" / "footfall_humanoid.glb"
TOLERANCE = 0.01  # [m] the deepest a vertex may be inside an obstacle
UP = Vector((0.0, 0.0, 1.0))


def native():
    from footfall.core import native as loader

    return loader.load()


def rig_scene():
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)
    check(bpy.ops.footfall.import_rig(filepath=str(RIG)) == {"FINISHED"}, "rig import failed")
    return bpy.context.scene.footfall_rig


def clearances(rig):
    """The planner's clearance per behaviour for the rig's character."""
    from footfall.bridge import rig_body, rig_import
    from footfall.core import character

    own, _ = character.derive_parameters(rig_import.profile_of(rig).dimensions, rig_body.body_of(rig))
    document = {"format": "footfall-scenario", "version": 1, "character": own,
                "agents": [{"name": "a", "position": [0, 0], "goals": [[1, 0]]}]}
    planner = native().BehavioralPlanner(native().parse_scenario(json.dumps(document), "rig.json"))
    return {b: planner.clearance(b) for b in ("side_step", "arms_in", "walk")}


def box(x0, x1, y0, y1, height):
    return {"polygon": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]], "height": height}


def door_scene():
    """The paper's door scene, as the core builds it."""
    scenario, start, goals = native().behavior_scene("door")
    obstacles = [{"polygon": [list(p) for p in o.polygon], "height": o.height, "base": o.base}
                 for o in scenario.obstacles]
    return obstacles, start, goals[0]


def corridor_scene(clear):
    """The paper's corridor (docs/full-body.md), its gaps sized to the
    character: 2 m walked with the arms in, 2.5 m between walls below the
    hands, 2 m side-stepped."""
    arms_in = 0.5 * (clear["arms_in"] + clear["walk"])
    narrow = 0.5 * (clear["side_step"] + clear["arms_in"])
    obstacles = []
    for x0, x1, half, height in ((0.0, 2.0, arms_in, 2.2), (2.0, 4.5, narrow, 0.55), (4.5, 6.5, narrow, 2.2)):
        obstacles += [box(x0, x1, half, 4.0, height), box(x0, x1, -4.0, -half, height)]
    return obstacles, (-2.0, 0.0), (8.5, 0.0)


def planned_and_applied(name, obstacles, start, goal):
    path = TMP / f"{name}.json"
    path.write_text(json.dumps({"format": "footfall-scenario", "version": 1, "obstacles": obstacles,
                                "agents": [{"name": "walker", "position": list(start), "goals": [list(goal)]}]}))
    check(bpy.ops.footfall.load_scenario(filepath=str(path)) == {"FINISHED"}, f"{name}: load failed")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, f"{name}: plan failed")
    from footfall.bridge import plan_store

    plan = plan_store.load_plan()
    (agent,) = plan.agents
    check(agent.status == native().AgentStatus.REACHED, f"{name}: the walker did not arrive ({agent.status})")
    check(bpy.ops.footfall.apply() == {"FINISHED"}, f"{name}: apply failed")
    return agent


def obstacle_trees():
    """Each obstacle as a BVH tree in world space, with its bounds."""
    trees = []
    for obj in bpy.data.collections["Footfall Obstacles"].all_objects:
        if obj.type != "MESH":
            continue
        points = [obj.matrix_world @ v.co for v in obj.data.vertices]
        tree = BVHTree.FromPolygons(points, [tuple(p.vertices) for p in obj.data.polygons])
        trees.append((tree, numpy.array(points).min(axis=0), numpy.array(points).max(axis=0)))
    return trees


def depth_inside(tree, point):
    """How deep `point` is inside the closed mesh (0 outside): odd crossings
    of a ray upwards, then the distance to the surface."""
    crossings, origin = 0, point.copy()
    while True:
        hit, _normal, _index, _distance = tree.ray_cast(origin, UP)
        if hit is None:
            break
        crossings += 1
        origin = hit + UP * 1e-6
    return tree.find_nearest(point)[3] if crossings % 2 else 0.0


def deepest_penetration(body_objects, frames):
    """Over the frames: the deepest any vertex of the rendered meshes is
    inside an obstacle, and where."""
    scene = bpy.context.scene
    trees = obstacle_trees()
    worst = (0.0, None)
    for frame in frames:
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        for obj in body_objects:
            points = evaluated_points(obj, depsgraph)
            for tree, low, high in trees:
                near = points[numpy.all((points > low - TOLERANCE) & (points < high + TOLERANCE), axis=1)]
                for point in near:
                    depth = depth_inside(tree, Vector(point))
                    if depth > worst[0]:
                        worst = (depth, (frame, tuple(round(float(c), 3) for c in point)))
    return worst


def expect_strips_name_the_sections(agent):
    from footfall.bridge import animate
    from footfall.core import clip_timing

    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    sections = clip_timing.sections([clip_timing.Step(s.start_time, s.end_time, s.foot.name.lower(),
                                                      s.kind.name.lower(), s.behavior.name.lower())
                                     for s in agent.footsteps])
    strips = sorted((strip for track in bpy.data.objects[agent.name].animation_data.nla_tracks
                     if track.name.startswith(animate.UPPER_BODY_TRACK) and not track.name.endswith(" idle")
                     for strip in track.strips), key=lambda strip: int(strip.name.split()[-1]))
    check(len(strips) == len(sections), f"{len(strips)} strips for {len(sections)} sections")
    for strip, section in zip(strips, sections):
        start, end = scene.frame_start + section.start * fps, scene.frame_start + section.end * fps
        check(strip.name.split()[0] == section.behavior, f"strip '{strip.name}' plays the {section.behavior} section")
        check(strip.frame_start <= start + 1e-4 and strip.frame_end >= end - 1e-4,
              f"{strip.name} spans {strip.frame_start}-{strip.frame_end}, its section {start}-{end}")
    return {s.behavior for s in sections}


def expect_the_rendered_body_clear(name, scene_of):
    rig = rig_scene()
    obstacles, start, goal = scene_of(rig)
    agent = planned_and_applied(name, obstacles, start, goal)
    behaviors = expect_strips_name_the_sections(agent)
    body = [obj for obj in bpy.data.objects["walker"].children_recursive if obj.type == "MESH"]
    check(body, "the instance has no mesh")
    scene = bpy.context.scene
    depth, where = deepest_penetration(body, range(scene.frame_start, scene.frame_end + 1))
    print(f"{name}: sections {sorted(behaviors)}; the rendered body at most {depth * 100:.2f} cm into an "
          f"obstacle{f' (frame, vertex: {where})' if where else ''}")
    check(depth <= TOLERANCE, f"{name}: the rendered body is {depth * 100:.2f} cm inside an obstacle at {where}")
    return behaviors


def test_through_the_door_the_rendered_body_stays_out():
    behaviors = expect_the_rendered_body_clear("door", lambda rig: door_scene())
    check("side_step" in behaviors, f"the door was passed with {sorted(behaviors)}, not side-stepped")


def test_along_the_corridor_the_rendered_body_stays_out():
    behaviors = expect_the_rendered_body_clear("corridor", lambda rig: corridor_scene(clearances(rig)))
    check({"arms_in", "side_step", "walk"} <= behaviors, f"the corridor was passed with {sorted(behaviors)}")


def test_the_check_sees_a_body_inside_a_box():
    """The check itself: a box put where the walker's hips are, after Apply, holds part of its body."""
    rig_scene()
    agent = planned_and_applied("open", [], (0.0, 0.0), (4.0, 0.0))
    scene = bpy.context.scene
    frame = scene.frame_start + round(0.5 * agent.end_time() * scene.render.fps / scene.render.fps_base)
    scene.frame_set(frame)
    hips = native().com_at(agent, (frame - scene.frame_start) * scene.render.fps_base / scene.render.fps).position
    bpy.ops.mesh.primitive_cube_add(size=0.2, location=(hips[0], hips[1], 0.9))
    cube = bpy.context.active_object
    for collection in list(cube.users_collection):
        collection.objects.unlink(cube)
    bpy.data.collections["Footfall Obstacles"].objects.link(cube)
    body = [obj for obj in bpy.data.objects["walker"].children_recursive if obj.type == "MESH"]
    depth, _where = deepest_penetration(body, [frame])
    check(depth > 0.05, f"a box at the hips holds the body only {depth * 100:.2f} cm deep")


if __name__ == "__main__":
    run([test_through_the_door_the_rendered_body_stays_out, test_along_the_corridor_the_rendered_body_stays_out,
         test_the_check_sees_a_body_inside_a_box])
