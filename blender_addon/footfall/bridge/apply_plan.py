# SPDX-License-Identifier: GPL-3.0-or-later
"""The Apply operator's work: find the plan and the rig, animate, and on any
failure remove everything the attempt created."""

import bpy

from ..core import native
from . import agent_rigs, animate, datablocks, rig_clips, scene_extract


class ApplyError(ValueError):
    """The plan or the rig is missing or unusable; the message says which."""


def _plan(ff, plan_filepath: str):
    if plan_filepath:
        path = bpy.path.abspath(plan_filepath)
        try:
            return ff.load_plan(path)
        except ValueError as error:
            raise ApplyError(str(error)) from error
    from . import plan_store

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


def run(context, plan_filepath: str = "", rig_name: str = ""):
    """Animates the plan on instances of the rig, replacing the agents of an
    earlier apply once the new ones are made; returns their armatures."""
    ff = native.load()
    plan = _plan(ff, plan_filepath)
    if not plan.agents:
        raise ApplyError("The plan has no agents")
    try:
        rigs = agent_rigs.rigs_of(context.scene, plan, agent_rigs.scene_rig(context.scene, rig_name))
    except agent_rigs.RigChoiceError as error:
        raise ApplyError(str(error)) from error
    if context.object is not None and context.object.mode != "OBJECT":
        bpy.ops.object.mode_set(mode="OBJECT")
    crowd = bpy.data.collections.get(animate.CROWD_COLLECTION)
    objects = list(crowd.objects) if crowd else []
    # Frees the agents' names (objects, armatures, actions) for the new instances.
    renamed = {}
    for obj in objects:
        for block in (obj, obj.data if obj.type == "ARMATURE" else None, *animate.own_actions(obj)):
            if block is not None and block not in renamed:
                renamed[block] = block.name
                block.name += " (replaced)"
    # An agent's empty gives its name to the agent's instance: it is renamed
    # "NAME (agent)" and keeps the name as a property (scene_extract.agent_name).
    named = []
    for agent in plan.agents:
        holder = bpy.data.objects.get(agent.name)
        if holder is not None and holder.type == "EMPTY" and holder not in renamed:
            renamed[holder] = holder.name
            if scene_extract.AGENT_NAME not in holder:
                holder[scene_extract.AGENT_NAME] = agent.name
                named.append(holder)
            holder.name = f"{agent.name} (agent)"
    before = datablocks.snapshot()
    window_manager = context.window_manager
    window_manager.progress_begin(0, 100)
    try:
        armatures = animate.apply_plan(ff, plan, rigs, context.scene,
                                       lambda f: window_manager.progress_update(int(100 * f)))
    except Exception:
        datablocks.remove_new(before)
        for block, name in renamed.items():
            block.name = name
        for holder in named:
            del holder[scene_extract.AGENT_NAME]
        raise
    finally:
        window_manager.progress_end()
    _remove(objects)
    rig_clips.remove_unused_copies()
    return armatures
