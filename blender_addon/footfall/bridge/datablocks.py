# SPDX-License-Identifier: GPL-3.0-or-later
"""Undoing what a failed operation created: a snapshot of the data-blocks
before, and the removal of everything new after."""

import bpy

# The collections of bpy.data that an import can add to, in an order that
# removes users before what they use.
KINDS = ("objects", "collections", "meshes", "armatures", "actions", "materials", "images", "textures", "cameras", "lights")


def snapshot():
    """The data-blocks that exist now, per kind."""
    return {kind: set(getattr(bpy.data, kind)[:]) for kind in KINDS}


def new_since(before, kind):
    """The data-blocks of `kind` created since `before`."""
    return [block for block in getattr(bpy.data, kind) if block not in before[kind]]


def remove_new(before):
    """Removes every data-block created since `before`."""
    for kind in KINDS:
        blocks = getattr(bpy.data, kind)
        for block in new_since(before, kind):
            blocks.remove(block)
