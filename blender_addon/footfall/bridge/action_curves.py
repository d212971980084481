# SPDX-License-Identifier: GPL-3.0-or-later
"""The F-curves of an action, through the API of the Blender running.

From Blender 4.4 on, actions are layered: their F-curves live in a channel bag
per slot (the data-block they animate), and Blender 5.0 drops the older
`Action.fcurves`. Before 4.4 they are the action's own. The add-on's actions
animate one armature object each, so they have one slot.
"""

import bpy

LAYERED = bpy.app.version >= (4, 4, 0)


def _slot(action):
    """The action's slot, made if it has none."""
    return action.slots[0] if len(action.slots) else action.slots.new(id_type="OBJECT", name=action.name)


def _channelbag(action):
    """The channel bag of the action's slot in its first layer's keyframe strip,
    made (with the slot, layer and strip) if it has none."""
    slot = _slot(action)
    layer = action.layers[0] if len(action.layers) else action.layers.new("Layer")
    strip = layer.strips[0] if len(layer.strips) else layer.strips.new(type="KEYFRAME")
    return strip.channelbag(slot, ensure=True)


def assign(obj, action) -> None:
    """Makes `action` the object's active action, animating it through the action's slot."""
    animation = obj.animation_data_create()
    animation.action = action
    if LAYERED:
        animation.action_slot = _slot(action)


def curves(action) -> list:
    """Every F-curve of the action."""
    if not LAYERED:
        return list(action.fcurves)
    return [curve for layer in action.layers for strip in layer.strips
            for bag in strip.channelbags for curve in bag.fcurves]


def curve(action, data_path: str, index: int, group: str):
    """The action's F-curve of `data_path`[`index`], made in `group` if it has none."""
    if not LAYERED:
        return action.fcurves.find(data_path, index=index) or \
            action.fcurves.new(data_path, index=index, action_group=group)
    bag = _channelbag(action)
    found = bag.fcurves.find(data_path, index=index)
    if found:
        return found
    made = bag.fcurves.new(data_path, index=index)
    made.group = bag.groups.get(group) or bag.groups.new(group)
    return made


def remove(action, fcurve) -> None:
    """Removes one of the action's F-curves."""
    if not LAYERED:
        action.fcurves.remove(fcurve)
        return
    for layer in action.layers:
        for strip in layer.strips:
            for bag in strip.channelbags:
                if any(c == fcurve for c in bag.fcurves):
                    bag.fcurves.remove(fcurve)
                    return
