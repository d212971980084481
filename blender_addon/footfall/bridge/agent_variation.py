# SPDX-License-Identifier: GPL-3.0-or-later
"""Per-agent variation drawn at random: each chosen agent's preferred speed
(its custom property "footfall_speed") from a range, and optionally its rig
("footfall_rig") from the imported rigs. The same seed and agents draw the
same values."""

import random
from typing import Dict, Sequence

from .scene_extract import AGENT_RIG, AGENT_SPEED, SceneError, agent_empties

MAX_SPEED = 10.0  # [m/s] the core's bound on a preferred speed


def randomize(scene, names: Sequence[str], seed: int, speeds: Sequence[float],
              rigs: Sequence[str] = ()) -> Dict[str, dict]:
    """Draws a speed in `speeds` (low, high) for each agent in `names`, and a
    rig among `rigs` if any are given, and sets them on the agents' empties;
    returns what each agent got. Raises SceneError, changing nothing, for no
    agents or a bad range."""
    low, high = speeds
    if not names:
        raise SceneError("No agents selected: select agents (their empties, goals or animated rigs) to vary")
    if not (0.0 < low <= high <= MAX_SPEED):
        raise SceneError(f"Speed range {low:g}-{high:g} m/s: needs 0 < lowest <= highest <= {MAX_SPEED:g}")
    empties = agent_empties(scene)
    draw = random.Random(seed)
    drawn = {}
    for name in sorted(names):  # the order the draws go in: names, not selection order
        values = {AGENT_SPEED: round(draw.uniform(low, high), 3)}
        if rigs:
            values[AGENT_RIG] = draw.choice(sorted(rigs))
        drawn[name] = values
    for name, values in drawn.items():
        for key, value in values.items():
            empties[name][key] = value
    return drawn
