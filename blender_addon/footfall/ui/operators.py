# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators: read properties, call the bridge, report. Errors leave the
scene as it was."""

import bpy
from bpy_extras.io_utils import ImportHelper

from ..core.bone_map import BoneMapError
from ..core.rig_profile import ProfileError
from .properties import mapping_of


class FOOTFALL_OT_import_rig(bpy.types.Operator, ImportHelper):
    """Import a glTF humanoid and map its bones for Footfall"""

    bl_idname = "footfall.import_rig"
    bl_label = "Import Rig"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".glb"
    filter_glob: bpy.props.StringProperty(default="*.glb;*.gltf", options={"HIDDEN"})

    def execute(self, context):
        from ..bridge import rig_import

        try:
            rig = rig_import.import_rig(self.filepath, mapping_of(context.scene.footfall_bone_map))
        except (rig_import.RigImportError, BoneMapError, ProfileError) as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        for note in rig.notes:
            self.report({"INFO"}, note)
        self.report({"INFO"}, f"Imported rig '{rig.armature.name}'")
        return {"FINISHED"}
