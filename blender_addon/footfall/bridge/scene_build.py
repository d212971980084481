# SPDX-License-Identifier: GPL-3.0-or-later
"""Adding a scenario to the Blender scene (docs/blender-scenes.md).

Each obstacle becomes a mesh "Obstacle N" in "Footfall Obstacles" (a prism's
polygon extruded from its base to its height, or a mesh obstacle's
triangles), each ground surface a mesh "Ground N" in "Footfall Ground"
(likewise), each agent an ARROWS empty in "Footfall Agents" turned to its
facing, standing on its ground (at the height given, else on the only ground
under it), with one SPHERE empty per goal parented to it, likewise on its
ground. The file's "character" and "planner" overrides replace those of the
same key in the scene's "footfall_overrides".

The scenario is validated by the core first. Either all of it is added, or
the scene is left exactly as it was.
"""

import json
import math
import pathlib
from typing import Sequence

import bpy

from ..core import native
from ..core.scenario import document_of, parse
from . import datablocks
from .scene_extract import (AGENT_CHARACTER, AGENT_SCALE, AGENTS, FACE_GOAL, GOAL_INDEX, GOAL_WAIT, GROUND, START_DELAY,
                            TIME_LIMIT, LEAVE_AT_GOAL, OBSTACLES, OVERRIDE_KEYS, OVERRIDES, collection_in, overrides)

AGENT_SIZE = 0.5  # [m] length of the agent empty's arrows
GOAL_SIZE = 0.25  # [m] radius of the goal spheres
NAME_BYTES = 63  # Blender shortens longer object names


class ScenarioError(ValueError):
    """The scenario cannot be added to the scene; the message names the file and the field."""


def load_file(scene, path: str) -> dict:
    """Validates the scenario file `path` with the core and adds it to the
    scene; returns the document added, with the core's defaults filled in.

    Raises ValueError "PATH: FIELD.PATH: problem" (ScenarioError for what
    the core accepts but the scene cannot hold)."""
    if pathlib.Path(path).suffix.lower() == ".xml":  # a SteerSuite test case, read by the core
        return build(scene, document_of(native.load().load_steersuite(path)), path)
    native.load().load_scenario(path)  # the core's messages: malformed JSON with line and column
    with open(path, encoding="utf-8") as file:
        document = json.load(file)
    return build(scene, document, path)


def build(scene, document: dict, source: str = "<scenario>", scene_ground: bool = False) -> dict:
    """Validates a scenario document with the core and adds its obstacles,
    ground, agents and overrides to the scene; returns it with the core's
    defaults (agent names, facings, heights) filled in. `source` names it in
    errors. `scene_ground`: the document's ground is the scene's already, to
    stand its agents on, not to add."""
    scenario = parse(document, source)
    complete = _complete(scenario, document)
    _check(complete, source)
    _heights(complete, scenario)
    given = {key: complete[key] for key in OVERRIDE_KEYS if key in complete}
    stored = overrides(scene) if given else {}
    before = datablocks.snapshot()
    linked = []
    try:
        obstacles = _collection(scene, OBSTACLES, linked)
        agents = _collection(scene, AGENTS, linked)
        # Agents first: they must get their names; obstacles and goals may take any free one.
        empties = [_add_agent(agent, agents) for agent in complete["agents"]]
        _add_shapes("Obstacle", complete["obstacles"], obstacles)
        if complete.get("ground") and not scene_ground:
            _add_shapes("Ground", complete["ground"], _collection(scene, GROUND, linked))
        for empty, agent in zip(empties, complete["agents"]):
            _add_goals(empty, agent, agents)
    except BaseException:
        for collection in linked:
            scene.collection.children.unlink(collection)
        datablocks.remove_new(before)
        raise
    # Last, so that nothing above can fail after the property changed.
    if given:
        scene[OVERRIDES] = json.dumps({**stored, **given})
    return complete


def _complete(scenario, document: dict) -> dict:
    """The document as the core read it: every default filled in."""
    complete = document_of(scenario)
    complete.update({key: document[key] for key in ("character", "planner") if document.get(key)})
    for read, given in zip(complete["agents"], document.get("agents", [])):
        if given.get("character"):
            read["character"] = given["character"]
    return complete


def _check(document: dict, source: str) -> None:
    """Refuses what the core accepts (in `document`) but a scene cannot hold."""
    for i, agent in enumerate(document["agents"]):
        name = agent["name"]
        if len(name.encode("utf-8")) > NAME_BYTES:
            raise ScenarioError(f"{source}: agents[{i}].name: longer than Blender's {NAME_BYTES}-byte object names")
        if name in bpy.data.objects:
            raise ScenarioError(f"{source}: agents[{i}].name: an object named '{name}' exists already "
                                "(an agent is the object of its name; rename one of them)")


def _heights(document: dict, scenario) -> None:
    """Every point of the agents as [x, y, z], on its ground: on the level
    nearest the height it was given with (the core has checked that one lies
    within 0.5 m of it), else on the only ground under it; without ground on
    the floor, z = 0 (the core has checked that a height given lies within
    0.5 m of it)."""
    ground = native.load().Ground(scenario.ground)

    def placed(point, headroom):
        if ground.empty():
            return [point[0], point[1], 0.0]
        near = point[2] if len(point) == 3 else None
        return [point[0], point[1], ground.standing_height(point[0], point[1], headroom, near)]

    for agent, spec in zip(document["agents"], scenario.agents):
        headroom = (spec.character or scenario.character).body_height
        agent["position"] = placed(agent["position"], headroom)
        agent["goals"] = [placed(goal, headroom) for goal in agent["goals"]]


