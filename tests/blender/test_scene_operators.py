"""Blender background test: footfall.load_scenario, footfall.plan and
footfall.randomize_agents, the scene's conventions read back by
scene_extract (loaded and hand-made), the
plan stored in the .blend, and errors that leave the scene as it was.

Run: blender -b --factory-startup -noaudio --python-exit-code 1 --python tests/blender/test_scene_operators.py
"""

import json
import math
import os
import pathlib
import sys
import tempfile

import bpy  # first: as a Python module, bpy puts Blender's own modules on the path
import addon_utils  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from harness import check, run  # noqa: E402
from mathutils import Matrix

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, os.environ.get("FOOTFALL_ADDON_DIR", str(ROOT / "blender_addon")))
TMP = pathlib.Path(tempfile.mkdtemp(prefix="footfall-scenes-"))
STEERSUITE = ROOT / "tests" / "data" / "steersuite"

L_SHAPE = [[2, 2], [3, 2], [3, 0], [4, 0], [4, -1], [2, -1]]  # concave, clockwise
BOX = [[5, 3], [6, 3], [6, 4], [5, 4]]
SCENARIO = {
    "format": "footfall-scenario", "version": 1,
    "obstacles": [{"polygon": L_SHAPE, "height": 1.5}, {"polygon": BOX}],
    "agents": [{"name": "alice", "position": [0, -2.5], "facing": 0.3, "goals": [[5, -2.5], [5.5, 1]]},
               {"name": "bob", "position": [0, 4.5], "goals": [[7, 5.5], [7, 2]]}],
    "character": {"mass": 65.0, "left": {"max_speed": 2.0}},
    "planner": {"max_expansions": 3000},
}
FACINGS = {"alice": 0.3, "bob": math.atan2(1, 7)}  # bob's default: toward his first goal



def close(a, b, tolerance=1e-6):
    return len(a) == len(b) and all(abs(x - y) <= tolerance for x, y in zip(a, b))


def fresh_scene():
    bpy.ops.wm.read_homefile(use_empty=True)
    addon_utils.enable("footfall", default_set=True, handle_error=None)


def write(name, content):
    path = TMP / name
    path.write_text(content if isinstance(content, str) else json.dumps(content))
    return str(path)


def extract():
    return read().document


def read():
    from footfall.bridge import scene_extract

    return scene_extract.read(bpy.context.scene)


def world_vertices(obj):
    return [obj.matrix_world @ v.co for v in obj.data.vertices]


