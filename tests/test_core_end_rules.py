"""Which path the automatic ends take: the main stem, the longest path, or the one a guide line shows.

The synthetic reservoirs are built from a wide main river (known ends: the middles of its flat caps) and long
but narrow side arms whose tips are the longest path's ends. Tolerances are fractions of the width of the
cap an end lies on, as in ``test_core_ends.py``.
"""

import math

import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon
from shapely.ops import unary_union

from incircu_plugin.core import find_ends, polygon_centerline
from incircu_plugin.core.errors import IncirCuError

#: Fraction of a flat cap's width within which a found end must match its midpoint (see test_core_ends.py).
FLAT_CAP_TOLERANCE = 0.01


def arm(points, width):
    """A flat-capped channel of constant ``width`` around a polyline."""
    return LineString(points).buffer(width / 2.0, cap_style="flat", join_style="mitre")


def straight_river_with_long_arm():
    """A 1000 x 40 river and a 900 x 6 arm leaving it at x = 600: arm + west reach is the longest path."""
    polygon = unary_union([arm([(0.0, 0.0), (1000.0, 0.0)], 40.0), arm([(600.0, 0.0), (600.0, 900.0)], 6.0)])
    return polygon, [(0.0, 0.0), (1000.0, 0.0)], [40.0, 40.0], (600.0, 900.0)


def widening_reservoir():
    """A reservoir widening from 20 (inflow) to 100 (dam) over 1500, with two arms 1200 x 8 and 1000 x 10."""
    valley = Polygon([(0.0, -10.0), (1500.0, -50.0), (1500.0, 50.0), (0.0, 10.0)])
    arms = [arm([(400.0, 0.0), (400.0, 1200.0)], 8.0), arm([(900.0, 0.0), (700.0, -1000.0)], 10.0)]
    return unary_union([valley, *arms]), [(0.0, 0.0), (1500.0, 0.0)], [20.0, 100.0], (400.0, 1200.0)


def dendritic_reservoir():
    """A meandering 3 km river, 60 wide, with a branching 2.2 km arm system 5 to 8 wide and a 1 km arm."""
    x = np.linspace(0.0, 3000.0, 301)
    axis = np.c_[x, 150.0 * np.sin(2.0 * math.pi * x / 1500.0)]
    first, second = axis[120], axis[200]
    branches = [
        arm([first, first + (100.0, 700.0), first + (300.0, 1400.0)], 8.0),
        arm([first + (100.0, 700.0), first + (-300.0, 1500.0), first + (-500.0, 2000.0)], 5.0),
        arm([second, second + (300.0, 900.0)], 6.0),
    ]
    polygon = unary_union([arm(axis, 60.0), *branches])
    return polygon, [tuple(axis[0]), tuple(axis[-1])], [60.0, 60.0], tuple(first + (-500.0, 2000.0))


RESERVOIRS = {
    "straight river, long arm": straight_river_with_long_arm,
    "widening reservoir": widening_reservoir,
    "dendritic reservoir": dendritic_reservoir,
}


def matched(found, expected, widths):
    """True when the two found ends are the two expected ones, each within its cap's tolerance."""
    found = [np.asarray(point.coords[0]) for point in found]
    for first, second in ((0, 1), (1, 0)):
        errors = [np.hypot(*(found[first] - expected[0])), np.hypot(*(found[second] - expected[1]))]
        if all(error <= FLAT_CAP_TOLERANCE * width for error, width in zip(errors, widths)):
            return True
    return False


@pytest.mark.parametrize("name", sorted(RESERVOIRS))
def test_main_stem_follows_the_wide_river_not_the_long_arm(name):
    polygon, expected, widths, _ = RESERVOIRS[name]()
    ends = find_ends(polygon)
    assert matched((ends.start, ends.end), np.asarray(expected), widths)


@pytest.mark.parametrize("name", sorted(RESERVOIRS))
def test_longest_path_runs_up_the_arm(name):
    polygon, _, _, arm_tip = RESERVOIRS[name]()
    ends = find_ends(polygon, rule="longest_path")
    assert min(Point(arm_tip).distance(end) for end in (ends.start, ends.end)) <= 10.0


def test_polygon_centerline_takes_the_end_rule():
    polygon, expected, widths, arm_tip = straight_river_with_long_arm()
    main = polygon_centerline(polygon, spacing=2.0)
    longest = polygon_centerline(polygon, spacing=2.0, end_rule="longest_path")
    line_ends = [main.line.boundary.geoms[0], main.line.boundary.geoms[1]]
    assert matched(line_ends, np.asarray(expected), widths)
    assert min(Point(arm_tip).distance(end) for end in longest.line.boundary.geoms) <= 10.0
    with pytest.raises(IncirCuError):
        polygon_centerline(polygon, end_rule="widest")
