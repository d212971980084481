# SPDX-License-Identifier: GPL-3.0-or-later
"""Which imported rig animates which agent, and the characters sized from
the rigs.

The scene's rig (the panel's Rig field, set by Import Rig; the only rig
imported when none is chosen) animates every agent and sizes the
scenario's character. An agent whose custom property "footfall_rig" names
another imported rig is animated with that one, and walks with a character
sized from it: its own `character` in the scenario.
"""

import re
from typing import Dict, Optional

import bpy

from ..core import native
from ..core.character import COM_ABOVE_HIPS, derive_parameters, scaled, scaled_problem, with_rig
from ..core.scenario import parse
from .rig_body import body_of
from .rig_import import imported_rigs, profile_of
from .scene_extract import AGENT_RIG, agent_empties

SCENE_RIG = "footfall_rig"  # the scene's property: the rig chosen in the panel
SIZE_TOLERANCE = 0.1  # a rig may stand this share taller or shorter than the character planned for


class RigChoiceError(ValueError):
    """No rig, or an unclear or unusable choice; the message says what to do."""


def _names(rigs) -> str:
    return ", ".join(sorted(r.name for r in rigs)) or "none"


def scene_rig(scene, name: str = "") -> Optional[bpy.types.Object]:
    """The rig named `name`, else the scene's chosen rig, else the only
    imported one; None when no rig is imported."""
    rigs = imported_rigs()
    if name:
        rig = bpy.data.objects.get(name)
        if rig is None or rig not in rigs:
            raise RigChoiceError(f"'{name}' is not a rig imported with Footfall's Import Rig (rigs: {_names(rigs)})")
        return rig
    chosen = getattr(scene, SCENE_RIG, None)
    if chosen is not None and chosen in rigs:
        return chosen
    if len(rigs) > 1:
        raise RigChoiceError(f"Several rigs are imported ({_names(rigs)}): choose the scene's rig in the Footfall "
                             "panel (Rig)")
    return rigs[0] if rigs else None


def agent_rig(agent: str, name) -> bpy.types.Object:
    """The imported rig that agent `agent`'s "footfall_rig" names (`name`)."""
    if not isinstance(name, str):
        raise RigChoiceError(f"Agent '{agent}': custom property '{AGENT_RIG}' must be a rig's name, got {name!r}")
    rig = bpy.data.objects.get(name)
    if rig is None or rig not in imported_rigs():
        raise RigChoiceError(f"Agent '{agent}': custom property '{AGENT_RIG}' names '{name}', which is not a rig "
                             f"imported with Footfall's Import Rig (rigs: {_names(imported_rigs())})")
    return rig


def sized(document: dict, agent_rigs: Dict[str, str], rig: Optional[bpy.types.Object]) -> dict:
    """The scenario document with its character sized from the scene's rig
    (where the scene sets no value itself), and every agent with a rig of
    its own walking with a character sized from that one, times its scale
    (where the agent sets no value itself; the core scales the scenario's
    character for the others)."""
    result = with_rig(document, profile_of(rig).dimensions, body_of(rig)) if rig is not None else dict(document)
    derived = {}  # per rig and scale: a crowd's agents share a few
    result["agents"] = [_sized_agent(entry, agent_rigs, rig, derived) for entry in result.get("agents", [])]
    return result


def _own_rig(entry: dict, agent_rigs: Dict[str, str], rig: Optional[bpy.types.Object]):
    """The agent's own rig when it is not the scene's `rig`, else None."""
    own = agent_rigs.get(entry["name"])
    if own is not None and (rig is None or own != rig.name):
        return agent_rig(entry["name"], own)
    return None


def _sized_agent(entry: dict, agent_rigs: Dict[str, str], rig, derived: dict) -> dict:
    own_rig = _own_rig(entry, agent_rigs, rig)
    if own_rig is None:
        return entry
    key = (own_rig.name, entry.get("scale", 1.0))
    if key not in derived:
        derived[key], _planner = derive_parameters(*scaled(profile_of(own_rig).dimensions, body_of(own_rig), key[1]))
    return {**entry, "character": {**derived[key], **entry.get("character", {})}}


def check_sizes(document: dict, sized_document: dict, agent_rigs: Dict[str, str],
                rig: Optional[bpy.types.Object], objects: Dict[str, str]) -> None:
    """Raises RigChoiceError, in the user's terms, for an agent whose scale
    takes the character it is sized from (its rig's, or the scene's) where
    the core will not plan it: `sized_document` is what sized() made of
    `document`, `objects` each agent's object by agent name. The core's own
    checks decide (they parse the document, as Plan would), so that the two
    never disagree; a refusal that is not the scale's (the agent plans at
    scale 1 no better) is left for Plan to report as the core words it."""
    try:
        parse(sized_document, "scene")
        return
    except ValueError as error:
        refusal = str(error).removeprefix("scene: ")
    found = re.match(r"agents\[(\d+)\]\.character\.", refusal)
    if found is None:
        return
    index = int(found[1])
    entry = sized_document["agents"][index]
    scale = entry.get("scale", 1.0)
    if scale == 1.0:
        return
    unscaled = _sized_agent({k: v for k, v in document["agents"][index].items() if k != "scale"}, agent_rigs, rig,
                            {})
    alone = {key: value for key, value in sized_document.items() if key not in ("agents", "obstacles")}
    try:
        parse({**alone, "agents": [unscaled]}, "scene")
    except ValueError:
        return  # not (only) its size: Plan reports the core's words
    chosen = _own_rig(entry, agent_rigs, rig) or rig
    character = {**sized_document.get("character", {}), **unscaled.get("character", {})}
    height = character.get("body_height", native.load().CharacterParams().body_height)
    raise RigChoiceError(scaled_problem(refusal, objects.get(entry["name"], entry["name"]),
                                        None if chosen is None else chosen.name, height, scale))


def rigs_of(scene, plan, rig: Optional[bpy.types.Object]) -> Dict[str, bpy.types.Object]:
    """The rig of each agent of `plan`: its empty's "footfall_rig" in the
    scene, else `rig`. Refuses an agent whose rig stands more than
    SIZE_TOLERANCE taller or shorter than the character it was planned with."""
    empties = agent_empties(scene)
    result = {}
    for agent in plan.agents:
        empty = empties.get(agent.name)
        own = empty.get(AGENT_RIG) if empty is not None else None
        chosen = rig if own is None else agent_rig(agent.name, own)
        if chosen is None:
            raise RigChoiceError("Import a rig first (Footfall > Import Rig)")
        planned = (agent.character or plan.character).com_height
        standing = COM_ABOVE_HIPS * profile_of(chosen).dimensions["hip_height"] * agent.scale
        if abs(standing / planned - 1.0) > SIZE_TOLERANCE:
            raise RigChoiceError(
                f"Agent '{agent.name}': rig '{chosen.name}' stands {100 * (standing / planned - 1):+.0f} % off the "
                f"character it was planned with (centre of mass {standing:.2f} m against {planned:.2f} m): plan "
                "again with this rig chosen (the panel's Rig, or the agent's 'footfall_rig')")
        result[agent.name] = chosen
    return result
