# SPDX-License-Identifier: GPL-3.0-or-later
"""The full-body planner's body (docs/full-body.md) measured from a rig:
14 capsules fitted to its skinned mesh in the rest pose (a limb the mesh
gives nothing usable takes the built-in body's radius, scaled to the rig),
each riding on the bones of its two joints, and placed in the planner's
travel frame.

Pure numpy: the Blender side (bridge/rig_body) gives the rest joints, the
vertices of each limb and the posed bone matrices.
"""

import math
from dataclasses import dataclass
from typing import Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

SIDES = ("left", "right")
Role = Tuple[str, ...]  # ("hips",) or ("left", "forearm"): a bone of the profile's map
Joint = Tuple[Role, str]  # a bone's "head" or "tail"


def _sided(limb: str, joints) -> Dict[str, Tuple[Joint, Joint]]:
    return {f"{limb}_{side}": tuple(((side, role), end) for role, end in joints) for side in SIDES}


# Each limb's axis, joint to joint, in the core's order (model/body.hpp).
LIMB_JOINTS: Dict[str, Tuple[Joint, Joint]] = {
    "head": ((("head",), "head"), (("head",), "tail")),
    "shoulders": ((("left", "upper_arm"), "head"), (("right", "upper_arm"), "head")),
    "torso": ((("hips",), "head"), (("neck",), "head")),
    "pelvis": ((("left", "thigh"), "head"), (("right", "thigh"), "head")),
    **_sided("upper_arm", (("upper_arm", "head"), ("forearm", "head"))),
    **_sided("forearm", (("forearm", "head"), ("hand", "tail"))),
    **_sided("thigh", (("thigh", "head"), ("shin", "head"))),
    **_sided("shin", (("shin", "head"), ("foot", "head"))),
    **_sided("foot", (("foot", "head"), ("toe", "tail"))),
}
LIMBS = tuple(LIMB_JOINTS)
# The limbs a vertex skinned mostly to a bone may belong to (the nearest axis wins).
MEMBERS: Dict[Role, Tuple[str, ...]] = {
    ("head",): ("head",),
    ("neck",): ("head", "torso"),
    ("chest",): ("shoulders", "torso"),
    ("spine",): ("torso",),
    ("hips",): ("torso", "pelvis"),
    **{(side, "upper_arm"): (f"upper_arm_{side}", "shoulders") for side in SIDES},
    **{(side, role): (f"forearm_{side}",) for side in SIDES for role in ("forearm", "hand")},
    **{(side, "thigh"): (f"thigh_{side}", "pelvis") for side in SIDES},
    **{(side, "shin"): (f"shin_{side}",) for side in SIDES},
    **{(side, role): (f"foot_{side}",) for side in SIDES for role in ("foot", "toe")},
}
# The core's built-in body (native/src/fullbody/builtin_motions.cpp at
# CharacterParams' defaults: 1.75 m tall): each limb's radius [m], and its
# leg length, hip to knee to ankle [m].
BUILTIN_RADII = {"head": 0.105, "shoulders": 0.13, "torso": 0.13, "pelvis": 0.13, "upper_arm": 0.045,
                 "forearm": 0.045, "thigh": 0.065, "shin": 0.065, "foot": 0.035}
BUILTIN_LEG_LENGTH = 2 * 0.51 * (0.53 - 0.039) * 1.75
# A fitted radius is usable from a tenth to four times the built-in body's, scaled to the rig.
USABLE_RADII = (0.1, 4.0)


@dataclass(frozen=True)
class Capsule:
    """A limb's capsule at rest: its ends (world space) and radius; each end
    rides on the bone of its joint."""

    a: numpy.ndarray
    b: numpy.ndarray
    radius: float
    bone_a: Role
    bone_b: Role


def segment_distances(points: numpy.ndarray, a: numpy.ndarray, b: numpy.ndarray) -> numpy.ndarray:
    """Distances of (n, 3) points from the segment a-b."""
    axis = b - a
    length2 = float(axis @ axis)
    t = numpy.zeros(len(points)) if length2 == 0 else numpy.clip((points - a) @ axis / length2, 0.0, 1.0)
    return numpy.linalg.norm(points - (a + t[:, None] * axis), axis=1)


