# SPDX-License-Identifier: GPL-3.0-or-later
"""A rig's dimensions, measured from its bones in the rest pose.

Positions are world-space (x, y, z) in metres, Z up, the ground at z = 0.
"""

import math
from typing import Dict, Mapping, Optional, Sequence, Tuple

Point3 = Tuple[float, float, float]


def _ground_distance(a: Point3, b: Point3) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def _foot_length(ankle: Point3, ball: Point3, toe_tail: Point3, points: Optional[Sequence[Point3]]) -> float:
    """Heel to toe tip: the extent of the foot's mesh along the ankle-to-ball
    direction on the ground. Without mesh points, ankle to the toe bone's tail
    (glTF keeps no bone tails, so an imported leaf bone's tail is a guess)."""
    if not points:
        return _ground_distance(ankle, toe_tail)
    axis = (ball[0] - ankle[0], ball[1] - ankle[1])
    norm = math.hypot(*axis)
    axis = (axis[0] / norm, axis[1] / norm)
    along = [(p[0] - ankle[0]) * axis[0] + (p[1] - ankle[1]) * axis[1] for p in points]
    return max(along) - min(along)


def measure(
    bone_map: Mapping[str, object],
    heads: Mapping[str, Point3],
    tails: Mapping[str, Point3],
    foot_points: Optional[Mapping[str, Sequence[Point3]]] = None,
) -> Dict[str, float]:
    """hip_height, leg_length, shoulder_width and foot_length of a mapped rig.

    hip_height: height of the hip joints (the thighs' heads), both sides averaged.
    leg_length: hip to knee to ankle (thigh head, shin head, foot head), averaged.
    shoulder_width: between the upper arms' heads.
    foot_length: heel to toe tip along the ground, averaged; `foot_points`
    ("left"/"right" -> the rest positions of the vertices skinned to that
    side's foot and toe bones) give the heel and the tip.
    """
    sides = [bone_map["left"], bone_map["right"]]
    hip_height = sum(heads[s["thigh"]][2] for s in sides) / 2
    leg_length = sum(
        math.dist(heads[s["thigh"]], heads[s["shin"]]) + math.dist(heads[s["shin"]], heads[s["foot"]]) for s in sides
    ) / 2
    shoulder_width = math.dist(heads[sides[0]["upper_arm"]], heads[sides[1]["upper_arm"]])
    foot_length = sum(
        _foot_length(heads[s["foot"]], heads[s["toe"]], tails[s["toe"]], (foot_points or {}).get(side))
        for side, s in zip(("left", "right"), sides)
    ) / 2
    return {
        "hip_height": hip_height,
        "leg_length": leg_length,
        "shoulder_width": shoulder_width,
        "foot_length": foot_length,
    }
