"""The catalogue series grow with their size: a larger bearing of a series is never rated lower.

Self-consistency of the estimated internal geometry (auxbearing.bearings.series, rule 2 along a series): the
fitted balls never shrink from one size to the next by more than BALL_SHRINK, and the four-point and angular
series, which take those balls, are rated higher size after size. Before the series-wide fit the 63 series'
best single-size fits alternated between 7 and 8 balls from 6314 on, and QJ314 (189.2 kN) came out above QJ315
(182.7 kN).
"""

import itertools

import pytest

from auxbearing.bearings.ratings import dynamic_load_rating, static_load_rating
from auxbearing.bearings.series import BALL_SHRINK, SERIES, fit_series, series_entries


def _sizes(key):
    return [e for e in series_entries().values() if e.series == key]


@pytest.mark.parametrize("key", sorted(SERIES))
def test_the_balls_of_a_series_do_not_shrink_with_its_size(key):
    for small, large in itertools.pairwise(_sizes(key)):
        assert large.bearing.ball_diameter >= (1.0 - BALL_SHRINK) * small.bearing.ball_diameter, large.name


@pytest.mark.parametrize("key", [k for k, s in SERIES.items() if s.type != "deep_groove"])
def test_the_estimated_series_are_rated_higher_size_after_size(key):
    # the deep groove series carry the maker's own ratings; the others are estimated from their balls
    for small, large in itertools.pairwise(_sizes(key)):
        assert dynamic_load_rating(large.bearing) > dynamic_load_rating(small.bearing), large.name
        assert static_load_rating(large.bearing) > static_load_rating(small.bearing), large.name


def test_the_series_fit_gives_up_a_little_error_for_balls_that_grow():
    # two sizes: the second's best fit (0.1 % off) would shrink the ball 5 %; its next best (1 % off) does not
    sizes = [[(8, 25.0e-3, 0.002)], [(9, 23.75e-3, 0.001), (8, 26.9e-3, 0.01)]]
    assert fit_series(sizes) == [(8, 25.0e-3, 0.002), (8, 26.9e-3, 0.01)]
    # within what the fit resolves (BALL_SHRINK) the best fits stand
    assert fit_series([[(8, 25.0e-3, 0.0)], [(9, 24.9e-3, 0.001), (8, 26.9e-3, 0.01)]])[1] == (9, 24.9e-3, 0.001)
    # no choice that grows: each size keeps its best
    assert fit_series([[(8, 30e-3, 0.0)], [(9, 20e-3, 0.001)]]) == [(8, 30e-3, 0.0), (9, 20e-3, 0.001)]
