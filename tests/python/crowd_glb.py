"""An independent reader of animated binary glTF 2.0 (.glb) files, for tests.

It follows the glTF 2.0 specification, not the conventions of any writer, so a
test that reads a crowd file through it sees what a conforming viewer would:
the scene hierarchy, node transforms and sampled animation. Where the file
breaks a rule that matters for that, it raises GlbError rather than guessing.
"""

import base64
import json
import pathlib
import struct
import urllib.parse

import numpy

MAGIC = 0x46546C67  # b"glTF"
JSON_CHUNK = 0x4E4F534A
BIN_CHUNK = 0x004E4942

COMPONENT_TYPES = {5120: "<i1", 5121: "<u1", 5122: "<i2", 5123: "<u2", 5125: "<u4", 5126: "<f4"}
# Normalised integers map to floats by c / max, and signed ones are clamped at -1.
NORMALISED_MAXIMA = {5120: 127.0, 5121: 255.0, 5122: 32767.0, 5123: 65535.0}
SPARSE_INDEX_TYPES = (5121, 5123, 5125)
# (columns, numbers per column); matrices are stored column by column.
ACCESSOR_TYPES = {"SCALAR": (1, 1), "VEC2": (1, 2), "VEC3": (1, 3), "VEC4": (1, 4),
                  "MAT2": (2, 2), "MAT3": (3, 3), "MAT4": (4, 4)}
# The animation paths that move nodes, with their rest values.
NODE_PATHS = {"translation": (0.0, 0.0, 0.0), "rotation": (0.0, 0.0, 0.0, 1.0), "scale": (1.0, 1.0, 1.0)}
INTERPOLATIONS = ("LINEAR", "STEP", "CUBICSPLINE")


class GlbError(ValueError):
    """The file breaks the glTF 2.0 rules this reader relies on, or lacks what was asked for."""


def z_up(points):
    """glTF Y-up (x, y, z) as Blender's Z-up (x, -z, y), for arrays of shape (..., 3)."""
    points = numpy.asarray(points, dtype=float)
    return numpy.stack([points[..., 0], -points[..., 2], points[..., 1]], axis=-1)


def _required(item, key, where):
    if key not in item:
        raise GlbError(f"{where} has no {key!r}")
    return item[key]


def _entry(items, index, where):
    """items[index], refusing what JSON allows but glTF does not (bools, negatives)."""
    if isinstance(index, bool) or not isinstance(index, int) or not 0 <= index < len(items):
        raise GlbError(f"{where} {index!r} does not exist (there are {len(items)})")
    return items[index]


