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


def _bake(copies, scene):
    """Bakes each armature's visual pose (IK and clips included) to a new action
    with a key on every channel at every frame, then removes its constraints,
    NLA tracks and old action. One scene evaluation per frame; keys written in bulk."""
    frames = list(range(scene.frame_start, scene.frame_end + 1))
    samples = {copy: {bone.name: [] for bone in copy.pose.bones} for copy in copies}
    for frame in frames:
        scene.frame_set(frame)
        for copy in copies:
            for bone in copy.pose.bones:
                local = copy.convert_space(pose_bone=bone, matrix=bone.matrix, from_space="POSE", to_space="LOCAL")
                samples[copy][bone.name].append(local.decompose())
    actions = []
    for copy in copies:
        action = bpy.data.actions.new(f"{copy.name} baked")
        for bone in copy.pose.bones:
            for constraint in list(bone.constraints):
                bone.constraints.remove(constraint)
            bone.rotation_mode = "QUATERNION"
            pose = samples[copy][bone.name]
            rotations = [rotation for _location, rotation, _scale in pose]
            for i in range(1, len(rotations)):
                if rotations[i - 1].dot(rotations[i]) < 0:  # the shorter way round
                    rotations[i].negate()
            path = f'pose.bones["{bone.name}"].'
            channels = [(path + "location", 3, [p[0] for p in pose], (0.0, 0.0, 0.0)),
                        (path + "rotation_quaternion", 4, rotations, (1.0, 0.0, 0.0, 0.0)),
                        (path + "scale", 3, [p[2] for p in pose], (1.0, 1.0, 1.0))]
            for data_path, size, values, rest in channels:
                # A channel that never leaves its rest value is left out: less for the exporter.
                if all(abs(v[i] - rest[i]) < 1e-7 for v in values for i in range(size)):
                    continue
                for index in range(size):
                    curve = action.fcurves.new(data_path, index=index, action_group=bone.name)
                    curve.keyframe_points.add(len(frames))
                    curve.keyframe_points.foreach_set(
                        "co", [x for frame, value in zip(frames, values) for x in (frame, value[index])])
                    curve.update()
        data = copy.animation_data
        for track in list(data.nla_tracks):
            data.nla_tracks.remove(track)
        data.action = None
        _remove_controls(copy, action)
        actions.append(action)
    return actions


def _remove_controls(armature, action) -> None:
    """Removes the IK foot targets and knee poles, which only drove the bake."""
    controls = [b.name for b in armature.data.bones if b.name.startswith(("footfall_ik_foot.", "footfall_pole."))]
    for curve in [c for c in action.fcurves if c.group and c.group.name in controls]:
        action.fcurves.remove(curve)
    previous = bpy.context.view_layer.objects.active
    bpy.context.view_layer.objects.active = armature
    bpy.ops.object.mode_set(mode="EDIT")
    for name in controls:
        armature.data.edit_bones.remove(armature.data.edit_bones[name])
    bpy.ops.object.mode_set(mode="OBJECT")
    bpy.context.view_layer.objects.active = previous


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
        baked = _bake(copies, scene)
        bpy.ops.object.select_all(action="DESELECT")
        for copy, armature, action in zip(copies, armatures, baked):
            track = copy.animation_data.nla_tracks.new()
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