def inside(point, polygon):
    """Even-odd rule."""
    x, y = point
    result = False
    for (x0, y0), (x1, y1) in zip(polygon, polygon[1:] + polygon[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            result = not result
    return result


def boundary_distance(point, polygon):
    def to_segment(a, b):
        ax, ay, bx, by = *a, *b
        length2 = (bx - ax) ** 2 + (by - ay) ** 2
        t = max(0.0, min(1.0, ((point[0] - ax) * (bx - ax) + (point[1] - ay) * (by - ay)) / length2))
        return math.dist(point, (ax + t * (bx - ax), ay + t * (by - ay)))

    return min(to_segment(a, b) for a, b in zip(polygon, polygon[1:] + polygon[:1]))


def footprints(obstacles):
    """Whether a point lies inside the footprint of one of the document's
    `obstacles`, as the core sees them."""
    from footfall.core import native

    core = native.load()
    parsed = core.parse_scenario(json.dumps({"format": "footfall-scenario", "version": 1, "obstacles": obstacles,
                                             "agents": []}), "extracted")
    footprint_map = core.ObstacleMap(parsed.obstacles)
    return lambda p: any(footprint_map.contains(i, p) for i in range(len(obstacles)))


def z_range(obstacles):
    heights = [v[2] for o in obstacles for v in o["mesh"]["vertices"]]
    return min(heights), max(heights)


def check_union(expected, covered, x_range, y_range, step=0.1):
    """Every sample point (not on an expected edge) is `covered` exactly if
    it is inside one of the `expected` polygons."""
    count = 0
    for i in range(int((x_range[1] - x_range[0]) / step)):
        for j in range(int((y_range[1] - y_range[0]) / step)):
            p = (x_range[0] + (i + 0.5) * step, y_range[0] + (j + 0.5) * step)
            if min(boundary_distance(p, e) for e in expected) < 1e-4:
                continue
            want = any(inside(p, e) for e in expected)
            check(covered(p) == want, f"{p}: inside the footprint should be {want}")
            count += want
    check(count > 0, "no sample point inside the expected footprint")


def convex_hull(points):
    points = sorted(set(points))

    def half(sequence):
        hull = []
        for p in sequence:
            while len(hull) >= 2 and ((hull[-1][0] - hull[-2][0]) * (p[1] - hull[-2][1])
                                      - (hull[-1][1] - hull[-2][1]) * (p[0] - hull[-2][0])) <= 0:
                hull.pop()
            hull.append(p)
        return hull[:-1]

    return half(points) + half(reversed(points))


def load_good_scenario():
    path = write("good.json", SCENARIO)
    check(bpy.ops.footfall.load_scenario(filepath=path) == {"FINISHED"}, "load_scenario did not finish")
    bpy.context.view_layer.update()
    return path


def test_load_builds_the_conventions_and_extracts_back():
    fresh_scene()
    load_good_scenario()
    agents = bpy.data.collections["Footfall Agents"]
    obstacles = bpy.data.collections["Footfall Obstacles"]
    check({c.name for c in bpy.context.scene.collection.children} == {agents.name, obstacles.name}, "collections")
    check(sorted(o.name for o in agents.objects) == ["alice", "alice goal 1", "alice goal 2",
                                                     "bob", "bob goal 1", "bob goal 2"], list(agents.objects))
    for spec in SCENARIO["agents"]:
        agent = bpy.data.objects[spec["name"]]
        check(agent.type == "EMPTY" and agent.parent is None, f"{agent.name}: not a top-level empty")
        check(close(agent.matrix_world.translation.xy, spec["position"]), f"{agent.name}: at {agent.location}")
        check(abs(agent.rotation_euler.z - FACINGS[agent.name]) < 1e-6, f"{agent.name}: facing {agent.rotation_euler}")
        goals = sorted(agent.children, key=lambda g: g["footfall_goal_index"])
        check([g.name for g in goals] == [f"{agent.name} goal {k}" for k in (1, 2)], [g.name for g in goals])
        check([g["footfall_goal_index"] for g in goals] == [1, 2], "goal indices")
        check(all(g.empty_display_type == "SPHERE" and abs(g.empty_display_size - 0.25) < 1e-9 for g in goals),
              "goals are spheres of size 0.25")
        for goal, point in zip(goals, spec["goals"]):
            check(close(goal.matrix_world.translation.xy, point), f"{goal.name}: at {goal.matrix_world.translation}")
    check(sorted(o.name for o in obstacles.objects) == ["Obstacle 0", "Obstacle 1"], list(obstacles.objects))
    for name, spec, height in (("Obstacle 0", L_SHAPE, 1.5), ("Obstacle 1", BOX, 2.0)):
        obj = bpy.data.objects[name]
        points = world_vertices(obj)
        check(abs(max(p.z for p in points) - height) < 1e-6 and abs(min(p.z for p in points)) < 1e-6,
              f"{name}: from {min(p.z for p in points)} to {max(p.z for p in points)}")
        check(len(obj.data.polygons) == len(spec) + 2, f"{name}: {len(obj.data.polygons)} faces")
        for corner in spec:
            check(any(close(p.xy, corner) for p in points), f"{name}: no vertex at {corner}")

    document = extract()
    check([a["name"] for a in document["agents"]] == ["alice", "bob"], document["agents"])
    for got, spec in zip(document["agents"], SCENARIO["agents"]):
        check(close(got["position"], spec["position"]), f"{got['name']}: position {got['position']}")
        check(abs(got["facing"] - FACINGS[got["name"]]) < 1e-6, f"{got['name']}: facing {got['facing']}")
        check(len(got["goals"]) == 2 and all(close(g, s) for g, s in zip(got["goals"], spec["goals"])),
              f"{got['name']}: goals {got['goals']}")
    check_union([L_SHAPE, BOX], footprints(document["obstacles"]), (0, 7), (-3, 5))
    # One mesh obstacle per face (a wall per edge, the box's bottom and top),
    # the L's concave bottom and top one per triangle.
    faces = {name: [o for o, owner in zip(document["obstacles"], read().obstacle_objects) if owner == name]
             for name in ("Obstacle 0", "Obstacle 1")}
    check([len(faces["Obstacle 0"]), len(faces["Obstacle 1"])] == [3 * len(L_SHAPE) - 4, len(BOX) + 2],
          {name: len(f) for name, f in faces.items()})
    check(close(z_range(faces["Obstacle 0"]), (0, 1.5)) and close(z_range(faces["Obstacle 1"]), (0, 2.0)),
          [z_range(f) for f in faces.values()])
    check(document["character"] == SCENARIO["character"], document.get("character"))
    check(document["planner"] == SCENARIO["planner"], document.get("planner"))


def link_to(collection, obj):
    for owner in obj.users_collection:
        owner.objects.unlink(obj)
    collection.objects.link(obj)


def new_empty(name, collection, parent=None, location=(0, 0, 0)):
    obj = bpy.data.objects.new(name, None)
    obj.parent = parent
    obj.location = location
    collection.objects.link(obj)
    return obj


def test_hand_made_agents_and_obstacles_are_extracted():
    fresh_scene()
    scene = bpy.context.scene
    agents = bpy.data.collections.new("Footfall Agents")
    obstacles = bpy.data.collections.new("Footfall Obstacles")
    scene.collection.children.link(agents)
    scene.collection.children.link(obstacles)
    hand = new_empty("hand", agents, location=(1, -2, 0.5))
    hand.rotation_euler.z = 1.0
    hand.scale = (2, 2, 2)
    new_empty("hand b", agents, hand, (1, 0, 0))["footfall_goal_index"] = 1
    new_empty("hand a", agents, hand, (0, 1, 0))["footfall_goal_index"] = 2
    plain = new_empty("plain", agents, location=(-3, 0, 0))
    new_empty("plain g2", agents, plain, (0, 2, 0))
    new_empty("plain g1", agents, plain, (2, 0, 0))
    new_empty("not a goal", scene.collection, plain, (5, 5, 0))  # outside the collections: ignored
    new_empty("not an agent", scene.collection, location=(9, 9, 0))
    plain.hide_set(True)  # hidden objects count

    bpy.ops.mesh.primitive_cube_add(size=2, location=(5, 5, 1), rotation=(0.3, 0.2, 0.7), scale=(1.5, 0.5, 1))
    cube = bpy.context.active_object
    link_to(obstacles, cube)
    bpy.ops.mesh.primitive_cube_add(size=1, location=(10, 0, 0.5))
    arrayed = bpy.context.active_object  # its modifier doubles it along +X
    arrayed.modifiers.new("Array", "ARRAY").count = 2
    link_to(obstacles, arrayed)
    arrayed.hide_set(True)
    bpy.context.view_layer.update()

    document = extract()
    check([a["name"] for a in document["agents"]] == ["hand", "plain"], document["agents"])
    hand_doc, plain_doc = document["agents"]
    c, s = math.cos(1.0), math.sin(1.0)
    # Half a metre up, off the floor: the height goes with the points, for the core to judge.
    check(close(hand_doc["position"], [1, -2, 0.5]) and abs(hand_doc["facing"] - 1.0) < 1e-6, hand_doc)
    check(close(hand_doc["goals"][0], [1 + 2 * c, -2 + 2 * s, 0.5]), f"goal by index first: {hand_doc['goals']}")
    check(close(hand_doc["goals"][1], [1 - 2 * s, -2 + 2 * c, 0.5]), hand_doc["goals"])
    check(plain_doc["goals"] == [[-1.0, 0.0], [-3.0, 2.0]], f"goals by name: {plain_doc['goals']}")
    check(abs(plain_doc["facing"]) < 1e-9, plain_doc)

    cube_points = world_vertices(cube)
    hull = convex_hull([(p.x, p.y) for p in cube_points])
    covered = footprints(document["obstacles"])
    check_union([hull], covered, (2, 8), (2, 8))
    cube_faces = [o for o, owner in zip(document["obstacles"], read().obstacle_objects) if owner == cube.name]
    check(close(z_range(cube_faces), (min(p.z for p in cube_points), max(p.z for p in cube_points))),
          f"the cube's faces in world space: {z_range(cube_faces)}")
    check_union([[[9.5, -0.5], [11.5, -0.5], [11.5, 0.5], [9.5, 0.5]]], covered, (9, 12), (-1, 1))
    check("character" not in document and "planner" not in document, "overrides without a property")


def test_plan_is_stored_and_saved_with_the_file():
    from footfall.bridge import plan_store

    fresh_scene()
    load_good_scenario()
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
    check(plan_store.TEXT_NAME in bpy.data.texts, f"no Text {plan_store.TEXT_NAME}")
    packed = len(bpy.data.texts[plan_store.TEXT_NAME].as_string())
    print(f"plan JSON {len(plan_store.load())} characters, stored in {packed}")
    # Version 2's compact JSON packs to about half its length (0.52 here; version 1's
    # spaces and repeated keys packed to a fifth), while the plain JSON would take its
    # whole length and base64 without zlib 4/3 of it: under 0.7 means zlib packed it.
    check(packed < 0.7 * len(plan_store.load()), "the stored plan is not packed")
    document = json.loads(plan_store.load())
    check({a["name"]: a["status"] for a in document["agents"]} == {"alice": "reached", "bob": "reached"},
          [(a["name"], a["status"]) for a in document["agents"]])
    check(document["character"]["mass"] == 65.0, "character override not planned with")
    text = plan_store.load()
    plan = plan_store.load_plan()
    check(len(plan.agents) == 2 and all(len(a.footsteps) > 0 for a in plan.agents), "the core cannot read the plan")

    path = str(TMP / "planned.blend")
    bpy.ops.wm.save_as_mainfile(filepath=path)
    bpy.ops.wm.read_homefile(use_empty=True)
    check(plan_store.load() is None, "a new file still has the plan")
    bpy.ops.wm.open_mainfile(filepath=path)
    check(plan_store.load() == text, "the reopened plan differs")
    check([a.name for a in plan_store.load_plan().agents] == ["alice", "bob"], "reopened plan")

    # A file saved before plans were packed keeps its plain JSON: it is read,
    # and the next Plan replaces it with the packed one.
    bpy.data.texts.remove(bpy.data.texts[plan_store.TEXT_NAME])
    bpy.data.texts.new(plan_store.PLAIN_TEXT_NAME).from_string(text)
    check(plan_store.load() == text, "the plain plan of an older file is not read")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
    check(plan_store.PLAIN_TEXT_NAME not in bpy.data.texts and plan_store.load() == text, "not replaced")
    # A damaged packed plan is named, not read as nonsense.
    bpy.data.texts[plan_store.TEXT_NAME].from_string(plan_store.HEADER + "\n!!!!")
    try:
        plan_store.load()
        check(False, "a damaged plan was read")
    except ValueError as error:
        check("footfall_plan: the packed plan is damaged" in str(error), str(error))


def test_the_plan_names_those_that_did_not_arrive():
    """An agent out of time is named, with its reason, in the report and on
    the panel, and select_unreached selects it alone."""
    from footfall.bridge import plan_store

    fresh_scene()
    load_good_scenario()
    bpy.data.objects["bob"]["footfall_time_limit"] = 0.5
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
    said = bpy.context.scene[plan_store.OUTCOME]
    check(said == "1/2 agents reached their goals; not there: 'bob' (time limit)", said)
    bpy.data.objects["alice"].select_set(True)
    check(bpy.ops.footfall.select_unreached() == {"FINISHED"}, "select_unreached failed")
    selected = sorted(o.name for o in bpy.context.selected_objects)
    check(selected == ["bob"], f"selected: {selected}")


def test_an_agents_own_speed_and_start():
    """footfall_speed sets an agent's preferred speed: it walks slower than
    without it; a value that is no number, or out of range, names the agent.
    footfall_start_delay keeps it standing until then."""
    from footfall.bridge import plan_store

    def alices_speed():
        check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
        alice = plan_store.load_plan().agents[0]
        walked = sum(math.dist(s.com_start, s.com_end) for s in alice.footsteps)
        return walked / alice.end_time()

    fresh_scene()
    load_good_scenario()
    usual = alices_speed()
    bpy.data.objects["alice"]["footfall_speed"] = 0.7
    slow = alices_speed()
    print(f"alice's mean speed {usual:.2f} m/s, {slow:.2f} m/s at footfall_speed 0.7")
    check(slow < 0.8 * usual, f"footfall_speed 0.7: {slow:.2f} m/s against {usual:.2f} m/s")
    bpy.data.objects["alice"]["footfall_speed"] = "fast"
    message = operator_error(bpy.ops.footfall.plan)
    check("Agent 'alice': custom property 'footfall_speed' must be a number of metres per second" in message, message)
    bpy.data.objects["alice"]["footfall_speed"] = 40.0
    message = operator_error(bpy.ops.footfall.plan)
    check("agents[0].character.preferred_speed" in message and "agent 'alice'" in message, message)
    del bpy.data.objects["alice"]["footfall_speed"]
    bpy.data.objects["alice"]["footfall_start_delay"] = 2.0  # she stands, then walks
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
    alice = plan_store.load_plan().agents[0]
    moved = [s.start_time for s in alice.footsteps if math.dist(s.com_start, s.com_end) > 0.0]
    check(moved and moved[0] >= 2.0, f"alice moved before her start: {moved[:1]}")
    check(extract()["agents"][0].get("start_delay") == 2.0, "footfall_start_delay not read")
    bpy.data.objects["alice"]["footfall_wait"] = 3.0
    check(extract()["agents"][0].get("goal_wait") == 3.0, "footfall_wait not read")


def test_randomize_draws_speeds_and_rigs_for_the_selected_agents():
    """randomize_agents sets footfall_speed (and with vary_rig, footfall_rig)
    on the selected agents only, within the range, the same for the same
    seed; a bad range or no selection changes nothing; Plan walks with them."""
    fresh_scene()
    load_good_scenario()
    alice, bob = bpy.data.objects["alice"], bpy.data.objects["bob"]

    def drawn(seed, **options):
        for obj in bpy.context.view_layer.objects:
            obj.select_set(obj in (alice, bpy.data.objects["bob goal 2"]))  # a goal stands for its agent
        check(bpy.ops.footfall.randomize_agents(seed=seed, **options) == {"FINISHED"}, "randomize failed")
        return alice.get("footfall_speed"), bob.get("footfall_speed"), alice.get("footfall_rig")

    first = drawn(7, speed_min=0.8, speed_max=1.0)
    check(all(0.8 <= speed <= 1.0 for speed in first[:2]), f"speeds out of range: {first}")
    check(drawn(7, speed_min=0.8, speed_max=1.0) == first, "the same seed drew other values")
    check(drawn(8, speed_min=0.8, speed_max=1.0) != first, "another seed drew the same values")
    check(first[2] is None, "a rig was drawn without vary_rig")
    check("footfall_scale" not in alice, "a size was drawn from the range 1-1")
    drawn(7, speed_min=0.8, speed_max=1.0, scale_min=0.85, scale_max=1.15)
    sizes = alice["footfall_scale"], bob["footfall_scale"]
    check(all(0.85 <= s <= 1.15 for s in sizes) and sizes[0] != sizes[1], f"sizes {sizes}")
    bob_speed = bob["footfall_speed"]
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj == alice)
    check(bpy.ops.footfall.randomize_agents(seed=1) == {"FINISHED"}, "randomize failed")
    check(bob["footfall_speed"] == bob_speed, "an agent not selected changed")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan with drawn speeds failed")

    before = inventory()
    for options, fragment in (({"speed_min": 1.5, "speed_max": 1.0}, "Speed range 1.5-1 m/s"),
                              ({"scale_min": 1.2, "scale_max": 1.1}, "Size range 1.2-1.1"),
                              ({"vary_rig": True}, "no rig is imported")):
        message = operator_error(bpy.ops.footfall.randomize_agents, **options)
        check(fragment in message, message)
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    check("No agents selected" in operator_error(bpy.ops.footfall.randomize_agents), "no selection accepted")
    check(inventory() == before, "a refused randomize changed the scene")

    check(bpy.ops.footfall.import_rig(filepath=str(ROOT / "rigs" / "footfall_humanoid.glb")) == {"FINISHED"},
          "rig import failed")
    rig = bpy.context.scene.footfall_rig.name
    check(drawn(3, vary_rig=True)[2] == rig and bob["footfall_rig"] == rig, "the rig was not drawn")


def test_scatter_places_agents_clear_of_obstacles_and_each_other():
    """scatter_agents: N agents in the selected mesh, goals in the active one,
    clear of obstacles and of every agent, facing their goals; the same seed
    places the same agents; a crowded region or a bad selection adds nothing."""
    fresh_scene()
    load_good_scenario()  # alice, bob and two obstacles, the L at (2-4, -1-2)
    bpy.ops.mesh.primitive_plane_add(size=6, location=(3, 0.5, 0))
    start = bpy.context.active_object
    start.name = "start area"
    bpy.ops.mesh.primitive_plane_add(size=4, location=(12, 0, 0))
    goal = bpy.context.active_object
    goal.name = "goal area"

    def scatter(**options):
        for obj in bpy.context.view_layer.objects:
            obj.select_set(obj in (start, goal))
        bpy.context.view_layer.objects.active = goal
        return bpy.ops.footfall.scatter_agents(**options)

    check(scatter(count=12, seed=4, spacing=0.9) == {"FINISHED"}, "scatter failed")
    bpy.context.view_layer.update()
    made = [bpy.data.objects[f"Agent {k}"] for k in range(1, 13)]
    check("Agent 13" not in bpy.data.objects, "too many agents")
    covered = footprints([o for o in extract()["obstacles"]])
    everyone = made + [bpy.data.objects["alice"], bpy.data.objects["bob"]]
    for agent in made:
        p = agent.matrix_world.translation
        check(0 <= p.x <= 6 and -2.5 <= p.y <= 3.5, f"{agent.name} at {p} is outside the start area")
        check(not any(covered((p.x + 0.3 * math.cos(a), p.y + 0.3 * math.sin(a))) for a in range(0, 7)),
              f"{agent.name} at {p} stands within 0.3 m of an obstacle")
        check(min((p.xy - o.matrix_world.translation.xy).length for o in everyone if o is not agent) >= 0.9 - 1e-6,
              f"{agent.name} stands nearer than 0.9 m to another agent")
        (target,) = agent.children
        q = target.matrix_world.translation
        check(10 <= q.x <= 14 and -2 <= q.y <= 2, f"{agent.name}'s goal at {q} is outside the goal area")
        check(abs(agent.rotation_euler.z - math.atan2(q.y - p.y, q.x - p.x)) < 1e-6, f"{agent.name} faces away")
    placed = [tuple(a.location) for a in made]
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")

    # The same seed in the same scene places the same agents.
    for agent in made:
        for obj in (*agent.children, agent):
            bpy.data.objects.remove(obj)
    check(scatter(count=12, seed=4, spacing=0.9) == {"FINISHED"}, "scatter failed")
    check([tuple(bpy.data.objects[f"Agent {k}"].location) for k in range(1, 13)] == placed, "another placement")

    before = inventory()
    message = operator_error(scatter, count=200, seed=1, spacing=0.9)
    check("Region 'start area' holds only" in message and "of 200 agents" in message, message)
    message = operator_error(bpy.ops.footfall.scatter_agents, start_region="Obstacle 0", goal_region="goal area")
    check("Region 'Obstacle 0' is an obstacle" in message, message)
    for obj in bpy.context.view_layer.objects:
        obj.select_set(False)
    check("Select the mesh to scatter agents in" in operator_error(bpy.ops.footfall.scatter_agents), "no selection")
    check(inventory() == before, "a refused scatter changed the scene")


class _Layout:
    """Stands in for a panel's layout: the labels and operators drawn."""

    def __init__(self):
        self.lines = []

    def label(self, text="", icon="NONE"):
        self.lines.append(text)

    def operator(self, idname, text="", icon="NONE"):
        self.lines.append(text or idname)
        return type("Properties", (), {})()

    def prop(self, data, name, text=""):
        self.lines.append(name)


def panel_lines(panel=None):
    """What a sidebar panel (the main one by default) draws for the scene as it is."""
    from footfall.ui.panel import FOOTFALL_PT_main

    stand_in = type("Panel", (), {"layout": _Layout()})()
    (panel or FOOTFALL_PT_main).draw(stand_in, bpy.context)
    return stand_in.layout.lines


def test_the_plan_is_out_of_date_once_the_scene_changes():
    """Moving an obstacle, an agent or a goal, scattering or randomizing
    marks the stored plan out of date; Plan makes it current; moving other
    objects does not, nor does a second move count twice. The panel names
    the rig of the active agent."""
    from footfall.bridge import plan_watch
    from footfall.ui.panel import _own_rig

    fresh_scene()
    load_good_scenario()
    scene = bpy.context.scene
    check(not plan_watch.is_stale(scene), "out of date before any plan")
    check("No plan yet" in panel_lines(), panel_lines())
    bpy.ops.mesh.primitive_cube_add(location=(20, 20, 0))  # not an obstacle
    outsider = bpy.context.active_object

    def planned():
        check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
        bpy.context.view_layer.update()
        check(not plan_watch.is_stale(scene), "out of date right after Plan")

    planned()
    outsider.location.x += 1
    bpy.context.view_layer.update()
    check(not plan_watch.is_stale(scene), "moving an object outside the Footfall collections made it out of date")
    for obj in (bpy.data.objects["Obstacle 1"], bpy.data.objects["alice"], bpy.data.objects["bob goal 2"]):
        obj.location.y += 0.2
        bpy.context.view_layer.update()
        check(plan_watch.is_stale(scene), f"moving '{obj.name}' left the plan current")
        counted = plan_watch.changes(scene)
        obj.location.y += 0.2
        bpy.context.view_layer.update()
        check(plan_watch.changes(scene) == counted, "a second move was counted again")
        planned()
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj.name == "bob")
    check(bpy.ops.footfall.randomize_agents(seed=2) == {"FINISHED"}, "randomize failed")
    check(plan_watch.is_stale(scene), "new speeds left the plan current")

    check("Out of date: agents, goals or obstacles changed since" in panel_lines(), panel_lines())
    planned()
    check("Out of date: agents, goals or obstacles changed since" not in panel_lines(), panel_lines())
    bpy.context.view_layer.objects.active = bpy.data.objects["bob"]
    check(_own_rig(bpy.context) == "bob: the scene's rig (none yet)", _own_rig(bpy.context))
    check("bob: the scene's rig (none yet)" in panel_lines(), panel_lines())
    bpy.data.objects["bob"]["footfall_rig"] = "tall"
    check(_own_rig(bpy.context) == "bob: rig 'tall' (footfall_rig)", _own_rig(bpy.context))
    bpy.context.view_layer.objects.active = outsider
    check(_own_rig(bpy.context) is None, "a rig named for an object that is no agent")


