# SPDX-License-Identifier: GPL-3.0-or-later
"""Operators for the scene (docs/blender-scenes.md): load a scenario file
into it, and plan it. Errors leave the scene and the stored plan as they were."""

import time

import bpy
from bpy_extras.io_utils import ImportHelper

from ..core import native
from .operator_errors import report_and_cancel
from .preferences import planning_threads


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


def _planning_input(context, names=None):
    """What Plan plans: the scene's document (its agents sized by their
    rigs), the stored plan the agents not in `names` keep (None when every
    agent is planned), and the read scene (to name objects in errors).
    Raises SceneError naming the object or field at fault."""
    from ..bridge import agent_rigs
    from ..bridge.scene_extract import AGENTS, SceneError, agent_empties, read

    extracted = read(context.scene)
    # The rigs' sizes set the strides; the scene's and agents' own overrides win.
    try:
        rig = agent_rigs.scene_rig(context.scene)
        document = agent_rigs.sized(extracted.document, extracted.agent_rigs, rig)
        # An agent scaled past what the core plans: named in the user's terms, before anything runs.
        objects = {name: empty.name for name, empty in agent_empties(context.scene).items()}
        agent_rigs.check_sizes(extracted.document, document, extracted.agent_rigs, rig, objects)
    except agent_rigs.RigChoiceError as error:
        raise SceneError(str(error)) from error
    if not document["agents"]:
        raise SceneError(f"No agents to plan: add empties to the collection '{AGENTS}', "
                         "or load a scenario (docs/blender-scenes.md)")
    return document, None if names is None else _stored_plan(), extracted


def _located(extracted, error: ValueError):
    """The core's error with the scene's objects behind the fields it names."""
    from ..bridge.scene_extract import SceneError

    message = str(error).replace("fixed: has no plan", "the stored plan has no plan", 1)
    return SceneError(extracted.locate(message))


def _input(context, selected_only: bool):
    """The agents to plan (None: every one) and what _planning_input gives."""
    from ..bridge.scene_extract import SceneError
    from ..bridge.selection import selected_agents

    names = None
    if selected_only:
        names = selected_agents(context.scene, context.selected_objects)
        if not names:
            raise SceneError("No agents selected: select agents (their empties, goals or animated rigs) "
                             "to plan again")
    return names, _planning_input(context, names)


def _height_span(footsteps) -> float:
    """How far an agent's highest foothold lies above its lowest [m]."""
    heights = [step.foot_height for step in footsteps]
    return max(heights) - min(heights) if heights else 0.0


def _store(operator, context, result, names, seconds, read_at: int):
    """Stores the plan of the scene as it was at change count `read_at`
    (plan_watch) and reports its outcome on `operator`."""
    from ..bridge import plan_store, plan_watch
    from ..core.plan_report import climbing, outcome, overlapping, unreachable

    ff = native.load()
    plan_store.store(ff.plan_to_json(result), result)
    plan_store.mark_planned(context.scene, names)
    plan_watch.mark_planned(context.scene, read_at)
    clashes = ""
    if names:  # fixed agents make way for no one: say who overlaps them
        metrics = ff.measure_plan(result)
        clashes = overlapping([(m.name, m.overlaps) for m in metrics.agents], set(names), metrics.rate)
    said = (outcome([(a.name, a.status == ff.AgentStatus.REACHED, a.reason) for a in result.agents])
            + unreachable([(a.name, str(a.narrowest)) for a in result.agents if a.narrowest is not None]) + clashes)
    if result.ground:
        said += climbing([_height_span(a.footsteps) for a in result.agents])
    context.scene[plan_store.OUTCOME] = said
    steps = sum(len(agent.footsteps) for agent in result.agents)
    fine = all(a.status == ff.AgentStatus.REACHED for a in result.agents) and not clashes
    level = "INFO" if fine else "WARNING"
    again = f"planned {', '.join(map(repr, names))} again among the others; " if names else ""
    operator.report({level}, f"{again}{said}; {steps} footsteps, planned in {seconds:.2f} s; stored in the Text "
                             f"'{plan_store.TEXT_NAME}'")
    return {"FINISHED"}


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
        """Plans at once (scripts, and Blender without a window)."""
        from ..bridge import plan_watch
        from ..core.plan_job import PlanJob

        window_manager = context.window_manager
        read_at = plan_watch.changes(context.scene)
        try:
            names, (document, fixed, extracted) = _input(context, self.selected_only)
            window_manager.progress_begin(0, 100)
            try:
                job = PlanJob(document, planning_threads(context), fixed, names)
                while not job.done:
                    window_manager.progress_update(round(100 * job.progress))
                    time.sleep(0.05)
                result = job.result()
            except ValueError as error:
                raise _located(extracted, error) from error
            finally:
                window_manager.progress_end()
        except (ValueError, native.CoreMissingError) as error:
            return report_and_cancel(self, error)
        return _store(self, context, result, names, job.seconds, read_at)

    def invoke(self, context, event):
        """In the interface: plans on a thread of its own, the progress in the
        status bar; Esc stops it, and a stopped run changes nothing."""
        from ..bridge import plan_watch
        from ..core.plan_job import PlanJob

        if context.window is None:
            return self.execute(context)
        self._read_at = plan_watch.changes(context.scene)
        try:
            names, (document, fixed, self._extracted) = _input(context, self.selected_only)
            self._job = PlanJob(document, planning_threads(context), fixed, names)
        except (ValueError, native.CoreMissingError) as error:
            return report_and_cancel(self, error)
        self._names = names
        self._timer = context.window_manager.event_timer_add(0.1, window=context.window)
        context.window_manager.modal_handler_add(self)
        self._say(context)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC":
            self._job.cancel()
            return {"RUNNING_MODAL"}
        if event.type == "TIMER":
            self._say(context)
        if not self._job.done:
            return {"PASS_THROUGH"}  # the interface stays live
        context.window_manager.event_timer_remove(self._timer)
        context.workspace.status_text_set(None)
        try:
            result = self._job.result()
        except ValueError as error:
            return report_and_cancel(self, _located(self._extracted, error))
        if self._job.cancelled:
            self.report({"WARNING"}, "Planning stopped (Esc): nothing changed, the stored plan stays")
            return {"CANCELLED"}
        return _store(self, context, result, self._names, self._job.seconds, self._read_at)

    def _say(self, context):
        state = "stopping" if self._job.cancelled else "Esc to stop"
        context.workspace.status_text_set(f"Footfall: planning, {round(100 * self._job.progress)} % ({state})")


classes = (FOOTFALL_OT_load_scenario, FOOTFALL_OT_plan)
