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


def _plan_scene(context):
    """Plans the scene with a progress bar; returns the plan and the seconds it took.
    Raises SceneError naming the object or field at fault."""
    from ..bridge import agent_rigs
    from ..bridge.scene_extract import AGENTS, SceneError, read
    from ..core.scenario import plan

    extracted = read(context.scene)
    # The rigs' sizes set the strides; the scene's and agents' own overrides win.
    try:
        document = agent_rigs.sized(extracted.document, extracted.agent_rigs, agent_rigs.scene_rig(context.scene))
    except agent_rigs.RigChoiceError as error:
        raise SceneError(str(error)) from error
    if not document["agents"]:
        raise SceneError(f"No agents to plan: add empties to the collection '{AGENTS}', "
                         "or load a scenario (docs/blender-scenes.md)")
    window_manager = context.window_manager
    window_manager.progress_begin(0, 100)
    start = time.perf_counter()
    try:
        result = plan(document, "scene", progress=lambda f: window_manager.progress_update(round(100 * f)))
    except ValueError as error:
        raise SceneError(extracted.locate(str(error))) from error
    finally:
        window_manager.progress_end()
    return result, time.perf_counter() - start


class FOOTFALL_OT_plan(bpy.types.Operator):
    """Plan the footsteps of every agent in the scene and store the plan in this file"""

    bl_idname = "footfall.plan"
    bl_label = "Plan"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        from ..bridge import plan_store

        try:
            result, seconds = _plan_scene(context)
        except (ValueError, native.CoreMissingError) as error:
            return report_and_cancel(self, error)
        from ..core.plan_report import outcome

        ff = native.load()
        plan_store.store(ff.plan_to_json(result))
        said = outcome([(a.name, a.status == ff.AgentStatus.REACHED, a.reason) for a in result.agents])
        context.scene[plan_store.OUTCOME] = said
        steps = sum(len(agent.footsteps) for agent in result.agents)
        level = "INFO" if all(a.status == ff.AgentStatus.REACHED for a in result.agents) else "WARNING"
        self.report({level}, f"{said}; {steps} footsteps, planned in {seconds:.2f} s; stored in the Text "
                             f"'{plan_store.TEXT_NAME}'")
        return {"FINISHED"}


classes = (FOOTFALL_OT_load_scenario, FOOTFALL_OT_plan)
