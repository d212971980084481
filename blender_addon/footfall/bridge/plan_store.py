# SPDX-License-Identifier: GPL-3.0-or-later
"""The scene's plan, kept in the .blend: the plan JSON (docs/file-formats.md)
compressed (zlib, then base64 in lines of 76 characters) in a Text
data-block named "footfall_plan", which Blender saves with the file. The
plan's JSON (version 2, compact) is mostly the digits of doubles, which zlib
packs little: it packs to about half its length (the demo's 49,314
characters to 26,617; version 1's spaces and repeated keys packed to a fifth).

Files saved before keep the plain JSON in a Text named "footfall_plan.json";
it is read as such, and replaced by the packed one at the next Plan.

The scene's property "footfall_replanned" (JSON text) lists the agents
planned again (Plan with selected_only) since the last Apply of the stored
plan, which the next Apply animates alone; without it (a Plan of every agent
since), Apply animates every agent.
"""

import base64
import json
import uuid
import zlib
from typing import Iterable, List, Optional, Tuple

import bpy

from ..core import native

TEXT_NAME = "footfall_plan"
PLAIN_TEXT_NAME = "footfall_plan.json"  # the plain JSON of older files
HEADER = "footfall-plan zlib base64 1"  # the packed text's first line
OUTCOME = "footfall_plan_outcome"  # the scene's property: what the last Plan reached, for the panel
REPLANNED = "footfall_replanned"  # the scene's property: agents planned again since the last Apply
REVISION = "footfall_revision"  # the Text's property: new at every store
LINE = 76
PACK_LEVEL = 1  # zlib's fastest: Plan packs at every run (docs/notes/blender-workflow.md)


def pack(text: str) -> str:
    packed = base64.b64encode(zlib.compress(text.encode("utf-8"), PACK_LEVEL)).decode("ascii")
    return "\n".join([HEADER, *(packed[i:i + LINE] for i in range(0, len(packed), LINE))])


def unpack(packed: str) -> str:
    header, _, body = packed.partition("\n")
    if header != HEADER:
        raise ValueError(f"{TEXT_NAME}: not a packed plan (its first line is not '{HEADER}')")
    try:
        return zlib.decompress(base64.b64decode("".join(body.split()), validate=True)).decode("utf-8")
    except (ValueError, zlib.error) as error:
        raise ValueError(f"{TEXT_NAME}: the packed plan is damaged ({error})") from error


# The plan last stored or read, and the core's reading of it: Apply right
# after Plan need not parse it again (1.7 s for bottleneck-evacuation's 58 MB).
_last_read = (None, None)


def store(text: str, plan=None) -> None:
    """Stores the plan JSON `text` (of the native Plan `plan`, if given),
    replacing a stored plan."""
    global _last_read
    packed = pack(text)  # first: nothing changes if packing fails
    block = bpy.data.texts.get(TEXT_NAME) or bpy.data.texts.new(TEXT_NAME)
    block.from_string(packed)
    block[REVISION] = uuid.uuid4().hex
    plain = bpy.data.texts.get(PLAIN_TEXT_NAME)
    if plain is not None:
        bpy.data.texts.remove(plain)
    _last_read = (text, plan)


def stored_packed() -> Optional[str]:
    """The stored plan as packed text (pack), or None if no plan is stored."""
    block = bpy.data.texts.get(TEXT_NAME)
    if block is not None:
        return block.as_string()
    text = load()
    return None if text is None else pack(text)


def revision() -> Optional[Tuple[int, Optional[str]]]:
    """What tells the stored plan from any other, cheaply (the overlay's
    cache key), or None if no plan is stored."""
    block = bpy.data.texts.get(TEXT_NAME) or bpy.data.texts.get(PLAIN_TEXT_NAME)
    return None if block is None else (block.as_pointer(), block.get(REVISION))


def load() -> Optional[str]:
    """The stored plan JSON, or None if no plan is stored. Raises ValueError
    if the packed text was damaged."""
    block = bpy.data.texts.get(TEXT_NAME)
    if block is not None:
        return unpack(block.as_string())
    plain = bpy.data.texts.get(PLAIN_TEXT_NAME)
    return None if plain is None else plain.as_string()


def load_plan():
    """The stored plan read by the core (a native Plan), or None if no plan
    is stored. Raises ValueError "footfall_plan: FIELD.PATH: problem" if the
    text was edited into an invalid plan."""
    global _last_read
    text = load()
    if text is None:
        return None
    if text != _last_read[0] or _last_read[1] is None:
        _last_read = (text, native.load().parse_plan(text, TEXT_NAME))
    return _last_read[1]


def pending(scene) -> Optional[List[str]]:
    """The agents whose plans changed since the last Apply, or None when all
    may have (a Plan of every agent, or no Apply recorded)."""
    return json.loads(scene[REPLANNED]) if REPLANNED in scene else None


def mark_planned(scene, names: Optional[Iterable[str]] = None) -> None:
    """Records a Plan: of the agents `names`, or with None of every agent."""
    if names is None:
        scene.pop(REPLANNED, None)
    elif REPLANNED in scene:  # else every agent is pending already
        scene[REPLANNED] = json.dumps(sorted(set(pending(scene)) | set(names)))


def mark_applied(scene) -> None:
    """Records an Apply of the whole stored plan: nothing is pending."""
    scene[REPLANNED] = "[]"
