# SPDX-License-Identifier: GPL-3.0-or-later
"""Reading the Blender scene back into a scenario document
(docs/blender-scenes.md). Pure reading: nothing in the scene changes.

Only objects in the three Footfall collections (or collections inside them)
count, hidden ones included:

- every MESH object in "Footfall Obstacles" gives one mesh obstacle per face
  of its evaluated mesh (modifiers applied), in world space: its footprint is
  the face seen from above, its surface the face in 3-D;
- every MESH object in "Footfall Ground" gives one ground surface, its
  evaluated mesh in world space: its faces facing up are walked on, and all
  of it is solid. Without any, the floor is z = 0;
- every EMPTY in "Footfall Agents" whose parent is not an agent is an agent:
  its name (its custom property "footfall_agent_name" if it has one: Apply
  names the rig instance after the agent and the empty "NAME (agent)"),
  world position and world rotation about Z (the height goes with the
  position where the scene has ground, or where it is not 0: the core
  refuses one off the floor); its child EMPTYs in that
  collection are its goals, by "footfall_goal_index", then by name; its
  custom properties "footfall_leave_at_goal" (true: it walks through its last
  goal and leaves the scene there), "footfall_time_limit" (its time budget
  in seconds; the core checks the range), "footfall_start_delay" and
  "footfall_wait" (seconds it stands before setting off, and at each goal
  but the last), "footfall_speed" (its preferred
  speed, m/s), "footfall_scale" (its body's size as a share of the
  character's, which Apply scales its rig by), "footfall_face_goal" (true:
  at its last goal it turns to face where that goal empty's X axis points),
  "footfall_character" (JSON text:
  overrides of the character for it alone) and "footfall_rig" (the name of
  the imported rig it is animated with, which sizes its character) are
  optional.

The scene's custom property "footfall_overrides" holds the "character" and
"planner" overrides as JSON text.
"""

import json
import math
import re
from dataclasses import dataclass, field
from typing import Dict, List

import bpy
import numpy as np

from ..core.scenario import AgentInput, ObstacleInput, ScenarioInput, scenario_document

OBSTACLES = "Footfall Obstacles"
GROUND = "Footfall Ground"
AGENTS = "Footfall Agents"
GOAL_INDEX = "footfall_goal_index"
LEAVE_AT_GOAL = "footfall_leave_at_goal"
AGENT_NAME = "footfall_agent_name"
AGENT_CHARACTER = "footfall_character"
AGENT_SPEED = "footfall_speed"
TIME_LIMIT = "footfall_time_limit"
START_DELAY = "footfall_start_delay"
GOAL_WAIT = "footfall_wait"
AGENT_SCALE = "footfall_scale"
FACE_GOAL = "footfall_face_goal"
AGENT_RIG = "footfall_rig"
OVERRIDES = "footfall_overrides"
OVERRIDE_KEYS = ("character", "planner")


class SceneError(ValueError):
    """The scene cannot be read as a scenario; the message names the object."""


@dataclass(frozen=True)
class SceneScenario:
    """The scene as a scenario document, and for each obstacle the name of
    the object whose face it is."""

    document: dict
    obstacle_objects: List[str]
    agent_rigs: Dict[str, str] = field(default_factory=dict)  # agent -> its custom property AGENT_RIG
    ground_objects: List[str] = field(default_factory=list)  # per ground surface, its object

    def locate(self, message: str) -> str:
        """The core's error `message` with the objects behind the
        agents[i], obstacles[i] and ground[i] that it names."""
        notes = []
        for kind, index in dict.fromkeys(re.findall(r"\b(agents|obstacles|ground)\[(\d+)\]", message)):
            if kind == "agents":
                notes.append(f"{kind}[{index}] is agent '{self.document['agents'][int(index)]['name']}'")
            elif kind == "ground":
                notes.append(f"{kind}[{index}] is '{self.ground_objects[int(index)]}'")
            else:
                notes.append(f"{kind}[{index}] is a face of '{self.obstacle_objects[int(index)]}'")
        return f"{message} ({'; '.join(notes)})" if notes else message


def collection_in(scene, name: str):
    """The collection `name` if it is in the scene's hierarchy, else None."""
    return next((c for c in scene.collection.children_recursive if c.name == name), None)


