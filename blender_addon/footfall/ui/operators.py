# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators: read properties, call the bridge, report. Errors leave the
scene as it was."""

import time

import bpy
from bpy_extras.io_utils import ExportHelper, ImportHelper

from ..bridge import animate, apply_plan, rig_clips
from ..core.bone_map import BoneMapError
from ..core.native import CoreMissingError
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
        from ..bridge import rig_import

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
    live: bpy.props.BoolProperty(
        name="Live", description="Pose the agents' legs and hips from the plan at each frame instead of keying them: "
        "a far smaller file and a faster Apply, but only Blender with Footfall plays it (keyed: any Blender, and "
        "editable keys)", default=False
    )

    def execute(self, context):
        """Applies at once (scripts, and Blender without a window)."""
        try:
            armatures = apply_plan.run(context, self.plan_filepath, self.rig, self.live)
        except APPLY_ERRORS as error:
            return report_and_cancel(self, error)
        return self._done(context, armatures)

    def invoke(self, context, event):
        """In the interface: an agent at a time between events, the progress
        in the status bar; Esc stops it, and a stopped Apply changes nothing."""
        if context.window is None:
            return self.execute(context)
        try:
            self._job = apply_plan.ApplyJob(context, self.plan_filepath, self.rig, self.live)
        except APPLY_ERRORS as error:
            return report_and_cancel(self, error)
        self._timer = context.window_manager.event_timer_add(0.02, window=context.window)
        context.window_manager.modal_handler_add(self)
        self._say(context)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC":
            self._end(context)
            self._job.cancel()
            self.report({"WARNING"}, "Apply stopped (Esc): nothing changed")
            return {"CANCELLED"}
        if event.type in VIEW_EVENTS:
            return {"PASS_THROUGH"}  # the view stays live
        if event.type != "TIMER":
            return {"RUNNING_MODAL"}  # edits (and undo) wait: Apply is writing the scene
        started = time.monotonic()
        try:
            while time.monotonic() - started < WORK_PER_EVENT:
                if not self._job.advance():
                    self._end(context)
                    return self._done(context, self._job.finish())
        except Exception as error:  # a refusal or not, what it made is gone (advance): say why and stop
            self._end(context)
            return report_and_cancel(self, error)
        self._say(context)
        return {"RUNNING_MODAL"}

    def _say(self, context):
        context.workspace.status_text_set(f"Footfall: applying, {round(100 * self._job.progress)} % (Esc to stop)")

    def _end(self, context):
        context.window_manager.event_timer_remove(self._timer)
        context.workspace.status_text_set(None)

    def _done(self, context, armatures):
        from ..bridge import plan_watch

        if not self.plan_filepath and plan_watch.is_stale(context.scene):
            self.report({"WARNING"}, f"Animated {len(armatures)} agents in '{animate.CROWD_COLLECTION}' from a plan "
                                     "that is out of date: agents, goals or obstacles changed since Plan")
        else:
            self.report({"INFO"}, f"Animated {len(armatures)} agents in '{animate.CROWD_COLLECTION}'")
        return {"FINISHED"}


# The events Apply lets through while it works: looking around the scene.
VIEW_EVENTS = {"MOUSEMOVE", "INBETWEEN_MOUSEMOVE", "MIDDLEMOUSE", "WHEELUPMOUSE", "WHEELDOWNMOUSE", "TRACKPADPAN",
               "TRACKPADZOOM", "MOUSEROTATE", "MOUSESMARTZOOM", "NDOF_MOTION"}
WORK_PER_EVENT = 0.25  # [s] of Apply's work between two looks at the events (a redraw of a crowd costs too)
# What Apply refuses with a message.
APPLY_ERRORS = (apply_plan.ApplyError, animate.TransformError, rig_clips.ClipError, CoreMissingError)


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
