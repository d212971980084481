# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators: read properties, call the bridge, report. Errors leave the
scene as it was."""

import bpy
from bpy_extras.io_utils import ExportHelper, ImportHelper

from ..core.bone_map import BoneMapError
from ..core.rig_profile import ProfileError
from .operator_errors import report_and_cancel
from .properties import mapping_of


class FOOTFALL_OT_import_rig(bpy.types.Operator, ImportHelper):
    """Import a glTF or FBX humanoid, or take an armature already in this file, and map its bones for Footfall"""

    bl_idname = "footfall.import_rig"
    bl_label = "Import Rig"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".glb"
    filter_glob: bpy.props.StringProperty(default="*.glb;*.gltf;*.fbx", options={"HIDDEN"})
    armature: bpy.props.StringProperty(
        name="Armature", description="An armature already in this file to use instead of a file (a Rigify rig, say)"
    )

    def invoke(self, context, event):
        if self.armature:
            return self.execute(context)
        return super().invoke(context, event)

    def execute(self, context):
        from ..bridge import rig_clips, rig_import

        try:
            rig = rig_import.import_rig("" if self.armature else self.filepath,
                                        mapping_of(context.scene.footfall_bone_map), self.armature)
        except (rig_import.RigImportError, rig_clips.ClipError, BoneMapError, ProfileError) as error:
            return report_and_cancel(self, error)
        for note in rig.notes:
            self.report({"INFO"}, note)
        context.scene.footfall_rig = rig.armature
        self.report({"INFO"}, f"Imported rig '{rig.armature.name}', the scene's rig now")
        return {"FINISHED"}


class FOOTFALL_OT_apply(bpy.types.Operator):
    """Animate one instance of the imported rig per agent, from the stored plan or a plan file,
    replacing the agents of an earlier Apply (after Plan of the selected agents, only theirs)"""

    bl_idname = "footfall.apply"
    bl_label = "Apply Plan"
    bl_options = {"REGISTER", "UNDO"}

    plan_filepath: bpy.props.StringProperty(
        name="Plan File", subtype="FILE_PATH", description="A plan file to apply; empty: the plan stored in this file"
    )
    rig: bpy.props.StringProperty(
        name="Rig", description="The imported rig to instance; empty: the scene's rig (the panel's Rig)"
    )

    def execute(self, context):
        from ..bridge import animate, apply_plan, rig_clips
        from ..core.native import CoreMissingError

        try:
            armatures = apply_plan.run(context, self.plan_filepath, self.rig)
        except (apply_plan.ApplyError, animate.TransformError, rig_clips.ClipError, CoreMissingError) as error:
            return report_and_cancel(self, error)
        from ..bridge import plan_watch

        if not self.plan_filepath and plan_watch.is_stale(context.scene):
            self.report({"WARNING"}, f"Animated {len(armatures)} agents in '{animate.CROWD_COLLECTION}' from a plan "
                                     "that is out of date: agents, goals or obstacles changed since Plan")
        else:
            self.report({"INFO"}, f"Animated {len(armatures)} agents in '{animate.CROWD_COLLECTION}'")
        return {"FINISHED"}


class FOOTFALL_OT_export_gltf(bpy.types.Operator, ExportHelper):
    """Bake every animated agent as Blender shows it and export the crowd as glTF, one animation per agent"""

    bl_idname = "footfall.export_gltf"
    bl_label = "Export Crowd glTF"

    filename_ext = ".glb"
    filter_glob: bpy.props.StringProperty(default="*.glb", options={"HIDDEN"})

    def execute(self, context):
        from ..bridge import export

        window_manager = context.window_manager
        window_manager.progress_begin(0, 100)
        try:
            count = export.export_crowd(self.filepath, context.scene,
                                        lambda f: window_manager.progress_update(int(100 * f)))
        except export.ExportError as error:
            return report_and_cancel(self, error)
        finally:
            window_manager.progress_end()
        self.report({"INFO"}, f"Exported {count} agents to {self.filepath}")
        return {"FINISHED"}
