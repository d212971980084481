# SPDX-License-Identifier: GPL-3.0-or-later
"""Baking the animated crowd and exporting it as glTF.

The scene is left as it is: temporary copies of the agents' armatures are
baked (visual keying, so IK and clips become plain bone keys; constraints
removed), each baked action is put on one NLA track named after its agent, so
that every agent becomes exactly one glTF animation, the copies get the
agents' meshes and are exported, and then removed with everything made for
them.
"""

import os

import bpy
from bpy_extras import anim_utils

from . import animate, datablocks


class ExportError(ValueError):
    """Nothing to export, or the exporter failed; the message says which."""


def crowd_armatures():
    """The armatures that footfall.apply made."""
    collection = bpy.data.collections.get(animate.CROWD_COLLECTION)
    return [o for o in collection.objects if o.type == "ARMATURE"] if collection else []


def _exporter_options(filepath: str) -> dict:
    """Options for Blender 3.4's exporter, and for 4.x where they were renamed."""
    available = bpy.ops.export_scene.gltf.get_rna_type().properties.keys()
    options = dict(filepath=filepath, export_format="GLB", use_selection=True, export_yup=True,
                   export_skins=True, export_animations=True, export_apply=False)
    if "export_animation_mode" in available:  # Blender 4.x
        options["export_animation_mode"] = "NLA_TRACKS"
    else:  # Blender 3.x
        options["export_nla_strips"] = True
    # The baked actions hold a key at every frame: they are written as they are,
    # without the exporter sampling the scene again.
    for name, value in (("export_anim_single_armature", False), ("export_force_sampling", False),
                        ("export_optimize_animation_size", False), ("export_cameras", False),
                        ("export_lights", False)):
        if name in available:
            options[name] = value
    return options


def _bodies_for(copy, armature, scene_collection):
    """Copies of the agent's meshes, deformed by `copy` (the mesh data shared)."""
    bodies = []
    for child in armature.children:
        body = child.copy()
        body.parent = copy
        for modifier in body.modifiers:
            if modifier.type == "ARMATURE":
                modifier.object = copy
        scene_collection.objects.link(body)
        bodies.append(body)
    return bodies


def _layer_collection(layer, collection):
    if layer.collection == collection:
        return layer
    for child in layer.children:
        found = _layer_collection(child, collection)
        if found is not None:
            return found
    return None


def export_crowd(filepath: str, scene) -> int:
    """Bakes and exports every agent animated by apply; returns how many."""
    armatures = crowd_armatures()
    if not armatures:
        raise ExportError("Nothing to export: apply a plan first (Footfall > Apply Plan)")
    before = datablocks.snapshot()
    names = {a: a.name for a in armatures}
    frame = scene.frame_current
    crowd = _layer_collection(bpy.context.view_layer.layer_collection, bpy.data.collections[animate.CROWD_COLLECTION])
    excluded = crowd.exclude
    try:
        # The animated agents leave the view layer while their copies are baked:
        # only the copies' armatures (no meshes) are evaluated at every frame.
        crowd.exclude = True
        # The copies take the agents' names, so that glTF nodes and animations carry them.
        for armature in armatures:
            armature.name = armature.name + " (animated)"
        copies = []
        for armature in armatures:
            copy = armature.copy()
            copy.data = armature.data.copy()
            copy.name = names[armature]
            scene.collection.objects.link(copy)
            copies.append(copy)
        bpy.context.view_layer.update()
        frames = range(scene.frame_start, scene.frame_end + 1)
        baked = anim_utils.bake_action_objects(
            [(copy, None) for copy in copies], frames=frames, only_selected=False, do_pose=True,
            do_object=False, do_visual_keying=True, do_constraint_clear=True, do_parents_clear=False, do_clean=False)
        bpy.ops.object.select_all(action="DESELECT")
        for copy, armature, action in zip(copies, armatures, baked):
            action.name = f"{copy.name} baked"
            data = copy.animation_data
            for track in list(data.nla_tracks):
                data.nla_tracks.remove(track)
            data.action = None
            track = data.nla_tracks.new()
            track.name = copy.name
            track.strips.new(copy.name, scene.frame_start, action)
            for obj in [copy, *_bodies_for(copy, armature, scene.collection)]:
                obj.select_set(True)
        # Written beside the target and moved into place: a failure leaves no half-written file.
        partial = filepath + ".partial.glb"
        try:
            result = bpy.ops.export_scene.gltf(**_exporter_options(partial))
            if "FINISHED" not in result:
                raise ExportError(f"{filepath}: Blender's glTF exporter did not finish")
            os.replace(partial, filepath)
        except (RuntimeError, OSError) as error:
            raise ExportError(f"{filepath}: the export failed: {error}") from error
        finally:
            if os.path.exists(partial):
                os.remove(partial)
        return len(copies)
    finally:
        datablocks.remove_new(before)
        for armature, name in names.items():
            armature.name = name
        crowd.exclude = excluded
        scene.frame_set(frame)
