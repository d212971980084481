# SPDX-License-Identifier: GPL-3.0-or-later
"""The visual bake: every bone of every armature as Blender evaluates it (IK,
constraints, NLA clips and all), at every frame, as glTF node transforms.

One scene evaluation per frame serves every armature. The armatures' meshes
are left out of the evaluation meanwhile (deforming them would be most of its
cost, and the bake needs only the bones), and the bone matrices are read in
bulk and converted a block of frames at a time.

An armature hidden from renders at a frame (an agent that has left) is
written there with its root bones scaled to zero: glTF viewers then draw
nothing of it (the exporters of Blender 3.4, 4.5 and 5.0 write no
KHR_node_visibility).
"""

from dataclasses import dataclass
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy

from ..core import node_motion

BLOCK = 64  # frames converted at once
MAX_SHEAR = 1e-3  # largest cosine between a pose's axes that counts as none


class BakeError(ValueError):
    """A pose that glTF cannot hold; the message names the agent, bone and frame."""


@dataclass
class BakedBones:
    """One armature's bones at every frame, as glTF node transforms."""

    names: List[str]
    parents: List[int]  # index of each bone's parent, or -1
    translations: numpy.ndarray  # (frames, bones, 3)
    rotations: numpy.ndarray  # (frames, bones, 4): x, y, z, w, continuous in sign
    scales: numpy.ndarray  # (frames, bones, 3)


def bone_parents(bones) -> List[int]:
    """Each bone's parent index in `bones` (armature or pose bones), or -1."""
    index = {bone.name: i for i, bone in enumerate(bones)}
    return [index[bone.parent.name] if bone.parent else -1 for bone in bones]


def rest_node_matrices(armature_data) -> numpy.ndarray:
    """The bones' rest poses as node transforms (bones, 4, 4)."""
    rest = numpy.array([numpy.array(bone.matrix_local) for bone in armature_data.bones])
    return node_motion.node_matrices(rest, bone_parents(armature_data.bones))


def bake(armatures, scene, frames: Sequence[int], progress: Optional[Callable[[float], None]] = None) -> List[BakedBones]:
    """Samples the armatures' bones at `frames`; the scene's frame is left at
    the last one. Armatures of one skeleton are converted together."""
    skeletons: Dict[Tuple[int, ...], List[int]] = {}
    for i, armature in enumerate(armatures):
        skeletons.setdefault(tuple(bone_parents(armature.pose.bones)), []).append(i)
    baked: List[Optional[BakedBones]] = [None] * len(armatures)
    groups = []
    for parents, members in skeletons.items():
        shape = (len(frames), len(members), len(parents))
        group = _Group(members, parents, numpy.empty(shape + (3,), numpy.float32),
                       numpy.empty(shape + (4,), numpy.float32), numpy.empty(shape + (3,), numpy.float32))
        for k, i in enumerate(members):
            baked[i] = BakedBones([b.name for b in armatures[i].pose.bones], list(parents), group.translations[:, k],
                                  group.rotations[:, k], group.scales[:, k])
        groups.append(group)
    bodies = [child for armature in armatures for child in armature.children if not child.hide_viewport]
    try:
        for body in bodies:
            body.hide_viewport = True
        for start in range(0, len(frames), BLOCK):
            block = frames[start:start + BLOCK]
            matrices = [numpy.empty((len(block), len(g.members), len(g.parents) * 16), numpy.float32) for g in groups]
            hidden = [numpy.zeros((len(block), len(g.members)), bool) for g in groups]
            for row, frame in enumerate(block):
                scene.frame_set(frame)
                for group, sampled, gone in zip(groups, matrices, hidden):
                    for k, i in enumerate(group.members):
                        armatures[i].pose.bones.foreach_get("matrix", sampled[row, k])
                        gone[row, k] = armatures[i].hide_render
            rows = slice(start, start + len(block))
            for group, sampled in zip(groups, matrices):
                # foreach_get gives Blender's column-major layout: transpose.
                poses = sampled.reshape(sampled.shape[:2] + (len(group.parents), 4, 4)).transpose(0, 1, 2, 4, 3)
                poses = poses.astype(float)
                _refuse_shear(poses, block, [armatures[i] for i in group.members])
                group.translations[rows], group.rotations[rows], group.scales[rows] = node_motion.decompose(
                    node_motion.node_matrices(poses, group.parents))
            for group, gone in zip(groups, hidden):
                roots = [b for b, parent in enumerate(group.parents) if parent < 0]
                rows_gone, members_gone = numpy.nonzero(gone)
                for b in roots:
                    group.scales[start + rows_gone, members_gone, b] = 0.0
            if progress:
                progress(min(start + BLOCK, len(frames)) / len(frames))
    finally:
        for body in bodies:
            body.hide_viewport = False
    for group in groups:
        group.rotations[:] = node_motion.continuous(group.rotations)
    return baked


def _refuse_shear(poses: numpy.ndarray, frames: Sequence[int], armatures) -> None:
    """A sheared bone (a non-uniform scale above a turned bone) cannot be
    written as glTF translation, rotation and scale: say where, and stop."""
    sheared = node_motion.shear(poses) > MAX_SHEAR
    if sheared.any():
        row, member, bone = (int(i[0]) for i in numpy.nonzero(sheared))
        armature = armatures[member]
        raise BakeError(f"agent '{armature.name}', bone '{armature.pose.bones[bone].name}', frame {frames[row]}: "
                         "the pose is sheared (a non-uniform scale above a turned bone); glTF cannot hold it")


@dataclass
class _Group:
    """Armatures of one skeleton and their bones' node transforms (frames, armatures, bones, ...)."""

    members: List[int]
    parents: Tuple[int, ...]
    translations: numpy.ndarray
    rotations: numpy.ndarray
    scales: numpy.ndarray
