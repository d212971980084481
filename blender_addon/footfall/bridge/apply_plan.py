# SPDX-License-Identifier: GPL-3.0-or-later
"""The Apply operator's work: find the plan and the rig, animate, and on any
failure remove everything the attempt created. After Plan of the selected
agents, Apply of the stored plan animates only the agents planned again, and
keeps the rigs of the others."""

import pathlib
from typing import Optional, Set

import bpy

from ..core import native
from . import agent_rigs, animate, datablocks, live_motion, plan_store, rig_clips, scene_extract


class ApplyError(ValueError):
    """The plan or the rig is missing or unusable; the message says which."""


def _plan(ff, plan_filepath: str):
    if plan_filepath:
        path = bpy.path.abspath(plan_filepath)
        try:
            return ff.load_plan(path)
        except ValueError as error:
            raise ApplyError(str(error)) from error
    try:
        plan = plan_store.load_plan()
    except ValueError as error:
        raise ApplyError(str(error)) from error
    if plan is None:
        raise ApplyError("No plan: run Plan first, or give a plan file")
    return plan


def _remove(objects) -> None:
    """Removes agents made by an earlier apply: objects, armatures, their own
    actions (the meshes stay: they are the rig's)."""
    for obj in objects:
        data = obj.data if obj.type == "ARMATURE" else None
        actions = animate.own_actions(obj)
        bpy.data.objects.remove(obj)
        for block, blocks in ((data, bpy.data.armatures), *((a, bpy.data.actions) for a in actions)):
            if block is not None and block.users == 0:
                blocks.remove(block)


def _top(obj):
    """The object at the top of `obj`'s parents: an agent's armature in the crowd."""
    while obj.parent is not None:
        obj = obj.parent
    return obj


def _to_animate(scene, plan, crowd_objects, whole: bool) -> Optional[Set[str]]:
    """The agents of `plan` to animate: those planned again since the last
    Apply of the stored plan, if the others all have their rigs in the crowd;
    None: every agent (`whole`, nothing pending, or a rig missing)."""
    pending = None if whole else plan_store.pending(scene)
    if not pending:
        return None
    animated = {obj.name for obj in crowd_objects if obj.type == "ARMATURE"}
    if any(agent.name not in animated for agent in plan.agents if agent.name not in pending):
        return None
    return set(pending)


class ApplyJob:
    """One Apply, an agent at a time (the modal operator's steps between
    events): made, it has found the plan and the rigs and freed the agents'
    names; `advance` animates the next agent; `finish` replaces the earlier
    crowd; `cancel`, or a failure in `advance`, leaves the scene as it was.
    `live`: the locomotion is posed at each frame, not keyed (live_motion)."""

    def __init__(self, context, plan_filepath: str = "", rig_name: str = "", live: bool = False):
        ff = native.load()
        plan = _plan(ff, plan_filepath)
        if not plan.agents:
            raise ApplyError("The plan has no agents")
        # What the live crowd plays, packed now: a plan file may change before finish().
        self._live_plan = None
        if live:
            self._live_plan = plan_store.pack(pathlib.Path(bpy.path.abspath(plan_filepath)).read_text(
                encoding="utf-8")) if plan_filepath else plan_store.stored_packed()
        try:
            rigs = agent_rigs.rigs_of(context.scene, plan, agent_rigs.scene_rig(context.scene, rig_name))
        except agent_rigs.RigChoiceError as error:
            raise ApplyError(str(error)) from error
        if context.object is not None and context.object.mode != "OBJECT":
            bpy.ops.object.mode_set(mode="OBJECT")
        self._scene, self._from_file = context.scene, bool(plan_filepath)
        crowd = bpy.data.collections.get(animate.CROWD_COLLECTION)
        objects = list(crowd.objects) if crowd else []
        only = _to_animate(context.scene, plan, objects, whole=bool(plan_filepath or rig_name))
        if only is not None:  # the others' rigs stay; those of agents no longer planned go
            planned = {agent.name for agent in plan.agents}
            objects = [obj for obj in objects if _top(obj).name in only or _top(obj).name not in planned]
        self._replaced = objects
        # Frees the agents' names (objects, armatures, actions) for the new instances.
        self._renamed = {}
        for obj in objects:
            for block in (obj, obj.data if obj.type == "ARMATURE" else None, *animate.own_actions(obj)):
                if block is not None and block not in self._renamed:
                    self._renamed[block] = block.name
                    block.name += " (replaced)"
        # An agent's empty gives its name to the agent's instance: it is renamed
        # "NAME (agent)" and keeps the name as a property (scene_extract.agent_name).
        self._named = []
        for agent in plan.agents:
            if only is not None and agent.name not in only:
                continue
            holder = bpy.data.objects.get(agent.name)
            if holder is not None and holder.type == "EMPTY" and holder not in self._renamed:
                self._renamed[holder] = holder.name
                if scene_extract.AGENT_NAME not in holder:
                    holder[scene_extract.AGENT_NAME] = agent.name
                    self._named.append(holder)
                holder.name = f"{agent.name} (agent)"
        self._before = datablocks.snapshot()
        self._steps = animate.applying(ff, plan, rigs, context.scene, only, live_motion.drive if live else None)
        self.progress = 0.0
        self.armatures = None  # the new agents' armatures, once every agent is animated

    def advance(self) -> bool:
        """Animates the next agent; False once there are none left."""
        try:
            self.progress = next(self._steps)
            return True
        except StopIteration as done:
            self.armatures = done.value
            return False
        except Exception:
            self.cancel()
            raise

    def cancel(self) -> None:
        """Removes what this Apply made and gives back the names it took."""
        self._steps.close()
        datablocks.remove_new(self._before)
        for block, name in self._renamed.items():
            block.name = name
        for holder in self._named:
            del holder[scene_extract.AGENT_NAME]
        live_motion.tidy()

    def finish(self):
        """Replaces the earlier crowd with the new one; returns its armatures."""
        _remove(self._replaced)
        rig_clips.remove_unused_copies()
        if self._live_plan is not None:
            live_motion.store_plan(self._live_plan)
            self._scene.render.use_lock_interface = True  # a render must not pose the crowd under the viewport
        live_motion.tidy()
        if self._from_file:
            plan_store.mark_planned(self._scene)  # the crowd is not the stored plan's
        else:
            plan_store.mark_applied(self._scene)
        return self.armatures


def run(context, plan_filepath: str = "", rig_name: str = "", live: bool = False):
    """Animates the plan on instances of the rig, replacing the agents of an
    earlier apply once the new ones are made (only those planned again, after
    a Plan of the selected agents); returns their armatures."""
    job = ApplyJob(context, plan_filepath, rig_name, live)
    window_manager = context.window_manager
    window_manager.progress_begin(0, 100)
    try:
        while job.advance():
            window_manager.progress_update(int(100 * job.progress))
    finally:
        window_manager.progress_end()
    return job.finish()
