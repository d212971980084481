# SPDX-License-Identifier: GPL-3.0-or-later
"""The scene's plan, kept in the .blend: the plan JSON text
(docs/file-formats.md) in a Text data-block named "footfall_plan.json",
which Blender saves with the file."""

from typing import Optional

import bpy

from ..core import native

TEXT_NAME = "footfall_plan.json"
OUTCOME = "footfall_plan_outcome"  # the scene's property: what the last Plan reached, for the panel


def store(text: str) -> None:
    """Stores `text` as the plan, replacing a stored one."""
    block = bpy.data.texts.get(TEXT_NAME)
    if block is None:
        block = bpy.data.texts.new(TEXT_NAME)
    block.from_string(text)


def load() -> Optional[str]:
    """The stored plan text, or None if no plan is stored."""
    block = bpy.data.texts.get(TEXT_NAME)
    return None if block is None else block.as_string()


def load_plan():
    """The stored plan read by the core (a native Plan), or None if no plan
    is stored. Raises ValueError "footfall_plan.json: FIELD.PATH: problem"
    if the text was edited into an invalid plan."""
    text = load()
    return None if text is None else native.load().parse_plan(text, TEXT_NAME)