def _split_chunks(data, name):
    """The JSON document and BIN chunk of a .glb, after checking the header and chunk framing."""
    if len(data) < 12:
        raise GlbError(f"{name}: {len(data)} bytes, shorter than the 12-byte GLB header")
    magic, version, length = struct.unpack_from("<III", data)
    if magic != MAGIC:
        raise GlbError(f"{name}: magic is {data[:4]!r}, not b'glTF'")
    if version != 2:
        raise GlbError(f"{name}: GLB container version {version}, not 2")
    if length != len(data):
        raise GlbError(f"{name}: the header says {length} bytes but the file has {len(data)} (truncated?)")
    chunks, offset = [], 12
    while offset < length:
        if offset + 8 > length:
            raise GlbError(f"{name}: the chunk header at byte {offset} is cut off")
        size, kind = struct.unpack_from("<II", data, offset)
        if offset + 8 + size > length:
            raise GlbError(f"{name}: the chunk at byte {offset} runs {offset + 8 + size - length} bytes past the end")
        if size % 4:
            raise GlbError(f"{name}: the chunk at byte {offset} is {size} bytes, not a multiple of 4")
        chunks.append((kind, data[offset + 8:offset + 8 + size]))
        offset += 8 + size
    if not chunks or chunks[0][0] != JSON_CHUNK:
        raise GlbError(f"{name}: the first chunk is not JSON")
    for position, (kind, _) in enumerate(chunks[1:], start=1):
        if kind == JSON_CHUNK or (kind == BIN_CHUNK and position != 1):
            raise GlbError(f"{name}: chunk {position} is a {'JSON' if kind == JSON_CHUNK else 'BIN'} chunk;"
                           " only chunk 0 may be JSON and only chunk 1 BIN")
    try:
        document = json.loads(chunks[0][1].decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise GlbError(f"{name}: the JSON chunk does not parse: {error}") from None
    if not isinstance(document, dict):
        raise GlbError(f"{name}: the JSON chunk is not an object")
    asset_version = str(document.get("asset", {}).get("version", ""))
    if asset_version.split(".")[0] != "2":
        raise GlbError(f"{name}: asset.version is {asset_version!r}, not 2.x")
    binary = chunks[1][1] if len(chunks) > 1 and chunks[1][0] == BIN_CHUNK else b""
    return document, binary


def _unit(quaternions):
    lengths = numpy.linalg.norm(quaternions, axis=-1, keepdims=True)
    if numpy.any(lengths < 1e-12):
        raise GlbError("a rotation quaternion has zero length")
    return quaternions / lengths


def _slerp(start, end, fraction):
    """Spherical linear interpolation along the shorter arc; fraction has shape (n, 1)."""
    start, end = _unit(start), _unit(end)
    cosine = numpy.sum(start * end, axis=-1, keepdims=True)
    end = numpy.where(cosine < 0, -end, end)  # q and -q are one rotation: take the shorter way
    angle = numpy.arccos(numpy.clip(numpy.abs(cosine), 0.0, 1.0))
    sine = numpy.sin(angle)
    close = sine < 1e-9  # (nearly) equal keys: linear weights are exact enough and do not divide by 0
    safe = numpy.where(close, 1.0, sine)
    weight_start = numpy.where(close, 1 - fraction, numpy.sin((1 - fraction) * angle) / safe)
    weight_end = numpy.where(close, fraction, numpy.sin(fraction * angle) / safe)
    return _unit(weight_start * start + weight_end * end)


def _rotation_matrices(quaternions):
    """(..., 3, 3) rotation matrices of (x, y, z, w) quaternions, normalised first."""
    x, y, z, w = numpy.moveaxis(_unit(quaternions), -1, 0)
    return numpy.stack([
        numpy.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], axis=-1),
        numpy.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], axis=-1),
        numpy.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=-2)


