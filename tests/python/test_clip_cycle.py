"""A rig's own clip as a gait cycle: forward kinematics of sampled channels,
and the cycle count and right heel strike found from the feet or hands."""

import math

import numpy
import pytest

from footfall.core import clip_cycle
from footfall.core.clip_cycle import BoneRest

FORWARD = numpy.array([0.0, -1.0, 0.0])  # the rig faces -Y, as Blender's glTF import leaves it
SAMPLES = 64


def translation(x, y, z):
    m = numpy.eye(4)
    m[:3, 3] = (x, y, z)
    return m


def legged_rig():
    """Hips, two three-bone legs and two arms hanging from a chest: rests as
    plain translations (bone-local axes = armature axes)."""
    bones = [BoneRest("root", None, translation(0, 0, 0)), BoneRest("hips", "root", translation(0, 0, 1.0)),
             BoneRest("chest", "hips", translation(0, 0, 1.4))]
    for side, x in (("L", 0.1), ("R", -0.1)):
        bones += [BoneRest(f"thigh.{side}", "hips", translation(x, 0, 0.95)),
                  BoneRest(f"shin.{side}", f"thigh.{side}", translation(x, 0, 0.5)),
                  BoneRest(f"foot.{side}", f"shin.{side}", translation(x, 0, 0.08)),
                  BoneRest(f"arm.{side}", "chest", translation(2 * x, 0, 1.4)),
                  BoneRest(f"hand.{side}", f"arm.{side}", translation(2 * x, 0, 0.8))]
    return {b.name: b for b in bones}


def swing(angles):
    """Bases turning bones about X by `angles` [rad] (a hanging limb swings
    toward +Y, backward, for a positive angle)."""
    rotation = clip_cycle.euler_matrices(numpy.column_stack((angles, 0 * angles, 0 * angles)))
    return clip_cycle.basis_matrices(numpy.zeros((len(angles), 3)), rotation, numpy.ones((len(angles), 3)))


def cycle_of(bases):
    heads = clip_cycle.pose_heads(legged_rig(), bases, ["foot.L", "foot.R", "hand.L", "hand.R"], SAMPLES)
    return clip_cycle.find_cycle(FORWARD, 0.9, heads["foot.L"], heads["foot.R"], heads["hand.L"], heads["hand.R"])


def test_rotations_follow_blenders_conventions():
    quarter_turn_z = clip_cycle.quaternion_matrices(numpy.array([[math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)]]))
    assert quarter_turn_z[0] @ [1, 0, 0] == pytest.approx([0, 1, 0])
    # "XYZ": about X first, then Y: (0, 1, 0) -> X 90° -> (0, 0, 1) -> Y 90° -> (1, 0, 0).
    turned = clip_cycle.euler_matrices(numpy.array([[math.pi / 2, math.pi / 2, 0.0]]), "XYZ")[0]
    assert turned @ [0, 1, 0] == pytest.approx([1, 0, 0])
    turned = clip_cycle.euler_matrices(numpy.array([[math.pi / 2, math.pi / 2, 0.0]]), "YXZ")[0]
    assert turned @ [0, 1, 0] == pytest.approx([0, 0, 1])


def test_a_bone_moves_with_its_parents():
    rig = legged_rig()
    t = numpy.arange(SAMPLES) / SAMPLES
    bases = {"hips": clip_cycle.basis_matrices(numpy.column_stack((0 * t, -2 * t, 0 * t)), numpy.tile(numpy.eye(3), (SAMPLES, 1, 1)),
                                               numpy.ones((SAMPLES, 3))),
             "thigh.L": swing(numpy.full(SAMPLES, math.pi / 2))}
    heads = clip_cycle.pose_heads(rig, bases, ["foot.L", "hand.R"], SAMPLES)
    # The thigh turned 90° about X lifts the leg backward to hip height; the hips carry it 2 m forward.
    assert heads["foot.L"][0] == pytest.approx([0.1, 0.87, 0.95])
    assert heads["foot.L"][-1] == pytest.approx([0.1, 0.87 - 2 * (SAMPLES - 1) / SAMPLES, 0.95])
    assert heads["hand.R"][0] == pytest.approx([-0.2, 0.0, 0.8])


@pytest.mark.parametrize("cycles, strike", [(1, 0.25), (1, 0.6), (2, 0.1), (3, 0.8)])
def test_the_right_heel_strikes_where_the_right_foot_is_furthest_ahead(cycles, strike):
    t = numpy.arange(SAMPLES) / SAMPLES
    wave = 0.4 * numpy.cos(2 * math.pi * (cycles * t - strike))
    # The right thigh turned back (negative about X) swings its foot forward; root motion on the hips.
    root = clip_cycle.basis_matrices(numpy.column_stack((0 * t, -1.3 * t, 0.03 * numpy.cos(4 * math.pi * cycles * t))),
                                     numpy.tile(numpy.eye(3), (SAMPLES, 1, 1)), numpy.ones((SAMPLES, 3)))
    found = cycle_of({"hips": root, "thigh.R": swing(-wave), "thigh.L": swing(wave),
                      "arm.L": swing(-0.5 * wave), "arm.R": swing(0.5 * wave)})
    assert (found.cycles, found.source) == (cycles, "feet")
    assert found.strike == pytest.approx(strike, abs=0.01)


def test_an_upper_body_clip_is_timed_by_its_hands():
    t = numpy.arange(SAMPLES) / SAMPLES
    wave = 0.3 * numpy.cos(2 * math.pi * (t - 0.4))  # left hand furthest forward at 0.4
    found = cycle_of({"arm.L": swing(-wave), "arm.R": swing(wave)})
    assert found.source == "hands"
    assert found.strike == pytest.approx(0.4, abs=0.01)


def test_a_clip_without_swing_keeps_the_convention():
    t = numpy.arange(SAMPLES) / SAMPLES
    found = cycle_of({"chest": swing(0.01 * numpy.sin(2 * math.pi * t))})
    assert found == clip_cycle.ClipCycle(1, clip_cycle.CONVENTION, "convention")