def _axis(a: numpy.ndarray, b: numpy.ndarray, points: numpy.ndarray) -> numpy.ndarray:
    """The points' long axis where they are clearly longer one way (twice
    the spread of the next), else the joints' direction; pointing a to b."""
    direction = (b - a) / numpy.linalg.norm(b - a)
    if len(points) < 3:
        return direction
    spreads, axes = numpy.linalg.eigh(numpy.cov((points - points.mean(axis=0)).T))
    if spreads[2] < 4.0 * spreads[1]:  # variances: twice the spread
        return direction
    longest = axes[:, 2]
    return longest if longest @ direction >= 0 else -longest


def _enclosing_circle(points: numpy.ndarray) -> Tuple[numpy.ndarray, float]:
    """The smallest circle holding 2-D points (Welzl's algorithm, iterative,
    in a fixed shuffled order)."""
    order = numpy.random.default_rng(0).permutation(len(points))
    p = [tuple(map(float, points[i])) for i in order]

    def circle2(u, v):
        centre = ((u[0] + v[0]) / 2, (u[1] + v[1]) / 2)
        return centre, math.dist(centre, u)

    def circle3(u, v, w):
        d = 2 * (u[0] * (v[1] - w[1]) + v[0] * (w[1] - u[1]) + w[0] * (u[1] - v[1]))
        if abs(d) < 1e-18:  # in a line: the widest pair's
            return max((circle2(u, v), circle2(u, w), circle2(v, w)), key=lambda c: c[1])
        uu, vv, ww = u[0] ** 2 + u[1] ** 2, v[0] ** 2 + v[1] ** 2, w[0] ** 2 + w[1] ** 2
        centre = ((uu * (v[1] - w[1]) + vv * (w[1] - u[1]) + ww * (u[1] - v[1])) / d,
                  (uu * (w[0] - v[0]) + vv * (u[0] - w[0]) + ww * (v[0] - u[0])) / d)
        return centre, math.dist(centre, u)

    def inside(c, q):
        return math.dist(c[0], q) <= c[1] * (1 + 1e-12) + 1e-15

    c = (p[0], 0.0)
    for i in range(1, len(p)):
        if inside(c, p[i]):
            continue
        c = (p[i], 0.0)
        for j in range(i):
            if inside(c, p[j]):
                continue
            c = circle2(p[i], p[j])
            for k in range(j):
                if not inside(c, p[k]):
                    c = circle3(p[i], p[j], p[k])
    return numpy.array(c[0]), c[1]


def fit(a: numpy.ndarray, b: numpy.ndarray, points: numpy.ndarray) -> Tuple[numpy.ndarray, numpy.ndarray, float]:
    """The capsule that holds every point: along their long axis (or the
    joints' direction a-b), its radius the smallest circle holding them seen
    along it, its ends as close together as that radius allows (not the
    joints: a leaf bone's tail is often a guess)."""
    direction = _axis(a, b, points)
    side = numpy.cross(direction, [1.0, 0.0, 0.0] if abs(direction[0]) < 0.9 else [0.0, 1.0, 0.0])
    side /= numpy.linalg.norm(side)
    up = numpy.cross(direction, side)
    relative = points - a
    along = relative @ direction
    centre, radius = _enclosing_circle(numpy.column_stack((relative @ side, relative @ up)))
    distance = numpy.hypot(relative @ side - centre[0], relative @ up - centre[1])
    # A point is inside when it is within the radius of the nearer end, or between the ends.
    give = numpy.sqrt(numpy.maximum(radius * radius - distance * distance, 0.0))
    start, end = float((along + give).min()), float((along - give).max())
    if start > end:
        start = end = 0.5 * (start + end)
    base = a + centre[0] * side + centre[1] * up
    return base + start * direction, base + end * direction, float(radius)


def limb_points(vertices: numpy.ndarray, roles: Sequence[Role], joints: Mapping[Joint, numpy.ndarray]
                ) -> Dict[str, numpy.ndarray]:
    """The vertices (n, 3) of each limb: a vertex's role (that of the bone it
    is skinned to most, or its nearest mapped ancestor; None: none) offers
    its limbs, and the one whose axis is nearest takes it."""
    chosen: Dict[str, List[int]] = {limb: [] for limb in LIMBS}
    by_role: Dict[Role, List[int]] = {}
    for i, role in enumerate(roles):
        if role in MEMBERS:
            by_role.setdefault(role, []).append(i)
    for role, indices in by_role.items():
        limbs = MEMBERS[role]
        points = vertices[indices]
        distances = numpy.stack([segment_distances(points, *(joints[j] for j in LIMB_JOINTS[limb]))
                                 for limb in limbs])
        nearest = distances.argmin(axis=0)
        for k, limb in enumerate(limbs):
            chosen[limb].extend(numpy.asarray(indices)[nearest == k].tolist())
    return {limb: vertices[indices] for limb, indices in chosen.items() if indices}


