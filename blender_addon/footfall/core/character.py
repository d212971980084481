# SPDX-License-Identifier: GPL-3.0-or-later
"""Planner parameters derived from a rig's dimensions, so that a tall rig
takes longer strides.

The paper's default character (COM 1 m high, steps 0.1-1 m, torso 0.6 m wide)
is a person of about 1.8 m: leg length 0.9 m. A rig is scaled from it by its
leg length L: lengths in proportion to L, and, for a walk that looks the same
at any size (equal Froude number v^2 / (g L)), speeds and step durations in
proportion to sqrt(L).
"""

import math
import re
from typing import Dict, Mapping, Optional, Tuple

from . import scenario

REFERENCE_LEG_LENGTH = 0.9  # [m] of the paper's default character
COM_ABOVE_HIPS = 1.05  # the COM stands about 5 % above the hip joints
ARM_THICKNESS = 0.1  # [m] per side outside the shoulder joints, at the reference size
DEFAULT_GAITS = ((0.6, 0.65), (1.3, 0.5), (1.6, 0.45))  # as PlannerParams' defaults
SIDE_STEP = (0.6, 1.2)  # the core's side step at the reference size: speed [m/s], cycle [s]
SOLE_WIDTH_SHARE = 0.10 / 0.26  # a sole's width over its length, as the core's default sole


def derive_parameters(dimensions: Mapping[str, float], body: Optional[Mapping] = None
                      ) -> Tuple[Dict[str, object], Dict[str, object]]:
    """(character overrides, planner overrides) for a scenario document;
    `body` (bridge/rig_body: the rig's height and its poses per behaviour)
    gives the full-body planner the rig's own body."""
    scale = dimensions["leg_length"] / REFERENCE_LEG_LENGTH
    time_scale = math.sqrt(scale)
    speed_scale = math.sqrt(scale)
    character = {
        "com_height": COM_ABOVE_HIPS * dimensions["hip_height"],
        "min_step_length": 0.1 * scale,
        "max_step_length": 1.0 * scale,
        "min_step_duration": 0.2 * time_scale,
        "max_step_duration": 0.8 * time_scale,
        "max_speed": 2.5 * speed_scale,
        "min_speed": 0.2 * speed_scale,
        "preferred_speed": 1.3 * speed_scale,
        "preferred_step_duration": 0.5 * time_scale,
        "torso_width": dimensions["shoulder_width"] + 2 * ARM_THICKNESS * scale,
        "torso_radius": 0.15 * scale,
        "shoulder_radius": 0.1 * scale,
        "foot_offset": 0.1 * scale,
        "foot_radius": 0.3 * dimensions["foot_length"],
        # The sole the planner fits on treads is the rig's foot (its heel a quarter of it behind the ankle).
        "sole_length": dimensions["foot_length"],
        "sole_width": SOLE_WIDTH_SHARE * dimensions["foot_length"],
    }
    if body is not None:
        walk = {"cycle_duration": 2 * character["preferred_step_duration"], "speed": character["preferred_speed"]}
        timing = {"walk": walk, "arms_in": walk,
                  "side_step": {"cycle_duration": SIDE_STEP[1] * time_scale, "speed": SIDE_STEP[0] * speed_scale}}
        character["body_height"] = body["height"]
        character["side_step_speed"] = timing["side_step"]["speed"]
        character["behaviors"] = {b: {**timing[b], "poses": poses} for b, poses in body["poses"].items()}
    planner = {
        "gaits": [{"speed": v * speed_scale, "duration": t * time_scale} for v, t in DEFAULT_GAITS],
    }
    return character, planner


def scaled(dimensions: Mapping[str, float], body: Optional[Mapping], scale: float
           ) -> Tuple[Dict[str, float], Optional[dict]]:
    """A rig's dimensions and body (bridge/rig_body) `scale` times as large."""
    if scale == 1.0:
        return dict(dimensions), None if body is None else dict(body)
    sized = {key: value * scale for key, value in dimensions.items()}
    if body is None:
        return sized, None
    poses = {behavior: [{limb: [v * scale for v in capsule] for limb, capsule in pose.items()} for pose in motion]
             for behavior, motion in body["poses"].items()}
    return sized, {"height": body["height"] * scale, "poses": poses}


