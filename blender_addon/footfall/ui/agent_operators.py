# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators on the agents themselves: variation drawn at random, and
selecting those the stored plan did not bring to their goals."""

import bpy

from .operator_errors import report_and_cancel


class FOOTFALL_OT_randomize_agents(bpy.types.Operator):
    """Draw a preferred speed (and optionally a rig) at random for each selected agent"""

    bl_idname = "footfall.randomize_agents"
    bl_label = "Randomize Agents"
    bl_options = {"REGISTER", "UNDO"}

    seed: bpy.props.IntProperty(name="Seed", description="The same seed draws the same values", default=0)
    speed_min: bpy.props.FloatProperty(name="Lowest Speed", description="Preferred speed drawn from here (m/s)",
                                       default=1.1, min=0.01, max=10.0, unit="VELOCITY")
    speed_max: bpy.props.FloatProperty(name="Highest Speed", description="Preferred speed drawn up to here (m/s)",
                                       default=1.5, min=0.01, max=10.0, unit="VELOCITY")
    vary_rig: bpy.props.BoolProperty(name="Vary Rig", description="Draw each agent's rig from the imported rigs",
                                     default=False)

    def execute(self, context):
        from ..bridge import agent_variation, rig_import
        from ..bridge.scene_extract import SceneError
        from ..bridge.selection import selected_agents

        try:
            rigs = [rig.name for rig in rig_import.imported_rigs()] if self.vary_rig else []
            if self.vary_rig and not rigs:
                raise SceneError("Vary Rig: no rig is imported (Import Rig first)")
            names = selected_agents(context.scene, context.selected_objects)
            drawn = agent_variation.randomize(context.scene, names, self.seed, (self.speed_min, self.speed_max),
                                              rigs)
        except SceneError as error:
            return report_and_cancel(self, error)
        self.report({"INFO"}, f"Drew {'speeds and rigs' if rigs else 'speeds'} for {len(drawn)} agents")
        return {"FINISHED"}


class FOOTFALL_OT_select_unreached(bpy.types.Operator):
    """Select the agents that the stored plan does not bring to all their goals (and nothing else)"""

    bl_idname = "footfall.select_unreached"
    bl_label = "Select Those Not There"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        from ..bridge import plan_store
        from ..bridge.scene_extract import SceneError, agent_empties
        from ..core import native

        try:
            plan = plan_store.load_plan()
            if plan is None:
                raise SceneError("No plan: run Plan first")
            reached = native.load().AgentStatus.REACHED
            empties = agent_empties(context.scene)
            unreached = [empties[a.name] for a in plan.agents if a.status != reached and a.name in empties]
        except ValueError as error:
            return report_and_cancel(self, error)
        for obj in context.view_layer.objects:
            obj.select_set(obj in unreached)
        if unreached:
            context.view_layer.objects.active = unreached[0]
        self.report({"INFO"}, f"Selected {len(unreached)} agents that do not reach their goals")
        return {"FINISHED"}


classes = (FOOTFALL_OT_randomize_agents, FOOTFALL_OT_select_unreached)