class CrowdGlb:
    """One .glb file: its JSON `document`, its BIN chunk `binary`, and what they describe."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        self.document, self.binary = _split_chunks(self.path.read_bytes(), self.path.name)
        self._buffers = {}
        self._parents = None
        self._animated = {}

    def _item(self, kind, index):
        return _entry(self.document.get(kind, []), index, kind)

    def _buffer(self, index):
        """The bytes of buffer `index`: the BIN chunk for buffer 0 without a uri, else the uri's data."""
        if index not in self._buffers:
            buffer = self._item("buffers", index)
            length = _required(buffer, "byteLength", f"buffer {index}")
            uri = buffer.get("uri")
            if uri is None:
                if index != 0:
                    raise GlbError(f"buffer {index} has no uri, but only buffer 0 may be the BIN chunk")
                # The BIN chunk may hold up to 3 bytes of padding beyond byteLength.
                if not length <= len(self.binary) <= length + 3:
                    raise GlbError(f"buffer 0 is {length} bytes but the BIN chunk is {len(self.binary)}")
                data = self.binary
            elif uri.startswith("data:"):
                header, _, payload = uri.partition(",")
                if not header.endswith(";base64"):
                    raise GlbError(f"buffer {index}: only base64 data URIs are supported")
                data = base64.b64decode(payload)
            else:
                try:
                    data = (self.path.parent / urllib.parse.unquote(uri)).read_bytes()
                except OSError as error:
                    raise GlbError(f"buffer {index}: cannot read {uri!r}: {error}") from None
            if len(data) < length:
                raise GlbError(f"buffer {index} is {length} bytes but its data has {len(data)}")
            self._buffers[index] = memoryview(data)[:length]
        return self._buffers[index]

    def _elements(self, view_index, offset, count, component, kind, where):
        """The raw elements of a (count, columns, numbers per column) block inside a bufferView."""
        view = self._item("bufferViews", view_index)
        buffer = self._buffer(_required(view, "buffer", f"bufferView {view_index}"))
        view_offset = view.get("byteOffset", 0)
        view_length = _required(view, "byteLength", f"bufferView {view_index}")
        if view_offset + view_length > len(buffer):
            raise GlbError(f"bufferView {view_index} ends at byte {view_offset + view_length},"
                           f" past its {len(buffer)}-byte buffer")
        dtype = numpy.dtype(COMPONENT_TYPES[component])
        columns, rows = ACCESSOR_TYPES[kind]
        column_stride = rows * dtype.itemsize
        if columns > 1:  # every matrix column starts on a 4-byte boundary
            column_stride += -column_stride % 4
        element = columns * column_stride
        stride = view.get("byteStride", element)
        if stride < element:
            raise GlbError(f"{where}: byteStride {stride} is less than its {element}-byte elements")
        if (view_offset + offset) % dtype.itemsize or stride % dtype.itemsize:
            raise GlbError(f"{where}: data is not aligned to its {dtype.itemsize}-byte components")
        end = offset + stride * (count - 1) + element
        if end > view_length:
            raise GlbError(f"{where}: {count} elements need {end} bytes of bufferView {view_index},"
                           f" which has {view_length}")
        return numpy.ndarray((count, columns, rows), dtype, buffer, view_offset + offset,
                             (stride, column_stride, dtype.itemsize))

    def accessor(self, index):
        """Accessor `index` as float64: shape (count,) for SCALAR, (count, n) for VECn and
        (count, n, n) for MATn (row, column), with normalisation and sparse values applied."""
        where = f"accessor {index}"
        accessor = self._item("accessors", index)
        component = _required(accessor, "componentType", where)
        kind = _required(accessor, "type", where)
        count = _required(accessor, "count", where)
        if component not in COMPONENT_TYPES:
            raise GlbError(f"{where}: componentType {component} is not a glTF 2.0 accessor type")
        if kind not in ACCESSOR_TYPES:
            raise GlbError(f"{where}: unknown type {kind!r}")
        if not isinstance(count, int) or count < 1:
            raise GlbError(f"{where}: count {count!r} is not a positive integer")
        normalized = accessor.get("normalized", False)
        if normalized and component not in NORMALISED_MAXIMA:
            raise GlbError(f"{where}: normalized is not allowed for componentType {component}")
        columns, rows = ACCESSOR_TYPES[kind]
        if "bufferView" in accessor:
            values = self._elements(accessor["bufferView"], accessor.get("byteOffset", 0), count,
                                    component, kind, where).astype(numpy.float64)
        else:  # no data: zeros, which a sparse block may replace
            values = numpy.zeros((count, columns, rows))
        if "sparse" in accessor:
            self._apply_sparse(accessor["sparse"], values, component, kind, where)
        if normalized:
            values = numpy.maximum(values / NORMALISED_MAXIMA[component], -1.0)
        if columns > 1:
            return values.transpose(0, 2, 1).copy()
        return values.reshape(count) if rows == 1 else values.reshape(count, rows)

    def _apply_sparse(self, sparse, values, component, kind, where):
        """Replaces the elements a sparse block lists, in place."""
        where = f"{where} sparse"
        count = _required(sparse, "count", where)
        if not isinstance(count, int) or count < 1:
            raise GlbError(f"{where}: count {count!r} is not a positive integer")
        indices, replacements = _required(sparse, "indices", where), _required(sparse, "values", where)
        index_type = _required(indices, "componentType", f"{where} indices")
        if index_type not in SPARSE_INDEX_TYPES:
            raise GlbError(f"{where}: indices componentType {index_type} is not 5121, 5123 or 5125")
        positions = self._elements(_required(indices, "bufferView", f"{where} indices"),
                                   indices.get("byteOffset", 0), count, index_type, "SCALAR",
                                   f"{where} indices").reshape(count).astype(numpy.int64)
        if numpy.any(numpy.diff(positions) <= 0) or positions[-1] >= len(values):
            raise GlbError(f"{where}: indices must increase strictly and stay below {len(values)}")
        values[positions] = self._elements(_required(replacements, "bufferView", f"{where} values"),
                                           replacements.get("byteOffset", 0), count, component, kind,
                                           f"{where} values")

    def animation_names(self):
        """The name of every animation, in file order ("" for an unnamed one)."""
        return [animation.get("name", "") for animation in self.document.get("animations", [])]

    def _animation(self, name):
        matches = [animation for animation in self.document.get("animations", [])
                   if animation.get("name", "") == name]
        if len(matches) != 1:
            raise GlbError(f"{len(matches)} animations are named {name!r}; expected exactly one")
        return matches[0]

    def animation_times(self, name):
        """Every key time of the animation's samplers, sorted, without repeats."""
        samplers = self._animation(name).get("samplers", [])
        # samplers often share one input accessor: read each once
        indices = {_required(sampler, "input", f"a sampler of {name!r}") for sampler in samplers}
        inputs = [self.accessor(index).reshape(-1) for index in sorted(indices)]
        return numpy.unique(numpy.concatenate(inputs)) if inputs else numpy.empty(0)

    def _node_samplers(self, name):
        """node index -> {path: sampler} of the animation's translation, rotation and scale channels."""
        if name not in self._animated:
            animation = self._animation(name)
            samplers = animation.get("samplers", [])
            animated = {}
            for channel in _required(animation, "channels", f"animation {name!r}"):
                target = _required(channel, "target", f"a channel of {name!r}")
                path = _required(target, "path", f"a channel target of {name!r}")
                # weights morph meshes; a target without a node (KHR_animation_pointer) is ignored per spec
                if path not in NODE_PATHS or "node" not in target:
                    continue
                node = target["node"]
                self._item("nodes", node)
                paths = animated.setdefault(node, {})
                if path in paths:
                    raise GlbError(f"animation {name!r} has two channels for node {node} {path}")
                paths[path] = _entry(samplers, _required(channel, "sampler", f"a channel of {name!r}"),
                                     f"animation {name!r} sampler")
            self._animated[name] = animated
        return self._animated[name]

    def _sample(self, sampler, path, times):
        """The sampler's value at each time, shape (len(times), 3 or 4)."""
        keys = self.accessor(_required(sampler, "input", "a sampler"))
        values = self.accessor(_required(sampler, "output", "a sampler"))
        interpolation = sampler.get("interpolation", "LINEAR")
        width = len(NODE_PATHS[path])
        if interpolation not in INTERPOLATIONS:
            raise GlbError(f"unknown sampler interpolation {interpolation!r}")
        if keys.ndim != 1:
            raise GlbError(f"sampler input accessor {sampler['input']} is not SCALAR")
        if numpy.any(numpy.diff(keys) <= 0):
            raise GlbError(f"sampler input accessor {sampler['input']} does not increase strictly")
        per_key = 3 if interpolation == "CUBICSPLINE" else 1
        if values.shape != (per_key * len(keys), width):
            raise GlbError(f"sampler output accessor {sampler['output']} has shape {values.shape}; a {path}"
                           f" {interpolation} sampler with {len(keys)} keys needs {(per_key * len(keys), width)}")
        if interpolation == "CUBICSPLINE":  # per key: in-tangent, value, out-tangent
            in_tangents, values, out_tangents = values.reshape(len(keys), 3, width).transpose(1, 0, 2)
        if interpolation == "STEP" or len(keys) == 1:
            return values[numpy.clip(numpy.searchsorted(keys, times, side="right") - 1, 0, len(keys) - 1)]
        # key interval k holds times in [keys[k], keys[k+1]); outside the keys the end values hold
        k = numpy.clip(numpy.searchsorted(keys, times, side="right") - 1, 0, len(keys) - 2)
        span = (keys[k + 1] - keys[k])[:, None]
        s = numpy.clip((times[:, None] - keys[k][:, None]) / span, 0.0, 1.0)
        if interpolation == "LINEAR":
            if path == "rotation":
                return _slerp(values[k], values[k + 1], s)
            return (1 - s) * values[k] + s * values[k + 1]
        s2, s3 = s * s, s * s * s
        return ((2 * s3 - 3 * s2 + 1) * values[k] + span * (s3 - 2 * s2 + s) * out_tangents[k]
                + (-2 * s3 + 3 * s2) * values[k + 1] + span * (s3 - s2) * in_tangents[k + 1])

    def _local_matrices(self, index, samplers, times):
        """Node `index`'s local matrix at each time, (len(times), 4, 4), animated paths overriding its own."""
        node = self._item("nodes", index)
        if "matrix" in node:
            if samplers:
                raise GlbError(f"node {index} is animated but has a matrix, which animated nodes must not")
            matrix = numpy.asarray(node["matrix"], dtype=float)
            if matrix.shape != (16,):
                raise GlbError(f"node {index}: matrix has {matrix.size} numbers, not 16")
            return numpy.repeat(matrix.reshape(4, 4).T[None], len(times), axis=0)  # stored column-major
        parts = {}
        for path, rest in NODE_PATHS.items():
            if path in samplers:
                parts[path] = self._sample(samplers[path], path, times)
            else:
                value = numpy.asarray(node.get(path, rest), dtype=float)
                if value.shape != (len(rest),):
                    raise GlbError(f"node {index}: {path} has {value.size} numbers, not {len(rest)}")
                parts[path] = numpy.broadcast_to(value, (len(times), len(rest)))
        local = numpy.zeros((len(times), 4, 4))
        local[:, :3, :3] = _rotation_matrices(parts["rotation"]) * parts["scale"][:, None, :]
        local[:, :3, 3] = parts["translation"]
        local[:, 3, 3] = 1.0
        return local

    def _parent_of(self):
        """child -> parent over all nodes, refusing a node listed as a child twice."""
        if self._parents is None:
            parents = {}
            for index, node in enumerate(self.document.get("nodes", [])):
                for child in node.get("children", []):
                    self._item("nodes", child)
                    if child in parents:
                        raise GlbError(f"node {child} is a child of both node {parents[child]} and node {index}")
                    parents[child] = index
            self._parents = parents
        return self._parents

    def world_matrices(self, animation, times, nodes=None):
        """node index -> (len(times), 4, 4) world matrices under the named animation (None: rest
        pose), for `nodes` (default: every node). Ancestors are computed once and shared."""
        times = numpy.atleast_1d(numpy.asarray(times, dtype=float))
        if times.ndim != 1:
            raise ValueError(f"times must be one-dimensional, not of shape {times.shape}")
        samplers = {} if animation is None else self._node_samplers(animation)
        parents = self._parent_of()
        node_count = len(self.document.get("nodes", []))
        nodes = range(node_count) if nodes is None else list(nodes)
        world = {}
        for start in nodes:
            chain, index = [], start
            while index is not None and index not in world:
                if len(chain) > node_count:
                    raise GlbError(f"the parents of node {start} form a cycle")
                chain.append(index)
                index = parents.get(index)
            above = None if index is None else world[index]
            for index in reversed(chain):
                local = self._local_matrices(index, samplers.get(index, {}), times)
                above = local if above is None else above @ local
                world[index] = above
        return {index: world[index] for index in nodes}

    def agent_root(self, name):
        """The index of the one root node of the default scene named `name`."""
        scene_index = self.document.get("scene", 0)
        scene = self._item("scenes", scene_index)
        matches = [index for index in scene.get("nodes", []) if self._item("nodes", index).get("name") == name]
        if len(matches) != 1:
            raise GlbError(f"{len(matches)} root nodes of scene {scene_index} are named {name!r}; expected one")
        return matches[0]

    def subtree(self, root):
        """node name -> index for every named node from `root` down; a name may occur only once."""
        found, seen, pending = {}, set(), [root]
        while pending:
            index = pending.pop()
            if index in seen:
                raise GlbError(f"node {index} is reached twice below node {root}")
            seen.add(index)
            node = self._item("nodes", index)
            name = node.get("name")
            if name is not None:
                if name in found:
                    raise GlbError(f"nodes {found[name]} and {index} below node {root} are both named {name!r}")
                found[name] = index
            pending.extend(reversed(node.get("children", [])))
        return found

    def skinned_primitives(self):
        """Per primitive of the skinned mesh: its POSITION, JOINTS_0 (ints)
        and WEIGHTS_0 arrays."""
        document = self.document
        mesh_node = next(n for n in document["nodes"] if "skin" in n and "mesh" in n)
        for primitive in document["meshes"][mesh_node["mesh"]]["primitives"]:
            attributes = primitive["attributes"]
            yield (self.accessor(attributes["POSITION"]), self.accessor(attributes["JOINTS_0"]).astype(int),
                   self.accessor(attributes["WEIGHTS_0"]))

    def world_positions(self, animation, times, names, root):
        """node name -> (len(times), 3) world translations, for named nodes below `root`."""
        below = self.subtree(root)
        missing = [name for name in names if name not in below]
        if missing:
            raise GlbError(f"no node named {', '.join(map(repr, missing))} below node {root}")
        matrices = self.world_matrices(animation, times, [below[name] for name in names])
        return {name: matrices[below[name]][:, :3, 3] for name in names}


def rewritten(source, target, change):
    """A copy of the .glb `source` at `target`, its JSON changed by `change(document)`."""
    data = source.read_bytes()
    length = struct.unpack_from("<I", data, 12)[0]
    document = json.loads(data[20:20 + length])
    change(document)
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + data[20 + length:]
    target.write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)


def with_stairs_up_clip(document):
    """The rig's arms_in animation again as "stairs_up": arms held in up the
    stairs, plainly unlike the walk."""
    arms_in = next(a for a in document["animations"] if a["name"] == "arms_in")
    document["animations"].append({**json.loads(json.dumps(arms_in)), "name": "stairs_up"})