def plain_value(value):
    return value.to_dict() if hasattr(value, "to_dict") else value.to_list() if hasattr(value, "to_list") else value


def inventory():
    """The data-blocks, the scene's collections and what they hold, and the custom properties."""
    scene = bpy.context.scene
    kinds = ("objects", "meshes", "collections", "texts")
    state = {kind: sorted(b.name for b in getattr(bpy.data, kind)) for kind in kinds}
    state["scene"] = sorted((c.name, sorted(o.name for o in c.objects)) for c in scene.collection.children_recursive)
    state["scene properties"] = {k: plain_value(v) for k, v in scene.items()}
    state["object properties"] = {o.name: {k: plain_value(v) for k, v in o.items()} for o in bpy.data.objects}
    return state


def operator_error(operator, **options):
    try:
        operator(**options)
    except RuntimeError as error:
        return str(error)
    raise AssertionError(f"{operator.idname()} gave no error")


def test_errors_leave_the_scene_as_it_was():
    from footfall.bridge import scene_build

    fresh_scene()
    check("No agents to plan" in operator_error(bpy.ops.footfall.plan), "planning an empty scene")
    good = load_good_scenario()
    bpy.ops.mesh.primitive_uv_sphere_add()  # something of the user's
    before = inventory()

    bad = write("nan.json", '{"format": "footfall-scenario", "version": 1, "agents": '
                            '[{"name": "carol", "position": [NaN, 1], "goals": [[3, 3]]}]}')
    message = operator_error(bpy.ops.footfall.load_scenario, filepath=bad)
    check("nan.json: agents[0].position[0]: must be a finite number" in message, message)
    check(inventory() == before, "a NaN position changed the scene")

    two = write("two.json", {"format": "footfall-scenario", "version": 1,
                             "obstacles": [{"polygon": [[0, 0], [1, 1]]}], "character": {"mass": 80}})
    message = operator_error(bpy.ops.footfall.load_scenario, filepath=two)
    check("two.json: obstacles[0].polygon: needs at least 3 points" in message, message)
    check(inventory() == before, "a 2-point polygon changed the scene")

    example = str(STEERSUITE / "EXAMPLE.xml")  # a goal type Footfall does not follow
    message = operator_error(bpy.ops.footfall.load_scenario, filepath=example)
    check("agent 'Agent A' (agent[4]): goal type 'fleeDynamicTarget' is not supported" in message, message)
    check(inventory() == before, "a refused SteerSuite case changed the scene")

    message = operator_error(bpy.ops.footfall.load_scenario, filepath=good)
    check("good.json: agents[0].name: an object named 'alice' exists already" in message, message)
    check(inventory() == before, "loading twice changed the scene")

    heights = write("heights.json", {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "dora", "position": [0, 8, 0.1], "goals": [[3, 8, 0]]}]})
    check(bpy.ops.footfall.load_scenario(filepath=heights) == {"FINISHED"}, "heights on the floor refused")
    check(tuple(bpy.data.objects["dora"].location) == (0, 8, 0), "dora is not on the floor")

    # A failure in the middle of building removes what was built: collections too.
    fresh_scene()
    before = inventory()
    def fail(*_args):
        raise RuntimeError("injected failure after the agents and obstacles were built (expected)")

    add_goals = scene_build._add_goals
    scene_build._add_goals = fail
    try:
        operator_error(bpy.ops.footfall.load_scenario, filepath=good)
    finally:
        scene_build._add_goals = add_goals
    check(inventory() == before, f"a failed build left {inventory()}")

    # Planning: a goal inside an obstacle is named with its objects; an agent without goals by name.
    load_good_scenario()
    bpy.data.objects["bob goal 2"].matrix_world = Matrix.Translation((5.5, 3.5, 0))  # inside the box
    message = operator_error(bpy.ops.footfall.plan)
    check("scene: agents[1].goals[1]: inside obstacles[" in message and "is agent 'bob'" in message
          and "is a face of 'Obstacle 1'" in message, message)
    lonely = bpy.data.objects.new("lonely", None)
    bpy.data.collections["Footfall Agents"].objects.link(lonely)
    message = operator_error(bpy.ops.footfall.plan)
    check("Agent 'lonely' has no goals" in message, message)
    check("footfall_plan" not in bpy.data.texts, "a failed plan stored a Text")


