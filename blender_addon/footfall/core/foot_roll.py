# SPDX-License-Identifier: GPL-3.0-or-later
"""Heel-toe roll: the foot's pitch through each stance and swing, and where
the ankle goes so that the point the foot rolls on stays put.

A walking foot strikes with its toes up, pivoting on the heel until it is
flat (the first FLAT_AT of the stance); it stays flat while the body passes
over it; from HEEL_OFF_AT of the stance on its heel rises, pivoting on the
ball (the toe joint), up to toe-off at the stance's end. In the swing the
pitch and the ankle's offset go smoothly from toe-off to the next heel
strike. Amplitudes grow with the step's speed up to the preferred speed.
A foot rolls in only from a moving step by the other foot and rolls off
only into one (a walk, or a stop that still carries the body forward), so
that starts, waits and side steps stay flat.

Pitch is positive with the toes up. Offsets are the ankle's displacement
from where it stands with the foot flat, along the foot's forward direction
and up [m]. Pure numpy: the caller gives the plan's steps as arrays.
"""

import math
from dataclasses import dataclass

import numpy

HEEL_STRIKE = math.radians(15)  # toes up at heel strike, at full speed
TOE_OFF = math.radians(30)  # heel up at toe-off, at full speed
FLAT_AT = 0.15  # of the stance: the foot is flat from here
HEEL_OFF_AT = 0.6  # of the stance: the heel rises from here


@dataclass(frozen=True)
class FootShape:
    """The foot seen from the side, flat on the ground, from the point under
    the ankle: the ankle's height, the heel's contact behind it, and the
    ball (toe joint) ahead of and above it [m]."""

    ankle_height: float
    heel_back: float
    ball_ahead: float
    ball_height: float

    def offset(self, pitch: numpy.ndarray):
        """The ankle's (forward, up) displacement at `pitch`: turning on the
        heel for the toes up, on the ball for the heel up."""
        toes_up = pitch > 0.0
        # The ankle seen from the pivot.
        vx = numpy.where(toes_up, self.heel_back, -self.ball_ahead)
        vz = numpy.where(toes_up, self.ankle_height, self.ankle_height - self.ball_height)
        c, s = numpy.cos(pitch), numpy.sin(pitch)
        return c * vx - s * vz - vx, s * vx + c * vz - vz


HEEL_SHARE = 0.25  # of the foot's length behind the ankle, for a foot without a mesh


def foot_shape(ankle, ball, forward, foot_length: float, points=()) -> FootShape:
    """The shape of a foot at rest, from its ankle (the foot bone's head) and
    ball (the toe bone's head), the rig's forward direction on the ground
    (unit), its length, and the positions of its mesh's vertices (world,
    Z up): the heel is the vertex furthest behind the ankle, else
    HEEL_SHARE of the length behind it."""
    ankle, ball, forward = (numpy.asarray(v, dtype=float) for v in (ankle, ball, forward))
    behind = [-float(numpy.dot(numpy.asarray(p, dtype=float) - ankle, forward)) for p in points]
    heel_back = max(behind) if behind and max(behind) > 0.0 else HEEL_SHARE * foot_length
    return FootShape(float(ankle[2]), heel_back, float(numpy.dot(ball - ankle, forward)), float(ball[2]))


@dataclass(frozen=True)
class Steps:
    """A plan's footsteps as arrays: start and end times [s], the foot
    (0 left, 1 right), whether the body goes over the feet (a walk or a
    stop; not a side step), and the COM's speed [m/s]."""

    start: numpy.ndarray
    end: numpy.ndarray
    foot: numpy.ndarray
    forward: numpy.ndarray
    speed: numpy.ndarray


def _smooth(w):
    w = numpy.clip(w, 0.0, 1.0)
    return w * w * (3.0 - 2.0 * w)


def roll(times: numpy.ndarray, planted: numpy.ndarray, side: int, steps: Steps, shape: FootShape,
         full_speed: float, leaves: bool = False):
    """(pitch [rad], forward offset [m], up offset [m]) of foot `side` at
    `times`, where `planted` says whether the plan has it planted. An agent
    that `leaves` walks on past its last step: its feet roll as if another
    step followed."""
    count = len(steps.start)
    pitch = numpy.zeros(len(times))
    if count == 0:
        return pitch, pitch.copy(), pitch.copy()
    amplitude = numpy.where(steps.forward, numpy.clip(steps.speed / full_speed, 0.0, 1.0), 0.0)
    rolling = amplitude > 0.0
    after = numpy.zeros(count, dtype=bool)  # swung in during the step before
    after[1:] = rolling[1:] & rolling[:-1] & (steps.foot[1:] != steps.foot[:-1])
    before = numpy.zeros(count, dtype=bool)  # swings during the step after
    before[:-1] = rolling[:-1] & rolling[1:] & (steps.foot[1:] != steps.foot[:-1])
    before[-1] = leaves and rolling[-1]
    strike = numpy.where(after, HEEL_STRIKE * amplitude, 0.0)
    toe_off = numpy.where(before, -TOE_OFF * amplitude, 0.0)

    k = numpy.clip(numpy.searchsorted(steps.start, times, side="right") - 1, 0, count - 1)
    started = times >= steps.start[k]
    u = numpy.clip((times - steps.start[k]) / numpy.maximum(steps.end[k] - steps.start[k], 1e-9), 0.0, 1.0)
    own = steps.foot[k] == side

    stance = own & planted & started
    in_strike = numpy.clip(1.0 - u / FLAT_AT, 0.0, 1.0) * strike[k]
    in_off = numpy.clip((u - HEEL_OFF_AT) / (1.0 - HEEL_OFF_AT), 0.0, 1.0) * toe_off[k]
    pitch = numpy.where(stance, in_strike + in_off, 0.0)
    forward, up = shape.offset(pitch)

    # In a walking step by the other foot this one swings from its toe-off
    # (the step before) to its heel strike (the step after).
    swing = ~own & ~planted & started & rolling[k]
    previous = numpy.where(k > 0, toe_off[numpy.maximum(k - 1, 0)], 0.0)
    walk_on = HEEL_STRIKE * amplitude[-1] if leaves else 0.0  # the step it would take next
    following = numpy.where(k + 1 < count, strike[numpy.minimum(k + 1, count - 1)], walk_on)
    w = _smooth(u)
    from_forward, from_up = shape.offset(previous)
    to_forward, to_up = shape.offset(following)
    pitch = numpy.where(swing, (1 - w) * previous + w * following, pitch)
    forward = numpy.where(swing, (1 - w) * from_forward + w * to_forward, forward)
    up = numpy.where(swing, (1 - w) * from_up + w * to_up, up)
    return pitch, forward, up
