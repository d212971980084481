# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators on the agents themselves: variation drawn at random."""

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


classes = (FOOTFALL_OT_randomize_agents,)