def footfall_native():
    from footfall.core import native

    return native.load()


def scatter_between(start, goal, **options):
    """Scatter Agents from a plane region `start` to one `goal`, each given as
    (centre, (size x, size y)), 0.8 m apart; the operator's result."""
    regions = []
    for centre, (x, y) in (start, goal):
        bpy.ops.mesh.primitive_plane_add(size=1, location=centre)
        regions.append(bpy.context.active_object)
        regions[-1].scale = (x, y, 1)
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in regions)
    bpy.context.view_layer.objects.active = regions[1]
    return bpy.ops.footfall.scatter_agents(spacing=0.8, **options)


def test_a_stair_scene_loads_and_plans_with_every_agent_on_its_level():
    """Ground in "Footfall Ground": loaded from a scenario, read back with
    the agents' heights, planned; agents scattered on it; an agent over no
    ground, or off the floor of a scene without ground, refused by name with
    the scene as it was."""
    from footfall.bridge import plan_store

    fresh_scene()
    stairs = ROOT / "tests" / "data" / "stairs.json"
    given = json.loads(stairs.read_text())
    check(bpy.ops.footfall.load_scenario(filepath=str(stairs)) == {"FINISHED"}, "the stairs did not load")
    bpy.context.view_layer.update()
    ground = bpy.data.collections["Footfall Ground"].objects
    check(len(ground) == len(given["ground"]), f"{len(ground)} ground objects")
    top = max(max(v.co.z for v in o.data.vertices) + o.location.z for o in ground)
    check(abs(top - 1.02) < 1e-6, f"the landing is at {top}")
    # The agents stand on their levels: the ups on the floor, the downs on the landing.
    for agent in given["agents"]:
        z = bpy.data.objects[agent["name"]].matrix_world.translation.z
        check(abs(z - (0.0 if agent["name"].startswith("up") else 1.02)) < 1e-6, f"{agent['name']} stands at {z}")
        goal = bpy.data.objects[f"{agent['name']} goal 1"].matrix_world.translation
        check(abs(goal.z - (agent["goals"][0][2] if len(agent["goals"][0]) == 3 else 0.0)) < 1e-6,
              f"its goal at {goal}")
    document = extract()
    check(len(document["ground"]) == len(given["ground"]) and all("mesh" in g for g in document["ground"]),
          "the ground is not read back")
    check(all(len(a["position"]) == 3 for a in document["agents"]), "the agents are read without heights")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "planning the stairs failed")
    plan = plan_store.load_plan()
    check(all(a.status.name == "REACHED" for a in plan.agents), "not every agent reached")
    check(plan.ground, "the plan has no ground")
    lines = panel_lines()
    # Eight prisms of 4 corners: a top, a bottom and 4 sides of 2 triangles each.
    check(f"Ground: {len(given['ground'])} objects, {12 * len(given['ground'])} triangles" in lines, lines)
    check(any(f"on ground: {len(given['agents'])} of {len(given['agents'])} agents climb or go down" in line
              for line in lines), lines)

    # Scattered over the flight and the floor before it, facing the landing:
    # each stands on its tread (feet on footholds), its goal up on the landing.
    # x from -7 to 2: the floor and the flight.
    check(scatter_between(((-2.5, 0, 0), (9, 2.6)), ((5, 0, 1.02), (4, 2.6)), count=10, seed=3,
                          prefix="Climber") == {"FINISHED"}, "scatter on ground failed")
    ground = footfall_native().Ground(footfall_native().parse_scenario(json.dumps(extract())).ground)
    on_treads = 0
    for k in range(1, 11):
        agent = bpy.data.objects[f"Climber {k}"]
        p, q = agent.matrix_world.translation, agent.children[0].matrix_world.translation
        check(abs(p.z - ground.standing_height(p.x, p.y, 1.8)) < 1e-6, f"{agent.name} at {p} is off the ground")
        check(abs(q.z - 1.02) < 1e-6, f"{agent.name}'s goal at {q} is not on the landing")
        on_treads += 0 < p.x < 1.8
    check(on_treads > 0, "no one was scattered on the flight")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "planning the scattered climbers failed")

    bpy.data.objects["up0"].location = (30.0, 0.0, 0.0)  # off the ground's end
    bpy.context.view_layer.update()  # the plan's watch counts the change now, not during Plan
    before = inventory()
    message = operator_error(bpy.ops.footfall.plan)
    check("over no ground to stand on" in message and "is agent 'up0'" in message, message)
    after = inventory()
    check(after == before, f"a refused plan changed the scene: {[k for k in after if after[k] != before[k]]}")

    fresh_scene()
    load_good_scenario()
    check("Ground: the floor z = 0" in panel_lines(), panel_lines())
    bpy.data.objects["alice"].location.z = 0.8  # a shelf that is not ground
    message = operator_error(bpy.ops.footfall.plan)
    check("at a height of 0.80 m, but the scenario has no ground" in message and "is agent 'alice'" in message,
          message)


