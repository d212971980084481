# SPDX-License-Identifier: GPL-3.0-or-later
"""Which agents an animator has selected: an agent's empty, one of its goals,
or its animated rig (or a mesh of it) in the crowd Apply made."""

from typing import Iterable, List

import bpy

from .animate import CROWD_COLLECTION
from .scene_extract import agent_empties


def selected_agents(scene, selected: Iterable) -> List[str]:
    """The names of the agents that the `selected` objects stand for, in
    name order."""
    empties = agent_empties(scene)
    agent_of = {empty: name for name, empty in empties.items()}
    crowd = bpy.data.collections.get(CROWD_COLLECTION)
    animated = {obj: obj.name for obj in (crowd.objects if crowd else ()) if obj.type == "ARMATURE"}
    names = set()
    for obj in selected:
        while obj is not None:  # up from a goal to its agent, from a mesh to its armature
            name = agent_of.get(obj) or animated.get(obj)
            if name in empties:
                names.add(name)
                break
            obj = obj.parent
    return sorted(names)
