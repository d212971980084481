"""The pieces of the crowd export that run outside Blender: bone poses as
glTF node transforms (node_motion) and the .glb container (glb)."""

import json
import math
import struct

import numpy
import pytest

from footfall.core import glb, node_motion


def rotation_matrix(axis, angle):
    x, y, z = numpy.asarray(axis, dtype=float) / numpy.linalg.norm(axis)
    c, s, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return numpy.array([[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                        [t * x * z - s * y, t * y * z + s * x, t * z * z + c]])


def quaternion(axis, angle):
    axis = numpy.asarray(axis, dtype=float) / numpy.linalg.norm(axis)
    return numpy.append(math.sin(angle / 2) * axis, math.cos(angle / 2))


def affine(rotation, translation=(0, 0, 0), scale=(1, 1, 1)):
    matrix = numpy.identity(4)
    matrix[:3, :3] = rotation * numpy.asarray(scale, dtype=float)
    matrix[:3, 3] = translation
    return matrix


def test_decompose_recovers_translation_rotation_and_scale():
    rng = numpy.random.default_rng(7)
    cases = [((1, 0, 0), math.pi), ((0, 1, 0), math.pi), ((0, 0, 1), math.pi), ((1, 1, 1), 2.0),
             ((0, 0, 1), 0.0), ((1, -2, 0.5), 3.1)]  # half turns take the x, y and z branches
    cases += [(rng.normal(size=3), rng.uniform(0, 2 * math.pi)) for _ in range(200)]
    matrices, expected = [], []
    for axis, angle in cases:
        t, s = rng.normal(size=3), rng.uniform(0.5, 2.0, size=3)
        matrices.append(affine(rotation_matrix(axis, angle), t, s))
        expected.append((t, quaternion(axis, angle), s))
    translations, rotations, scales = node_motion.decompose(numpy.array(matrices))
    for (t, q, s), t2, q2, s2 in zip(expected, translations, rotations, scales):
        assert numpy.allclose(t2, t) and numpy.allclose(s2, s)
        assert abs(abs(numpy.dot(q2, q)) - 1) < 1e-9, (q, q2)  # q and -q are one rotation
        assert abs(numpy.linalg.norm(q2) - 1) < 1e-12


def test_shear_is_zero_for_rotation_and_scale_only():
    turned = affine(rotation_matrix((1, 2, 3), 0.7), (1, 2, 3), (0.5, 2.0, 1.0))
    assert node_motion.shear(turned) < 1e-12
    # A non-uniform scale above a turned bone shears it.
    sheared = affine(numpy.identity(3), scale=(1.0, 3.0, 1.0)) @ affine(rotation_matrix((0, 0, 1), 0.6))
    assert node_motion.shear(sheared) > 0.1


def test_continuous_takes_the_short_way():
    angles = numpy.linspace(0, 6 * math.pi, 100)  # three full turns: q alone wraps to -q
    rotations = numpy.array([quaternion((0, 0, 1), a) for a in angles])
    rotations[1::3] *= -1  # and some signs flipped at random
    smooth = node_motion.continuous(rotations[:, None, :])[:, 0]
    assert numpy.all(numpy.sum(smooth[1:] * smooth[:-1], axis=1) > 0)
    assert numpy.allclose(numpy.abs(numpy.sum(smooth * rotations, axis=1)), 1)  # the same rotations


def test_node_matrices_are_relative_to_the_parent_and_roots_turn_y_up():
    hips = affine(rotation_matrix((1, 0, 0), math.pi / 2), (0, 0, 1))
    spine = hips @ affine(rotation_matrix((0, 0, 1), 0.3), (0, 0.1, 0))
    poses = numpy.array([[hips, spine]])  # one frame, two bones
    nodes = node_motion.node_matrices(poses, [-1, 0])
    assert numpy.allclose(nodes[0, 1], affine(rotation_matrix((0, 0, 1), 0.3), (0, 0.1, 0)))
    # Blender's +90 degrees about X (a bone pointing up) is glTF's identity, one metre up in Y.
    assert numpy.allclose(nodes[0, 0], affine(numpy.identity(3), (0, 1, 0)))


def test_glb_round_trip_with_added_floats(tmp_path):
    file = glb.Glb({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 3}]}, bytearray(b"abc"))
    times = file.add_floats(numpy.array([0.0, 0.5, 1.0]), bounds=True)
    rotations = file.add_floats(numpy.array([[0, 0, 0, 1.0], [0, 0, 1.0, 0]]))
    path = tmp_path / "a.glb"
    glb.write(file, str(path))
    data = path.read_bytes()
    assert data[:4] == b"glTF" and struct.unpack_from("<II", data, 4) == (2, len(data))
    back = glb.read(str(path))
    document = back.document
    assert document["accessors"][times] == {"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR",
                                            "min": [0.0], "max": [1.0]}
    assert document["accessors"][rotations]["type"] == "VEC4" and "min" not in document["accessors"][rotations]
    view = document["bufferViews"][1]
    assert view["byteOffset"] % 4 == 0 and view["byteOffset"] >= 3  # after the old data, aligned
    values = numpy.frombuffer(bytes(back.binary[view["byteOffset"]:view["byteOffset"] + view["byteLength"]]), "<f4")
    assert values.tolist() == [0, 0, 0, 1, 0, 0, 1, 0]
    assert document["buffers"][0]["byteLength"] == len(back.binary) and len(back.binary) % 4 == 0
    assert bytes(back.binary[:3]) == b"abc"
    json_length = struct.unpack_from("<I", data, 12)[0]
    assert json_length % 4 == 0 and json.loads(data[20:20 + json_length]) == document


def test_glb_refuses_what_is_not_one(tmp_path):
    path = tmp_path / "a.glb"
    path.write_bytes(b'{"asset": {}}')
    with pytest.raises(glb.GlbError, match="not a binary glTF"):
        glb.read(str(path))
    path.write_bytes(b"glTF" + struct.pack("<IIII", 2, 999, 4, glb.JSON_CHUNK))
    with pytest.raises(glb.GlbError, match="999 bytes declared, 20 found"):
        glb.read(str(path))
    path.write_bytes(b"glTF" + struct.pack("<IIII", 2, 20, 4, glb.JSON_CHUNK))
    with pytest.raises(glb.GlbError, match="a chunk of 4 bytes at byte 12 runs past the end"):
        glb.read(str(path))
