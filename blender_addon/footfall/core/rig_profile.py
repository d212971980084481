# SPDX-License-Identifier: GPL-3.0-or-later
"""Rig profiles: which bone plays which role, which clip plays which
behaviour, and the rig's dimensions (docs/rig-profile.md).

A profile is read from JSON and checked field by field; errors name the file
and the field, like the core's scenario errors.
"""

import json
import math
from dataclasses import dataclass, field
from typing import Dict, Optional

from .bone_map import CENTER_ROLES, LIMB_ROLES, SIDES

BEHAVIORS = ("walk", "arms_in", "side_step", "idle")
# Clips for walking up and down stairs: played where the rig has them (else
# the walk plays), never made procedurally.
STAIR_CLIPS = ("stairs_up", "stairs_down")
CLIP_ROLES = BEHAVIORS + STAIR_CLIPS
DIMENSIONS = ("hip_height", "leg_length", "shoulder_width", "foot_length")


@dataclass
class RigProfile:
    """A rig's bone map, clips (None: no clip, a procedural one is used) and dimensions [m]."""

    bones: Dict[str, object]
    clips: Dict[str, Optional[str]] = field(default_factory=lambda: {b: None for b in BEHAVIORS})
    dimensions: Dict[str, float] = field(default_factory=dict)
    rig: Optional[str] = None

    def to_document(self) -> dict:
        document = {
            "format": "footfall-rig-profile",
            "version": 1,
            "bones": self.bones,
            "clips": self.clips,
            "dimensions": {k: round(v, 4) for k, v in self.dimensions.items()},
        }
        if self.rig:
            document["rig"] = self.rig
        return document


class ProfileError(ValueError):
    """A profile field is missing or wrong; the message names the file and field."""


def _fail(source, path, message):
    raise ProfileError(f"{source}: {path}: {message}")


def _name(value, source, path):
    if not isinstance(value, str) or not value:
        _fail(source, path, "expected a bone name (a non-empty string)")
    return value


def parse(document, source: str = "<profile>", partial: bool = False) -> RigProfile:
    """A RigProfile from a profile document. With `partial`, bones and
    dimensions may be left out (a user's mapping that detection completes)."""
    if not isinstance(document, dict):
        _fail(source, "(top level)", "expected an object")
    if document.get("format") != "footfall-rig-profile":
        _fail(source, "format", 'expected "footfall-rig-profile"')
    if document.get("version") != 1:
        _fail(source, "version", f"unsupported version {document.get('version')!r} (this Footfall reads 1)")
    unknown = set(document) - {"format", "version", "rig", "facing", "bones", "clips", "dimensions"}
    if unknown:
        _fail(source, sorted(unknown)[0], "unknown field")

    bones_in = document.get("bones", {})
    if not isinstance(bones_in, dict):
        _fail(source, "bones", "expected an object")
    bones: Dict[str, object] = {}
    for key in bones_in:
        if key not in CENTER_ROLES + SIDES:
            _fail(source, f"bones.{key}", "unknown role")
    for role in CENTER_ROLES:
        if role in bones_in:
            bones[role] = _name(bones_in[role], source, f"bones.{role}")
        elif not partial:
            _fail(source, f"bones.{role}", "missing")
    for side in SIDES:
        limbs = bones_in.get(side, {})
        if not isinstance(limbs, dict):
            _fail(source, f"bones.{side}", "expected an object")
        bones[side] = {}
        for key in limbs:
            if key not in LIMB_ROLES:
                _fail(source, f"bones.{side}.{key}", "unknown role")
        for role in LIMB_ROLES:
            if role in limbs:
                bones[side][role] = _name(limbs[role], source, f"bones.{side}.{role}")
            elif not partial:
                _fail(source, f"bones.{side}.{role}", "missing")

    clips_in = document.get("clips", {})
    if not isinstance(clips_in, dict):
        _fail(source, "clips", "expected an object")
    for key in clips_in:
        if key not in CLIP_ROLES:
            _fail(source, f"clips.{key}", f"unknown behaviour (one of {', '.join(CLIP_ROLES)})")
    clips = {}
    for behavior in CLIP_ROLES:
        value = clips_in.get(behavior)
        if value is not None and (not isinstance(value, str) or not value):
            _fail(source, f"clips.{behavior}", "expected a clip name or null")
        if behavior in BEHAVIORS or value is not None:
            clips[behavior] = value

    dimensions_in = document.get("dimensions", {})
    if not isinstance(dimensions_in, dict):
        _fail(source, "dimensions", "expected an object")
    dimensions = {}
    for key in dimensions_in:
        if key not in DIMENSIONS:
            _fail(source, f"dimensions.{key}", "unknown dimension")
    for key in DIMENSIONS:
        if key not in dimensions_in:
            if not partial:
                _fail(source, f"dimensions.{key}", "missing")
            continue
        value = dimensions_in[key]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
            _fail(source, f"dimensions.{key}", f"expected a positive number of metres, got {value!r}")
        dimensions[key] = float(value)
    return RigProfile(bones=bones, clips=clips, dimensions=dimensions, rig=document.get("rig"))


def load(path: str, partial: bool = False) -> RigProfile:
    """Reads a profile file; ProfileError names the file and field."""
    try:
        with open(path, encoding="utf-8") as stream:
            document = json.load(stream)
    except OSError as error:
        raise ProfileError(f"{path}: cannot read the file ({error.strerror})") from error
    except json.JSONDecodeError as error:
        raise ProfileError(f"{path}: not valid JSON: {error.msg} at line {error.lineno}, column {error.colno}") from error
    return parse(document, path, partial)