def builtin_radius(limb: str, leg_length: float) -> float:
    """The built-in body's radius of `limb`, scaled to a rig by its leg length:
    the length the rig's other parameters scale by (core/character), and
    measured joint to joint (the length of a leaf bone, the head, a hand or a
    toe, is often an importer's guess)."""
    kind = limb.rsplit("_", 1)[0] if limb.endswith(SIDES) else limb
    return BUILTIN_RADII[kind] * leg_length / BUILTIN_LEG_LENGTH


def _unusable(a: numpy.ndarray, b: numpy.ndarray, radius: float, builtin: float) -> Optional[str]:
    """Why a fitted capsule is no use to the planner (its limb's built-in
    radius, scaled to the rig, `builtin`), or None: not finite, or a radius
    out of USABLE_RADII."""
    if not (numpy.isfinite(a).all() and numpy.isfinite(b).all() and math.isfinite(radius)):
        return "its vertices give no finite capsule"
    low, high = USABLE_RADII
    if not low * builtin <= radius <= high * builtin:
        return f"its vertices give a radius of {radius:.3g} m"
    return None


def _rest_capsule(a: numpy.ndarray, b: numpy.ndarray, points: Optional[numpy.ndarray], builtin: float
                  ) -> Tuple[numpy.ndarray, numpy.ndarray, float, Optional[str]]:
    """A limb's capsule fitted to its points; where they give none usable,
    along its joints a-b with its built-in radius `builtin`, and why."""
    if points is None:
        return a, b, builtin, "no vertices of its own"
    fitted = fit(a, b, points)
    why = _unusable(*fitted, builtin)
    return (*fitted, None) if why is None else (a, b, builtin, why)


def rest_capsules(joints: Mapping[Joint, numpy.ndarray], points: Mapping[str, numpy.ndarray], leg_length: float
                  ) -> Tuple[Dict[str, Capsule], Dict[str, str]]:
    """Every limb's capsule at rest, fitted to its points; and the limbs whose
    points give none usable, each with why: those run joint to joint with
    the built-in body's radius, scaled to the rig."""
    capsules, fallbacks = {}, {}
    for limb, (joint_a, joint_b) in LIMB_JOINTS.items():
        a, b, radius, why = _rest_capsule(joints[joint_a], joints[joint_b], points.get(limb),
                                          builtin_radius(limb, leg_length))
        capsules[limb] = Capsule(a, b, radius, joint_a[0], joint_b[0])
        if why is not None:
            fallbacks[limb] = why
    return capsules, fallbacks


def travel_frame(root: numpy.ndarray, facing: numpy.ndarray, across: bool) -> numpy.ndarray:
    """The 4x4 matrix from world space to the travel frame: origin on the
    ground under `root`, +x the direction of travel, +z up. The body faces
    `facing` (horizontal); `across` (a side step) travels a quarter turn to
    the right of it, so that the body faces +y."""
    forward = numpy.array([facing[0], facing[1], 0.0])
    forward /= numpy.linalg.norm(forward)
    x = numpy.array([forward[1], -forward[0], 0.0]) if across else forward
    y = numpy.cross([0.0, 0.0, 1.0], x)
    frame = numpy.eye(4)
    frame[0, :3], frame[1, :3], frame[2, :3] = x, y, (0.0, 0.0, 1.0)
    frame[:3, 3] = -frame[:3, :3] @ numpy.array([root[0], root[1], 0.0])
    return frame


def lateral_extent(poses: Sequence[Mapping[str, Sequence[float]]]) -> float:
    """The farthest any capsule's surface reaches across the way (|y|) in
    the travel frame, over the poses [limb: ax, ay, az, bx, by, bz, r]."""
    return max(max(abs(c[1]), abs(c[4])) + c[6] for pose in poses for c in pose.values())
