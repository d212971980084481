# SPDX-License-Identifier: GPL-3.0-or-later
"""Binary glTF (.glb) files: read one, append float data as accessors, write it.

A .glb holds a JSON chunk and at most one binary chunk, which is buffer 0.
"""

import json
import struct
from dataclasses import dataclass

import numpy

MAGIC = b"glTF"
JSON_CHUNK = 0x4E4F534A
BIN_CHUNK = 0x004E4942
FLOAT = 5126
ACCESSOR_TYPES = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}


class GlbError(ValueError):
    """The file is not a binary glTF this module can read; the message says why."""


@dataclass
class Glb:
    document: dict
    binary: bytearray

    def add_floats(self, values: numpy.ndarray, bounds: bool = False) -> int:
        """Appends rows of 1-4 floats as a new accessor (with min and max if
        `bounds`, as animation inputs need); returns its index."""
        values = numpy.ascontiguousarray(values, dtype="<f4")
        width = 1 if values.ndim == 1 else values.shape[1]
        self.binary.extend(b"\0" * (-len(self.binary) % 4))
        views = self.document.setdefault("bufferViews", [])
        views.append({"buffer": 0, "byteOffset": len(self.binary), "byteLength": values.nbytes})
        self.binary.extend(values.tobytes())
        accessor = {"bufferView": len(views) - 1, "componentType": FLOAT, "count": len(values),
                    "type": ACCESSOR_TYPES[width]}
        if bounds:
            rows = values.reshape(len(values), width)
            accessor["min"] = rows.min(axis=0).tolist()
            accessor["max"] = rows.max(axis=0).tolist()
        accessors = self.document.setdefault("accessors", [])
        accessors.append(accessor)
        return len(accessors) - 1


def read(path: str) -> Glb:
    with open(path, "rb") as file:
        data = file.read()
    if len(data) < 20 or data[:4] != MAGIC:
        raise GlbError(f"{path}: not a binary glTF file")
    version, length = struct.unpack_from("<II", data, 4)
    if version != 2 or length != len(data):
        raise GlbError(f"{path}: glTF version {version}, {length} bytes declared, {len(data)} found")
    document, binary, offset = None, bytearray(), 12
    while offset + 8 <= length:
        size, kind = struct.unpack_from("<II", data, offset)
        if offset + 8 + size > length:
            raise GlbError(f"{path}: a chunk of {size} bytes at byte {offset} runs past the end")
        chunk = data[offset + 8:offset + 8 + size]
        if kind == JSON_CHUNK:
            document = json.loads(chunk)
        elif kind == BIN_CHUNK:
            binary = bytearray(chunk)
        offset += 8 + size
    if offset != length:
        raise GlbError(f"{path}: {length - offset} bytes after the last chunk")
    if document is None:
        raise GlbError(f"{path}: no JSON chunk")
    return Glb(document, binary)


def write(glb: Glb, path: str) -> None:
    glb.binary.extend(b"\0" * (-len(glb.binary) % 4))
    if glb.binary:
        buffers = glb.document.setdefault("buffers", [{}])
        buffers[0]["byteLength"] = len(glb.binary)
    text = json.dumps(glb.document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    chunks = [struct.pack("<II", len(text), JSON_CHUNK), text]
    if glb.binary:
        chunks += [struct.pack("<II", len(glb.binary), BIN_CHUNK), glb.binary]
    total = 12 + sum(len(c) for c in chunks)
    with open(path, "wb") as file:
        file.write(MAGIC + struct.pack("<II", 2, total))
        for chunk in chunks:
            file.write(chunk)