def with_rig(document: dict, dimensions: Mapping[str, float], body: Optional[Mapping] = None) -> dict:
    """A scenario document whose character and planner take the rig's derived
    parameters, except where the document sets its own."""
    character, planner = derive_parameters(dimensions, body)
    result = dict(document)
    result["character"] = {**character, **document.get("character", {})}
    result["planner"] = {**planner, **document.get("planner", {})}
    return result


# What each derived field is in the user's terms, and the dimension it comes
# from; any other (strides, speeds, step durations, gaits) from the leg length.
MEASURED_BY = {"com_height": ("hip_height", "a centre of mass"), "torso_width": ("shoulder_width", "a torso"),
               "foot_radius": ("foot_length", "a foot"), "sole_length": ("foot_length", "a foot"),
               "sole_width": ("foot_length", "a foot")}
# The core's words for a value out of its range: "must be in [LOW, HIGH], got VALUE".
OUT_OF_RANGE = re.compile(r"must be in .(\S+), (\S+)., got (\S+)")


def problem(dimensions: Mapping[str, float], body: Optional[Mapping], rig: str, remedy: str = "scale the rig"
            ) -> Optional[str]:
    """Why the core would refuse the character derived from rig `rig`, in
    the user's terms, ending in `remedy`; None if it plans. It asks the
    core's own checks, so that Import Rig refuses exactly what Plan would."""
    character, planner = derive_parameters(dimensions, body)
    try:
        scenario.parse(scenario.scenario_document(scenario.ScenarioInput(character=character, planner=planner)), rig)
        return None
    except ValueError as error:  # "RIG: FIELD.PATH: problem"
        where, _, why = str(error).removeprefix(f"{rig}: ").partition(": ")
    field = where.rsplit(".", 1)[-1]
    tall = f"rig '{rig}'" + (f" is {body['height']:.2f} m tall" if body else "")
    limits = OUT_OF_RANGE.match(why)
    if field == "body_height" and limits:
        return f"{tall}; Footfall plans bodies from {limits[1]} to {limits[2]} m tall: {remedy}"
    if ".poses[" in where:  # character.behaviors.BEHAVIOR.poses[i].LIMB
        gives = f"its {where.split('.')[2]} clip gives its {field} a capsule"
    else:
        dimension, what = MEASURED_BY.get(field, ("leg_length", "strides and paces"))
        gives = f"its {dimension.replace('_', ' ')} of {dimensions[dimension]:.2f} m gives {what}"
    return f"{tall}; {gives} Footfall cannot plan ({where}: {why}): {remedy}"


def scaled_problem(refusal: str, agent: str, rig: Optional[str], height: float, scale: float) -> str:
    """The core's `refusal` ("agents[i].character.FIELD: problem") of an
    agent whose scale takes the character it is sized from (rig `rig`, None
    for the scene's character, `height` m tall) outside what the core plans,
    in the user's terms: the agent, its rig, the heights, the limits and
    which way its scale must go."""
    where, _, why = refusal.partition(": ")
    path = where.split(".character.", 1)[-1]
    who = f"agent '{agent}': " + (f"its rig '{rig}'" if rig else "the scene's character") + f" ({height:.2f} m)"
    limits = OUT_OF_RANGE.match(why)
    if limits is None:
        remedy = "change its scale"
    elif float(limits[3]) > float(limits[2]):
        remedy = "lower its scale"
    else:
        remedy = "raise its scale"
    if path == "body_height" and limits:
        least, most = float(limits[1]), float(limits[2])
        if remedy.startswith("lower"):
            remedy += f" to {math.floor(100 * most / height + 1e-9) / 100:.2f} or less"
        else:
            remedy += f" to {math.ceil(100 * least / height - 1e-9) / 100:.2f} or more"
        return (f"{who} at scale {scale:.2f} is {height * scale:.2f} m tall; Footfall plans bodies from "
                f"{limits[1]} to {limits[2]} m: {remedy}")
    field = path.rsplit(".", 1)[-1]
    what = "a body capsule" if ".poses[" in path else MEASURED_BY.get(field, ("", "strides and paces"))[1]
    return f"{who} at scale {scale:.2f} gives {what} Footfall cannot plan (character.{path}: {why}): {remedy}"
