# SPDX-License-Identifier: GPL-3.0-or-later
"""A rig's dimensions, measured from its bones in the rest pose.

Positions are world-space (x, y, z) in metres, Z up, the ground at z = 0.
"""

import math
from typing import Dict, Mapping, Tuple

Point3 = Tuple[float, float, float]


def _ground_distance(a: Point3, b: Point3) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def measure(bone_map: Mapping[str, object], heads: Mapping[str, Point3], tails: Mapping[str, Point3]) -> Dict[str, float]:
    """hip_height, leg_length, shoulder_width and foot_length of a mapped rig.

    hip_height: height of the hip joints (the thighs' heads), both sides averaged.
    leg_length: hip to knee to ankle (thigh head, shin head, foot head), averaged.
    shoulder_width: between the upper arms' heads.
    foot_length: along the ground from the ankle (foot head) to the toe tip (toe tail), averaged.
    """
    sides = [bone_map["left"], bone_map["right"]]
    hip_height = sum(heads[s["thigh"]][2] for s in sides) / 2
    leg_length = sum(
        math.dist(heads[s["thigh"]], heads[s["shin"]]) + math.dist(heads[s["shin"]], heads[s["foot"]]) for s in sides
    ) / 2
    shoulder_width = math.dist(heads[sides[0]["upper_arm"]], heads[sides[1]["upper_arm"]])
    foot_length = sum(_ground_distance(heads[s["foot"]], tails[s["toe"]]) for s in sides) / 2
    return {
        "hip_height": hip_height,
        "leg_length": leg_length,
        "shoulder_width": shoulder_width,
        "foot_length": foot_length,
    }
