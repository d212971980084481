"""The height of a plan's ground under points, for the tests that check
bodies against it (a foot in a riser, a sole through a tread)."""

import numpy


def ground_heights(prisms, points):
    """The highest prism top over each of `points` (n, 2), -inf where none: even-odd per polygon."""
    highest = numpy.full(len(points), -numpy.inf)
    x, y = points[:, 0], points[:, 1]
    for prism in prisms:
        polygon = numpy.asarray(prism["polygon"], dtype=float)
        inside = numpy.zeros(len(points), dtype=bool)
        for (ax, ay), (bx, by) in zip(polygon, numpy.roll(polygon, -1, axis=0)):
            crosses = (ay > y) != (by > y)
            with numpy.errstate(divide="ignore", invalid="ignore"):
                at = ax + (y - ay) * (bx - ax) / (by - ay)
            inside ^= crosses & (x < at)
        highest = numpy.where(inside, numpy.maximum(highest, prism["height"]), highest)
    return highest
