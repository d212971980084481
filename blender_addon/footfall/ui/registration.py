# SPDX-License-Identifier: GPL-3.0-or-later
"""One ordered tuple of the add-on's Blender classes, registered in order."""

import bpy

from .panel import FOOTFALL_PT_main

classes = (FOOTFALL_PT_main,)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)


def unregister():
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
