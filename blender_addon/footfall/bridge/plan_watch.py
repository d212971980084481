# SPDX-License-Identifier: GPL-3.0-or-later
"""Whether the stored plan is out of date. The scene counts the changes to
what Plan reads (its property "footfall_scene_changes"): a handler counts an
object of the Footfall collections that moves or changes shape, and the
operators that change agents' properties or add agents count too. Plan
records the count it read the scene at ("footfall_planned_at"); the plan is
out of date when the count has moved on since. So a change made while a
plan is under way leaves the new plan out of date."""

import bpy
from bpy.app.handlers import persistent

from . import plan_store
from .scene_extract import AGENTS, OBSTACLES, collection_in

CHANGES = "footfall_scene_changes"
PLANNED_AT = "footfall_planned_at"


def changes(scene) -> int:
    return scene.get(CHANGES, 0)


def note_change(scene) -> None:
    """Counts a change, once after the last Plan (later ones change nothing
    more, and a property written at every step of a drag would be waste)."""
    if plan_store.OUTCOME in scene and not is_stale(scene):
        scene[PLANNED_AT] = changes(scene)  # a plan from before the count: it was current until now
        scene[CHANGES] = changes(scene) + 1


def mark_planned(scene, read_at: int) -> None:
    """Records a plan of the scene as it was at change count `read_at`."""
    scene[PLANNED_AT] = read_at


def is_stale(scene) -> bool:
    return plan_store.OUTCOME in scene and scene.get(PLANNED_AT, changes(scene)) != changes(scene)


@persistent
def _on_depsgraph_update(scene, depsgraph) -> None:
    if plan_store.OUTCOME not in scene or is_stale(scene):
        return  # no plan, or known to be out of date: nothing to watch
    changed = [update.id.original for update in depsgraph.updates
               if (update.is_updated_transform or update.is_updated_geometry)
               and isinstance(update.id, bpy.types.Object)]
    if not changed:
        return  # playback and most edits move nothing: the collections are not walked
    watched = set()
    for name in (AGENTS, OBSTACLES):
        collection = collection_in(scene, name)
        if collection is not None:
            watched.update(collection.all_objects)
    if any(obj in watched for obj in changed):
        note_change(scene)


def register() -> None:
    bpy.app.handlers.depsgraph_update_post.append(_on_depsgraph_update)


def unregister() -> None:
    if _on_depsgraph_update in bpy.app.handlers.depsgraph_update_post:
        bpy.app.handlers.depsgraph_update_post.remove(_on_depsgraph_update)
