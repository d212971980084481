# SPDX-License-Identifier: GPL-3.0-or-later
"""Baking the animated crowd and exporting it as glTF.

Blender 3.4's exporter bakes animation too slowly for crowds, so the work is
split:

1. bake: every bone of every agent as Blender evaluates it (IK, clips and
   all), at every frame of the scene (bake.py);
2. Blender's exporter writes the crowd without animation: per agent, a copy
   of its armature without the IK controls, in rest pose, and its skinned
   meshes, named after the agent;
3. one glTF animation per agent, named after it, is added to that file: a
   linear channel per bone and per translation, rotation and scale, keyed at
   every frame at time frame / frame rate (as Blender's exporter keys),
   leaving out channels that stay at the bone's rest.

Before 3, every bone's rest is checked against what the exporter wrote, so
that an exporter with other bone conventions fails loudly instead of writing
wrong motion. The scene is left as it was; the file is written beside the
target and moved into place, so a failure leaves no half-written file.
"""

import os
from typing import Callable, Dict, List, Optional

import bpy
import numpy

from ..core import glb, node_motion
from . import animate, bake, datablocks

REST_TOLERANCE = 1e-4  # [m, or per unit] the exporter's rest against ours
STILL_TOLERANCE = 1e-5  # a channel closer than this to its rest at every frame is left out


class ExportError(ValueError):
    """Nothing to export, or the exporter failed; the message says which."""


def _exporter_options(filepath: str) -> dict:
    """Options for Blender 3.4's exporter, and for 4.x where they were renamed:
    the selected objects and their skins, without animation."""
    available = bpy.ops.export_scene.gltf.get_rna_type().properties.keys()
    options = dict(filepath=filepath, export_format="GLB", use_selection=True, export_yup=True,
                   export_skins=True, export_animations=False, export_apply=False)
    for name, value in (("export_cameras", False), ("export_lights", False), ("export_current_frame", False)):
        if name in available:
            options[name] = value
    return options


def _still_copies(armatures, names: Dict[object, str], scene_collection) -> List[bpy.types.Object]:
    """Still copies of the armatures under the given names, without animation,
    constraints or IK controls, with copies of their meshes (the mesh data
    shared) deformed by them, all shown (bake() writes when agents are gone)."""
    copies = []
    for armature in armatures:
        copy = armature.copy()
        copy.data = armature.data.copy()
        copy.name = names[armature]
        copy.animation_data_clear()
        copy.hide_viewport = copy.hide_render = False  # one that has left is hidden now
        for bone in copy.pose.bones:
            for constraint in list(bone.constraints):
                bone.constraints.remove(constraint)
        scene_collection.objects.link(copy)
        copies.append(copy)
    _remove_controls(copies)
    for copy, armature in zip(copies, armatures):
        for child in armature.children:
            body = animate.deformed_copy(child, copy, scene_collection)
            body.animation_data_clear()
            body.hide_viewport = body.hide_render = False
    return copies


def _remove_controls(copies) -> None:
    """Removes the IK foot targets and knee poles, in one edit session for all
    (each mode switch updates the whole scene)."""
    view_layer = bpy.context.view_layer
    bpy.ops.object.select_all(action="DESELECT")
    for copy in copies:
        copy.select_set(True)
    view_layer.objects.active = copies[0]
    bpy.ops.object.mode_set(mode="EDIT")
    try:
        for copy in copies:
            bones = copy.data.edit_bones
            for bone in [b for b in bones if b.name.startswith(animate.CONTROL_PREFIXES)]:
                bones.remove(bone)
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")


def _node_matrix(node: dict) -> numpy.ndarray:
    if "matrix" in node:
        return numpy.array(node["matrix"], dtype=float).reshape(4, 4).T  # glTF is column-major
    x, y, z, w = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
    rotation = numpy.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    matrix = numpy.identity(4)
    matrix[:3, :3] = rotation * numpy.array(node.get("scale", (1.0, 1.0, 1.0)))
    matrix[:3, 3] = node.get("translation", (0.0, 0.0, 0.0))
    return matrix


def _bone_nodes(document: dict, agent: str) -> Dict[str, int]:
    """The node of each bone under the agent's armature node (a scene root)."""
    nodes = document["nodes"]
    roots = [i for scene in document.get("scenes", []) for i in scene.get("nodes", [])]
    found = [i for i in roots if nodes[i].get("name") == agent]
    if len(found) != 1:
        raise ExportError(f"agent '{agent}': the exporter wrote {len(found)} armature nodes by that name")
    bones, stack = {}, list(nodes[found[0]].get("children", []))
    while stack:
        i = stack.pop()
        if "mesh" not in nodes[i]:
            bones[nodes[i]["name"]] = i
            stack.extend(nodes[i].get("children", []))
    return bones


