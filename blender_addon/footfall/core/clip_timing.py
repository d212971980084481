# SPDX-License-Identifier: GPL-3.0-or-later
"""When each upper-body clip plays: the plan's steps grouped into sections of
one behaviour, and each section's clip scaled and phased to its steps.

A clip cycle spans two steps (a left and a right). Walking clips are phased so
that the clip's right heel strike (where its right foot is furthest ahead;
in the procedural clips and an upper-body clip, its left arm swung furthest
forward: arms swing opposite to the legs) falls on the plan's right heel
strikes. A stop and standing still play "idle", except where the planner held
the arms in or turned the body side-on (it tests a stop there in that
behaviour's standing pose): there the stop plays its behaviour's clip.
"""

from dataclasses import dataclass
from typing import Collection, List, Sequence, Tuple

import numpy


@dataclass(frozen=True)
class Step:
    """What timing needs of a footstep: times [s], foot, kind and behaviour."""

    start: float
    end: float
    foot: str  # "left" or "right"
    kind: str  # "walk", "stop", "side_step" or "start"
    behavior: str  # "walk", "arms_in", "side_step"
    climb: int = 0  # 1 up a stair, -1 down one (ff.stair_climbs), 0 elsewhere


@dataclass(frozen=True)
class Section:
    """Consecutive steps playing one clip (clip_of())."""

    behavior: str
    start: float
    end: float
    steps: Sequence[Step]


@dataclass(frozen=True)
class StripTiming:
    """An NLA strip: where it plays [frames], which window of the clip it
    loops, how much it is stretched and how many times it repeats."""

    frame_start: float
    action_frame_start: float
    action_frame_end: float
    scale: float
    repeat: float


def clip_of(step: Step, available: Collection[str] = ()) -> str:
    """The clip a step plays: its behaviour's, "idle" for a stop walking,
    "stairs_up" or "stairs_down" for a walk up or down a stair where that
    clip is `available`."""
    if step.kind == "stop" and step.behavior == "walk":
        return "idle"
    stairs = {1: "stairs_up", -1: "stairs_down"}.get(step.climb)
    if step.behavior == "walk" and stairs in available:
        return stairs
    return step.behavior


def walking(clip: str) -> bool:
    """True for the clips played at a share of their amplitude by speed."""
    return clip in ("walk", "stairs_up", "stairs_down")


def sections(steps: Sequence[Step], available: Collection[str] = ()) -> List[Section]:
    """The steps grouped into runs of one clip (clip_of, with the stair clips
    `available`)."""
    result: List[Section] = []
    run: List[Step] = []
    for step in steps:
        if run and clip_of(step, available) != clip_of(run[0], available):
            result.append(_section(run, available))
            run = []
        run.append(step)
    if run:
        result.append(_section(run, available))
    return result


def _section(run: List[Step], available: Collection[str]) -> Section:
    return Section(clip_of(run[0], available), run[0].start, run[-1].end, tuple(run))


# How far each behaviour's arms reach across the way, narrowest first: the
# planner checks a section's own body only over its own time.
REACH = {"side_step": 0, "arms_in": 1, "idle": 2, "walk": 3, "stairs_up": 3, "stairs_down": 3}


def cross_fades(sections: Sequence[Section], blend: float) -> List[Tuple[float, float]]:
    """Per section, (lead, tail) [s]: how long its clip plays before its start
    and past its end, over the neighbour's. A boundary's cross-fade (2 *
    `blend` long) lies wholly in the section that reaches wider: a clip that
    holds the arms in has them in from its section's start, and swinging arms
    swing out only once theirs has begun."""
    fades = [[0.0, 0.0] for _ in sections]
    for i in range(1, len(sections)):
        if REACH[sections[i].behavior] > REACH[sections[i - 1].behavior]:
            fades[i - 1][1] = 2.0 * blend
        else:
            fades[i][0] = 2.0 * blend
    return [(lead, tail) for lead, tail in fades]


def strip_timing(section: Section, clip_start: float, clip_end: float, fps: float, frame_offset: float,
                 lead: float = 0.0, tail: float = 0.0, strike: float = 0.25) -> StripTiming:
    """The strip that plays one cycle of a cyclic clip (frames
    clip_start..clip_end) over a section, from `lead` seconds before it to
    `tail` seconds past its end (the overlaps where neighbouring sections
    cross-fade), with the clip's right heel strike, at `strike` of its
    cycle, on the section's. Frame = frame_offset + time * fps."""
    cycle = clip_end - clip_start  # frames of the clip
    start = section.start - lead
    duration = section.end + tail - start
    walking = [s for s in section.steps if s.kind == "walk"]
    if section.behavior == "idle" or not walking:
        scale = 1.0
        phase = 0.0
    else:
        step_time = sum(s.end - s.start for s in walking) / len(walking)
        scale = 2.0 * step_time * fps / cycle
        rights = [s.start for s in walking if s.foot == "right"]
        right_strike = rights[0] if rights else walking[0].start + step_time
        # The clip frame playing at the strip's start, so that the clip's
        # strike falls on the right heel strike.
        phase = (strike * cycle - (right_strike - start) * fps / scale) % cycle
    repeat = max(duration * fps / (cycle * scale), 1e-3)
    return StripTiming(
        frame_start=frame_offset + start * fps,
        action_frame_start=clip_start + phase,
        action_frame_end=clip_start + phase + cycle,
        scale=scale,
        repeat=repeat,
    )


def fade(frames, frame_start: float, frame_end: float, blend_in: float, blend_out: float):
    """A strip's influence at the frames from its blend in and out [frames],
    as Blender's NLA fades a strip whose influence is not keyed."""
    frames = numpy.asarray(frames, dtype=float)
    influence = numpy.ones_like(frames)
    if blend_in > 0:
        influence = numpy.minimum(influence, (frames - frame_start) / blend_in)
    if blend_out > 0:
        influence = numpy.minimum(influence, (frame_end - frames) / blend_out)
    return numpy.clip(influence, 0.0, 1.0)
