# SPDX-License-Identifier: GPL-3.0-or-later
"""Importing a humanoid rig (a glTF or FBX file, or an armature already in the
Blender file): Blender's importer, then the bone map, clips and dimensions,
stored on the armature as its rig profile.

Either the whole import succeeds, or everything it created is removed again.
"""

import json
import pathlib
from dataclasses import dataclass, field
from typing import Dict, List, Optional

import bpy

from ..core import bone_map, character, rig_measure, rig_profile
from ..core.rig_profile import RigProfile
from . import datablocks, rig_body, rig_clips

PROFILE_PROPERTY = "footfall_profile"


class RigImportError(ValueError):
    """The file is not a humanoid rig Footfall can use; the message says why."""


@dataclass
class ImportedRig:
    """The imported armature object, its profile, and notes for the user."""

    armature: bpy.types.Object
    profile: RigProfile
    notes: List[str] = field(default_factory=list)


def _run_gltf_importer(filepath: str) -> None:
    # Debian's Blender 3.4 importer uses numpy.bool, which numpy 1.24 removed.
    import numpy

    if "bool" not in numpy.__dict__:  # hasattr() would warn
        numpy.bool = bool
    options = {"filepath": filepath}
    # From Blender 4.x on the importer gives bones a display shape, a stray
    # Icosphere object in the file; the option to leave it out is newer than 3.4.
    if "disable_bone_shape" in bpy.ops.import_scene.gltf.get_rna_type().properties.keys():
        options["disable_bone_shape"] = True
    _run_importer(bpy.ops.import_scene.gltf, "glTF", options)


def _run_importer(operator, kind: str, options: dict) -> None:
    filepath = options["filepath"]
    try:
        result = operator(**options)
    except RuntimeError as error:
        raise RigImportError(f"{filepath}: Blender's {kind} importer failed: {error}") from error
    if "FINISHED" not in result:
        raise RigImportError(f"{filepath}: Blender's {kind} importer did not finish")


# The rig files Import Rig reads, by suffix: Blender's importer for each.
IMPORTERS = {
    ".glb": _run_gltf_importer,
    ".gltf": _run_gltf_importer,
    ".fbx": lambda filepath: _run_importer(bpy.ops.import_scene.fbx, "FBX", {"filepath": filepath}),
}


def _merge(first: Dict[str, object], second: Dict[str, object]) -> Dict[str, object]:
    """A bone map with the roles of `first`, and of `second` where `first` has none."""
    merged = {k: (dict(v) if isinstance(v, dict) else v) for k, v in second.items()}
    for role, value in first.items():
        if isinstance(value, dict):
            merged.setdefault(role, {}).update(value)
        else:
            merged[role] = value
    return merged


def _bone_map(armature, given: Dict[str, object], rig: str):
    """The rig's bone map, and notes naming the bones found from the
    skeleton's shape rather than by name."""
    world = armature.matrix_world
    bones = [bone_map.Bone(b.name, b.parent.name if b.parent else None,
                           tuple(world @ b.head_local), tuple(world @ b.tail_local)) for b in armature.data.bones]
    mapping, _missing = bone_map.detect_partial(bones, given)
    bone_map.validate_map(mapping, [b.name for b in bones], rig)
    by_name, _ = bone_map.detect_partial([bone_map.Bone(b.name, b.parent) for b in bones], given)
    shaped = [f"{side}.{role} = '{bone}'" for side in bone_map.SIDES for role, bone in mapping[side].items()
              if by_name[side].get(role) != bone]
    notes = [f"bones found from the skeleton's shape: {', '.join(shaped)}"] if shaped else []
    return mapping, notes


def foot_skin(armature, bones: Dict[str, object]) -> Dict[str, list]:
    """Each side's foot as skinned, over every mesh the armature deforms:
    the rest position of each vertex weighted to that side's foot or toe
    bone, with its weights on the two, (x, y, z, foot weight, toe weight)."""
    skin = {"left": [], "right": []}
    meshes = [o for o in bpy.data.objects if o.type == "MESH" and
              any(m.type == "ARMATURE" and m.object == armature for m in o.modifiers)]
    for mesh in meshes:
        roles = {}  # vertex group index -> (side, 0 foot or 1 toe)
        for side in skin:
            for k, role in enumerate(("foot", "toe")):
                group = mesh.vertex_groups.get(bones[side][role])
                if group is not None:
                    roles[group.index] = (side, k)
        world = mesh.matrix_world
        for vertex in mesh.data.vertices:
            weights = {}
            for element in vertex.groups:
                if element.group in roles:
                    side, k = roles[element.group]
                    weights.setdefault(side, [0.0, 0.0])[k] += element.weight
            for side, (foot, toe) in weights.items():
                skin[side].append((*(world @ vertex.co), foot, toe))
    return skin


