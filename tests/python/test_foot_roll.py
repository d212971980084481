"""Heel-toe roll: the point a foot rolls on stays put, the pitch is
continuous through stance and swing, and starts and stops stay flat."""

import math

import numpy
import pytest

from footfall.core import foot_roll
from footfall.core.foot_roll import FootShape, Steps

SHAPE = FootShape(ankle_height=0.085, heel_back=0.065, ball_ahead=0.135, ball_height=0.025)


def turned(point, pitch):
    c, s = math.cos(pitch), math.sin(pitch)
    return numpy.array([c * point[0] - s * point[1], s * point[0] + c * point[1]])


@pytest.mark.parametrize("heel_rising", [False, True])
def test_the_foot_turns_on_its_heel_or_its_ball(heel_rising):
    steps = walk(3)
    t = numpy.array([0.5 + (0.95 if heel_rising else 0.05) * 0.5])  # the second stance: toe-off, or heel strike
    pitch, forward, up = foot_roll.roll(t, numpy.array([True]), 1, steps, SHAPE, 1.3)
    assert (pitch[0] < 0) == heel_rising and pitch[0] != 0
    ankle = numpy.array([0.0, SHAPE.ankle_height])
    moved = ankle + [forward[0], up[0]]
    heel, ball = numpy.array([-SHAPE.heel_back, 0.0]), numpy.array([SHAPE.ball_ahead, SHAPE.ball_height])
    pivot = ball if heel_rising else heel
    # The foot turned by the pitch about its ankle's new place leaves the pivot where it was.
    assert moved + turned(pivot - ankle, pitch[0]) == pytest.approx(pivot, abs=1e-12)


def walk(count, duration=0.5, speed=1.3, waits=()):
    """Steps by alternate feet; `waits` stand still (stops that carry the body nowhere)."""
    start = numpy.arange(count) * duration
    moving = numpy.array([k not in waits for k in range(count)])
    return Steps(start, start + duration, numpy.arange(count) % 2, numpy.ones(count, dtype=bool),
                 numpy.where(moving, speed, 0.0))


def planted_for(times, steps, side):
    """As the plan has it: the foot of the step under way is planted, the other swings."""
    k = numpy.clip(numpy.searchsorted(steps.start, times, side="right") - 1, 0, len(steps.start) - 1)
    return (steps.foot[k] == side) | (steps.speed[k] == 0.0)


def test_the_roll_is_continuous_and_reaches_its_amplitudes():
    steps = walk(8)
    times = numpy.linspace(0.0, 4.0, 8001)
    for side in (0, 1):
        pitch, forward, up = foot_roll.roll(times, planted_for(times, steps, side), side, steps, SHAPE, 1.3)
        for values in (pitch, forward, up):
            assert numpy.max(numpy.abs(numpy.diff(values))) < 0.01  # no jumps between samples 0.5 ms apart
        assert pitch.max() == pytest.approx(foot_roll.HEEL_STRIKE, rel=1e-3)
        assert pitch.min() == pytest.approx(-foot_roll.TOE_OFF, rel=1e-3)
        mid_stance = (steps.start + 0.4 * 0.5)[steps.foot == side]
        assert numpy.interp(mid_stance, times, pitch) == pytest.approx(0.0, abs=1e-12)


def test_starts_and_waits_stay_flat():
    steps = walk(6, waits=(5,))
    times = numpy.linspace(0.0, 3.0, 3001)
    for side in (0, 1):
        pitch, _, _ = foot_roll.roll(times, planted_for(times, steps, side), side, steps, SHAPE, 1.3)
        assert pitch[0] == 0.0  # from standing: the swinging foot only starts to raise its toes
        if side == 0:  # the first step's own foot: no heel strike, flat until its heel rises
            assert pitch[times < 0.6 * 0.5] == pytest.approx(0.0)
        assert pitch[times >= 2.5] == pytest.approx(0.0)  # the wait, and the step before it at its end
        assert abs(pitch[numpy.searchsorted(times, 2.49)]) < math.radians(2)


def test_one_that_leaves_rolls_on_past_its_last_step():
    steps = walk(6)
    times = numpy.linspace(0.0, 3.0, 3001)
    last = times >= 2.5 + 0.59 * 0.5  # late in the last step's stance, before its heel would rise
    side = int(steps.foot[-1])
    staying, _, _ = foot_roll.roll(times, planted_for(times, steps, side), side, steps, SHAPE, 1.3)
    leaving, _, _ = foot_roll.roll(times, planted_for(times, steps, side), side, steps, SHAPE, 1.3, leaves=True)
    assert staying[last] == pytest.approx(0.0)
    assert leaving[-1] == pytest.approx(-foot_roll.TOE_OFF)
    other = 1 - side
    swinging, _, _ = foot_roll.roll(times, planted_for(times, steps, other), other, steps, SHAPE, 1.3, leaves=True)
    assert swinging[-1] == pytest.approx(foot_roll.HEEL_STRIKE)


def test_a_side_step_does_not_roll():
    steps = walk(6)
    sideways = Steps(steps.start, steps.end, steps.foot, numpy.array([True, True, False, False, True, True]),
                     steps.speed)
    times = numpy.linspace(0.0, 3.0, 3001)
    for side in (0, 1):
        pitch, _, _ = foot_roll.roll(times, planted_for(times, sideways, side), side, sideways, SHAPE, 1.3)
        assert pitch[(times >= 1.0) & (times < 2.0)] == pytest.approx(0.0)


def test_a_slow_step_rolls_less():
    fast, slow = walk(6), walk(6, speed=0.65)
    times = numpy.linspace(0.0, 3.0, 3001)
    pitch_fast, _, _ = foot_roll.roll(times, planted_for(times, fast, 0), 0, fast, SHAPE, 1.3)
    pitch_slow, _, _ = foot_roll.roll(times, planted_for(times, slow, 0), 0, slow, SHAPE, 1.3)
    assert pitch_slow.min() == pytest.approx(0.5 * pitch_fast.min(), rel=1e-3)


def test_the_heel_comes_from_the_mesh_or_the_foots_length():
    ankle, ball, forward = (0.0, 0.0, 0.08), (0.13, 0.0, 0.02), (1.0, 0.0, 0.0)
    mesh = [(-0.06, 0.02, 0.0, 1.0, 0.0), (0.2, 0.0, 0.0, 0.0, 1.0), (0.05, -0.03, 0.1, 0.6, 0.4)]
    assert foot_roll.foot_shape(ankle, ball, forward, 0.26, mesh).heel_back == pytest.approx(0.06)
    assert foot_roll.foot_shape(ankle, ball, forward, 0.26).heel_back == pytest.approx(0.26 * foot_roll.HEEL_SHARE)
    assert foot_roll.foot_shape(ankle, ball, forward, 0.26).ball_ahead == pytest.approx(0.13)
