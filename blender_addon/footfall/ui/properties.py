# SPDX-License-Identifier: GPL-3.0-or-later
"""Scene properties: the rig that animates the agents, and the bone fields
that complete a rig's bone map when detection fails."""

import bpy

from ..core.bone_map import CENTER_ROLES, LIMB_ROLES, SIDES

MAPPING_FIELDS = [(role, None, role) for role in CENTER_ROLES] + [
    (f"{side}_{role}", side, role) for side in SIDES for role in LIMB_ROLES
]


def _annotations():
    return {
        name: bpy.props.StringProperty(
            name=name.replace("_", " ").title(),
            description=f"Bone of the rig that plays the {name.replace('_', ' ')} (empty: detect it)",
        )
        for name, _side, _role in MAPPING_FIELDS
    }


FOOTFALL_PG_bone_map = type(
    "FOOTFALL_PG_bone_map",
    (bpy.types.PropertyGroup,),
    {"__annotations__": _annotations(), "__doc__": "Bone names that override detection, per role."},
)


def mapping_of(fields) -> dict:
    """The filled-in fields as a bone map ({"hips": ..., "left": {...}})."""
    mapping = {}
    for name, side, role in MAPPING_FIELDS:
        value = getattr(fields, name).strip()
        if not value:
            continue
        if side:
            mapping.setdefault(side, {})[role] = value
        else:
            mapping[role] = value
    return mapping


def _is_imported_rig(_scene, obj) -> bool:
    from ..bridge.rig_import import PROFILE_PROPERTY

    return obj.type == "ARMATURE" and PROFILE_PROPERTY in obj


def register():
    bpy.types.Scene.footfall_bone_map = bpy.props.PointerProperty(type=FOOTFALL_PG_bone_map)
    bpy.types.Scene.footfall_rig = bpy.props.PointerProperty(
        type=bpy.types.Object, name="Rig", poll=_is_imported_rig,
        description="The imported rig that animates the agents and sizes their character (an agent's "
                    "custom property 'footfall_rig' names another for it alone)")


def unregister():
    del bpy.types.Scene.footfall_rig
    del bpy.types.Scene.footfall_bone_map
