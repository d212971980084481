"""crowd_glb, the tests' own glTF reader, against small .glb files built here
byte by byte and values worked out by hand."""

import json
import math
import struct

import numpy
import pytest

from crowd_glb import CrowdGlb, GlbError, z_up

DTYPES = {5120: "<i1", 5121: "<u1", 5122: "<i2", 5123: "<u2", 5125: "<u4", 5126: "<f4"}
C45 = math.sqrt(0.5)  # cos 45 degrees = sin 45 degrees


def glb_bytes(document, binary=b""):
    """A .glb container: header, JSON chunk padded with spaces, BIN chunk padded with zeros."""
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
    if binary:
        binary += b"\0" * (-len(binary) % 4)
        chunks += struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


class Builder:
    """A glTF document and its BIN chunk, grown one bufferView or accessor at a time."""

    def __init__(self):
        self.binary = bytearray()
        self.document = {"asset": {"version": "2.0"}, "bufferViews": [], "accessors": []}

    def view(self, data, **extra):
        self.binary += b"\0" * (-len(self.binary) % 4)
        self.document["bufferViews"].append({"buffer": 0, "byteOffset": len(self.binary),
                                             "byteLength": len(data), **extra})
        self.binary += data
        return len(self.document["bufferViews"]) - 1

    def accessor(self, values, kind, component=5126, **extra):
        values = numpy.asarray(values, dtype=DTYPES[component])
        accessors = self.document["accessors"]
        accessors.append({"bufferView": self.view(values.tobytes()), "componentType": component,
                          "count": len(values), "type": kind, **extra})
        return len(accessors) - 1

    def write(self, path):
        self.document["buffers"] = [{"byteLength": len(self.binary)}]
        path.write_bytes(glb_bytes(self.document, bytes(self.binary)))
        return CrowdGlb(path)


def about_y(degrees):
    half = math.radians(degrees) / 2
    return [0.0, math.sin(half), 0.0, math.cos(half)]