def test_a_bridge_scene_loads_and_plans_with_its_levels_apart():
    """tests/data/bridge.json in Blender: a footbridge's deck over a street.
    Loaded with those crossing on the bank and those under it on the street;
    one moved onto the deck stands on it (read with its height); planned, every
    one reaches on its own level; agents scattered on the deck stand on it;
    one lifted between the levels is refused naming it, the scene as it was."""
    from footfall.bridge import plan_store

    fresh_scene()
    bridge = ROOT / "tests" / "data" / "bridge.json"
    check(bpy.ops.footfall.load_scenario(filepath=str(bridge)) == {"FINISHED"}, "the bridge did not load")
    bpy.context.view_layer.update()
    for agent in json.loads(bridge.read_text())["agents"]:
        z = bpy.data.objects[agent["name"]].matrix_world.translation.z
        check(abs(z - (2.89 if agent["name"].startswith("over") else 0.0)) < 1e-6, f"{agent['name']} stands at {z}")
    bpy.data.objects["over0"].location = (-0.4, -3.5, 2.89)  # on the deck over the street (its goal too)
    bpy.context.view_layer.update()
    position = next(a["position"] for a in extract()["agents"] if a["name"] == "over0")
    check(max(abs(a - b) for a, b in zip(position, [-0.4, -3.5, 2.89])) < 1e-6, position)
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "planning the bridge failed")
    plan = plan_store.load_plan()
    check(all(a.status.name == "REACHED" for a in plan.agents), "not every agent reached")
    for agent in plan.agents:
        heights = {round(s.foot_height, 6) for s in agent.footsteps}
        check(heights == ({2.89} if agent.name.startswith("over") else {0.0}), f"{agent.name} on {heights}")

    # Scattered on the deck (a region drawn on it, over the street), bound for
    # the north bank: each stands on the deck, not on the street under it.
    check(scatter_between(((0, 0, 2.89), (1.6, 6)), ((-6, 9, 2.89), (8, 4)), count=4, seed=2,
                          prefix="Crosser") == {"FINISHED"}, "scatter on the deck failed")
    for k in range(1, 5):
        p = bpy.data.objects[f"Crosser {k}"].matrix_world.translation
        check(abs(p.z - 2.89) < 1e-6 and abs(p.x) < 1 and abs(p.y) < 4, f"Crosser {k} at {p} is not on the deck")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "planning those scattered on the deck failed")

    bpy.data.objects["under0"].location = (-0.2, -1.5, 1.4)  # under the deck, on neither level
    bpy.context.view_layer.update()
    before = inventory()
    message = operator_error(bpy.ops.footfall.plan)
    check("no ground to stand on within 0.50 m of its height 1.40 m" in message and "is agent 'under0'" in message,
          message)
    after = inventory()
    check(after == before, f"a refused plan changed the scene: {[k for k in after if after[k] != before[k]]}")