def _members(scene, name: str) -> list:
    collection = collection_in(scene, name)
    return list(collection.all_objects) if collection else []


def overrides(scene) -> dict:
    """The parameter overrides stored on the scene ({"character": {...},
    "planner": {...}}, either may be missing); their values are checked by
    the core when planning."""
    text = scene.get(OVERRIDES)
    if text is None:
        return {}
    where = f"Scene '{scene.name}', custom property '{OVERRIDES}'"
    if not isinstance(text, str):
        raise SceneError(f"{where}: must be JSON text, got {type(text).__name__}")
    try:
        value = json.loads(text)
    except json.JSONDecodeError as error:
        raise SceneError(f"{where}: not valid JSON: {error}") from error
    if not (isinstance(value, dict) and set(value) <= set(OVERRIDE_KEYS)
            and all(isinstance(v, dict) for v in value.values())):
        raise SceneError(f"{where}: must be a JSON object with a 'character' and/or a 'planner' object, got {text}")
    return value


def _point(vector, with_height: bool) -> List[float]:
    """[x, y], or [x, y, z] where the scene has ground or z is not 0."""
    if with_height or vector.z != 0.0:
        return [float(vector.x), float(vector.y), float(vector.z)]
    return [float(vector.x), float(vector.y)]


def _goal_order(goal):
    """Sort key: goals with an index first, by index, then the others by name."""
    index = goal.get(GOAL_INDEX)
    if index is None:
        return (1, 0, goal.name)
    if isinstance(index, float) and index.is_integer():  # the UI makes float properties by default
        index = int(index)
    if not isinstance(index, int):
        raise SceneError(f"Goal '{goal.name}': custom property '{GOAL_INDEX}' must be an integer, got {index!r}")
    return (0, index, goal.name)


def agent_name(agent) -> str:
    """The agent's name: its custom property AGENT_NAME, else the empty's name."""
    name = agent.get(AGENT_NAME, agent.name)
    if not isinstance(name, str) or not name:
        raise SceneError(f"Agent '{agent.name}': custom property '{AGENT_NAME}' must be a name, got {name!r}")
    return name


def _agent_objects(objects) -> list:
    """The agents among `objects`: empties whose parent is not an agent."""
    empties = {o for o in objects if o.type == "EMPTY"}

    def is_agent(obj):
        return obj in empties and not (obj.parent is not None and is_agent(obj.parent))

    return sorted(filter(is_agent, empties), key=agent_name)


def _agents(objects, depsgraph, on_ground: bool) -> List[AgentInput]:
    empties = {o for o in objects if o.type == "EMPTY"}
    agents = []
    for agent in _agent_objects(objects):
        goals = sorted((child for child in agent.children if child in empties), key=_goal_order)
        if not goals:
            raise SceneError(f"Agent '{agent.name}' has no goals: parent one or more empties to it "
                             f"in '{AGENTS}' (docs/blender-scenes.md)")
        world = agent.evaluated_get(depsgraph).matrix_world
        agents.append(AgentInput(
            name=agent_name(agent),
            position=_point(world.translation, on_ground),
            goals=[_point(goal.evaluated_get(depsgraph).matrix_world.translation, on_ground) for goal in goals],
            facing=_facing(world),
            leave_at_goal=_flag(agent, LEAVE_AT_GOAL),
            character=_own_character(agent),
            time_limit=_number(agent, TIME_LIMIT, "seconds"),
            start_delay=_number(agent, START_DELAY, "seconds"),
            goal_wait=_number(agent, GOAL_WAIT, "seconds"),
            scale=_number(agent, AGENT_SCALE, "times the character's size"),
            **_goal_facings(agent, goals, depsgraph),
        ))
    return agents


def _goal_facings(agent, goals, depsgraph) -> dict:
    """The facings at the agent's goals: a goal empty's turn where the agent
    (for its last goal) or the goal itself has FACE_GOAL; as end_facing when
    only the last goal has one."""
    facings = [_facing(goal.evaluated_get(depsgraph).matrix_world)
               if _flag(goal, FACE_GOAL) or (goal is goals[-1] and _flag(agent, FACE_GOAL)) else None
               for goal in goals]
    if all(f is None for f in facings[:-1]):
        return {"end_facing": facings[-1]}
    return {"goal_facings": facings}