def _check_rest(document: dict, agent: str, copy, bone_nodes: Dict[str, int]) -> None:
    """The exporter's bone nodes must be the rest poses in Footfall's convention (node_motion)."""
    ours = bake.rest_node_matrices(copy.data)
    for bone, matrix in zip(copy.data.bones, ours):
        if bone.name not in bone_nodes:
            raise ExportError(f"agent '{agent}': the exporter wrote no node for bone '{bone.name}'")
        written = _node_matrix(document["nodes"][bone_nodes[bone.name]])
        if numpy.abs(written - matrix).max() > REST_TOLERANCE:
            raise ExportError(f"agent '{agent}', bone '{bone.name}': the glTF exporter wrote a rest pose "
                              "in a convention Footfall does not know; the animation would be wrong")


def _animation(file: glb.Glb, agent: str, baked: bake.BakedBones, bone_nodes: Dict[str, int], times: int) -> dict:
    """One animation for the agent: a channel per bone and property that leaves its rest."""
    nodes = file.document["nodes"]
    channels, samplers = [], []
    for index, name in enumerate(baked.names):
        if name not in bone_nodes:
            continue  # an IK control
        node = nodes[bone_nodes[name]]
        for path, values, rest in (("translation", baked.translations, node.get("translation", (0.0, 0.0, 0.0))),
                                   ("rotation", baked.rotations, node.get("rotation", (0.0, 0.0, 0.0, 1.0))),
                                   ("scale", baked.scales, node.get("scale", (1.0, 1.0, 1.0)))):
            series = values[:, index]
            rest = numpy.array(rest)
            still = numpy.abs(series - rest).max() if path != "rotation" else min(
                numpy.abs(series - rest).max(), numpy.abs(series + rest).max())  # q and -q are one rotation
            if still < STILL_TOLERANCE:
                continue
            samplers.append({"input": times, "output": file.add_floats(series), "interpolation": "LINEAR"})
            channels.append({"sampler": len(samplers) - 1, "target": {"node": bone_nodes[name], "path": path}})
    return {"name": agent, "channels": channels, "samplers": samplers}


def _export_still_crowd(filepath: str, copies: List[bpy.types.Object]) -> None:
    bpy.ops.object.select_all(action="DESELECT")
    for copy in copies:
        for obj in (copy, *copy.children):
            obj.select_set(True)
    try:
        result = bpy.ops.export_scene.gltf(**_exporter_options(filepath))
    except RuntimeError as error:
        # The operator's error carries the exporter's traceback: its last line says what failed.
        lines = [line for line in str(error).splitlines() if line.strip() and not line.startswith("Location:")]
        raise ExportError(f"{filepath}: Blender's glTF exporter failed: {lines[-1] if lines else error}") from error
    if "FINISHED" not in result:
        raise ExportError(f"{filepath}: Blender's glTF exporter did not finish")


def export_crowd(filepath: str, scene, progress: Optional[Callable[[float], None]] = None) -> int:
    """Bakes and exports every agent animated by apply; returns how many.
    `progress` gets the share of the bake done, from 0 to 1."""
    armatures = animate.crowd_armatures()
    if not armatures:
        raise ExportError("Nothing to export: apply a plan first (Footfall > Apply Plan)")
    folder = os.path.dirname(os.path.abspath(filepath))
    if not os.path.isdir(folder) or not os.access(folder, os.W_OK):
        raise ExportError(f"{filepath}: the folder {folder} does not exist or cannot be written to")
    frames = list(range(scene.frame_start, scene.frame_end + 1))
    fps = scene.render.fps / scene.render.fps_base
    before = datablocks.snapshot()
    names = {armature: armature.name for armature in armatures}
    frame = scene.frame_current
    view_layer = bpy.context.view_layer
    selected, active = [o for o in view_layer.objects if o.select_get()], view_layer.objects.active
    partial = filepath + ".partial.glb"
    try:
        baked = bake.bake(armatures, scene, frames, progress)
        scene.frame_set(frame)
        # The copies take the agents' names, so that glTF nodes and animations carry them.
        for armature in armatures:
            armature.name += " (animated)"
        copies = _still_copies(armatures, names, scene.collection)
        _export_still_crowd(partial, copies)
        file = glb.read(partial)
        times = file.add_floats(numpy.array(frames, dtype=float) / fps, bounds=True)
        animations = file.document.setdefault("animations", [])
        for copy, sampled in zip(copies, baked):
            bone_nodes = _bone_nodes(file.document, copy.name)
            _check_rest(file.document, copy.name, copy, bone_nodes)
            animations.append(_animation(file, copy.name, sampled, bone_nodes, times))
        glb.write(file, partial)
        os.replace(partial, filepath)
        return len(copies)
    except (OSError, glb.GlbError, bake.BakeError) as error:
        raise ExportError(f"{filepath}: the export failed: {error}") from error
    finally:
        if os.path.exists(partial):
            os.remove(partial)
        datablocks.remove_new(before)
        for armature, name in names.items():
            armature.name = name
        for obj in view_layer.objects:
            obj.select_set(obj in selected)
        view_layer.objects.active = active
        scene.frame_set(frame)
