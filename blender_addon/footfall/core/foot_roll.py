# SPDX-License-Identifier: GPL-3.0-or-later
"""Heel-toe roll: the foot's pitch through each stance and swing, and where
the ankle goes so that the point the foot rolls on stays put.

The model (docs/animation.md) is the core's, shared with the headless glTF
writer: footfall._native.foot_roll. A walking foot strikes with its toes up,
pivoting on the heel, is flat while the body passes over it, and rises on
its ball up to toe-off; amplitudes grow with the step's speed; starts, waits
and side steps stay flat. Here: the foot's shape from the rig, and the plan's
steps as arrays for the core.

Pitch is positive with the toes up. Offsets are the ankle's displacement
from where it stands with the foot flat, along the foot's forward direction
and up [m].
"""

from dataclasses import astuple, dataclass

import numpy

from . import native

_AMPLITUDES = native.load().FOOT_ROLL
HEEL_STRIKE = _AMPLITUDES["heel_strike"]  # toes up at heel strike, at full speed [rad]
TOE_OFF = _AMPLITUDES["toe_off"]  # heel up at toe-off, at full speed [rad]
HEEL_SHARE = _AMPLITUDES["heel_share"]  # of the foot's length behind the ankle, for a foot without a mesh
STAIR_RISE = _AMPLITUDES["stair_rise"]  # a step rising or dropping more is a stair's: set down flat [m]


@dataclass(frozen=True)
class FootShape:
    """The foot seen from the side, flat on the ground, from the point under
    the ankle: the ankle's height, the heel's contact behind it, and the
    ball (toe joint) ahead of and above it [m]; and the most its heel rises
    in a stance [rad] (the core's steepest_toe_off: no more than lets the
    skin under the ball slide a few millimetres)."""

    ankle_height: float
    heel_back: float
    ball_ahead: float
    ball_height: float
    toe_off_limit: float = TOE_OFF


def foot_shape(ankle, ball, forward, foot_length: float, skin=()) -> FootShape:
    """The shape of a foot at rest, from its ankle (the foot bone's head) and
    ball (the toe bone's head), the rig's forward direction on the ground
    (unit), its length, and its mesh's vertices skinned to the foot or toe
    bone (rows of world x, y, z (Z up), foot weight, toe weight): the heel
    is the vertex (weighted at least half to either) furthest behind the
    ankle, else HEEL_SHARE of the length behind it."""
    ankle, ball, forward = (numpy.asarray(v, dtype=float) for v in (ankle, ball, forward))
    skin = numpy.asarray(skin, dtype=float).reshape(-1, 5)
    ahead = (skin[:, :3] - ankle) @ forward
    behind = -ahead[numpy.maximum(skin[:, 3], skin[:, 4]) >= 0.5]
    heel_back = float(behind.max()) if behind.size and behind.max() > 0.0 else HEEL_SHARE * foot_length
    shape = (float(ankle[2]), heel_back, float(numpy.dot(ball - ankle, forward)), float(ball[2]))
    sole = numpy.column_stack((ahead, skin[:, 2], skin[:, 3], skin[:, 4]))
    return FootShape(*shape, native.load().steepest_toe_off(shape, sole))


@dataclass(frozen=True)
class Steps:
    """A plan's footsteps as arrays: start and end times [s], the foot
    (0 left, 1 right), whether the body goes over the feet (a walk or a
    stop; not a side step, nor a stair's step), and the COM's speed [m/s]."""

    start: numpy.ndarray
    end: numpy.ndarray
    foot: numpy.ndarray
    forward: numpy.ndarray
    speed: numpy.ndarray


def roll(times: numpy.ndarray, planted: numpy.ndarray, side: int, steps: Steps, shape: FootShape,
         full_speed: float, leaves: bool = False):
    """(pitch [rad], forward offset [m], up offset [m]) of foot `side` at
    `times`, where `planted` says whether the plan has it planted. An agent
    that `leaves` walks on past its last step: its feet roll as if another
    step followed."""
    return native.load().foot_roll(
        numpy.asarray(times, dtype=float), numpy.asarray(planted, dtype=bool), side,
        numpy.asarray(steps.start, dtype=float), numpy.asarray(steps.end, dtype=float),
        numpy.asarray(steps.foot, dtype=numpy.int32), numpy.asarray(steps.forward, dtype=bool),
        numpy.asarray(steps.speed, dtype=float), astuple(shape), full_speed, leaves)
