# SPDX-License-Identifier: GPL-3.0-or-later
"""One ordered tuple of the add-on's Blender classes, registered in order."""

import bpy

from ..bridge import live_motion, plan_watch
from . import agent_operators, overlay, preferences, properties, scene_operators
from .operators import FOOTFALL_OT_apply, FOOTFALL_OT_export_gltf, FOOTFALL_OT_import_rig
from .panel import FOOTFALL_PT_agent, FOOTFALL_PT_bone_map, FOOTFALL_PT_main

classes = (
    preferences.FOOTFALL_AP_preferences,
    properties.FOOTFALL_PG_bone_map,
    *scene_operators.classes,
    *agent_operators.classes,
    FOOTFALL_OT_import_rig,
    FOOTFALL_OT_apply,
    FOOTFALL_OT_export_gltf,
    FOOTFALL_PT_main,
    FOOTFALL_PT_agent,
    FOOTFALL_PT_bone_map,
)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    properties.register()
    overlay.register()
    plan_watch.register()
    live_motion.register()


def unregister():
    live_motion.unregister()
    plan_watch.unregister()
    overlay.unregister()
    properties.unregister()
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