def agent_empties(scene) -> Dict[str, object]:
    """The scene's agent empties by agent name."""
    return {agent_name(o): o for o in _agent_objects(_members(scene, AGENTS))}


def _number(agent, prop: str, unit: str):
    """The agent's custom property `prop` as a number, None if it has none
    (its range is the core's to check)."""
    value = agent.get(prop)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"Agent '{agent.name}': custom property '{prop}' must be a number of {unit}, got {value!r}")
    return float(value)


def _own_character(agent):
    """The agent's character overrides: its preferred speed, and what its
    JSON text sets (which wins)."""
    speed = _number(agent, AGENT_SPEED, "metres per second")
    value = {} if speed is None else {"preferred_speed": speed}
    text = agent.get(AGENT_CHARACTER)
    if text is None:
        return value or None
    where = f"Agent '{agent.name}': custom property '{AGENT_CHARACTER}'"
    try:
        given = json.loads(text) if isinstance(text, str) else None
    except json.JSONDecodeError as error:
        raise SceneError(f"{where}: not valid JSON: {error}") from error
    if not isinstance(given, dict):
        raise SceneError(f"{where}: must be JSON text of an object of character fields, got {text!r}")
    return {**value, **given}


def _rig_names(objects) -> Dict[str, str]:
    rigs = {}
    for agent in _agent_objects(objects):
        name = agent.get(AGENT_RIG)
        if name is None:
            continue
        if not isinstance(name, str) or not name:
            raise SceneError(f"Agent '{agent.name}': custom property '{AGENT_RIG}' must be a rig's name, got {name!r}")
        rigs[agent_name(agent)] = name
    return rigs


def _flag(agent, prop: str) -> bool:
    value = agent.get(prop, False)
    if value not in (True, False, 0, 1):
        raise SceneError(f"Agent '{agent.name}': custom property '{prop}' must be true or false, got {value!r}")
    return bool(value)


def _facing(world) -> float:
    """Where an object's local X axis points, seen from above [rad]."""
    return math.atan2(world[1][0], world[0][0])


@dataclass(frozen=True)
class WorldMesh:
    """An object's evaluated mesh in world space, as arrays."""

    points: np.ndarray  # (vertices, 3) [m]
    triangles: np.ndarray  # (triangles, 3) vertex indices
    triangle_faces: np.ndarray  # (triangles,) the face each triangle is of
    loop_starts: np.ndarray  # (faces,) each face's first corner in loop_vertices
    loop_vertices: np.ndarray  # (corners,) vertex indices, face after face


