# SPDX-License-Identifier: GPL-3.0-or-later
"""A rig's own clip as a gait cycle: how many cycles it holds and where in
the cycle the right heel strikes, found from the motion of its feet (or,
for an upper-body clip, of its hands).

The poses in numpy, the cycle from them by the core (find_gait_cycle, which
the headless rig reader uses too): the caller samples the clip's channels
per bone (Blender's F-curves) and gives the bones' rest matrices in
armature space. The poses are computed as Blender does for bones that
inherit their parent's rotation and scale: pose = parent pose @ (parent
rest^-1 @ rest) @ basis, basis = T(location) R(rotation) S(scale).
"""

from dataclasses import dataclass
from typing import Dict, Optional, Sequence

import numpy

from . import native

CONVENTION = 0.25  # where the procedural clips put the right heel strike (left arm forward), as the core's GaitCycle


@dataclass(frozen=True)
class BoneRest:
    name: str
    parent: Optional[str]
    matrix: numpy.ndarray  # 4x4, armature space


@dataclass(frozen=True)
class ClipCycle:
    """`cycles` gait cycles over the clip's frame range; the right heel
    strikes at `strike` (a fraction of a cycle, from the range's start);
    `source` says what showed it: "feet", "hands" or "convention"."""

    cycles: int
    strike: float
    source: str


def quaternion_matrices(q: numpy.ndarray) -> numpy.ndarray:
    """(n, 3, 3) rotations of (n, 4) quaternions (w, x, y, z), normalised."""
    q = q / numpy.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    return numpy.stack([
        numpy.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], axis=1),
        numpy.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], axis=1),
        numpy.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], axis=1),
    ], axis=1)


def _axis_rotation(axis: int, angles: numpy.ndarray) -> numpy.ndarray:
    c, s = numpy.cos(angles), numpy.sin(angles)
    m = numpy.zeros((len(angles), 3, 3))
    i, j = (axis + 1) % 3, (axis + 2) % 3  # cyclic, so that every turn is right-handed
    m[:, axis, axis] = 1.0
    m[:, i, i], m[:, i, j], m[:, j, i], m[:, j, j] = c, -s, s, c
    return m


def euler_matrices(angles: numpy.ndarray, order: str = "XYZ") -> numpy.ndarray:
    """(n, 3, 3) rotations of (n, 3) Euler angles in Blender's sense: order
    "XYZ" turns about X first, so R = Rz Ry Rx."""
    result = numpy.broadcast_to(numpy.eye(3), (len(angles), 3, 3)).copy()
    for letter in order:
        axis = "XYZ".index(letter)
        result = _axis_rotation(axis, angles[:, axis]) @ result
    return result


def basis_matrices(location: numpy.ndarray, rotation: numpy.ndarray, scale: numpy.ndarray) -> numpy.ndarray:
    """(n, 4, 4) pose bases from (n, 3) locations, (n, 3, 3) rotations and (n, 3) scales."""
    basis = numpy.zeros((len(location), 4, 4))
    basis[:, :3, :3] = rotation * scale[:, None, :]
    basis[:, :3, 3] = location
    basis[:, 3, 3] = 1.0
    return basis


def pose_matrices(rests: Dict[str, BoneRest], bases: Dict[str, numpy.ndarray], names: Sequence[str],
                  count: int) -> Dict[str, numpy.ndarray]:
    """Armature-space pose matrices (count, 4, 4) of the bones `names` at each
    sample; a bone without a basis in `bases` stays at its rest relative to
    its parent."""
    poses: Dict[str, numpy.ndarray] = {}

    def pose(name: str) -> numpy.ndarray:
        if name not in poses:
            bone = rests[name]
            local = bone.matrix if bone.parent is None else numpy.linalg.inv(rests[bone.parent].matrix) @ bone.matrix
            above = numpy.broadcast_to(numpy.eye(4), (count, 4, 4)) if bone.parent is None else pose(bone.parent)
            basis = bases.get(name, numpy.broadcast_to(numpy.eye(4), (count, 4, 4)))
            poses[name] = above @ local @ basis
        return poses[name]

    return {name: pose(name) for name in names}


def pose_heads(rests: Dict[str, BoneRest], bases: Dict[str, numpy.ndarray], names: Sequence[str],
               count: int) -> Dict[str, numpy.ndarray]:
    """Armature-space heads (count, 3) of the bones `names` at each sample."""
    return {name: matrices[:, :3, 3] for name, matrices in pose_matrices(rests, bases, names, count).items()}


def find_cycle(forward: numpy.ndarray, leg_length: float, left_foot: numpy.ndarray, right_foot: numpy.ndarray,
               left_hand: numpy.ndarray, right_hand: numpy.ndarray) -> ClipCycle:
    """The cycle of a clip sampled evenly over its frame range (end left out):
    the right heel strikes where the right foot is furthest ahead of the
    left (along `forward`, the rig's facing); a clip whose feet keep still is
    timed by its hands, the left hand furthest ahead at the right heel strike
    (arms swing against the legs). `leg_length` in the same units."""
    cycles, strike, source = native.load().find_gait_cycle(
        (right_foot - left_foot) @ forward, (left_hand - right_hand) @ forward, leg_length)
    return ClipCycle(cycles, strike, source)
