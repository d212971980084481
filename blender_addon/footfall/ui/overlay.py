# SPDX-License-Identifier: GPL-3.0-or-later
"""The viewport overlay: the stored plan drawn over the 3D Viewport
(core/plan_overlay), two batches a redraw whatever the crowd's size, while
the scene's "Show Plan" (footfall_show_overlay) is on."""

from typing import Optional

import bpy

from ..bridge import plan_store
from ..core.plan_overlay import Lines, PlanOverlay

_handle = None
_cached = {"revision": None, "overlay": None, "batch": None}
# Blender 4 names the shader "FLAT_COLOR"; 3.4 knows it as "3D_FLAT_COLOR".
_FLAT_COLOR = "FLAT_COLOR" if bpy.app.version >= (4, 0, 0) else "3D_FLAT_COLOR"


def scene_time(scene) -> float:
    """The plan's time at the scene's current frame [s] (Apply's: the plan
    starts at the scene's first frame)."""
    fps = scene.render.fps / scene.render.fps_base
    return (scene.frame_current + scene.frame_subframe - scene.frame_start) / fps


def overlay_of(scene) -> Optional[PlanOverlay]:
    """The stored plan's overlay, made once per stored plan; None without a
    readable plan or with the overlay off."""
    if not scene.footfall_show_overlay:
        return None
    revision = plan_store.revision()
    if revision is None:
        return None
    if revision != _cached["revision"]:
        _cached.update(revision=revision, overlay=None, batch=None)
        try:
            plan = plan_store.load_plan()
        except ValueError:
            return None  # a damaged plan: Apply and the panel say so
        _cached["overlay"] = PlanOverlay(plan) if plan is not None else None
    return _cached["overlay"]


def _batch(lines: Lines):
    import gpu
    from gpu_extras.batch import batch_for_shader

    shader = gpu.shader.from_builtin(_FLAT_COLOR)
    return shader, batch_for_shader(shader, "LINES", {"pos": lines.points, "color": lines.colors})


def _draw() -> None:
    scene = bpy.context.scene
    overlay = overlay_of(scene)
    if overlay is None or not len(overlay.fixed.points):
        return
    import gpu

    if _cached["batch"] is None:
        _cached["batch"] = _batch(overlay.fixed)
    gpu.state.depth_test_set("LESS_EQUAL")
    gpu.state.blend_set("ALPHA")
    for shader, batch in (_cached["batch"], _batch(overlay.under_way(scene_time(scene)))):
        batch.draw(shader)
    gpu.state.depth_test_set("NONE")
    gpu.state.blend_set("NONE")


def register() -> None:
    global _handle
    bpy.types.Scene.footfall_show_overlay = bpy.props.BoolProperty(
        name="Show Plan", default=True,
        description="Draw the stored plan in the viewport: each agent's path coloured by behaviour (walking "
                    "blue, arms in green, side-stepping red), its footprints, the steps under way at the "
                    "current frame in yellow, and a cross where an agent that did not arrive stopped")
    if not bpy.app.background:
        _handle = bpy.types.SpaceView3D.draw_handler_add(_draw, (), "WINDOW", "POST_VIEW")


def unregister() -> None:
    global _handle
    if _handle is not None:
        bpy.types.SpaceView3D.draw_handler_remove(_handle, "WINDOW")
        _handle = None
    _cached.update(revision=None, overlay=None, batch=None)
    del bpy.types.Scene.footfall_show_overlay
