# SPDX-License-Identifier: GPL-3.0-or-later
"""Per-agent variation drawn at random: each chosen agent's preferred speed
(its custom property "footfall_speed") from a range, optionally its size
("footfall_scale") from another, and its rig ("footfall_rig") from the
imported rigs. The same seed and agents draw the same values."""

import random
from typing import Dict, Sequence

import bpy

from ..core import character, native
from .scene_extract import AGENT_RIG, AGENT_SCALE, AGENT_SPEED, SceneError, agent_empties


def randomize(scene, names: Sequence[str], seed: int, speeds: Sequence[float],
              rigs: Sequence[str] = (), scales: Sequence[float] = (1.0, 1.0)) -> Dict[str, dict]:
    """Draws a speed in `speeds` (low, high) for each agent in `names`, a
    size in `scales` unless it is (1, 1), and a rig among `rigs` if any are
    given, and sets them on the agents' empties; returns what each agent got.
    Raises SceneError, changing nothing, for no agents or a bad range."""
    low, high = speeds
    core = native.load()  # the core's bounds, which it checks the agents against
    most_speed, (least_scale, most_scale) = core.MOST_SPEED, core.SCALE_RANGE
    if not names:
        raise SceneError("No agents selected: select agents (their empties, goals or animated rigs) to vary")
    if not (0.0 < low <= high <= most_speed):
        raise SceneError(f"Speed range {low:g}-{high:g} m/s: needs 0 < lowest <= highest <= {most_speed:g}")
    if not (least_scale <= scales[0] <= scales[1] <= most_scale):
        raise SceneError(f"Size range {scales[0]:g}-{scales[1]:g}: needs {least_scale:g} <= lowest <= highest "
                         f"<= {most_scale:g}")
    empties = agent_empties(scene)
    if tuple(scales) != (1.0, 1.0):
        _check_size_range(scene, [empties[name] for name in names], rigs, scales)
    draw = random.Random(seed)
    drawn = {}
    for name in sorted(names):  # the order the draws go in: names, not selection order
        values = {AGENT_SPEED: round(draw.uniform(low, high), 3)}
        if tuple(scales) != (1.0, 1.0):
            values[AGENT_SCALE] = round(draw.uniform(*scales), 3)
        if rigs:
            values[AGENT_RIG] = draw.choice(sorted(rigs))
        drawn[name] = values
    for name, values in drawn.items():
        for key, value in values.items():
            empties[name][key] = value
    return drawn


def _check_size_range(scene, agents, rigs: Sequence[str], scales: Sequence[float]) -> None:
    """Raises SceneError, in the user's terms, when a size in `scales` takes
    a rig the agents may be drawn (`rigs`), or else one they walk with (their
    own or the scene's), outside what the core plans: the core's own checks
    decide (character.problem), as at Import Rig and at Plan."""
    from . import agent_rigs
    from .rig_body import body_of
    from .rig_import import profile_of

    try:
        if rigs:
            chosen = {bpy.data.objects[name] for name in rigs}
        else:
            scene_rig = agent_rigs.scene_rig(scene)
            chosen = {agent_rigs.agent_rig(agent.name, agent[AGENT_RIG]) if AGENT_RIG in agent else scene_rig
                      for agent in agents}
    except agent_rigs.RigChoiceError as error:
        raise SceneError(str(error)) from error
    for rig in sorted((r for r in chosen if r is not None), key=lambda r: r.name):
        for size in dict.fromkeys(scales):
            refused = character.problem(*character.scaled(profile_of(rig).dimensions, body_of(rig), size), rig.name,
                                        "narrow the size range")
            if refused:
                raise SceneError(f"Size range {scales[0]:g}-{scales[1]:g}: at {size:g}, {refused}")
