# SPDX-License-Identifier: GPL-3.0-or-later
"""Adding a scenario to the Blender scene (docs/blender-scenes.md).

Each obstacle becomes a prism mesh "Obstacle N" in "Footfall Obstacles" (the
polygon extruded from the ground to its height), each agent an ARROWS empty
in "Footfall Agents" turned to its facing, with one SPHERE empty per goal
parented to it. The file's "character" and "planner" overrides replace those
of the same key in the scene's "footfall_overrides".

The scenario is validated by the core first. Either all of it is added, or
the scene is left exactly as it was.
"""

import json
import math
import pathlib

import bmesh
import bpy

from ..core import native
from ..core.scenario import document_of, parse
from . import datablocks
from .scene_extract import (AGENT_CHARACTER, AGENTS, GOAL_INDEX, GOAL_WAIT, START_DELAY, TIME_LIMIT, LEAVE_AT_GOAL, MIN_AREA, OBSTACLES, OVERRIDE_KEYS,
                            OVERRIDES, collection_in, overrides, signed_area)

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


def build(scene, document: dict, source: str = "<scenario>") -> dict:
    """Validates a scenario document with the core and adds its obstacles,
    agents and overrides to the scene; returns it with the core's defaults
    (agent names, facings, heights) filled in. `source` names it in errors."""
    complete = _complete(parse(document, source), document)
    _check(complete, source)
    given = {key: complete[key] for key in OVERRIDE_KEYS if key in complete}
    stored = overrides(scene) if given else {}
    before = datablocks.snapshot()
    linked = []
    try:
        obstacles = _collection(scene, OBSTACLES, linked)
        agents = _collection(scene, AGENTS, linked)
        # Agents first: they must get their names; obstacles and goals may take any free one.
        empties = [_add_agent(agent, agents) for agent in complete["agents"]]
        number = 0
        for obstacle in complete["obstacles"]:
            while f"Obstacle {number}" in bpy.data.objects:
                number += 1
            _add_obstacle(f"Obstacle {number}", obstacle["polygon"], obstacle["height"], obstacles)
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
    """Refuses what the core accepts but a scene cannot hold."""
    for i, obstacle in enumerate(document["obstacles"]):
        if abs(signed_area(obstacle["polygon"])) <= MIN_AREA:
            raise ScenarioError(f"{source}: obstacles[{i}].polygon: encloses no area, so it would have no "
                                "footprint in Blender (docs/blender-scenes.md)")
    for i, agent in enumerate(document["agents"]):
        name = agent["name"]
        if len(name.encode("utf-8")) > NAME_BYTES:
            raise ScenarioError(f"{source}: agents[{i}].name: longer than Blender's {NAME_BYTES}-byte object names")
        if name in bpy.data.objects:
            raise ScenarioError(f"{source}: agents[{i}].name: an object named '{name}' exists already "
                                "(an agent is the object of its name; rename one of them)")


def _collection(scene, name: str, linked: list):
    """The collection `name` of the scene; made, or linked under the scene
    collection (and appended to `linked`), if the scene has none."""
    collection = collection_in(scene, name)
    if collection is None:
        collection = bpy.data.collections.get(name) or bpy.data.collections.new(name)
        scene.collection.children.link(collection)
        linked.append(collection)
    return collection


def _add_obstacle(name: str, polygon, height: float, collection) -> None:
    """A prism: the polygon from z=0 to `height`, n-gon bottom and top,
    normals outward; the origin at the bottom centre of its bounding box."""
    ring = polygon if signed_area(polygon) > 0 else polygon[::-1]  # counter-clockwise
    cx = (min(p[0] for p in ring) + max(p[0] for p in ring)) / 2
    cy = (min(p[1] for p in ring) + max(p[1] for p in ring)) / 2
    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    try:
        bottom = [bm.verts.new((x - cx, y - cy, 0.0)) for x, y in ring]
        top = [bm.verts.new((x - cx, y - cy, height)) for x, y in ring]
        bm.faces.new(reversed(bottom))
        bm.faces.new(top)
        count = len(ring)
        for k in range(count):
            bm.faces.new((bottom[k], bottom[(k + 1) % count], top[(k + 1) % count], top[k]))
        bm.to_mesh(mesh)
    finally:
        bm.free()
    obj = bpy.data.objects.new(name, mesh)
    obj.location = (cx, cy, 0.0)
    collection.objects.link(obj)


def _add_agent(agent: dict, collection):
    """The agent's empty, its X axis along the facing."""
    obj = bpy.data.objects.new(agent["name"], None)
    obj.empty_display_type = "ARROWS"
    obj.empty_display_size = AGENT_SIZE
    obj.location = (*agent["position"], 0.0)
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
    collection.objects.link(obj)
    return obj


def _add_goals(empty, agent: dict, collection) -> None:
    """The agent's goals as child empties of its empty (identity parent
    inverse: their locations are in the agent's frame), numbered from 1."""
    x, y = agent["position"]
    cos, sin = math.cos(agent["facing"]), math.sin(agent["facing"])
    for number, (gx, gy) in enumerate(agent["goals"], start=1):
        goal = bpy.data.objects.new(f"{agent['name']} goal {number}", None)
        goal.empty_display_type = "SPHERE"
        goal.empty_display_size = GOAL_SIZE
        goal.parent = empty
        dx, dy = gx - x, gy - y
        goal.location = (cos * dx + sin * dy, -sin * dx + cos * dy, 0.0)
        goal[GOAL_INDEX] = number
        collection.objects.link(goal)
