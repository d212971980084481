# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators for the scene (docs/blender-scenes.md): load a scenario file
into it, and plan it. Errors leave the scene and the stored plan as they were."""

import time

import bpy
from bpy_extras.io_utils import ImportHelper

from ..core import native
from .operator_errors import report_and_cancel


class FOOTFALL_OT_load_scenario(bpy.types.Operator, ImportHelper):
    """Add the obstacles and agents of a Footfall scenario file (or a SteerSuite test case) to the scene"""

    bl_idname = "footfall.load_scenario"
    bl_label = "Load Scenario"
    bl_options = {"REGISTER", "UNDO"}

    filename_ext = ".json"
    filter_glob: bpy.props.StringProperty(default="*.json;*.xml", options={"HIDDEN"})

    def execute(self, context):
        from ..bridge import scene_build

        try:
            document = scene_build.load_file(context.scene, bpy.path.abspath(self.filepath))
        except (ValueError, native.CoreMissingError) as error:
            return report_and_cancel(self, error)
        self.report({"INFO"}, f"Added {len(document['agents'])} agents and "
                              f"{len(document['obstacles'])} obstacles from {self.filepath}")
        return {"FINISHED"}


def _stored_plan():
    """The stored plan (native), which the agents not selected keep."""
    from ..bridge import plan_store
    from ..bridge.scene_extract import SceneError

    fixed = plan_store.load_plan()  # a ValueError names a damaged Text
    if fixed is None:
        raise SceneError("No stored plan for the agents not selected to keep: plan every agent first")
    return fixed


def _plan_scene(context, names=None):
    """Plans the scene with a progress bar (only the agents `names`, the
    others keeping their stored plans, if given); returns the plan and the
    seconds it took. Raises SceneError naming the object or field at fault."""
    from ..bridge import agent_rigs
    from ..bridge.scene_extract import AGENTS, SceneError, read
    from ..core.scenario import plan, replan

    extracted = read(context.scene)
    # The rigs' sizes set the strides; the scene's and agents' own overrides win.
    try:
        document = agent_rigs.sized(extracted.document, extracted.agent_rigs, agent_rigs.scene_rig(context.scene))
    except agent_rigs.RigChoiceError as error:
        raise SceneError(str(error)) from error
    if not document["agents"]:
        raise SceneError(f"No agents to plan: add empties to the collection '{AGENTS}', "
                         "or load a scenario (docs/blender-scenes.md)")
    fixed = None if names is None else _stored_plan()
    window_manager = context.window_manager
    window_manager.progress_begin(0, 100)
    start = time.perf_counter()

    def progress(fraction):
        window_manager.progress_update(round(100 * fraction))

    try:
        if names is None:
            result = plan(document, "scene", progress=progress)
        else:
            result = replan(document, fixed, names, "scene", progress=progress)
    except ValueError as error:
        message = str(error).replace("fixed: has no plan", "the stored plan has no plan", 1)
        raise SceneError(extracted.locate(message)) from error
    finally:
        window_manager.progress_end()
    return result, time.perf_counter() - start


class FOOTFALL_OT_plan(bpy.types.Operator):
    """Plan the footsteps of every agent in the scene (or of the selected ones, among the stored plans of
    the others) and store the plan in this file"""

    bl_idname = "footfall.plan"
    bl_label = "Plan"
    bl_options = {"REGISTER", "UNDO"}

    selected_only: bpy.props.BoolProperty(
        name="Selected Only",
        description="Plan only the selected agents (their empties, goals or animated rigs) again; the others keep "
                    "their stored plans, and the next Apply animates only those planned again",
        default=False,
    )

    def execute(self, context):
        from ..bridge import plan_store, plan_watch
        from ..bridge.scene_extract import SceneError
        from ..bridge.selection import selected_agents

        try:
            names = None
            if self.selected_only:
                names = selected_agents(context.scene, context.selected_objects)
                if not names:
                    raise SceneError("No agents selected: select agents (their empties, goals or animated rigs) "
                                     "to plan again")
            result, seconds = _plan_scene(context, names)
        except (ValueError, native.CoreMissingError) as error:
            return report_and_cancel(self, error)
        from ..core.plan_report import outcome

        ff = native.load()
        plan_store.store(ff.plan_to_json(result), result)
        plan_store.mark_planned(context.scene, names)
        plan_watch.clear(context.scene)
        said = outcome([(a.name, a.status == ff.AgentStatus.REACHED, a.reason) for a in result.agents])
        context.scene[plan_store.OUTCOME] = said
        steps = sum(len(agent.footsteps) for agent in result.agents)
        level = "INFO" if all(a.status == ff.AgentStatus.REACHED for a in result.agents) else "WARNING"
        again = f"planned {', '.join(map(repr, names))} again among the others; " if names else ""
        self.report({level}, f"{again}{said}; {steps} footsteps, planned in {seconds:.2f} s; stored in the Text "
                             f"'{plan_store.TEXT_NAME}'")
        return {"FINISHED"}


classes = (FOOTFALL_OT_load_scenario, FOOTFALL_OT_plan)
