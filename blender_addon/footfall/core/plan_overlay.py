# SPDX-License-Identifier: GPL-3.0-or-later
"""What the viewport overlay draws of a plan, as line segments: each
agent's path coloured by behaviour (the paper's Figure 4: walking blue, arms
in green, side-stepping red), its footprints (left light, right dark), a
cross where an agent that did not arrive stopped, and, at any time, the
footprints of the steps under way. Pure numpy: ui/overlay draws it."""

from dataclasses import dataclass

import numpy

BEHAVIOR_COLORS = {
    "walk": (0.2, 0.45, 1.0, 1.0),
    "arms_in": (0.15, 0.8, 0.2, 1.0),
    "side_step": (0.95, 0.15, 0.1, 1.0),
}
FOOT_COLORS = ((0.92, 0.92, 0.92, 0.8), (0.45, 0.45, 0.45, 0.8))  # left, right
FAILED_COLOR = (1.0, 0.1, 0.9, 1.0)
CURRENT_COLOR = (1.0, 0.85, 0.0, 1.0)
LIFT = 0.01  # [m] above the ground, clear of its faces
FAILED_SIZE = 0.3  # [m] half the cross's width
FOOT_LENGTH_PER_RADIUS = 1 / 0.3  # the character's foot circle is 0.3 of the foot's length (core/character)
FOOT_WIDTH = 0.38  # of its length


@dataclass(frozen=True)
class Lines:
    """Segments to draw: points (2n, 3) and their colours (2n, 4), float32."""

    points: numpy.ndarray
    colors: numpy.ndarray

    @staticmethod
    def join(parts) -> "Lines":
        parts = [p for p in parts if len(p.points)]
        if not parts:
            return Lines(numpy.zeros((0, 3), numpy.float32), numpy.zeros((0, 4), numpy.float32))
        return Lines(numpy.concatenate([p.points for p in parts]).astype(numpy.float32),
                     numpy.concatenate([p.colors for p in parts]).astype(numpy.float32))


def _outlines(centres: numpy.ndarray, yaws: numpy.ndarray, length: numpy.ndarray) -> numpy.ndarray:
    """(n, 8, 3): each footprint's outline, four segments of a rectangle."""
    along = numpy.column_stack((numpy.cos(yaws), numpy.sin(yaws)))
    across = numpy.column_stack((-along[:, 1], along[:, 0]))
    half_l, half_w = 0.5 * length[:, None], 0.5 * FOOT_WIDTH * length[:, None]
    corners = [centres + sl * half_l * along + sw * half_w * across for sl, sw in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    ring = numpy.stack([corners[i % 4] for i in (0, 1, 1, 2, 2, 3, 3, 0)], axis=1)
    return numpy.concatenate([ring, numpy.full(ring.shape[:2] + (1,), LIFT)], axis=2)


class PlanOverlay:
    """A plan's overlay, computed once: the lines that stay, and per step
    what to highlight while it is under way."""

    def __init__(self, plan):
        parts, starts, ends, outlines = [], [], [], []
        for agent in plan.agents:
            steps = agent.footsteps
            if not steps:
                continue
            radius = (agent.character or plan.character).foot_radius
            chords = numpy.array([(*s.com_start, LIFT, *s.com_end, LIFT) for s in steps]).reshape(-1, 3)
            parts.append(Lines(chords, numpy.repeat([BEHAVIOR_COLORS[s.behavior.name.lower()] for s in steps], 2,
                                                    axis=0)))
            ring = _outlines(numpy.array([s.foot_position for s in steps]),
                             numpy.array([s.foot_orientation for s in steps]),
                             numpy.full(len(steps), radius * FOOT_LENGTH_PER_RADIUS))
            parts.append(Lines(ring.reshape(-1, 3),
                               numpy.repeat([FOOT_COLORS[s.foot.name != "LEFT"] for s in steps], 8, axis=0)))
            if agent.status.name != "REACHED":
                (x, y), d = steps[-1].com_end, FAILED_SIZE
                cross = [(x - d, y - d, LIFT), (x + d, y + d, LIFT), (x - d, y + d, LIFT), (x + d, y - d, LIFT)]
                parts.append(Lines(numpy.array(cross), numpy.tile(FAILED_COLOR, (4, 1))))
            starts.append([s.start_time for s in steps])
            ends.append([s.end_time for s in steps])
            outlines.append(ring)
        self.fixed = Lines.join(parts)
        self._starts = numpy.concatenate(starts) if starts else numpy.zeros(0)
        self._ends = numpy.concatenate(ends) if ends else numpy.zeros(0)
        self._outlines = numpy.concatenate(outlines) if outlines else numpy.zeros((0, 8, 3))

    def under_way(self, time: float) -> Lines:
        """The footprints of every step under way at `time` [s]."""
        rings = self._outlines[(self._starts <= time) & (time < self._ends)].reshape(-1, 3)
        return Lines.join([Lines(rings, numpy.tile(CURRENT_COLOR, (len(rings), 1)))])