class RecordingOperator:
    """Stands in for an operator instance in a direct call of its `execute`:
    the properties it reads, and the reports it makes."""

    def __init__(self, **properties):
        self.__dict__.update(properties)
        self.reports = []

    def report(self, levels, message):
        self.reports.append((levels, message))


def test_planning_an_agent_again_where_fixed_agents_walk_names_it():
    """The agents not selected keep their plans and make way for no one: bo,
    kept at his start for 10 s, stands where ann walks once he had gone. The
    plan is stored, and the report and the panel's outcome name him."""
    from footfall.bridge import plan_store, scene_build
    from footfall.ui import scene_operators

    fresh_scene()
    scene = bpy.context.scene
    scene_build.build(scene, {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "goals": [[10, 0]], "start_delay": 3.0},
        {"name": "bo", "position": [6, 0], "facing": 1.5708, "goals": [[6, 5]]}]}, "crossing")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check("overlapping" not in scene[plan_store.OUTCOME], scene[plan_store.OUTCOME])
    bpy.data.objects["bo"]["footfall_start_delay"] = 10.0
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj.name == "bo")
    stand_in = RecordingOperator(selected_only=True)
    check(scene_operators.FOOTFALL_OT_plan.execute(stand_in, bpy.context) == {"FINISHED"}, "plan again failed")
    (levels, message), = stand_in.reports
    check(levels == {"WARNING"} and "overlapping others: 'bo' (" in message and "ann'" not in message, message)
    check("overlapping others: 'bo'" in scene[plan_store.OUTCOME], scene[plan_store.OUTCOME])
    moving = [s for s in plan_store.load_plan().agents[1].footsteps if math.dist(s.com_start, s.com_end) > 0.01]
    check(moving[0].start_time >= 9.9, f"bo's new plan was not stored: he sets off at {moving[0].start_time} s")


def test_an_agent_too_wide_for_the_door_is_named_with_where():
    """A room behind a door 0.52 m wide: 'big' (scale 1.6) needs about 0.57 m
    side-stepping, 'small' walks through with its arms in, 'stroller' walks
    outside. Plan reports a WARNING naming big and the door's width, the
    panel shows it on a line of its own, and the others reach their goals."""
    from footfall.bridge import plan_store, scene_build
    from footfall.ui import scene_operators

    def box(x0, y0, x1, y1):
        return {"polygon": [[x0, y0], [x1, y0], [x1, y1], [x0, y1]], "height": 2.2}

    fresh_scene()
    scene = bpy.context.scene
    scene_build.build(scene, {"format": "footfall-scenario", "version": 1, "obstacles": [
        box(5, -2.2, 5.2, -0.26), box(5, 0.26, 5.2, 2.2), box(5, 2, 9.2, 2.2), box(5, -2.2, 9.2, -2),
        box(9, -2.2, 9.2, 2.2)], "agents": [
        {"name": "big", "position": [1, 1], "goals": [[7.5, 1]], "scale": 1.6},
        {"name": "small", "position": [1, -1], "goals": [[7.5, -1]]},
        {"name": "stroller", "position": [0, 3.5], "goals": [[3, 4.5]]}]}, "door")
    stand_in = RecordingOperator(selected_only=False)
    check(scene_operators.FOOTFALL_OT_plan.execute(stand_in, bpy.context) == {"FINISHED"}, "plan failed")
    (levels, message), = stand_in.reports
    said = "'big' cannot reach its goal: the way at (5.10, 0.00) is 0.52 m wide, its body needs 0.57"
    check(levels == {"WARNING"} and said in message and "2/3 agents reached their goals" in message, message)
    check(any(line.startswith(said) for line in panel_lines()), panel_lines())
    plan = plan_store.load_plan()
    check([a.reason for a in plan.agents] == ["unreachable", "", ""], [a.reason for a in plan.agents])
    check(plan.agents[0].narrowest is not None and plan.agents[1].narrowest is None, "narrowest not stored")


def test_the_panel_says_how_the_crowd_is_animated():
    from footfall.bridge import scene_build

    fresh_scene()
    check(bpy.ops.footfall.import_rig(filepath=str(ROOT / "rigs" / "footfall_humanoid.glb")) == {"FINISHED"},
          "rig import failed")
    scene_build.build(bpy.context.scene, {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "goals": [[3, 0]]}, {"name": "bo", "position": [0, 2], "goals": [[3, 2]]}]},
        "two")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check(not [line for line in panel_lines() if line.startswith("Crowd:")], panel_lines())
    check(bpy.ops.footfall.apply(live=True) == {"FINISHED"}, "live apply failed")
    check("Crowd: 2 agents live (posed from the plan at each frame)" in panel_lines(), panel_lines())
    check(bpy.ops.footfall.apply() == {"FINISHED"}, "apply failed")
    check("Crowd: 2 agents keyed" in panel_lines(), panel_lines())


