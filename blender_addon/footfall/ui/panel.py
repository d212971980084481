# SPDX-License-Identifier: GPL-3.0-or-later
"""The Footfall sidebar panels."""

import bpy

from ..core import native
from .properties import MAPPING_FIELDS


class _FootfallSidebarTab:
    """Where Footfall's panels stand: the 3D Viewport's sidebar, tab "Footfall"
    (a sub-panel must stand where its parent does)."""

    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Footfall"


def _own_rig(context):
    """Which rig animates the active agent, said for the panel (None when
    the active object is no agent's empty)."""
    from ..bridge.scene_extract import AGENT_RIG, agent_empties, agent_name

    active = context.active_object
    if active is None or active not in agent_empties(context.scene).values():
        return None
    rig = active.get(AGENT_RIG)
    if rig is not None:
        return f"{agent_name(active)}: rig '{rig}' (footfall_rig)"
    scene_rig = context.scene.footfall_rig
    return f"{agent_name(active)}: the scene's rig" + (f" '{scene_rig.name}'" if scene_rig else " (none yet)")


def _ground_said(context) -> str:
    """How much ground the scene has, said for the panel: its objects and
    their evaluated triangles, or the floor z = 0."""
    from ..bridge.scene_extract import GROUND, collection_in

    collection = collection_in(context.scene, GROUND)
    meshes = [o for o in collection.all_objects if o.type == "MESH"] if collection else []
    if not meshes:
        return "Ground: the floor z = 0"
    depsgraph = context.evaluated_depsgraph_get()
    # A face of n corners is n - 2 triangles.
    triangles = sum(len(mesh.loops) - 2 * len(mesh.polygons)
                    for mesh in (o.evaluated_get(depsgraph).data for o in meshes))
    return f"Ground: {len(meshes)} object{'s' if len(meshes) != 1 else ''}, {triangles} triangles"


class FOOTFALL_PT_main(_FootfallSidebarTab, bpy.types.Panel):
    """Shows whether Footfall's planning core is ready."""

    bl_idname = "FOOTFALL_PT_main"
    bl_label = "Footfall"

    def draw(self, context):
        self.layout.label(text=native.status())
        self.layout.operator("footfall.load_scenario", icon="FILE_FOLDER")
        self.layout.operator("footfall.plan", icon="TRACKING")
        again = self.layout.operator("footfall.plan", text="Plan Selected Again", icon="RESTRICT_SELECT_OFF")
        again.selected_only = True
        from ..bridge import plan_watch
        from ..bridge.plan_store import OUTCOME
        from ..core.plan_report import NOT_THERE

        if OUTCOME not in context.scene:
            self.layout.label(text="No plan yet")
        else:
            self.layout.prop(context.scene, "footfall_show_overlay")
            if plan_watch.is_stale(context.scene):
                self.layout.label(text="Out of date: agents, goals or obstacles changed since", icon="ERROR")
            for line in context.scene[OUTCOME].split("; "):
                self.layout.label(text=line)
            if NOT_THERE in context.scene[OUTCOME]:
                self.layout.operator("footfall.select_unreached", icon="RESTRICT_SELECT_OFF")
        self.layout.label(text=_ground_said(context))
        self.layout.operator("footfall.scatter_agents", icon="PARTICLES")
        self.layout.operator("footfall.randomize_agents", icon="MOD_NOISE")
        self.layout.operator("footfall.import_rig", icon="ARMATURE_DATA")
        self.layout.prop(context.scene, "footfall_rig")
        own_rig = _own_rig(context)
        if own_rig is not None:
            self.layout.label(text=own_rig, icon="ARMATURE_DATA")
        active = context.active_object
        from ..bridge.rig_import import PROFILE_PROPERTY

        if active is not None and active.type == "ARMATURE" and PROFILE_PROPERTY not in active:
            use = self.layout.operator("footfall.import_rig", text=f"Use '{active.name}' as Rig", icon="ARMATURE_DATA")
            use.armature = active.name
        self.layout.operator("footfall.apply", icon="ANIM")
        self.layout.operator("footfall.apply", text="Apply Live", icon="PLAY").live = True
        from ..bridge.live_motion import crowd_state

        state = crowd_state()
        if state:
            self.layout.label(text=state)
        self.layout.operator("footfall.export_gltf", icon="EXPORT")


class FOOTFALL_PT_agent(_FootfallSidebarTab, bpy.types.Panel):
    """The active agent's own properties (its empty's custom properties)."""

    bl_idname = "FOOTFALL_PT_agent"
    bl_label = "Agent"
    bl_parent_id = "FOOTFALL_PT_main"

    @classmethod
    def poll(cls, context):
        from ..bridge.agent_fields import active_agent

        return active_agent(context.scene, context.active_object) is not None

    def draw(self, context):
        from ..bridge.agent_fields import FIELDS, active_agent
        from ..bridge.scene_extract import agent_name

        agent = active_agent(context.scene, context.active_object)
        self.layout.label(text=agent_name(agent), icon="EMPTY_ARROWS")
        for field in FIELDS:
            if field.key in agent:
                self.layout.prop(agent, f'["{field.key}"]', text=field.label)
            else:
                self.layout.operator("footfall.set_agent_property", text=f"Set {field.label}").key = field.key


class FOOTFALL_PT_bone_map(_FootfallSidebarTab, bpy.types.Panel):
    """Bone names for Import Rig, where detection cannot find them."""

    bl_idname = "FOOTFALL_PT_bone_map"
    bl_label = "Bone Mapping"
    bl_parent_id = "FOOTFALL_PT_main"
    bl_options = {"DEFAULT_CLOSED"}

    def draw(self, context):
        layout = self.layout
        layout.label(text="Empty fields are detected")
        fields = context.scene.footfall_bone_map
        for name, _side, _role in MAPPING_FIELDS:
            layout.prop(fields, name)