def y_rotation(degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return numpy.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


@pytest.fixture
def crowd(tmp_path):
    """An agent whose hip turns 0 -> 90 degrees about Y over 2 s (LINEAR), a STEP-moved
    node, a CUBICSPLINE-moved and turned node, and a second root holding a non-root "agent".
    Channels for weights or without a node (KHR_animation_pointer) must not move anything."""
    b = Builder()
    two_keys = b.accessor([0.0, 2.0], "SCALAR")
    three_keys = b.accessor([0.0, 1.0, 2.0], "SCALAR")
    zero = [0.0] * 4
    samplers = [
        {"input": two_keys, "output": b.accessor([about_y(0), about_y(90)], "VEC4")},
        {"input": three_keys, "output": b.accessor([[0, 0, 0], [0, 0, 1], [0, 0, 2]], "VEC3"),
         "interpolation": "STEP"},
        # per key: in-tangent, value, out-tangent; the out-tangent of key 0 is 3 units/s
        {"input": two_keys, "interpolation": "CUBICSPLINE",
         "output": b.accessor([[0, 0, 0], [0, 0, 0], [3, 0, 0], [0, 0, 0], [1, 0, 0], [0, 0, 0]], "VEC3")},
        {"input": two_keys, "interpolation": "CUBICSPLINE",
         "output": b.accessor([zero, about_y(0), zero, zero, about_y(90), zero], "VEC4")},
        {"input": two_keys, "output": b.accessor([0.0, 1.0], "SCALAR")},
        # -q is the same rotation as q; slerp must still take the 90-degree way
        {"input": two_keys, "output": b.accessor([about_y(0), [-v for v in about_y(90)]], "VEC4")},
    ]
    pointer = {"KHR_animation_pointer": {"pointer": "/nodes/0/translation"}}
    b.document.update(
        scene=0,
        scenes=[{"nodes": [0, 5]}],
        nodes=[{"name": "agent", "translation": [1, 2, 3], "children": [1, 3, 4]},
               {"name": "hip", "translation": [0, 1, 0], "children": [2]},
               {"name": "foot", "translation": [1, 0, 0]},
               {"name": "stepper"},
               {"name": "spline"},
               {"name": "bystander", "children": [6]},
               {"name": "agent"}],
        animations=[
            {"name": "walk", "samplers": samplers[:5], "channels": [
                {"sampler": 0, "target": {"node": 1, "path": "rotation"}},
                {"sampler": 1, "target": {"node": 3, "path": "translation"}},
                {"sampler": 2, "target": {"node": 4, "path": "translation"}},
                {"sampler": 3, "target": {"node": 4, "path": "rotation"}},
                {"sampler": 4, "target": {"node": 3, "path": "weights"}},
                {"sampler": 1, "target": {"path": "pointer", "extensions": pointer}},
                {"sampler": 1, "target": {"path": "translation"}}]},  # no node: ignored
            {"name": "walk_flipped", "samplers": [samplers[5]], "channels": [
                {"sampler": 0, "target": {"node": 1, "path": "rotation"}}]},
        ],
    )
    return b.write(tmp_path / "crowd.glb")


def test_names_times_roots_and_subtrees(crowd):
    assert crowd.animation_names() == ["walk", "walk_flipped"]
    numpy.testing.assert_array_equal(crowd.animation_times("walk"), [0.0, 1.0, 2.0])
    assert crowd.agent_root("agent") == 0  # node 6 is also "agent", but not a root of the scene
    assert crowd.subtree(0) == {"agent": 0, "hip": 1, "foot": 2, "stepper": 3, "spline": 4}
    with pytest.raises(GlbError, match="0 root nodes"):
        crowd.agent_root("hip")
    with pytest.raises(GlbError, match="0 animations"):
        crowd.animation_times("run")


def test_rest_pose_is_the_node_translations(crowd):
    positions = crowd.world_positions(None, [0.0, 1.0], ["foot"], root=0)
    numpy.testing.assert_allclose(positions["foot"], [[2, 3, 3], [2, 3, 3]])


def test_linear_rotation_turns_the_child_offset(crowd):
    """foot = agent translation + hip offset + hip rotation applied to (1, 0, 0), which about
    Y is (cos a, 0, -sin a); a is 45 degrees halfway, 22.5 (slerp, not nlerp) at a quarter,
    and the end values hold outside the keys."""
    times = [-1.0, 0.5, 1.0, 2.0, 3.0]
    angles = numpy.radians([0.0, 22.5, 45.0, 90.0, 90.0])
    expected = numpy.stack([1 + numpy.cos(angles), numpy.full(5, 3.0), 3 - numpy.sin(angles)], axis=-1)
    for animation in ("walk", "walk_flipped"):
        positions = crowd.world_positions(animation, times, ["foot", "hip"], root=0)
        numpy.testing.assert_allclose(positions["foot"], expected, atol=1e-6)
        numpy.testing.assert_allclose(positions["hip"], numpy.tile([1, 3, 3], (5, 1)), atol=1e-6)
    hip = crowd.world_matrices("walk", [1.0], nodes=[1])[1][0]
    numpy.testing.assert_allclose(hip[:3, :3], y_rotation(45), atol=1e-6)


def test_step_holds_each_key_until_the_next(crowd):
    positions = crowd.world_positions("walk", [-1.0, 0.5, 1.0, 1.999, 5.0], ["stepper"], root=0)
    numpy.testing.assert_allclose(positions["stepper"][:, 2], 3 + numpy.array([0, 0, 1, 1, 2]))


def test_cubic_spline_scales_tangents_by_the_key_interval(crowd):
    """Keys 0 -> 1 over 2 s with out-tangent 3/s: at s = 1/2, h01 = 1/2 and 2 s * h10 * 3 = 0.75;
    at s = 1/4, h01 = 0.15625 and 2 s * 0.140625 * 3 = 0.84375. The rotation keys (0 and 90
    degrees about Y, zero tangents) meet halfway at 45 degrees once normalised."""
    matrices = crowd.world_matrices("walk", [0.5, 1.0], nodes=[4])[4]
    numpy.testing.assert_allclose(matrices[:, :3, 3], [[1 + 1.0, 2, 3], [1 + 1.25, 2, 3]], atol=1e-6)
    numpy.testing.assert_allclose(matrices[1, :3, :3], y_rotation(45), atol=1e-6)
    rotation = matrices[0, :3, :3]
    numpy.testing.assert_allclose(rotation @ rotation.T, numpy.identity(3), atol=1e-6)


def test_node_matrix_is_column_major(tmp_path):
    """A root matrix turning 90 degrees about Z and moving to (4, 5, 6): the child's (1, 0, 0)
    lands at (4, 6, 6). Animating a node that has a matrix is refused."""
    b = Builder()
    column_major = [0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1]
    matrices = b.accessor([column_major], "MAT4")
    keys = b.accessor([0.0], "SCALAR")
    b.document.update(scenes=[{"nodes": [0]}],
                      nodes=[{"name": "agent", "matrix": column_major, "children": [1]},
                             {"name": "tip", "translation": [1, 0, 0]}],
                      animations=[{"name": "bad", "samplers": [
                          {"input": keys, "output": b.accessor([[0, 0, 0]], "VEC3")}],
                          "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}])
    glb = b.write(tmp_path / "matrix.glb")
    numpy.testing.assert_allclose(glb.world_positions(None, [0.0], ["tip"], root=0)["tip"], [[4, 6, 6]])
    matrix = glb.accessor(matrices)
    assert matrix.shape == (1, 4, 4)
    numpy.testing.assert_array_equal(matrix[0, :3, 3], [4, 5, 6])
    assert matrix[0, 1, 0] == 1  # x goes to y
    with pytest.raises(GlbError, match="has a matrix"):
        glb.world_matrices("bad", [0.0])


def test_accessor_offsets_strides_normalisation_sparse_and_matrix_padding(tmp_path):
    b = Builder()
    b.view(b"\0" * 4)  # so the interleaved view does not start at byte 0
    interleaved = numpy.arange(18, dtype="<f4").reshape(3, 6)  # per vertex: position, normal
    view = b.view(interleaved.tobytes(), byteStride=24)
    accessors = b.document["accessors"]
    for offset in (0, 12):
        accessors.append({"bufferView": view, "byteOffset": offset, "componentType": 5126,
                          "count": 3, "type": "VEC3"})
    shorts = b.accessor([[0, 65535, 13107, 32768], [1, 2, 3, 4]], "VEC4", 5123, normalized=True)
    bytes_ = b.accessor([-128, -127, 0, 127], "SCALAR", 5120, normalized=True)
    sparse_indices, sparse_values = b.view(bytes([1, 3])), b.view(numpy.array([20, 40], "<f4").tobytes())
    sparse = {"count": 2, "indices": {"bufferView": sparse_indices, "componentType": 5121},
              "values": {"bufferView": sparse_values}}
    patched = b.accessor([1, 2, 3, 4, 5], "SCALAR", sparse=sparse)
    accessors.append({"componentType": 5126, "count": 5, "type": "SCALAR", "sparse": sparse})
    # a MAT2 of bytes pads each 2-byte column to 4 bytes
    padded = b.view(bytes([1, 2, 99, 99, 3, 4, 99, 99]))
    accessors.append({"bufferView": padded, "componentType": 5121, "count": 1, "type": "MAT2"})
    glb = b.write(tmp_path / "accessors.glb")

    numpy.testing.assert_array_equal(glb.accessor(0), interleaved[:, :3])
    numpy.testing.assert_array_equal(glb.accessor(1), interleaved[:, 3:])
    numpy.testing.assert_allclose(glb.accessor(shorts)[0], [0, 1, 0.2, 32768 / 65535])
    numpy.testing.assert_array_equal(glb.accessor(bytes_), [-1, -1, 0, 1])
    numpy.testing.assert_array_equal(glb.accessor(patched), [1, 20, 3, 40, 5])
    numpy.testing.assert_array_equal(glb.accessor(patched + 1), [0, 20, 0, 40, 0])
    numpy.testing.assert_array_equal(glb.accessor(patched + 2), [[[1, 3], [2, 4]]])
    assert glb.accessor(0).dtype == numpy.float64


def test_malformed_files_raise_glb_error(tmp_path, crowd):
    whole = crowd.path.read_bytes()
    cases = {"truncated": whole[:-4], "magic": b"gLTF" + whole[4:], "header": whole[:10],
             "not_json": glb_bytes({"asset": {"version": "2.0"}}).replace(b'"asset"', b"'asset'")}
    for name, data in cases.items():
        (tmp_path / name).write_bytes(data)
        with pytest.raises(GlbError):
            CrowdGlb(tmp_path / name)


def test_a_file_without_a_bin_chunk_has_empty_binary(tmp_path):
    (tmp_path / "empty.glb").write_bytes(glb_bytes({"asset": {"version": "2.0"}}))
    assert CrowdGlb(tmp_path / "empty.glb").binary == b""


def test_bad_references_raise_glb_error(tmp_path):
    b = Builder()
    b.accessor([1.0, 2.0], "SCALAR")
    b.document["accessors"].append({"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR"})
    b.document.update(scenes=[{"nodes": [0]}],
                      nodes=[{"name": "agent", "children": [1, 2]}, {"name": "hand"}, {"name": "hand"}])
    glb = b.write(tmp_path / "bad.glb")
    with pytest.raises(GlbError, match="bufferView 0"):
        glb.accessor(1)
    with pytest.raises(GlbError, match="accessors 7 does not exist"):
        glb.accessor(7)
    with pytest.raises(GlbError, match="both named 'hand'"):
        glb.subtree(0)


def test_z_up():
    numpy.testing.assert_array_equal(z_up([[1, 2, 3], [0, 1, 0]]), [[1, -3, 2], [0, 0, 1]])
