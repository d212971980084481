"""The height of a plan's ground under points, for the tests that check
bodies against it (a foot in a riser, a sole through a tread)."""

import numpy

REACH = 0.5  # [m] a surface further above a point is a level over it (a deck), not its ground


def ground_heights(prisms, points):
    """The highest prism top over each of `points`, -inf where none: even-odd
    per polygon. Points (n, 3) count only tops at most REACH above them (under
    a bridge's deck, the street); points (n, 2) every top."""
    points = numpy.asarray(points, dtype=float)
    highest = numpy.full(len(points), -numpy.inf)
    x, y = points[:, 0], points[:, 1]
    ceiling = points[:, 2] + REACH if points.shape[1] == 3 else numpy.full(len(points), numpy.inf)
    for prism in prisms:
        polygon = numpy.asarray(prism["polygon"], dtype=float)
        inside = numpy.zeros(len(points), dtype=bool)
        for (ax, ay), (bx, by) in zip(polygon, numpy.roll(polygon, -1, axis=0)):
            crosses = (ay > y) != (by > y)
            with numpy.errstate(divide="ignore", invalid="ignore"):
                at = ax + (y - ay) * (bx - ax) / (by - ay)
            inside ^= crosses & (x < at)
        counts = inside & (prism["height"] <= ceiling)
        highest = numpy.where(counts, numpy.maximum(highest, prism["height"]), highest)
    return highest
