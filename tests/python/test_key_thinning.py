"""keys_to_keep (footfall._native, Apply's keys): Bezier keys whose curves
(cubic Hermite) reproduce every sample within the tolerance; a stretch that
stands still needs only its ends."""

import numpy
import pytest


def curves(times, values, kept, slopes):
    """The keys' curves at `times` (cubic Hermite between kept samples)."""
    out = numpy.empty_like(values)
    segment = numpy.clip(numpy.searchsorted(kept, numpy.arange(len(times)), side="right") - 1, 0, len(kept) - 2)
    a, b = kept[segment], kept[segment + 1]
    h = (times[b] - times[a])[:, None]
    u = ((times - times[a]) / (times[b] - times[a]))[:, None]
    out = ((2 * u**3 - 3 * u**2 + 1) * values[a] + (u**3 - 2 * u**2 + u) * h * slopes[segment]
           + (3 * u**2 - 2 * u**3) * values[b] + (u**3 - u**2) * h * slopes[segment + 1])
    return out


def test_a_foot_standing_still_is_keyed_at_the_ends_of_its_stances(ff):
    times = numpy.arange(200.0)
    swing = 0.35 - 0.35 * numpy.cos(numpy.linspace(0, numpy.pi, 21))
    x = numpy.concatenate([numpy.zeros(50), swing[1:], numpy.full(60, 0.7), 0.7 + swing[1:], numpy.full(50, 1.4)])
    values = numpy.column_stack((x, numpy.zeros(200)))
    kept, slopes = ff.keys_to_keep(times, values, [1e-4])
    same_as_before = numpy.concatenate(([False], x[1:] == x[:-1]))
    same_as_after = numpy.concatenate((x[:-1] == x[1:], [False]))
    assert not numpy.any((same_as_before & same_as_after)[kept]), kept  # no key inside a stance, only at its ends
    still = same_as_before | same_as_after
    assert numpy.allclose(curves(times, values, kept, slopes)[still], values[still], rtol=0, atol=1e-12)


@pytest.mark.parametrize("tolerance", [1e-2, 1e-3, 1e-4])
def test_every_sample_comes_back_within_the_tolerance(ff, tolerance):
    times = numpy.arange(0.0, 300.0)
    rng = numpy.random.default_rng(3)
    values = numpy.column_stack((0.03 * numpy.sin(times / 4.0), numpy.cumsum(rng.normal(0, 1e-3, len(times))),
                                 numpy.where(times < 150, 0.0, 1.0)))  # a smooth bob, a wander and a jump
    scales = numpy.array([1.0, 2.0, 1.0])
    kept, slopes = ff.keys_to_keep(times, values, list(tolerance * scales))
    assert kept[0] == 0 and kept[-1] == len(times) - 1 and numpy.all(numpy.diff(kept) > 0)
    assert slopes.shape == (len(kept), 3)
    error = numpy.abs(curves(times, values, kept, slopes) - values) / scales
    assert error.max() <= tolerance * (1 + 1e-9)
    assert len(kept) < len(times)


def test_straight_keys_pass_within_the_tolerance_too(ff):
    times = numpy.arange(0.0, 300.0)
    values = (0.03 * numpy.sin(times / 4.0))[:, None]
    kept, _slopes = ff.keys_to_keep(times, values, [1e-4], cubic=False)
    assert numpy.abs(numpy.interp(times, times[kept], values[kept, 0]) - values[:, 0]).max() <= 1e-4 * (1 + 1e-9)
    assert len(ff.keys_to_keep(times, values, [1e-4])[0]) < len(kept)  # cubic ones are fewer


def test_a_looser_tolerance_keeps_fewer_keys(ff):
    times = numpy.linspace(0, 10, 500)
    values = numpy.sin(times)[:, None]
    counts = [len(ff.keys_to_keep(times, values, [t])[0]) for t in (1e-7, 1e-5, 1e-3)]
    assert counts[0] > counts[1] > counts[2] >= 2


def test_two_samples_are_both_kept(ff):
    kept, slopes = ff.keys_to_keep([0.0, 1.0], [[0.0], [5.0]], [0.1])
    assert list(kept) == [0, 1] and slopes.tolist() == [[5.0], [5.0]]


def test_bad_input_is_refused(ff):
    for times, values, tolerance in (([0.0, 1.0], [0.0], [0.1]), ([0.0, 1.0], [[0.0, 1.0], [1.0, 2.0]], [0.1] * 3),
                                     ([0.0, 1.0], [0.0, 1.0], [0.0]), ([1.0, 1.0], [0.0, 1.0], [0.1]),
                                     ([0.0, 1.0], [0.0, float("nan")], [0.1])):
        with pytest.raises(ValueError, match="keys_to_keep"):
            ff.keys_to_keep(times, values, tolerance)