def test_failing_operators_report_and_cancel():
    """Every operator, of either module, fails alike: one ERROR report with the
    message, {'CANCELLED'} returned (bpy.ops raises on the report and hides what
    execute returned, so execute is called directly), and the scene as it was."""
    from footfall.ui import agent_operators, operators, scene_operators

    fresh_scene()
    bpy.ops.mesh.primitive_uv_sphere_add()  # something of the user's
    bpy.context.scene.footfall_bone_map  # reading the fields (as the panel does) stores them on the scene
    bpy.context.scene.footfall_rig
    before = inventory()
    bad = write("bad-position.json", {"format": "footfall-scenario", "version": 1,
                                      "agents": [{"name": "dan", "position": [1], "goals": [[3, 3]]}]})
    failures = (
        (scene_operators.FOOTFALL_OT_load_scenario, {"filepath": bad}, "bad-position.json: agents[0].position"),
        (scene_operators.FOOTFALL_OT_plan, {"selected_only": False}, "No agents to plan"),
        (scene_operators.FOOTFALL_OT_plan, {"selected_only": True}, "No agents selected"),
        (agent_operators.FOOTFALL_OT_randomize_agents,
         {"seed": 0, "speed_min": 1.1, "speed_max": 1.5, "scale_min": 1.0, "scale_max": 1.0, "vary_rig": False}, "No agents selected"),
        (agent_operators.FOOTFALL_OT_select_unreached, {}, "No plan: run Plan first"),
        (agent_operators.FOOTFALL_OT_set_agent_property, {"key": "footfall_speed"}, "No agent is active"),
        (operators.FOOTFALL_OT_import_rig, {"filepath": str(TMP / "missing.glb"), "armature": ""},
         "missing.glb: no such file"),
        (operators.FOOTFALL_OT_import_rig, {"filepath": "", "armature": "Sphere"},
         "armature 'Sphere': a mesh, not an armature"),
        (operators.FOOTFALL_OT_apply, {"plan_filepath": "", "rig": "", "live": False}, "No plan: run Plan first"),
        (operators.FOOTFALL_OT_apply, {"plan_filepath": "", "rig": "", "live": True}, "No plan: run Plan first"),
        (operators.FOOTFALL_OT_export_gltf, {"filepath": str(TMP / "none.glb")}, "Nothing to export"),
    )
    for operator, properties, fragment in failures:
        stand_in = RecordingOperator(**properties)
        result = operator.execute(stand_in, bpy.context)
        check(result == {"CANCELLED"}, f"{operator.bl_idname} returned {result}")
        check(len(stand_in.reports) == 1 and stand_in.reports[0][0] == {"ERROR"}
              and fragment in stand_in.reports[0][1], f"{operator.bl_idname} reported {stand_in.reports}")
        check(inventory() == before, f"a failed {operator.bl_idname} changed the scene")


CORRIDOR = {
    "format": "footfall-scenario", "version": 1,
    "obstacles": [
        {"polygon": [[0, 1], [8, 1], [8, 1.3], [0, 1.3]], "height": 2.5},      # the corridor's walls
        {"polygon": [[0, -1.3], [8, -1.3], [8, -1], [0, -1]], "height": 2.5},
        {"polygon": [[3.8, -1], [4.2, -1], [4.2, 1], [3.8, 1]], "base": 2.1, "height": 2.3},  # a beam above the head
        {"mesh": {"vertices": [[6, 0.5, 0], [6.4, 0.5, 0], [6.2, 0.9, 0], [6.2, 0.7, 0.8]],  # a tetrahedron
                  "triangles": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]}},
    ],
    "agents": [{"name": "walker", "position": [0.5, 0], "goals": [[7.5, 0]]}],
}


def test_obstacles_keep_their_shape_in_3d():
    """A beam above the head lets the corridor through, in the scene built
    from a file and in what Plan reads back; a mesh obstacle keeps its
    triangles; a vertical plane is a thin wall."""
    fresh_scene()
    check(bpy.ops.footfall.load_scenario(filepath=write("corridor.json", CORRIDOR)) == {"FINISHED"}, "load failed")
    bpy.context.view_layer.update()
    beam, tetrahedron = bpy.data.objects["Obstacle 2"], bpy.data.objects["Obstacle 3"]
    beam_z = [p.z for p in world_vertices(beam)]
    check(close((min(beam_z), max(beam_z)), (2.1, 2.3)), f"the beam from {min(beam_z)} to {max(beam_z)}")
    given = CORRIDOR["obstacles"][3]["mesh"]
    check(len(tetrahedron.data.polygons) == 4 and all(any(close(p, v) for p in world_vertices(tetrahedron))
                                                         for v in given["vertices"]), "the mesh obstacle's shape")
    scene = read()
    beam_faces = [o for o, owner in zip(scene.document["obstacles"], scene.obstacle_objects) if owner == beam.name]
    check(close(z_range(beam_faces), (2.1, 2.3)), f"the beam read from {z_range(beam_faces)}")
    covered = footprints(scene.document["obstacles"])
    check(covered((6.2, 0.65)) and not covered((6.2, 0.3)), "the tetrahedron's footprint")

    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
    from footfall.bridge import plan_store

    def widest():  # how far from the corridor's middle the walker's feet go
        walker = json.loads(plan_store.load())["agents"][0]
        check(walker["status"] == "reached", f"walker: {walker['status']}")
        return max(abs(p[1]) for p in walker["footsteps"]["foot_position"])

    check(widest() < 1, "the walker left the corridor: the beam blocked it")
    # A single vertical plane across the corridor is a thin wall: the walker goes round the outside.
    bpy.ops.mesh.primitive_plane_add(size=2.2, location=(5, 0, 1.1), rotation=(math.pi / 2, 0, math.pi / 2))
    link_to(bpy.data.collections["Footfall Obstacles"], bpy.context.active_object)
    bpy.context.view_layer.update()
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan did not finish")
    check(widest() > 1.3, "the walker went through the wall")


def test_steersuite_case_loads():
    """doorway-two-way: two agents facing each other, the walls of the door (Y-up mapped to Z-up)."""
    fresh_scene()
    check(bpy.ops.footfall.load_scenario(filepath=str(STEERSUITE / "doorway-two-way.xml")) == {"FINISHED"},
          "load failed")
    agents = bpy.data.collections["Footfall Agents"]
    a, b = bpy.data.objects["A"], bpy.data.objects["B"]
    check(a.name in agents.objects and b.name in agents.objects, "agents missing")
    check((a.location.x, a.location.y) == (-10, -1) and (b.location.x, b.location.y) == (10, -1),
          f"positions {tuple(a.location)}, {tuple(b.location)}")
    check(abs(a.rotation_euler.z) < 1e-6 and abs(abs(b.rotation_euler.z) - math.pi) < 1e-6, "facings")
    check(len(bpy.data.collections["Footfall Obstacles"].objects) == 4, "the walls of the doorway")
    # SteerSuite's agents leave at their goal; the property says so and reads back.
    check(a.get("footfall_leave_at_goal") and b.get("footfall_leave_at_goal"), "leave_at_goal not set")
    check(all(agent.get("leave_at_goal") is True for agent in extract()["agents"]), "leave_at_goal not read back")
    # Its goals' timeDuration (1000 s each) is each agent's time budget.
    check(a.get("footfall_time_limit") == 1000.0, f"time limit {a.get('footfall_time_limit')}")
    check(all(agent.get("time_limit") == 1000.0 for agent in extract()["agents"]), "time_limit not read back")
    b["footfall_leave_at_goal"] = "yes"
    try:
        extract()
        check(False, "a bad footfall_leave_at_goal was accepted")
    except ValueError as error:
        check("Agent 'B': custom property 'footfall_leave_at_goal' must be true or false" in str(error), str(error))


