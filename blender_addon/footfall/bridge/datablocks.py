# SPDX-License-Identifier: GPL-3.0-or-later
"""Undoing what a failed operation created: a snapshot of the data-blocks
before, and the removal of everything new after."""

import bpy

# The collections of bpy.data that an import can add to, in an order that
# removes users before what they use.
KINDS = ("objects", "collections", "meshes", "armatures", "actions", "materials", "images", "textures", "cameras", "lights")


def snapshot():
    """The data-blocks that exist now, per kind, with their names."""
    return {kind: {block: block.name for block in getattr(bpy.data, kind)} for kind in KINDS}


def new_since(before, kind):
    """The data-blocks of `kind` created since `before`."""
    return [block for block in getattr(bpy.data, kind) if block not in before[kind]]


def remove_new(before):
    """Removes every data-block created since `before`, and gives the others
    back their names (Blender 3.4 gives a name taken by a new block's rename
    to the block that had it, as "NAME.001")."""
    for kind in KINDS:
        blocks = getattr(bpy.data, kind)
        for block in new_since(before, kind):
            blocks.remove(block)
        for block, name in before[kind].items():
            try:
                if block.name != name:
                    block.name = name
            except ReferenceError:
                continue  # removed since: nothing to name