def foot_points(armature, bones: Dict[str, object]) -> Dict[str, list]:
    """Rest positions of the vertices skinned (weight >= 0.5) to each side's
    foot or toe bone, over every mesh the armature deforms."""
    return {side: [row[:3] for row in rows if max(row[3], row[4]) >= 0.5]
            for side, rows in foot_skin(armature, bones).items()}


def _imported_armature(path: pathlib.Path, before) -> bpy.types.Object:
    """Runs Blender's importer for the file; the one armature it made."""
    importer = IMPORTERS.get(path.suffix.lower())
    if importer is None:
        raise RigImportError(f"{path}: Import Rig reads glTF (.glb, .gltf) and FBX (.fbx) files; for a rig "
                             "already in this Blender file, give its armature instead (armature=\"Name\")")
    importer(str(path))
    armatures = [o for o in datablocks.new_since(before, "objects") if o.type == "ARMATURE"]
    if len(armatures) != 1:
        raise RigImportError(f"{path}: expected one armature, found {len(armatures)}")
    # The template itself stays out of renders: Apply makes the crowd's instances.
    for obj in (armatures[0], *armatures[0].children_recursive):
        obj.hide_render = True
    return armatures[0]


def _scene_armature(name: str) -> bpy.types.Object:
    obj = bpy.data.objects.get(name)
    if obj is None or obj.type != "ARMATURE":
        armatures = sorted(o.name for o in bpy.data.objects if o.type == "ARMATURE")
        what = "no object" if obj is None else f"a {obj.type.lower()}, not an armature"
        raise RigImportError(f"armature '{name}': {what} of that name (armatures: {', '.join(armatures) or 'none'})")
    return obj


def import_rig(filepath: str = "", mapping: Optional[Dict[str, object]] = None,
               armature: str = "") -> ImportedRig:
    """Imports the rig at `filepath` (glTF or FBX), or takes the armature
    object named `armature` already in the file (a Rigify rig, say).
    `mapping` (roles to bone names) and a profile beside the file (same name,
    .json) win over detection.

    Raises RigImportError, bone_map.BoneMapError, rig_profile.ProfileError or
    rig_clips.ClipError,
    leaving the scene as it was.
    """
    if bool(filepath) == bool(armature):
        raise RigImportError("Import Rig needs a rig file (filepath) or an armature in this file (armature), "
                             "one of the two")
    given = RigProfile(bones={})
    if filepath:
        path = pathlib.Path(filepath)
        if not path.is_file():
            raise RigImportError(f"{filepath}: no such file")
        beside = path.with_suffix(".json")
        if beside.is_file():
            given = rig_profile.load(str(beside), partial=True)
    given_bones = _merge(mapping or {}, given.bones)

    before = datablocks.snapshot()
    try:
        rig = _imported_armature(path, before) if filepath else _scene_armature(armature)
        source = path.name if filepath else rig.name
        bones, notes = _bone_map(rig, given_bones, source)
        world = rig.matrix_world
        heads = {b.name: tuple(world @ b.head_local) for b in rig.data.bones}
        tails = {b.name: tuple(world @ b.tail_local) for b in rig.data.bones}
        dimensions = rig_measure.measure(bones, heads, tails, foot_points(rig, bones))
        actions = datablocks.new_since(before, "actions") if filepath else rig_clips.actions_of(rig)
        clips, clip_notes = rig_clips.choose(rig, bones, given.clips, actions, source)
        notes += clip_notes
        profile = RigProfile(bones=bones, clips=clips, dimensions=dimensions, rig=source)
        body, body_notes = rig_body.measured(rig, profile)
        notes += body_notes
        refused = character.problem(dimensions, body, source)  # a rig that imports plans
        if refused:
            raise RigImportError(refused)
        rig[PROFILE_PROPERTY] = json.dumps(profile.to_document())  # last: a failure changes nothing
        if body is not None:
            rig[rig_body.BODY_PROPERTY] = json.dumps(body)
        elif rig_body.BODY_PROPERTY in rig:
            del rig[rig_body.BODY_PROPERTY]
    except Exception:
        datablocks.remove_new(before)
        raise
    return ImportedRig(rig, profile, notes)


def imported_rigs():
    """The armatures imported with Footfall's Import Rig."""
    return [o for o in bpy.data.objects if o.type == "ARMATURE" and PROFILE_PROPERTY in o]


def profile_of(armature) -> RigProfile:
    """The profile stored on an imported armature."""
    if PROFILE_PROPERTY not in armature:
        raise RigImportError(f"'{armature.name}' was not imported with Footfall's Import Rig")
    return rig_profile.parse(json.loads(armature[PROFILE_PROPERTY]), armature.name)
