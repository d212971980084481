# SPDX-License-Identifier: GPL-3.0-or-later
"""The Footfall sidebar panel."""

import bpy

from ..core import native


class FOOTFALL_PT_main(bpy.types.Panel):
    """Shows whether Footfall's planning core is ready."""

    bl_idname = "FOOTFALL_PT_main"
    bl_label = "Footfall"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Footfall"

    def draw(self, context):
        self.layout.label(text=native.status())
