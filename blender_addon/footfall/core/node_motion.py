# SPDX-License-Identifier: GPL-3.0-or-later
"""Bone poses as glTF node transforms: each bone relative to its glTF parent
node, split into translation, rotation and scale.

Blender's glTF exporter writes an armature's bones as nodes in the bones' own
frames: a child bone's node is its rest matrix relative to its parent bone's,
and a root bone's node also carries the turn from Blender's Z-up to glTF's
Y-up. With poses P in armature space, a posed bone's node transform is
inv(P_parent) @ P, or Y_UP @ P for a root bone.
"""

import numpy

# Blender (x, y, z) -> glTF (x, z, -y)
Y_UP = numpy.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def node_matrices(poses: numpy.ndarray, parents) -> numpy.ndarray:
    """Node transforms (..., bones, 4, 4) from armature-space bone matrices
    (..., bones, 4, 4); parents[i] is bone i's parent index, or -1."""
    parents = numpy.asarray(parents)
    roots = parents < 0
    # Each bone below its parent's inverse; the roots below Y_UP.
    below = _affine_inverse(poses)[..., numpy.where(roots, 0, parents), :, :]
    below[..., roots, :, :] = Y_UP
    return below @ poses


def _affine_inverse(matrices: numpy.ndarray) -> numpy.ndarray:
    """Inverses of affine matrices whose linear parts have orthogonal columns
    (rotation times scale, no shear): (R S)^-1 = S^-2 (R S)^T. Far faster than
    a general inverse for the millions of small matrices of a crowd's bake."""
    linear = matrices[..., :3, :3]
    inverse_linear = numpy.swapaxes(linear / numpy.sum(linear * linear, axis=-2, keepdims=True), -1, -2)
    inverse = numpy.zeros_like(matrices)
    inverse[..., :3, :3] = inverse_linear
    inverse[..., :3, 3] = -numpy.einsum("...ij,...j->...i", inverse_linear, matrices[..., :3, 3])
    inverse[..., 3, 3] = 1.0
    return inverse


def shear(matrices: numpy.ndarray) -> numpy.ndarray:
    """Per matrix (..., 4, 4), the largest cosine between two columns of its
    linear part: 0 for rotation times scale, which glTF's translation,
    rotation and scale can hold; more for a sheared one, which they cannot."""
    columns = [matrices[..., :3, k] for k in range(3)]
    lengths = [numpy.sqrt(numpy.sum(c * c, axis=-1)) for c in columns]
    cosines = [numpy.abs(numpy.sum(columns[a] * columns[b], axis=-1)) / (lengths[a] * lengths[b])
               for a, b in ((0, 1), (0, 2), (1, 2))]
    return numpy.maximum(numpy.maximum(cosines[0], cosines[1]), cosines[2])


def decompose(matrices: numpy.ndarray):
    """Translations (..., 3), unit rotations (..., 4) as glTF's x, y, z, w, and
    scales (..., 3) of affine matrices (..., 4, 4) without shear or mirroring."""
    translations = matrices[..., :3, 3]
    linear = matrices[..., :3, :3]
    scales = numpy.linalg.norm(linear, axis=-2)  # the columns' lengths
    return translations, _quaternions(linear / scales[..., None, :]), scales


def _quaternions(r: numpy.ndarray) -> numpy.ndarray:
    """Unit quaternions (x, y, z, w) of rotation matrices, each computed from
    its largest component so that none loses precision."""
    m00, m11, m22 = r[..., 0, 0], r[..., 1, 1], r[..., 2, 2]
    sx, sy, sz = r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0], r[..., 1, 0] - r[..., 0, 1]
    pxy, pxz, pyz = r[..., 0, 1] + r[..., 1, 0], r[..., 0, 2] + r[..., 2, 0], r[..., 1, 2] + r[..., 2, 1]
    # Each row is 4 q_k times q, for k = x, y, z, w.
    candidates = numpy.stack([
        numpy.stack([1.0 + m00 - m11 - m22, pxy, pxz, sx], axis=-1),
        numpy.stack([pxy, 1.0 - m00 + m11 - m22, pyz, sy], axis=-1),
        numpy.stack([pxz, pyz, 1.0 - m00 - m11 + m22, sz], axis=-1),
        numpy.stack([sx, sy, sz, 1.0 + m00 + m11 + m22], axis=-1),
    ], axis=-2)
    largest = numpy.argmax(numpy.stack([m00 - m11 - m22, m11 - m00 - m22, m22 - m00 - m11, m00 + m11 + m22], axis=-1), axis=-1)
    chosen = numpy.take_along_axis(candidates, largest[..., None, None], axis=-2)[..., 0, :]
    return chosen / numpy.linalg.norm(chosen, axis=-1, keepdims=True)


def continuous(rotations: numpy.ndarray) -> numpy.ndarray:
    """Quaternions (frames, ..., 4) with signs flipped so that each is on the
    same side as the frame before: interpolation then takes the short way."""
    flips = numpy.sum(rotations[1:] * rotations[:-1], axis=-1) < 0
    signs = numpy.concatenate([numpy.ones_like(flips[:1], dtype=float),
                               numpy.where(numpy.cumsum(flips, axis=0) % 2 == 1, -1.0, 1.0)])
    return rotations * signs[..., None]
