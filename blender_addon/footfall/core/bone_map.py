# SPDX-License-Identifier: GPL-3.0-or-later
"""Finds a humanoid's bones by name and hierarchy, whatever the naming scheme.

Limbs are found by name: a side marker (``.L``/``_l``/``-L``/`` L`` suffixes,
``Left``/``L_`` prefixes, any ``namespace:`` such as ``mixamorig:`` dropped)
and a base name from a list of synonyms (``upper_arm``, ``UpperArm``,
``upperarm``, Mixamo's ``Arm``...). The trunk is found by hierarchy, which no
naming scheme can fool: the hips are where both legs meet, the chest where both
arms meet, the spine is the first bone from the hips toward the chest. The neck
and head are found by name, or else as the bones above the chest.
"""

import re
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Tuple

from . import bone_structure

CENTER_ROLES = ("hips", "spine", "chest", "neck", "head")
LIMB_ROLES = ("upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe")
SIDES = ("left", "right")

# Base names after normalisation (lower case, no separators).
LIMB_SYNONYMS = {
    "upper_arm": {"upperarm", "arm", "uparm", "armupper"},
    "forearm": {"forearm", "lowerarm", "elbow", "armlower"},
    "hand": {"hand", "wrist"},
    "thigh": {"thigh", "upleg", "upperleg", "legupper", "thighbone"},
    "shin": {"shin", "calf", "leg", "lowerleg", "knee", "leglower"},
    "foot": {"foot", "ankle"},
    "toe": {"toe", "toes", "toebase", "ball", "toe0", "toes0"},
}
NECK_NAMES = {"neck", "neck01", "neck1"}
HEAD_NAMES = {"head"}


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


def _normalise(text: str) -> str:
    return re.sub(r"[^a-z0-9]", "", text.lower())


_SIDE_SUFFIX = re.compile(r"^(?P<base>.+?)[._\- ](?P<side>l|r|left|right)$", re.IGNORECASE)
_SIDE_PREFIX = re.compile(r"^(?P<side>left|right|l|r)(?P<sep>[._\- ]?)(?P<base>.+)$", re.IGNORECASE)


def split_side(name: str):
    """(side, normalised base name) of a bone name; side is None for the trunk.

    >>> split_side("mixamorig:LeftForeArm")
    ('left', 'forearm')
    >>> split_side("upper_arm.R")
    ('right', 'upperarm')
    """
    name = name.rsplit(":", 1)[-1]
    match = _SIDE_SUFFIX.match(name)
    if match:
        side = "left" if match.group("side").lower().startswith("l") else "right"
        return side, _normalise(match.group("base"))
    match = _SIDE_PREFIX.match(name)
    if match:
        word = match.group("side")
        # "Left"/"Right" may run into the base ("LeftArm"); a bare "L"/"R" needs a
        # separator ("L_Arm"), or "Leg" would read as the left "eg".
        if word.lower() in ("left", "right") or match.group("sep"):
            side = "left" if word.lower().startswith("l") else "right"
            return side, _normalise(match.group("base"))
    return None, _normalise(name)


def _ancestors(name: str, parents: Dict[str, Optional[str]]) -> List[str]:
    chain = []
    while name is not None and name not in chain:
        chain.append(name)
        name = parents.get(name)
    return chain


def _meeting_point(a: str, b: str, parents: Dict[str, Optional[str]]) -> Optional[str]:
    """The lowest common ancestor of two bones (proper ancestors only)."""
    above_a = _ancestors(a, parents)[1:]
    above_b = set(_ancestors(b, parents)[1:])
    return next((bone for bone in above_a if bone in above_b), None)


def _by_name(bones: Sequence[Bone], parents, side: Optional[str], names) -> Optional[str]:
    """The bone of `side` whose base name is one of `names`; nearest the root wins."""
    found = [bone.name for bone in bones if split_side(bone.name) in {(side, n) for n in names}]
    return min(found, key=lambda b: (len(_ancestors(b, parents)), b), default=None)


def _length(bone: Bone) -> float:
    return sum((t - h) ** 2 for h, t in zip(bone.head, bone.tail)) ** 0.5


def _continues(bone: Bone, child: Bone) -> bool:
    """True if `child` starts nearer `bone`'s tail than half its length (or
    the rest geometry is not known)."""
    if bone.tail is None or child.head is None:
        return True
    gap = sum((c - t) ** 2 for c, t in zip(child.head, bone.tail)) ** 0.5
    return gap < 0.5 * _length(bone)


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
    geometry (bone_structure).
    """
    given = given or {}
    parents = {bone.name: bone.parent for bone in bones}
    mapping: Dict[str, object] = {side: {} for side in SIDES}
    missing = []
    shape: Optional[Dict[str, Dict[str, str]]] = None  # found when first wanted
    for side in SIDES:
        for role in LIMB_ROLES:
            found = (given.get(side) or {}).get(role) or _by_name(bones, parents, side, LIMB_SYNONYMS[role])
            if found is None:
                shape = bone_structure.limbs(bones) if shape is None else shape
                found = shape.get(side, {}).get(role)
            if found is None:
                missing.append(f"{side}.{role}")
            else:
                mapping[side][role] = found

    def both(role):
        return mapping["left"].get(role), mapping["right"].get(role)

    thighs, arms = both("thigh"), both("upper_arm")
    hips = _meeting_point(*thighs, parents) if None not in thighs else None
    chest = _meeting_point(*arms, parents) if None not in arms else None
    spine = None
    if hips and chest and hips in _ancestors(chest, parents):
        path = _ancestors(chest, parents)
        below_chest = path[: path.index(hips)]  # chest ... first bone above the hips
        spine = below_chest[-1] if len(below_chest) > 1 else None
    head = _by_name(bones, parents, None, HEAD_NAMES)
    neck = _by_name(bones, parents, None, NECK_NAMES)
    if chest and head is None:
        # The chain that rises from the chest, neither arm's: the neck its first
        # bone, the head where it ends or branches (into a face's bones), as
        # Rigify's spine.004 to spine.006 are.
        arm_chains = set().union(*(_ancestors(a, parents) for a in arms if a))
        above = [b for b in bones if b.parent == chest and b.name not in arm_chains]
        if len(above) > 1 and all(b.head is not None and b.tail is not None for b in above):
            above = [max(above, key=lambda b: (b.tail[2] - b.head[2]) / (_length(b) or 1.0))]
        if len(above) == 1:
            chain = [above[0]]
            while True:
                children = [b for b in bones if b.parent == chain[-1].name]
                # Only a bone that goes on from the last one's tail (Rigify's
                # face bone starts back at the head's root, inside it).
                if len(children) != 1 or not _continues(chain[-1], children[0]):
                    break
                chain.append(children[0])
            neck, head = (chain[0].name, chain[-1].name) if len(chain) > 1 else (None, chain[0].name)
    if neck is None and head is not None and parents.get(head) not in (None, chest):
        neck = parents[head]
    for role, bone in zip(CENTER_ROLES, (hips, spine, chest, neck, head)):
        bone = given.get(role) or bone
        if bone is None:
            missing.append(role)
        else:
            mapping[role] = bone
    return mapping, missing


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
