"""The planner's body fitted to a rig: capsules that hold the mesh, limbs
that take the vertices nearest their axes, and the travel frame."""

import math

import numpy
import pytest

from footfall.core import body_capsules
from footfall.core.body_capsules import LIMB_JOINTS, LIMBS


def box_points(low, high, count=6):
    axes = [numpy.linspace(a, b, count) for a, b in zip(low, high)]
    return numpy.array([(x, y, z) for x in axes[0] for y in axes[1] for z in axes[2]])


def test_a_fitted_capsule_holds_every_point_and_hugs_them():
    rng = numpy.random.default_rng(3)
    # A foot: a block 0.26 long, 0.1 wide, 0.08 tall, its joints (ankle to a
    # guessed toe tail) off its middle and past its tip.
    points = box_points((-0.06, -0.05, 0.0), (0.20, 0.05, 0.08)) + rng.normal(0, 1e-3, (216, 3))
    a, b, radius = body_capsules.fit(numpy.array([0.0, 0.0, 0.09]), numpy.array([0.35, 0.0, 0.0]), points)
    distances = body_capsules.segment_distances(points, a, b)
    assert distances.max() <= radius + 1e-12
    assert radius < 0.075  # the block's half diagonal across is 0.064
    assert max(a[0], b[0]) < 0.21 and min(a[0], b[0]) > -0.07  # within the block, not out to the tail at 0.35


def test_a_point_cloud_along_its_axis_gives_a_thin_capsule():
    points = numpy.array([(0.0, 0.0, z) for z in numpy.linspace(0.2, 0.8, 20)] +
                         [(0.04, 0.0, 0.5), (-0.04, 0.0, 0.5), (0.0, 0.04, 0.5)])
    a, b, radius = body_capsules.fit(numpy.array([0.0, 0.0, 0.0]), numpy.array([0.0, 0.0, 1.0]), points)
    assert radius == pytest.approx(0.04)
    assert sorted([a[2], b[2]]) == pytest.approx([0.24, 0.76], abs=1e-9)  # the caps reach 0.2 and 0.8


def test_vertices_go_to_the_nearest_limb_their_bone_offers():
    joints = {joint: numpy.zeros(3) for ends in LIMB_JOINTS.values() for joint in ends}
    joints[("hips",), "head"], joints[("neck",), "head"] = numpy.array([0, 0, 1.0]), numpy.array([0, 0, 1.5])
    joints[("left", "thigh"), "head"] = numpy.array([0, 0.1, 0.95])
    joints[("right", "thigh"), "head"] = numpy.array([0, -0.1, 0.95])
    vertices = numpy.array([[0.0, 0.0, 1.3], [0.0, 0.05, 0.93], [0.0, 0.0, 1.2]])
    roles = [("hips",), ("hips",), None]
    points = body_capsules.limb_points(vertices, roles, joints)
    assert set(points) == {"torso", "pelvis"}
    assert points["torso"].tolist() == [[0.0, 0.0, 1.3]]
    assert points["pelvis"].tolist() == [[0.0, 0.05, 0.93]]


def spread_joints():
    return {joint: numpy.array([0.0, 0.0, float(i)]) for i, joint in
            enumerate(j for ends in LIMB_JOINTS.values() for j in ends)}


def test_every_limb_gets_a_capsule_bare_ones_the_built_in_bodys_scaled_by_the_legs():
    joints = spread_joints()
    capsules, fallbacks = body_capsules.rest_capsules(joints, {}, leg_length=0.9)
    assert tuple(capsules) == LIMBS and len(LIMBS) == 14
    # The built-in body's shin (0.065 m) on legs 0.9 m long instead of its 0.876.
    assert capsules["shin_left"].radius == pytest.approx(0.065 * 0.9 / 0.876435, abs=1e-6)
    assert capsules["forearm_right"].bone_b == ("right", "hand")
    assert fallbacks == {limb: "no vertices of its own" for limb in LIMBS}


@pytest.mark.filterwarnings("ignore:invalid value encountered in divide:RuntimeWarning")  # joints that coincide
def test_a_limb_whose_vertices_give_no_usable_capsule_takes_the_built_in_radius():
    """One vertex (radius 0), two on the axis of joints that coincide (not
    finite), one far off (an absurd radius): each limb runs joint to joint
    with the built-in body's radius scaled to the rig, and says why; a limb
    with a mesh keeps its own capsule."""
    joints = spread_joints()
    joints[("right", "forearm"), "head"] = joints[("right", "upper_arm"), "head"]  # the right upper arm has no length
    arm = joints[("left", "upper_arm"), "head"]
    points = {
        "upper_arm_left": numpy.array([arm + (0.0, 0.0, 0.2)]),
        "upper_arm_right": numpy.array([joints[("right", "upper_arm"), "head"]] * 2),
        # A thigh, and a vertex 3 m off it (a cape skinned to the thigh, say).
        "thigh_left": numpy.vstack([box_points((-0.06, -0.06, 16.2), (0.06, 0.06, 19.8)), [(3.0, 0.0, 18.0)]]),
        "shin_left": box_points((-0.05, -0.05, 20.2), (0.05, 0.05, 23.8)),
    }
    capsules, fallbacks = body_capsules.rest_capsules(joints, points, leg_length=0.9)
    assert fallbacks["upper_arm_left"] == "its vertices give a radius of 0 m"
    assert fallbacks["upper_arm_right"] == "its vertices give no finite capsule"
    assert fallbacks["thigh_left"] == "its vertices give a radius of 1.53 m"
    assert "shin_left" not in fallbacks and capsules["shin_left"].radius == pytest.approx(0.05 * math.sqrt(2))
    for limb in ("upper_arm_left", "upper_arm_right", "thigh_left"):
        capsule, (joint_a, joint_b) = capsules[limb], LIMB_JOINTS[limb]
        assert capsule.radius == pytest.approx(body_capsules.builtin_radius(limb, 0.9))
        assert capsule.a.tolist() == joints[joint_a].tolist() and capsule.b.tolist() == joints[joint_b].tolist()


@pytest.mark.parametrize("across", [False, True])
def test_the_travel_frame_puts_the_root_under_the_pelvis(across):
    facing = numpy.array([math.cos(0.3), math.sin(0.3), 0.0])
    frame = body_capsules.travel_frame(numpy.array([2.0, 1.0, 0.93]), facing, across)
    ahead = frame @ numpy.array([2.0 + facing[0], 1.0 + facing[1], 0.5, 1.0])
    # Walking, the body's front is ahead (+x); side-stepping it faces +y and travels to its right.
    assert ahead[:3] == pytest.approx([0.0, 1.0, 0.5] if across else [1.0, 0.0, 0.5])
    assert (frame @ numpy.array([2.0, 1.0, 0.0, 1.0]))[:3] == pytest.approx([0.0, 0.0, 0.0])


def test_lateral_extent_is_the_widest_reach_across():
    pose = {limb: [0, 0, 0, 0, 0, 1, 0.1] for limb in LIMBS}
    pose["forearm_left"] = [0, 0.2, 1, 0.1, 0.3, 0.8, 0.05]
    assert body_capsules.lateral_extent([pose]) == pytest.approx(0.35)
