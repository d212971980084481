# SPDX-License-Identifier: GPL-3.0-or-later
"""Finds a humanoid's limbs from the shape of its skeleton, where the bone
names follow no scheme ("leg_joint_L_1", "Bone.017").

Needs each bone's rest head and tail in the world (Z up). The legs are the
two chains that descend from where they meet (the hips) to the lowest bones;
the arms the two that reach farthest to either side of the body from where
they meet (the chest). Along a chain, from its end: a leg's toe, foot, shin
and thigh; an arm's hand (the bone whose children are fingers, or the end),
forearm and upper arm. Left is left of the rig's facing, which its feet give
(heel to toe).
"""

from typing import Dict, List, Optional, Sequence

Point3 = Sequence[float]


def _chain(bone: str, stop: str, parents: Dict[str, Optional[str]]) -> List[str]:
    """The bones from `bone` up to, not including, its ancestor `stop`, nearest `stop` first."""
    chain = []
    while bone is not None and bone != stop:
        chain.append(bone)
        bone = parents.get(bone)
    return list(reversed(chain)) if bone == stop else []


def _common_ancestor(a: str, b: str, parents) -> Optional[str]:
    above_a = []
    while a is not None:
        above_a.append(a)
        a = parents.get(a)
    seen = set(above_a[1:])
    while b is not None:
        b = parents.get(b)
        if b in seen:
            return b
    return None


def limbs(bones) -> Dict[str, Dict[str, str]]:
    """{"left": {role: bone}, "right": {...}} for the roles the shape shows;
    empty when a bone has no rest geometry or no two legs are found."""
    if not bones or any(b.head is None or b.tail is None for b in bones):
        return {}
    parents = {b.name: b.parent for b in bones}
    at = {b.name: b for b in bones}
    children: Dict[str, List[str]] = {b.name: [] for b in bones}
    for b in bones:
        if b.parent in children:
            children[b.parent].append(b.name)
    leaves = sorted((b.name for b in bones if not children[b.name]),
                    key=lambda n: (min(at[n].head[2], at[n].tail[2]), n))
    # The legs: the lowest chain end, and the lowest other one whose chain
    # meets it three bones or more above both.
    legs = None
    for other in leaves[1:]:
        hips = _common_ancestor(leaves[0], other, parents)
        if hips and len(_chain(leaves[0], hips, parents)) >= 3 and len(_chain(other, hips, parents)) >= 3:
            legs = (hips, leaves[0], other)
            break
    if legs is None:
        return {}
    hips, *ends = legs
    chains = [_chain(end, hips, parents) for end in ends]
    # The facing: heel to toe of both feet; left is up x facing.
    forward = [0.0, 0.0]
    for chain in chains:
        foot = at[chain[-2]] if len(chain) >= 4 else at[chain[-1]]
        forward[0] += foot.tail[0] - foot.head[0]
        forward[1] += foot.tail[1] - foot.head[1]
    left_axis = (-forward[1], forward[0])
    origin = at[hips].head

    def leftward(name: str) -> float:
        return (at[name].tail[0] - origin[0]) * left_axis[0] + (at[name].tail[1] - origin[1]) * left_axis[1]

    found: Dict[str, Dict[str, str]] = {"left": {}, "right": {}}
    for chain in chains:
        side = "left" if leftward(chain[-1]) > 0 else "right"
        roles = ("thigh", "shin", "foot", "toe") if len(chain) >= 4 else ("thigh", "shin", "foot")
        found[side].update(zip(roles, chain[-len(roles):]))
    if set(found["left"]) == set() or set(found["right"]) == set():
        return {}  # both legs on one side: the facing is not what the feet say
    # The arms: the bones reaching farthest to either side, off the legs.
    in_legs = set(chains[0]) | set(chains[1])
    rest = [b.name for b in bones if b.name not in in_legs and b.name != hips]
    if not rest:
        return found
    left_end, right_end = max(rest, key=leftward), min(rest, key=leftward)
    chest = _common_ancestor(left_end, right_end, parents)
    if chest is None or leftward(left_end) <= 0 or leftward(right_end) >= 0:
        return found
    for side, end in (("left", left_end), ("right", right_end)):
        chain = _chain(end, chest, parents)
        hand = next((b for b in chain if len(children[b]) > 1), chain[-1])
        upto = chain[:chain.index(hand) + 1]
        if len(upto) >= 3:
            found[side].update(zip(("upper_arm", "forearm", "hand"), upto[-3:]))
    return found
