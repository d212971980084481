# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on's preferences: how many threads the core plans on."""

import os

import bpy

ADDON = __package__.rpartition(".")[0]  # "footfall", or "bl_ext.<repository>.footfall" as an extension
MAX_THREADS = 64  # the core's bound
EVERY_CORE = min(os.cpu_count() or 1, MAX_THREADS)


class FOOTFALL_AP_preferences(bpy.types.AddonPreferences):
    bl_idname = ADDON

    threads: bpy.props.IntProperty(
        name="Planning Threads",
        description="Threads the planning core plans on (the plan is the same for any number)",
        default=EVERY_CORE, min=1, max=MAX_THREADS,
    )

    def draw(self, context):
        self.layout.prop(self, "threads")


def planning_threads(context) -> int:
    """The preference, or every core when the add-on's preferences are not there."""
    addon = context.preferences.addons.get(ADDON)
    if addon is None or addon.preferences is None:
        return EVERY_CORE
    return addon.preferences.threads
