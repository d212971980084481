# SPDX-License-Identifier: GPL-3.0-or-later
"""Finds a humanoid's bones by name and hierarchy, whatever the naming scheme.

The detection itself is the core's (footfall._native.detect_bones, shared
with the headless rig reader; docs/rig-profile.md): limbs by a side marker
and a base name among synonyms, or from the skeleton's shape where names say
nothing; the trunk where the limbs meet. Here: the bones as plain data, the
mapping as nested dicts, and the error that lists what is missing.
"""

from dataclasses import dataclass
from typing import Dict, Optional, Sequence, Tuple

from . import native

CENTER_ROLES = ("hips", "spine", "chest", "neck", "head")
LIMB_ROLES = ("upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe")
SIDES = ("left", "right")


@dataclass(frozen=True)
class Bone:
    """A bone of the rig: its name, its parent's name (None at a root), and
    its rest head and tail in the world (Z up), where known."""

    name: str
    parent: Optional[str]
    head: Optional[Tuple[float, float, float]] = None
    tail: Optional[Tuple[float, float, float]] = None


MAX_LISTED_BONES = 200  # of the rig's bones, in an error


class BoneMapError(ValueError):
    """Some roles could not be mapped; ``missing`` lists them ("left.toe", ...),
    ``unknown`` the roles a mapping gave a bone the rig does not have."""

    def __init__(self, rig: str, missing: Sequence[str], unknown: Optional[Dict[str, str]] = None,
                 bone_names: Optional[Sequence[str]] = None):
        self.missing = list(missing)
        self.unknown = dict(unknown or {})
        parts = []
        not_found = [role for role in self.missing if role not in self.unknown]
        if not_found:
            parts.append(f"Footfall could not find these bones in '{rig}': {', '.join(not_found)}.")
        if self.unknown:
            named = ", ".join(f"{role} = '{bone}'" for role, bone in self.unknown.items())
            parts.append(f"The mapping names bones '{rig}' does not have: {named}.")
        if bone_names:
            listed = list(bone_names)[:MAX_LISTED_BONES]
            more = len(bone_names) - len(listed)
            parts.append(f"Its bones: {', '.join(listed)}" + (f" and {more} more." if more else "."))
        parts.append("Supply a mapping: a rig profile JSON beside the file (same name, .json; see "
                     "docs/rig-profile.md), or the bone fields in the Footfall panel.")
        super().__init__(" ".join(parts))


def split_side(name: str):
    """(side, normalised base name) of a bone name; side is None for the trunk.

    >>> split_side("mixamorig:LeftForeArm")
    ('left', 'forearm')
    >>> split_side("upper_arm.R")
    ('right', 'upperarm')
    """
    side, base = native.load().split_side(name)
    return side or None, base


def detect(bones: Sequence[Bone], rig: str = "rig") -> Dict[str, object]:
    """The bone map of a humanoid: {"hips": name, ..., "left": {...}, "right": {...}}.

    Raises BoneMapError listing every role it could not map.
    """
    mapping, missing = detect_partial(bones)
    if missing:
        raise BoneMapError(rig, missing, bone_names=[b.name for b in bones])
    return mapping


def detect_partial(bones: Sequence[Bone], given: Optional[Dict[str, object]] = None):
    """(the roles found, the roles missing as "left.toe", "hips", ...).

    Roles in `given` are taken as they are, and the trunk is found from the
    limbs given as well as from those found. Limbs whose names say nothing
    are found from the skeleton's shape when the bones carry their rest
    geometry.
    """
    flat = {}
    for key, value in (given or {}).items():
        if isinstance(value, dict):
            flat.update({f"{key}.{role}": bone for role, bone in value.items() if bone})
        elif value:
            flat[key] = value
    found, missing = native.load().detect_bones([(b.name, b.parent, b.head, b.tail) for b in bones], flat)
    mapping: Dict[str, object] = {side: {} for side in SIDES}
    for role, bone in found.items():
        side, _, limb = role.partition(".")
        if limb:
            mapping[side][limb] = bone
        else:
            mapping[role] = bone
    return mapping, list(missing)


def validate_map(mapping: Dict[str, object], bone_names, rig: str = "rig") -> None:
    """Checks that a given map names every role with a bone of the rig; the
    error tells roles left out from roles given a bone the rig lacks, and
    lists the rig's bones."""
    bone_names = list(bone_names)
    names = set(bone_names)
    given = [(role, mapping.get(role)) for role in CENTER_ROLES]
    for side in SIDES:
        limbs = mapping.get(side) or {}
        given += [(f"{side}.{role}", limbs.get(role)) for role in LIMB_ROLES]
    missing = [role for role, bone in given if bone is None]
    unknown = {role: bone for role, bone in given if bone is not None and bone not in names}
    if missing or unknown:
        raise BoneMapError(rig, missing + list(unknown), unknown, bone_names)
