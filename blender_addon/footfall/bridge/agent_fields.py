# SPDX-License-Identifier: GPL-3.0-or-later
"""The agent properties an animator sets per agent in the panel: the custom
properties scene_extract reads, with a label and the value a new one
starts from."""

from dataclasses import dataclass
from typing import Optional

from . import agent_rigs
from .scene_extract import (AGENT_RIG, AGENT_SCALE, AGENT_SPEED, FACE_GOAL, GOAL_WAIT, START_DELAY, TIME_LIMIT,
                            agent_empties)


@dataclass(frozen=True)
class AgentField:
    key: str  # the custom property
    label: str
    default: object  # what a new one holds


FIELDS = (
    AgentField(AGENT_SPEED, "Speed (m/s)", 1.3),
    AgentField(AGENT_SCALE, "Size", 1.0),
    AgentField(START_DELAY, "Start Delay (s)", 0.0),
    AgentField(GOAL_WAIT, "Wait at Goals (s)", 0.0),
    AgentField(TIME_LIMIT, "Time Limit (s)", 300.0),
    AgentField(AGENT_RIG, "Rig", ""),
    AgentField(FACE_GOAL, "Face as Last Goal", True),
)
BY_KEY = {field.key: field for field in FIELDS}


def active_agent(scene, active) -> Optional[object]:
    """The agent's empty that the active object is (or is a goal of)."""
    empties = set(agent_empties(scene).values())
    while active is not None:
        if active in empties:
            return active
        active = active.parent
    return None


def start_value(scene, field: AgentField):
    """What a new property starts at: the default, the scene's rig for a rig."""
    if field.key == AGENT_RIG:
        rig = agent_rigs.scene_rig(scene)
        return rig.name if rig is not None else ""
    return field.default
