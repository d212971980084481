# SPDX-License-Identifier: GPL-3.0-or-later
"""Footfall: crowds that walk footstep by footstep.

The planning core is the compiled module ``footfall._native``; ``core`` holds
pure Python that works without Blender, ``bridge`` moves data between
Blender and ``core``, and ``ui`` holds the Blender classes. Nothing here
imports ``bpy`` at module level, so the package imports outside Blender.
"""

bl_info = {
    "name": "Footfall",
    "author": "Footfall developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Footfall",
    "description": "Plans crowds footstep by footstep and animates rigs on the plan",
    "category": "Animation",
}


def register():
    """Registers the add-on's Blender classes."""
    from .ui import registration

    registration.register()


def unregister():
    """Unregisters them, in reverse order."""
    from .ui import registration

    registration.unregister()