def _collection(scene, name: str, linked: list):
    """The collection `name` of the scene; made, or linked under the scene
    collection (and appended to `linked`), if the scene has none."""
    collection = collection_in(scene, name)
    if collection is None:
        collection = bpy.data.collections.get(name) or bpy.data.collections.new(name)
        scene.collection.children.link(collection)
        linked.append(collection)
    return collection


def _add_shapes(prefix: str, shapes, collection) -> None:
    """A mesh object "PREFIX N" (the first free numbers) for each of `shapes`."""
    number = 0
    for shape in shapes:
        while f"{prefix} {number}" in bpy.data.objects:
            number += 1
        _add_shape(f"{prefix} {number}", shape, collection)


def _add_shape(name: str, shape: dict, collection) -> None:
    """A mesh object for an obstacle or a ground surface of the document: its
    mesh as given, or its prism (the polygon from `base` to `height`, n-gon
    bottom and top, normals outward); the origin at the bottom centre of its
    bounding box."""
    if "mesh" in shape:
        points = [tuple(v) for v in shape["mesh"]["vertices"]]
        faces = [tuple(t) for t in shape["mesh"]["triangles"]]
    else:
        # An obstacle's base defaults to 0, a ground surface's to min(0, height): the same for both.
        points, faces = _prism(shape["polygon"], shape.get("base", min(0.0, shape["height"])), shape["height"])
    origin = [(min(p[axis] for p in points) + max(p[axis] for p in points)) / 2 for axis in (0, 1)]
    origin.append(min(p[2] for p in points))
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(c - o for c, o in zip(p, origin)) for p in points], [], faces)
    mesh.validate()  # drops what Blender cannot hold (a triangle naming one vertex twice)
    obj = bpy.data.objects.new(name, mesh)
    obj.location = origin
    collection.objects.link(obj)


def _signed_area(polygon: Sequence[Sequence[float]]) -> float:
    """Area of a polygon in the XY plane [m²]: positive counter-clockwise."""
    count = len(polygon)
    return 0.5 * sum(polygon[k][0] * polygon[(k + 1) % count][1] - polygon[(k + 1) % count][0] * polygon[k][1]
                     for k in range(count))


def _prism(polygon, base: float, height: float):
    """The vertices and faces of `polygon` extruded from `base` to `height`."""
    ring = polygon if _signed_area(polygon) > 0 else polygon[::-1]  # counter-clockwise
    count = len(ring)
    points = [(x, y, base) for x, y in ring] + [(x, y, height) for x, y in ring]
    faces = [tuple(reversed(range(count))), tuple(range(count, 2 * count))]
    faces += [(k, (k + 1) % count, count + (k + 1) % count, count + k) for k in range(count)]
    return points, faces


def _add_agent(agent: dict, collection):
    """The agent's empty, its X axis along the facing."""
    obj = bpy.data.objects.new(agent["name"], None)
    obj.empty_display_type = "ARROWS"
    obj.empty_display_size = AGENT_SIZE
    obj.location = agent["position"]
    obj.rotation_euler = (0.0, 0.0, agent["facing"])
    if agent.get("leave_at_goal"):
        obj[LEAVE_AT_GOAL] = True
    if agent.get("character"):
        obj[AGENT_CHARACTER] = json.dumps(agent["character"])
    if agent.get("time_limit"):
        obj[TIME_LIMIT] = float(agent["time_limit"])
    if agent.get("start_delay"):
        obj[START_DELAY] = float(agent["start_delay"])
    if agent.get("goal_wait"):
        obj[GOAL_WAIT] = float(agent["goal_wait"])
    if agent.get("scale"):
        obj[AGENT_SCALE] = float(agent["scale"])
    if agent.get("end_facing") is not None:
        obj[FACE_GOAL] = True
    collection.objects.link(obj)
    return obj


def _add_goals(empty, agent: dict, collection) -> None:
    """The agent's goals as child empties of its empty (identity parent
    inverse: their locations are in the agent's frame), numbered from 1."""
    x, y, z = agent["position"]
    cos, sin = math.cos(agent["facing"]), math.sin(agent["facing"])
    facings = list(agent.get("goal_facings") or [None] * len(agent["goals"]))
    if agent.get("end_facing") is not None:
        facings[-1] = agent["end_facing"]
    for number, (gx, gy, gz) in enumerate(agent["goals"], start=1):
        goal = bpy.data.objects.new(f"{agent['name']} goal {number}", None)
        goal.empty_display_type = "SPHERE"
        goal.empty_display_size = GOAL_SIZE
        goal.parent = empty
        dx, dy = gx - x, gy - y
        goal.location = (cos * dx + sin * dy, -sin * dx + cos * dy, gz - z)
        facing = facings[number - 1]
        if facing is not None:
            goal.rotation_euler = (0.0, 0.0, facing - agent["facing"])  # in the agent's frame
            if number < len(facings) or agent.get("end_facing") is None:
                goal[FACE_GOAL] = True  # the agent's own flag stands for its last goal's end_facing
        goal[GOAL_INDEX] = number
        collection.objects.link(goal)