def test_the_overlay_draws_the_stored_plan():
    """The overlay's lines come from the stored plan, made once per plan,
    none while "Show Plan" is off; the panel shows the toggle with a plan."""
    from footfall.ui import overlay

    fresh_scene()
    load_good_scenario()
    scene = bpy.context.scene
    check(overlay.overlay_of(scene) is None, "an overlay without a plan")
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    first = overlay.overlay_of(scene)
    check(first is not None and len(first.fixed.points) > 0, "no overlay for the plan")
    check(overlay.overlay_of(scene) is first, "the overlay was made again for the same plan")
    scene.frame_set(scene.frame_start + round(scene.render.fps / scene.render.fps_base))  # a second in
    check(len(first.under_way(overlay.scene_time(scene)).points) > 0, "no step under way a second in")
    check("footfall_show_overlay" in panel_lines(), panel_lines())
    scene.footfall_show_overlay = False
    check(overlay.overlay_of(scene) is None, "an overlay while Show Plan is off")
    scene.footfall_show_overlay = True
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    check(overlay.overlay_of(scene) is not first, "a new plan kept the old overlay")


def test_the_agent_panel_sets_and_shows_an_agents_properties():
    """With an agent (or one of its goals) active, the Agent panel shows its
    properties as fields, and offers to set those it does not have; Set gives
    the agent the property at its starting value, and Plan reads it."""
    from footfall.ui.panel import FOOTFALL_PT_agent

    fresh_scene()
    load_good_scenario()
    alice = bpy.data.objects["alice"]
    bpy.context.view_layer.objects.active = bpy.data.objects["bob"]
    check(FOOTFALL_PT_agent.poll(bpy.context), "no Agent panel for an agent")
    bpy.context.view_layer.objects.active = next(c for c in alice.children)  # a goal stands for its agent
    lines = panel_lines(FOOTFALL_PT_agent)
    check(lines[0] == "alice" and "Set Speed (m/s)" in lines and "Set Size" in lines, lines)
    check(bpy.ops.footfall.set_agent_property(key="footfall_scale") == {"FINISHED"}, "set failed")
    check(alice["footfall_scale"] == 1.0, f"size {alice.get('footfall_scale')}")
    lines = panel_lines(FOOTFALL_PT_agent)
    check('["footfall_scale"]' in lines and "Set Size" not in lines, lines)
    alice["footfall_scale"] = 0.9
    check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
    from footfall.bridge import plan_store

    check({a.name: a.scale for a in plan_store.load_plan().agents}["alice"] == 0.9, "the size was not planned")
    before = inventory()
    check("not an agent property" in operator_error(bpy.ops.footfall.set_agent_property, key="footfall_mood"),
          "a made-up property was set")
    bpy.context.view_layer.objects.active = None
    check(not FOOTFALL_PT_agent.poll(bpy.context), "an Agent panel with no agent active")
    check("No agent is active" in operator_error(bpy.ops.footfall.set_agent_property, key="footfall_speed"),
          "set with no agent active")
    check(inventory() == before, "a refused set changed the scene")


def test_an_agent_turns_as_its_last_goal_is_turned():
    """A scenario's end_facing loads as the last goal empty's turn (and the
    agent's footfall_face_goal); Plan turns the agent that way at its goal,
    as the goal is turned in the scene, and not without the flag."""
    from footfall.bridge import plan_store

    fresh_scene()
    path = write("turn.json", {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "facing": 0.3, "goals": [[2, 1], [4, 0]], "end_facing": 1.2}]})
    check(bpy.ops.footfall.load_scenario(filepath=path) == {"FINISHED"}, "load failed")
    bpy.context.view_layer.update()
    ann, goal = bpy.data.objects["ann"], bpy.data.objects["ann goal 2"]
    check(bool(ann.get("footfall_face_goal")), "the flag was not set")  # 3.4 holds a bool as 1
    x_axis = goal.matrix_world.col[0]
    check(abs(math.atan2(x_axis.y, x_axis.x) - 1.2) < 1e-6, "the last goal is not turned to the end facing")
    check(abs(extract()["agents"][0]["end_facing"] - 1.2) < 1e-6, extract()["agents"][0])

    def last_phi():
        check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
        return plan_store.load_plan().agents[0].footsteps[-1].phi

    check(abs(math.remainder(last_phi() - 1.2, math.tau)) < 1e-6, "the agent did not turn to its goal's facing")
    goal.rotation_euler.z += 1.0
    bpy.context.view_layer.update()
    check(abs(math.remainder(last_phi() - 2.2, math.tau)) < 1e-6, "the agent did not follow the turned goal")
    ann["footfall_face_goal"] = False
    check(abs(math.remainder(last_phi() - 2.2, math.tau)) > 0.1, "the agent turned without the flag")


def test_an_agent_faces_a_goal_it_waits_at_as_that_goal_is_turned():
    """A scenario's goal_facings load as the goal empties' turns, each goal
    with footfall_face_goal of its own; Plan turns the agent at the first
    goal and it waits there facing that way."""
    from footfall.bridge import plan_store

    fresh_scene()
    path = write("turns.json", {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": "ann", "position": [0, 0], "goals": [[3, 0], [3, 3]], "goal_wait": 2.0,
         "goal_facings": [-1.5, None]}]})
    check(bpy.ops.footfall.load_scenario(filepath=path) == {"FINISHED"}, "load failed")
    bpy.context.view_layer.update()
    first, last = bpy.data.objects["ann goal 1"], bpy.data.objects["ann goal 2"]
    check(bool(first.get("footfall_face_goal")) and not last.get("footfall_face_goal")
          and not bpy.data.objects["ann"].get("footfall_face_goal"), "the flags are not the goals' own")
    facings = extract()["agents"][0].get("goal_facings")
    check(facings is not None and abs(facings[0] + 1.5) < 1e-6 and facings[1] is None, extract()["agents"][0])

    def waiting_phi():
        check(bpy.ops.footfall.plan() == {"FINISHED"}, "plan failed")
        steps = plan_store.load_plan().agents[0].footsteps
        return max(steps, key=lambda s: s.end_time - s.start_time).phi  # the wait is its longest step

    check(abs(math.remainder(waiting_phi() + 1.5, math.tau)) < 1e-5, "the agent does not face its goal as it waits")
    first.rotation_euler.z = 0.5
    bpy.context.view_layer.update()
    check(abs(math.remainder(waiting_phi() - 0.5, math.tau)) < 1e-5, "the agent did not follow the turned goal")


run([test_load_builds_the_conventions_and_extracts_back, test_obstacles_keep_their_shape_in_3d, test_hand_made_agents_and_obstacles_are_extracted,
     test_plan_is_stored_and_saved_with_the_file, test_the_plan_names_those_that_did_not_arrive,
     test_an_agents_own_speed_and_start, test_randomize_draws_speeds_and_rigs_for_the_selected_agents,
     test_scatter_places_agents_clear_of_obstacles_and_each_other, test_the_plan_is_out_of_date_once_the_scene_changes,
     test_errors_leave_the_scene_as_it_was, test_planning_an_agent_again_where_fixed_agents_walk_names_it,
     test_an_agent_too_wide_for_the_door_is_named_with_where,
     test_the_panel_says_how_the_crowd_is_animated,
     test_failing_operators_report_and_cancel, test_steersuite_case_loads, test_the_overlay_draws_the_stored_plan,
     test_the_agent_panel_sets_and_shows_an_agents_properties, test_an_agent_turns_as_its_last_goal_is_turned,
     test_an_agent_faces_a_goal_it_waits_at_as_that_goal_is_turned,
     test_a_stair_scene_loads_and_plans_with_every_agent_on_its_level,
     test_a_bridge_scene_loads_and_plans_with_its_levels_apart])