def world_mesh(obj, depsgraph) -> WorldMesh:
    """The object's evaluated mesh (modifiers applied) in world space, read
    in bulk (foreach_get)."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        triangles = _read(mesh.loop_triangles, "vertices", 3, np.int32).reshape(-1, 3)
        triangle_faces = _read(mesh.loop_triangles, "polygon_index", 1, np.int32)
        loop_starts = _read(mesh.polygons, "loop_start", 1, np.int32)
        loop_vertices = _read(mesh.loops, "vertex_index", 1, np.int32)
        local = _read(mesh.vertices, "co", 3, np.float32)  # Blender keeps single precision
        world = np.array(evaluated.matrix_world, dtype=np.float64)
    finally:
        evaluated.to_mesh_clear()
    points = local.reshape(-1, 3).astype(np.float64) @ world[:3, :3].T + world[:3, 3]
    return WorldMesh(points, triangles, triangle_faces, loop_starts, loop_vertices)


def _read(collection, attribute: str, width: int, dtype) -> np.ndarray:
    values = np.empty(width * len(collection), dtype=dtype)
    collection.foreach_get(attribute, values)
    return values


def _faces(obj, depsgraph) -> List[ObstacleInput]:
    """The object's evaluated faces in world space, one mesh obstacle each
    (a face whose outline seen from above is concave, one per triangle): the
    core's footprint of a mesh is its hull, which is then the face's own
    outline (a segment for a face on edge), and the full-body planner meets
    the real surfaces in 3-D."""
    mesh = world_mesh(obj, depsgraph)
    if len(mesh.triangles) == 0:
        raise SceneError(f"Obstacle '{obj.name}' has no faces: Footfall reads an obstacle's faces "
                         f"(fill its outline, or give a wall a thickness)")
    convex = _convex_from_above(mesh.points[:, :2], mesh.loop_starts, mesh.loop_vertices)
    # Triangles of a convex face share its key; those of a concave one get their own.
    faces = mesh.triangle_faces
    keys = np.where(convex[faces], faces, len(convex) + np.arange(len(faces)))
    order = np.argsort(keys, kind="stable")
    groups = np.split(mesh.triangles[order], np.flatnonzero(np.diff(keys[order])) + 1)
    obstacles = []
    for triangles in groups:
        used, local_triangles = np.unique(triangles, return_inverse=True)
        obstacles.append(ObstacleInput(mesh=(mesh.points[used].tolist(), local_triangles.reshape(-1, 3).tolist())))
    return obstacles


def _convex_from_above(xy: np.ndarray, loop_starts: np.ndarray, loop_vertices: np.ndarray) -> np.ndarray:
    """Per face: true if its outline seen from above turns one way only (a
    face on edge, all straight, counts as convex)."""
    totals = np.diff(np.append(loop_starts, len(loop_vertices)))
    face_of_loop = np.repeat(np.arange(len(loop_starts)), totals)
    loop = np.arange(len(loop_vertices))
    start, total = loop_starts[face_of_loop], totals[face_of_loop]
    here = xy[loop_vertices]
    ahead = xy[loop_vertices[start + (loop - start + 1) % total]] - here
    behind = here - xy[loop_vertices[start + (loop - start - 1) % total]]
    turn = behind[:, 0] * ahead[:, 1] - behind[:, 1] * ahead[:, 0]
    slack = 1e-9 * np.linalg.norm(ahead, axis=1) * np.linalg.norm(behind, axis=1)
    left = np.logical_or.reduceat(turn > slack, loop_starts)
    right = np.logical_or.reduceat(turn < -slack, loop_starts)
    return ~(left & right)


def _obstacles(objects, depsgraph):
    obstacles, owners = [], []
    for obj in sorted((o for o in objects if o.type == "MESH"), key=lambda o: o.name):
        faces = _faces(obj, depsgraph)
        obstacles += faces
        owners += [obj.name] * len(faces)
    return obstacles, owners


def _ground(objects, depsgraph):
    """Per MESH object, its evaluated mesh in world space as one ground surface; and their names."""
    ground, owners = [], []
    for obj in sorted((o for o in objects if o.type == "MESH"), key=lambda o: o.name):
        mesh = world_mesh(obj, depsgraph)
        if len(mesh.triangles) == 0:
            raise SceneError(f"Ground '{obj.name}' has no faces: Footfall walks on a ground object's faces")
        ground.append(ObstacleInput(mesh=(mesh.points.tolist(), mesh.triangles.tolist())))
        owners.append(obj.name)
    return ground, owners


def _depsgraph(scene):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    if depsgraph.scene != scene:
        raise SceneError(f"Scene '{scene.name}' is not the active scene; only the active scene can be read")
    return depsgraph


def read_obstacles(scene):
    """The scene's obstacles (ObstacleInput), and for each the name of the
    object whose face it is."""
    return _obstacles(_members(scene, OBSTACLES), _depsgraph(scene))


def read_ground(scene):
    """The scene's ground surfaces (ObstacleInput), and for each its object's name."""
    return _ground(_members(scene, GROUND), _depsgraph(scene))


def read(scene) -> SceneScenario:
    """The scene as a scenario document, with the objects behind its
    obstacles. Raises SceneError naming the object that cannot be read."""
    depsgraph = _depsgraph(scene)
    obstacles, owners = _obstacles(_members(scene, OBSTACLES), depsgraph)
    ground, ground_owners = _ground(_members(scene, GROUND), depsgraph)
    members = _members(scene, AGENTS)
    agents = _agents(members, depsgraph, bool(ground))
    params = overrides(scene)
    document = scenario_document(ScenarioInput(agents=agents, obstacles=obstacles, ground=ground,
                                               character=params.get("character", {}),
                                               planner=params.get("planner", {})))
    return SceneScenario(document, owners, _rig_names(members), ground_owners)


def extract(scene) -> dict:
    """The scene as a scenario document (docs/file-formats.md)."""
    return read(scene).document
