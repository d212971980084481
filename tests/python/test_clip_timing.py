"""Upper-body clip timing: sections of one behaviour, clips phased to steps."""

import math

import pytest

from footfall.core.clip_timing import Step, cross_fades, sections, strip_timing


def clip_frame_at(timing, frame, clip_start):
    """The frame of the cyclic clip (starting at clip_start) that a strip
    plays at scene frame `frame`, as Blender's NLA maps it."""
    local = (frame - timing.frame_start) / timing.scale
    cycle = timing.action_frame_end - timing.action_frame_start
    return clip_start + math.fmod(timing.action_frame_start - clip_start + local, cycle)


def walk(n, start=0.0, duration=0.5, first="left", behavior="walk"):
    feet = [first, "right" if first == "left" else "left"]
    return [Step(start + i * duration, start + (i + 1) * duration, feet[i % 2], "walk", behavior) for i in range(n)]


def test_sections_split_on_behaviour_and_stops():
    steps = walk(4) + walk(3, start=2.0, first="left", behavior="arms_in") + [Step(3.5, 4.0, "right", "stop", "walk")]
    result = sections(steps)
    assert [s.behavior for s in result] == ["walk", "arms_in", "idle"]
    assert (result[1].start, result[1].end) == (2.0, 3.5)
    assert len(result[0].steps) == 4


def test_a_stop_held_arms_in_or_side_on_plays_its_behaviours_clip():
    """Waiting in a door frame, the arms stay in: the planner tested the stop
    in that behaviour's standing pose, not idle's."""
    steps = (walk(2, behavior="arms_in") + [Step(1.0, 1.5, "left", "stop", "arms_in")]
             + [Step(1.5, 2.0, "right", "side_step", "side_step"), Step(2.0, 2.5, "left", "stop", "side_step")]
             + [Step(2.5, 3.0, "right", "stop", "walk")])
    result = sections(steps)
    assert [s.behavior for s in result] == ["arms_in", "side_step", "idle"]
    assert [len(s.steps) for s in result] == [3, 2, 1]


def test_cross_fades_lie_in_the_section_that_reaches_wider():
    steps = (walk(2) + walk(2, start=1.0, behavior="arms_in") + [Step(2.0, 2.5, "left", "stop", "walk")]
             + [Step(2.5, 3.0, "right", "side_step", "side_step")] + walk(2, start=3.0))
    result = sections(steps)
    assert [s.behavior for s in result] == ["walk", "arms_in", "idle", "side_step", "walk"]
    # Into a narrower section the clips change before it begins; into a wider one after.
    assert cross_fades(result, 0.25) == [(0.0, 0.0), (0.5, 0.5), (0.0, 0.0), (0.5, 0.5), (0.0, 0.0)]


@pytest.mark.parametrize("first", ["left", "right"])
def test_walk_clip_is_phased_to_right_heel_strikes(first):
    fps, clip_start, clip_end = 24.0, 1.0, 25.0
    (section,) = sections(walk(8, start=1.0, duration=0.55, first=first))
    timing = strip_timing(section, clip_start, clip_end, fps, frame_offset=1.0)
    # Two steps per clip cycle.
    assert timing.scale * (clip_end - clip_start) == pytest.approx(2 * 0.55 * fps)
    for step in section.steps:
        frame = clip_frame_at(timing, 1.0 + step.start * fps, clip_start)
        quarter = clip_start + 0.25 * (clip_end - clip_start)
        three_quarters = clip_start + 0.75 * (clip_end - clip_start)
        # Right heel strike: left arm forward (quarter); left heel strike: three quarters.
        assert frame == pytest.approx(quarter if step.foot == "right" else three_quarters, abs=1e-9)
    assert timing.repeat * timing.scale * 24 == pytest.approx((section.end - section.start) * fps)


def test_idle_plays_at_its_own_pace():
    (section,) = sections([Step(5.0, 5.5, "left", "stop", "walk")])
    timing = strip_timing(section, 1.0, 49.0, 24.0, frame_offset=1.0, tail=2.0)
    assert timing.scale == 1.0 and timing.action_frame_start == 1.0
    assert timing.repeat == pytest.approx(2.5 * 24 / 48)


@pytest.mark.parametrize("strike", [0.0, 0.4, 0.9])
def test_a_clips_own_heel_strike_falls_on_the_right_heel_strikes(strike):
    fps, clip_start, clip_end = 30.0, 5.0, 35.0
    (section,) = sections(walk(6, start=0.5, duration=0.6))
    timing = strip_timing(section, clip_start, clip_end, fps, frame_offset=1.0, lead=0.25, strike=strike)
    for step in section.steps:
        if step.foot == "right":
            frame = clip_frame_at(timing, 1.0 + step.start * fps, clip_start)
            cycle = clip_end - clip_start
            off = (frame - clip_start - strike * cycle + cycle / 2) % cycle - cycle / 2
            assert off == pytest.approx(0.0, abs=1e-9)


def test_fades_as_blenders_nla_fades_a_strip():
    from footfall.core.clip_timing import fade

    frames = [10, 12, 14, 20, 26, 28, 30]
    # A strip from frame 10 to 30 that blends in and out over 4 frames.
    assert list(fade(frames, 10.0, 30.0, 4.0, 4.0)) == [0.0, 0.5, 1.0, 1.0, 1.0, 0.5, 0.0]
    # Without blends it plays at full influence throughout.
    assert list(fade(frames, 10.0, 30.0, 0.0, 0.0)) == [1.0] * 7
