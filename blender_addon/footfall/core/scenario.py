# SPDX-License-Identifier: GPL-3.0-or-later
"""Scenario documents from plain Python data, and planning them.

A scenario document is the scenario file format (docs/file-formats.md) as a
dict. Scenes extracted from Blender are turned into one here, then validated
and planned by the core, which names the field of any bad value.
"""

import json
from dataclasses import dataclass, field
from typing import Optional, Sequence, Tuple

from . import native

Point = Tuple[float, float]


@dataclass(frozen=True)
class AgentInput:
    """One agent: name, standing position [m] (x, y, or x, y, z: on ground,
    the height it stands at), goals [m] (likewise), facing [rad] (None:
    toward the first goal), whether it walks through its last goal and
    leaves the scene there (instead of coming to rest on it), overrides of
    the scenario's character for it alone (its own size, say), its time
    budget [s] (None: the planner's default, from max_time and its route),
    how long it stands before it sets off and at each goal but the last [s],
    its body's size as a share of the scenario's character (None: 1), and
    the facing it turns to at its last goal [rad] (None: as it arrives)."""

    name: str
    position: Point
    goals: Sequence[Point]
    facing: Optional[float] = None
    leave_at_goal: bool = False
    character: Optional[dict] = None
    time_limit: Optional[float] = None
    start_delay: Optional[float] = None
    goal_wait: Optional[float] = None
    scale: Optional[float] = None
    end_facing: Optional[float] = None
    goal_facings: Optional[Sequence[Optional[float]]] = None  # one per goal, None for none


@dataclass(frozen=True)
class ObstacleInput:
    """A polygon [m] in the ground plane, extruded from `base` to `height` [m];
    or, with `mesh` (vertices [[x, y, z], ...] [m], triangles [[i, j, k], ...]),
    that shape instead, the polygon and heights unused."""

    polygon: Sequence[Point] = ()
    height: float = 2.0
    base: float = 0.0
    mesh: Optional[Tuple[Sequence[Sequence[float]], Sequence[Sequence[int]]]] = None


@dataclass(frozen=True)
class ScenarioInput:
    """Agents, obstacles, parameter overrides and ground (field names as in the file format)."""

    agents: Sequence[AgentInput] = ()
    obstacles: Sequence[ObstacleInput] = ()
    character: dict = field(default_factory=dict)
    planner: dict = field(default_factory=dict)
    ground: Sequence[ObstacleInput] = ()  # walkable surfaces; none: the floor z = 0


def _point(p):
    """[x, y], or [x, y, z] for a point given with its height."""
    return [float(c) for c in p]


def _obstacle_entry(obstacle: ObstacleInput, default_base: float = 0.0) -> dict:
    """The file's entry of an obstacle, or of a ground surface (whose base
    defaults to min(0, height): `default_base` is then that)."""
    if obstacle.mesh is not None:
        vertices, triangles = obstacle.mesh
        return {"mesh": {"vertices": [[float(c) for c in v] for v in vertices],
                         "triangles": [[int(k) for k in t] for t in triangles]}}
    entry = {"polygon": [_point(p) for p in obstacle.polygon], "height": float(obstacle.height)}
    if obstacle.base != default_base:
        entry["base"] = float(obstacle.base)
    return entry


def _ground_entry(surface: ObstacleInput) -> dict:
    return _obstacle_entry(surface, min(0.0, surface.height))


def obstacle_input(obstacle) -> ObstacleInput:
    """The ObstacleInput of a native Obstacle (a prism or a mesh)."""
    if obstacle.is_mesh:
        return ObstacleInput(mesh=(obstacle.mesh_vertices, obstacle.mesh_triangles))
    return ObstacleInput(obstacle.polygon, obstacle.height, obstacle.base)


def scenario_document(scenario: ScenarioInput) -> dict:
    """The scenario as a document of the scenario file format."""
    agents = []
    for agent in scenario.agents:
        entry = {
            "name": agent.name,
            "position": _point(agent.position),
            "goals": [_point(g) for g in agent.goals],
        }
        if agent.facing is not None:
            entry["facing"] = float(agent.facing)
        if agent.leave_at_goal:
            entry["leave_at_goal"] = True
        if agent.character:
            entry["character"] = dict(agent.character)
        if agent.time_limit is not None:
            entry["time_limit"] = float(agent.time_limit)
        if agent.start_delay is not None:
            entry["start_delay"] = float(agent.start_delay)
        if agent.goal_wait is not None:
            entry["goal_wait"] = float(agent.goal_wait)
        if agent.scale is not None:
            entry["scale"] = float(agent.scale)
        if agent.end_facing is not None:
            entry["end_facing"] = float(agent.end_facing)
        if agent.goal_facings is not None:
            entry["goal_facings"] = [None if f is None else float(f) for f in agent.goal_facings]
        agents.append(entry)
    document = {
        "format": "footfall-scenario",
        "version": 1,
        "obstacles": [_obstacle_entry(o) for o in scenario.obstacles],
        "agents": agents,
    }
    if scenario.ground:
        document["ground"] = [_ground_entry(g) for g in scenario.ground]
    if scenario.character:
        document["character"] = dict(scenario.character)
    if scenario.planner:
        document["planner"] = dict(scenario.planner)
    return document


def _with_height(point, height):
    return tuple(point) if height is None else (*point, height)


def document_of(scenario) -> dict:
    """The document of a scenario the core has read (a native Scenario, as
    from a SteerSuite file), its agents, obstacles and ground; parameters at
    their defaults. Points keep the heights they were given with."""
    def goals(a):
        heights = list(a.goal_heights) or [None] * len(a.goals)
        return [_with_height(g, h) for g, h in zip(a.goals, heights)]

    return scenario_document(ScenarioInput(
        agents=[AgentInput(a.name, _with_height(a.position, a.height), goals(a), a.facing, a.leave_at_goal,
                           time_limit=a.time_limit or None,
                           start_delay=a.start_delay or None, goal_wait=a.goal_wait or None,
                           scale=None if a.scale == 1.0 else a.scale, end_facing=a.end_facing,
                           goal_facings=list(a.goal_facings) or None)
                for a in scenario.agents],
        obstacles=[obstacle_input(o) for o in scenario.obstacles],
        ground=[obstacle_input(g) for g in scenario.ground]))


def parse(document: dict, source: str = "<scene>"):
    """Validates a document with the core; returns its native Scenario.

    Raises ValueError "SOURCE: FIELD.PATH: problem" for bad input. Non-finite
    numbers are passed through so that the core can name their field.
    """
    return native.load().parse_scenario(json.dumps(document, allow_nan=True), source)


def plan(document: dict, source: str = "<scene>", progress=None, cancel=None, threads: int = 1):
    """Validates and plans a document on `threads` threads (the plan is the
    same for any number); returns the native Plan."""
    core = native.load()
    return core.plan_scenario(parse(document, source), progress=progress, cancel=cancel, threads=threads)


def replan(document: dict, fixed, names, source: str = "<scene>", progress=None, cancel=None, threads: int = 1):
    """Validates a document and plans the agents `names` again among the
    others, which keep their plans in `fixed` (a native Plan); returns the
    native Plan of every agent. ValueError "agents: ..." or "fixed: ..." names
    an unknown agent, or one neither named nor in `fixed`."""
    core = native.load()
    return core.replan_agents(parse(document, source), fixed, list(names), progress=progress, cancel=cancel,
                              threads=threads)
