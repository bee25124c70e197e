"""Which path the automatic ends take: the main stem, the longest path, or the one a guide line shows.

The synthetic reservoirs are built from a wide main river (known ends: the middles of its flat caps) and long
but narrow side arms whose tips are the longest path's ends. Tolerances are fractions of the width of the
cap an end lies on, as in ``test_core_ends.py``.
"""

import math

import numpy as np
import pytest
import shapely
import shapely.ops
from shapely.geometry import LineString, Point, Polygon
from shapely.ops import unary_union

from incircu_plugin.core import find_ends, polygon_centerline
from incircu_plugin.core.errors import IncirCuError, InvalidGeometryError

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


def rough_guide(path, width, piece=150.0, gap=50.0, grid=None):
    """A guide line made rough on purpose from an exact axis ``path``.

    The axis is extended by two widths beyond both ends (out of the polygon), cut into ``piece``-long
    pieces with ``gap``-long gaps, each piece offset by 0.75 ``width`` to alternate sides (out of the
    polygon: farther than the bank), and its vertices rounded to a ``grid`` (a third of the width).
    """
    path = np.asarray(path, dtype=float)
    head = (path[0] - path[1]) / np.hypot(*(path[0] - path[1]))
    tail = (path[-1] - path[-2]) / np.hypot(*(path[-1] - path[-2]))
    line = LineString(np.vstack([path[0] + 2.0 * width * head, path, path[-1] + 2.0 * width * tail]))
    grid = grid or width / 3.0
    pieces = []
    for index, start in enumerate(np.arange(0.0, line.length, piece + gap)):
        cut = shapely.ops.substring(line, start, min(start + piece, line.length))
        if cut.length <= 0.0:
            continue
        shifted = cut.offset_curve((0.75 if index % 2 else -0.75) * width)
        for part in shapely.get_parts(shifted):
            if part.length > 0.0:
                pieces.append(LineString(np.round(np.asarray(part.coords) / grid) * grid))
    return pieces


def dendritic_axes():
    """The exact axes of :func:`dendritic_reservoir`: the main river, the 8-wide arm and its 5-wide branch."""
    x = np.linspace(0.0, 3000.0, 301)
    axis = np.c_[x, 150.0 * np.sin(2.0 * math.pi * x / 1500.0)]
    first = axis[120]
    return (
        axis,
        np.array([first, first + (100.0, 700.0), first + (300.0, 1400.0)]),
        np.array([first + (100.0, 700.0), first + (-300.0, 1500.0), first + (-500.0, 2000.0)]),
    )


def same_centerline(result, reference, widths):
    """Assert two centerlines have the same ends (within the caps' tolerance) and the same course."""
    reference_ends = np.array([reference.line.coords[0], reference.line.coords[-1]])
    assert matched(list(result.line.boundary.geoms), reference_ends, widths)
    assert result.line.hausdorff_distance(reference.line) <= 2.0 * FLAT_CAP_TOLERANCE * max(widths)


def test_rough_guide_along_the_main_river_with_a_tributary_gives_the_exact_centerline():
    polygon, expected, widths, _ = dendritic_reservoir()
    axis, arm_axis, _ = dendritic_axes()
    tributary = rough_guide(arm_axis[::-1], 8.0, piece=120.0, gap=60.0)
    guide = shapely.MultiLineString(rough_guide(axis, 60.0) + tributary)
    assert not polygon.contains(guide)
    result = polygon_centerline(polygon, guide=guide, spacing=3.0)
    reference = polygon_centerline(polygon, expected, spacing=3.0)
    assert result.ends_from == "guide" and result.ends_found
    same_centerline(result, reference, widths)


def test_rough_guide_up_a_side_arm_gives_the_exact_centerline_of_that_arm():
    polygon, _, _, arm_tip = dendritic_reservoir()
    axis, arm_axis, branch_axis = dendritic_axes()
    junction = 120
    course = np.vstack([branch_axis[::-1], arm_axis[:1], axis[junction + 1 :]])
    pieces = rough_guide(course[:3], 5.0, piece=100.0, gap=40.0) + rough_guide(course[2:], 8.0)
    guide = shapely.MultiLineString(pieces)
    result = polygon_centerline(polygon, guide=guide, spacing=3.0)
    reference = polygon_centerline(polygon, [arm_tip, tuple(axis[-1])], spacing=3.0)
    assert result.ends_from == "guide"
    same_centerline(result, reference, [5.0, 60.0])


def test_split_points_win_over_the_guide():
    polygon, expected, _, arm_tip = straight_river_with_long_arm()
    guide = LineString([arm_tip, (600.0, 0.0), (1000.0, 0.0)])
    result = polygon_centerline(polygon, expected, guide=guide, spacing=2.0)
    assert result.ends_from == "split_points" and not result.ends_found
    guided = polygon_centerline(polygon, guide=guide, spacing=2.0)
    assert guided.ends_from == "guide"
    assert min(Point(arm_tip).distance(end) for end in guided.line.boundary.geoms) <= FLAT_CAP_TOLERANCE * 6.0


def test_a_guide_far_away_falls_back_to_the_automatic_ends_with_a_note():
    polygon, expected, widths, _ = straight_river_with_long_arm()
    result = polygon_centerline(polygon, guide=LineString([(0.0, 5000.0), (1000.0, 5000.0)]), spacing=2.0)
    assert result.ends_from == "automatic"
    assert any("guide" in note for note in result.notes)
    assert matched(list(result.line.boundary.geoms), np.asarray(expected), widths)


def test_a_guide_that_is_not_a_line_gets_a_typed_error():
    polygon, _, _, _ = straight_river_with_long_arm()
    with pytest.raises(InvalidGeometryError):
        polygon_centerline(polygon, guide=Point(0.0, 0.0))
