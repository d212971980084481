# SPDX-License-Identifier: GPL-3.0-or-later
"""Whether the stored plan is out of date: a handler marks it so (the
scene's property "footfall_plan_stale") when an object of the Footfall
collections moves or changes shape after Plan; Plan clears it; the
operators that change agents' properties or add agents mark it."""

import bpy
from bpy.app.handlers import persistent

from . import plan_store
from .scene_extract import AGENTS, OBSTACLES, collection_in

STALE = "footfall_plan_stale"


def mark_stale(scene) -> None:
    if plan_store.OUTCOME in scene and not scene.get(STALE):
        scene[STALE] = True


def clear(scene) -> None:
    scene.pop(STALE, None)


def is_stale(scene) -> bool:
    return bool(scene.get(STALE))


@persistent
def _on_depsgraph_update(scene, depsgraph) -> None:
    if plan_store.OUTCOME not in scene or scene.get(STALE):
        return  # no plan, or known to be out of date: nothing to watch
    watched = set()
    for name in (AGENTS, OBSTACLES):
        collection = collection_in(scene, name)
        if collection is not None:
            watched.update(collection.all_objects)
    for update in depsgraph.updates:
        if (update.is_updated_transform or update.is_updated_geometry) and \
                isinstance(update.id, bpy.types.Object) and update.id.original in watched:
            scene[STALE] = True
            return


def register() -> None:
    bpy.app.handlers.depsgraph_update_post.append(_on_depsgraph_update)


def unregister() -> None:
    if _on_depsgraph_update in bpy.app.handlers.depsgraph_update_post:
        bpy.app.handlers.depsgraph_update_post.remove(_on_depsgraph_update)
