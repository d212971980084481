# SPDX-License-Identifier: GPL-3.0-or-later
"""Agents scattered at random: N agents standing in one region (a mesh seen
from above), each with a goal in a second region, clear of the obstacles
(their parts below the body's height) and of every agent, new or already in
the scene. On a scene's ground ("Footfall Ground") each stands, and each goal
lies, on the ground under it, at its height, where a body can stand (both
feet on footholds, facing its goal). The same seed, regions and scene give
the same agents."""

import math
from typing import List

import bpy
import numpy as np

from ..core import native
from ..core.scenario import ScenarioInput, scenario_document
from . import scene_build
from .scene_extract import SceneError, agent_empties, overrides, read_ground, read_obstacles, world_mesh

TRIES_PER_AGENT = 200  # draws before a crowded region is given up


def scatter(scene, start_region, goal_region, count: int, seed: int, spacing: float, prefix: str) -> List[str]:
    """Adds `count` agents named PREFIX 1, PREFIX 2, ... (the next free
    numbers) standing in `start_region`, each facing its goal in
    `goal_region` (mesh objects); agents stand, and goals lie, at least
    `spacing` apart. Returns their names. Raises SceneError, changing nothing,
    when a region is no mesh or is an obstacle, or holds fewer than `count`."""
    obstacles, owners = read_obstacles(scene)
    for role, region in (("start", start_region), ("goal", goal_region)):
        if region is None or region.type != "MESH":
            raise SceneError(f"The {role} region must be a mesh object (seen from above)")
        if region.name in owners:
            raise SceneError(f"Region '{region.name}' is an obstacle: a region is a mesh outside "
                             f"'Footfall Obstacles' (a floor plane, say)")
    core = native.load()
    character = core.CharacterParams()
    for key, value in overrides(scene).get("character", {}).items():
        if key in ("torso_width", "body_height"):
            setattr(character, key, value)
    blocked = core.ObstacleMap([_native_obstacle(core, o) for o in obstacles], character.body_height)
    clearance = max(spacing / 2, character.torso_width / 2)  # the standing body's shoulders
    rng = np.random.default_rng(seed)
    standing = [tuple(empty.matrix_world.translation.xy) for empty in agent_empties(scene).values()]
    surfaces = read_ground(scene)[0]
    if surfaces:
        starts, goals = _draw_on_ground(rng, core.Ground([_native_obstacle(core, g) for g in surfaces]), character,
                                        start_region, goal_region, count, spacing, clearance, blocked, core, standing)
    else:
        starts = [p[:2] for p in _draw(rng, _triangles_from_above(start_region), count, spacing, clearance, blocked,
                                       core, standing, start_region.name)]
        goals = [p[:2] for p in _draw(rng, _triangles_from_above(goal_region), count, spacing, clearance, blocked,
                                      core, [], goal_region.name)]
    names = _free_names(prefix, count)
    document = {"format": "footfall-scenario", "version": 1, "agents": [
        {"name": name, "position": list(start), "goals": [list(goal)],
         "facing": _facing(start, goal)}
        for name, start, goal in zip(names, starts, goals)]}
    if surfaces:  # for the core to judge where they stand
        document["ground"] = scenario_document(ScenarioInput(ground=surfaces))["ground"]
    try:
        scene_build.build(scene, document, "scatter_agents", scene_ground=True)
    except ValueError as error:  # what the core refuses: named, nothing added
        raise SceneError(str(error)) from error
    return names


def _facing(start, goal) -> float:
    return math.atan2(goal[1] - start[1], goal[0] - start[0])


def _draw_on_ground(rng, ground, character, start_region, goal_region, count, spacing, clearance, blocked, core,
                    taken):
    """(starts, goals) as _draw's, on `ground` (x, y, z): the goals drawn
    first where a body stands, then each start where a body stands facing its
    goal; each on the level of ground nearest its region there (the deck of a
    bridge, for a region drawn on it; the street, for one drawn under it)."""
    def height(point):
        return ground.standing_height(point[0], point[1], character.body_height, point[2])

    def stands_facing_goal(point, k):
        z = height(point)
        return z is not None and ground.standing_problem(
            character, point[0], point[1], _facing(point, goals[k]), z) is None

    goals = _draw(rng, _triangles_from_above(goal_region), count, spacing, clearance, blocked, core, [],
                  goal_region.name, lambda point, _: height(point) is not None)
    starts = _draw(rng, _triangles_from_above(start_region), count, spacing, clearance, blocked, core, taken,
                   start_region.name, stands_facing_goal)
    return ([(*p[:2], height(p)) for p in starts], [(*p[:2], height(p)) for p in goals])


def _native_obstacle(core, obstacle):
    if obstacle.mesh is not None:
        return core.Obstacle.from_mesh(*obstacle.mesh)
    return core.Obstacle(obstacle.polygon, obstacle.height, obstacle.base)


def _triangles_from_above(region) -> np.ndarray:
    """The region's evaluated triangles in the world, shape (n, 3, 3), those
    seen edge-on from above left out."""
    mesh = world_mesh(region, bpy.context.evaluated_depsgraph_get())
    triangles = mesh.points[mesh.triangles]
    area = np.abs(_cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]))
    triangles = triangles[area > 1e-12]
    if len(triangles) == 0:
        raise SceneError(f"Region '{region.name}' covers no area seen from above")
    return triangles


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _draw(rng, triangles, count, spacing, clearance, blocked, core, taken, region_name, stands=None):
    """`count` points (x, y, z) drawn uniformly over `triangles` seen from
    above, each clear of the obstacles by `clearance` and `spacing` from the
    others and from `taken` (points in plan), and, given `stands`, where
    stands(point, how many drawn before) holds."""
    area = np.abs(_cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]))
    weights = area / area.sum()
    points, others = [], list(taken)
    for _ in range(TRIES_PER_AGENT * count):
        if len(points) == count:
            break
        a, b, c = triangles[rng.choice(len(triangles), p=weights)]
        u, v = rng.random(2)
        if u + v > 1:
            u, v = 1 - u, 1 - v
        point = a + u * (b - a) + v * (c - a)
        if any(math.dist(point[:2], other[:2]) < spacing for other in others):
            continue
        if blocked.overlaps(core.Circle(tuple(point[:2]), clearance)):
            continue
        point = tuple(round(float(coordinate), 6) for coordinate in point)
        if stands is not None and not stands(point, len(points)):
            continue
        points.append(point)
        others.append(point)
    if len(points) < count:
        ground = " on ground they can stand on" if stands is not None else ""
        raise SceneError(f"Region '{region_name}' holds only {len(points)} of {count} agents {spacing:g} m apart, "
                         f"clear of the obstacles{ground}: fewer agents, less spacing or a larger region")
    return points


def _free_names(prefix: str, count: int) -> List[str]:
    names, number = [], 1
    while len(names) < count:
        name = f"{prefix} {number}"
        if name not in bpy.data.objects and f"{name} goal 1" not in bpy.data.objects:
            names.append(name)
        number += 1
    return names
