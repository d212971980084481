# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators on the agents themselves: agents scattered over a region,
variation drawn at random, and selecting those the stored plan did not
bring to their goals."""

import bpy

from .operator_errors import report_and_cancel


class FOOTFALL_OT_randomize_agents(bpy.types.Operator):
    """Draw a preferred speed (and optionally a size and a rig) at random for each selected agent"""

    bl_idname = "footfall.randomize_agents"
    bl_label = "Randomize Agents"
    bl_options = {"REGISTER", "UNDO"}

    seed: bpy.props.IntProperty(name="Seed", description="The same seed draws the same values", default=0)
    speed_min: bpy.props.FloatProperty(name="Lowest Speed", description="Preferred speed drawn from here (m/s)",
                                       default=1.1, min=0.01, max=10.0, unit="VELOCITY")
    speed_max: bpy.props.FloatProperty(name="Highest Speed", description="Preferred speed drawn up to here (m/s)",
                                       default=1.5, min=0.01, max=10.0, unit="VELOCITY")
    scale_min: bpy.props.FloatProperty(name="Smallest Size", description="Body size drawn from here, as a share of "
                                       "the character's (1 and 1: sizes are not drawn)", default=1.0, min=0.5, max=1.6)
    scale_max: bpy.props.FloatProperty(name="Largest Size", description="Body size drawn up to here, as a share of "
                                       "the character's", default=1.0, min=0.5, max=1.6)
    vary_rig: bpy.props.BoolProperty(name="Vary Rig", description="Draw each agent's rig from the imported rigs",
                                     default=False)

    def execute(self, context):
        from ..bridge import agent_variation, plan_watch, rig_import
        from ..bridge.scene_extract import SceneError
        from ..bridge.selection import selected_agents

        try:
            rigs = [rig.name for rig in rig_import.imported_rigs()] if self.vary_rig else []
            if self.vary_rig and not rigs:
                raise SceneError("Vary Rig: no rig is imported (Import Rig first)")
            names = selected_agents(context.scene, context.selected_objects)
            drawn = agent_variation.randomize(context.scene, names, self.seed, (self.speed_min, self.speed_max),
                                              rigs, (self.scale_min, self.scale_max))
        except SceneError as error:
            return report_and_cancel(self, error)
        plan_watch.note_change(context.scene)
        what = ["speeds"] + (["sizes"] if (self.scale_min, self.scale_max) != (1.0, 1.0) else []) + (["rigs"] if rigs else [])
        self.report({"INFO"}, f"Drew {', '.join(what)} for {len(drawn)} agents")
        return {"FINISHED"}


class FOOTFALL_OT_scatter_agents(bpy.types.Operator):
    """Add agents at random in the selected mesh, each with a goal in the active one, clear of obstacles and of each other"""

    bl_idname = "footfall.scatter_agents"
    bl_label = "Scatter Agents"
    bl_options = {"REGISTER", "UNDO"}

    count: bpy.props.IntProperty(name="Count", description="How many agents to add", default=10, min=1,
                                 max=10000)
    seed: bpy.props.IntProperty(name="Seed", description="The same seed places the same agents", default=0)
    spacing: bpy.props.FloatProperty(name="Spacing", description="Least distance between two agents, and between "
                                     "two goals (m)", default=0.8, min=0.1, max=100.0, unit="LENGTH")
    start_region: bpy.props.StringProperty(name="Start Region", description="Mesh the agents stand in (empty: "
                                           "the selected mesh that is not active)")
    goal_region: bpy.props.StringProperty(name="Goal Region", description="Mesh their goals lie in (empty: the "
                                          "active mesh)")
    prefix: bpy.props.StringProperty(name="Name", description="Agents are named NAME 1, NAME 2, ...",
                                     default="Agent")

    def execute(self, context):
        from ..bridge import agent_scatter, plan_watch
        from ..bridge.scene_extract import SceneError

        try:
            start, goal = self._regions(context)
            names = agent_scatter.scatter(context.scene, start, goal, self.count, self.seed, self.spacing,
                                          self.prefix)
        except SceneError as error:
            return report_and_cancel(self, error)
        plan_watch.note_change(context.scene)
        self.report({"INFO"}, f"Added {len(names)} agents in '{start.name}' with goals in '{goal.name}'")
        return {"FINISHED"}

    def _regions(self, context):
        from ..bridge.scene_extract import SceneError

        def named(name):
            if name not in bpy.data.objects:
                raise SceneError(f"No object named '{name}' to scatter agents in")
            return bpy.data.objects[name]

        meshes = [o for o in context.selected_objects if o.type == "MESH"]
        active = context.view_layer.objects.active
        goal = named(self.goal_region) if self.goal_region else (active if active in meshes else None)
        others = [o for o in meshes if o is not goal]
        if self.start_region:
            start = named(self.start_region)
        else:
            start = others[0] if len(others) == 1 else (goal if not others else None)
        if start is None or goal is None:
            raise SceneError("Select the mesh to scatter agents in, then shift-select the mesh for their goals "
                             "(or one mesh for both)")
        return start, goal


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


class FOOTFALL_OT_set_agent_property(bpy.types.Operator):
    """Give the active agent this property (then edit it in the panel)"""

    bl_idname = "footfall.set_agent_property"
    bl_label = "Set Agent Property"
    bl_options = {"REGISTER", "UNDO"}

    key: bpy.props.StringProperty(name="Property", description="The agent's custom property, as footfall_speed")

    def execute(self, context):
        from ..bridge import agent_fields, agent_rigs, plan_watch
        from ..bridge.scene_extract import SceneError

        try:
            field = agent_fields.BY_KEY.get(self.key)
            if field is None:
                raise SceneError(f"'{self.key}' is not an agent property (one of "
                                 f"{', '.join(sorted(agent_fields.BY_KEY))})")
            agent = agent_fields.active_agent(context.scene, context.active_object)
            if agent is None:
                raise SceneError("No agent is active: click an agent's empty or one of its goals")
            value = agent_fields.start_value(context.scene, field)
        except (SceneError, agent_rigs.RigChoiceError) as error:
            return report_and_cancel(self, error)
        agent[field.key] = value
        plan_watch.note_change(context.scene)
        return {"FINISHED"}


classes = (FOOTFALL_OT_scatter_agents, FOOTFALL_OT_randomize_agents, FOOTFALL_OT_select_unreached,
           FOOTFALL_OT_set_agent_property)
