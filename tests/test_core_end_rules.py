"""Which path the automatic ends take: the main stem, the longest path, or the one a guide line shows.

The synthetic reservoirs (``tests/support/reservoirs.py``) are built from a wide main river (known ends: the
middles of its flat caps) and long but narrow side arms whose tips are the longest path's ends. Tolerances are fractions of the width of the
cap an end lies on, as in ``test_core_ends.py``.
"""

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Point

from incircu_plugin.core import find_ends, polygon_centerline
from incircu_plugin.core.errors import IncirCuError, InvalidGeometryError
from tests.support.reservoirs import (
    RESERVOIRS,
    dendritic_axes,
    dendritic_reservoir,
    rough_guide,
    straight_river_with_long_arm,
)

#: Fraction of a flat cap's width within which a found end must match its midpoint (see test_core_ends.py).
FLAT_CAP_TOLERANCE = 0.01


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
