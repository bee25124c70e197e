"""Automatic ends of shapes without a dominant trunk: compact shapes and stars (``find_ends``, step 5).

Every expected end is known by construction: a rectangle's short sides' middles, an ellipse's tips, a star's
tips, or (for a square or a regular polygon, which have no longest axis) any pair symmetric across the
centre, checked by mirroring the polygon in the line through both ends. The ends are computed in closed form
(a ray from the centroid meets the ring), so their tolerance is a rounding one: ``ROUNDING`` of the shape's
size. The centerline between them is traced within ``DEFAULT_TOLERANCE_PER_WIDTH`` of the width, so a line
through the centre is checked to that.
"""

import math

import numpy as np
import pytest
from shapely import affinity
from shapely.geometry import LineString, Point, box

from incircu_plugin.core import find_ends, polygon_centerline
from incircu_plugin.core.ends import COMPACT, ELONGATED, STAR, find_ends_together
from incircu_plugin.core.engine import DEFAULT_TOLERANCE_PER_WIDTH
from tests.support import compact_shapes

#: Rounding of a closed-form end, as a fraction of the shape's size (its bounding-box diagonal).
ROUNDING = 1e-9

#: An elongated shape's rounded cap is centred within this fraction of its width (see ``test_core_ends.py``).
ROUND_CAP_TOLERANCE = 0.02

#: Where the shapes are put (the answers must not depend on where a shape lies or how it is turned).
PLACEMENTS = [((0.0, 0.0), 0.0), ((1234.5, -678.9), 0.3), ((-5e5, 2e5), 2.0)]


def size(polygon):
    """Bounding-box diagonal of a polygon, CRS units."""
    west, south, east, north = polygon.bounds
    return math.hypot(east - west, north - south)


def ends_array(ends):
    """The two ends of an ``EndsResult`` as a (2, 2) array."""
    return np.array([ends.start.coords[0], ends.end.coords[0]])


def pair_error(found, expected):
    """Largest distance between two unordered pairs of points, CRS units."""
    expected = np.asarray(expected, dtype=float)
    return min(np.hypot(*(found - expected).T).max(), np.hypot(*(found - expected[::-1]).T).max())


def mirror_error(polygon, ends):
    """How far the polygon mirrored in the line through ``ends`` lies from itself (Hausdorff), CRS units."""
    (x0, y0), (x1, y1) = ends
    angle = math.atan2(y1 - y0, x1 - x0)
    moved = affinity.translate(polygon, -x0, -y0)
    mirrored = affinity.rotate(
        affinity.scale(affinity.rotate(moved, -angle, (0, 0), use_radians=True), 1.0, -1.0, 1.0, (0, 0)),
        angle,
        (0, 0),
        use_radians=True,
    )
    return affinity.translate(mirrored, x0, y0).hausdorff_distance(polygon)


def trace_tolerance(polygon):
    """The centerline's tracing tolerance on a compact shape, CRS units: a share of its narrowest width."""
    return DEFAULT_TOLERANCE_PER_WIDTH * 2.0 * polygon.exterior.distance(polygon.centroid)


@pytest.mark.parametrize("centre, turn", PLACEMENTS)
@pytest.mark.parametrize("aspect", [1.05, 1.3, 1.6])
def test_a_compact_rectangle_gets_the_middles_of_its_short_sides(aspect, centre, turn):
    polygon = compact_shapes.rectangle(10.0 * aspect, 10.0, centre, turn)
    ends = find_ends(polygon)
    assert not ends.elongated and ends.kind == COMPACT
    expected = compact_shapes.rectangle_ends(10.0 * aspect, centre, turn)
    assert pair_error(ends_array(ends), expected) <= ROUNDING * size(polygon) + 1e-15 * np.abs(centre).max()


@pytest.mark.parametrize("centre, turn", PLACEMENTS)
def test_a_square_gets_the_middles_of_two_opposite_sides(centre, turn):
    polygon = compact_shapes.rectangle(10.0, 10.0, centre, turn)
    ends = find_ends(polygon)
    found = ends_array(ends)
    assert ends.kind == COMPACT
    tolerance = ROUNDING * size(polygon) + 1e-15 * np.abs(centre).max()
    across = [compact_shapes.rectangle_ends(10.0, centre, turn + quarter) for quarter in (0.0, math.pi / 2.0)]
    assert min(pair_error(found, pair) for pair in across) <= tolerance


def test_a_segmentized_square_is_still_cut_between_opposite_side_middles():
    polygon = box(0.0, 0.0, 1.0, 1.0).segmentize(1.0 / 14.0)
    found = ends_array(find_ends(polygon))
    options = ([(0.0, 0.5), (1.0, 0.5)], [(0.5, 0.0), (0.5, 1.0)])
    assert min(pair_error(found, pair) for pair in options) <= ROUNDING * size(polygon)


@pytest.mark.parametrize("centre, turn", PLACEMENTS)
@pytest.mark.parametrize("sides", [3, 4, 5, 6, 7, 8, 9, 12, 20, 64])
def test_a_regular_polygon_gets_symmetric_ends_across_its_centre(sides, centre, turn):
    polygon = compact_shapes.regular_polygon(sides, 10.0, centre, turn)
    ends = find_ends(polygon)
    found = ends_array(ends)
    tolerance = ROUNDING * size(polygon) + 1e-15 * np.abs(centre).max()
    assert ends.kind == COMPACT
    assert LineString(found).distance(polygon.centroid) <= tolerance
    assert mirror_error(polygon, found) <= 1e3 * tolerance
    # Across the whole shape: at least the inscribed circle's diameter apart.
    assert np.hypot(*(found[0] - found[1])) >= 2.0 * polygon.exterior.distance(polygon.centroid) - tolerance


@pytest.mark.parametrize("centre, turn", PLACEMENTS)
@pytest.mark.parametrize("vertices", [8, 10, 16, 64])
@pytest.mark.parametrize("minor", [4.0, 6.0, 8.5])
@pytest.mark.parametrize("half_step", [False, True])
def test_an_ellipse_gets_its_tips_at_any_vertex_count(vertices, minor, half_step, centre, turn):
    phase = math.pi / vertices if half_step else 0.0
    polygon = compact_shapes.ellipse(vertices, 10.0, minor, centre, turn, phase)
    ends = find_ends(polygon)
    reach = 10.0 * math.cos(phase)
    expected = np.asarray(centre) + reach * np.array(
        [[-math.cos(turn), -math.sin(turn)], [math.cos(turn), math.sin(turn)]]
    )
    tolerance = ROUNDING * size(polygon) + 1e-15 * np.abs(centre).max()
    if ends.elongated:
        # A long ellipse keeps its skeleton path's ends: the apex of a rounded cap, the middle of its arc
        # (within 2 % of the width, as in test_core_ends.py).
        assert ends.kind == ELONGATED
        tolerance = ROUND_CAP_TOLERANCE * 2.0 * minor
    else:
        assert ends.kind == COMPACT
    assert pair_error(ends_array(ends), expected) <= tolerance


@pytest.mark.parametrize("vertices", [8, 10, 16, 64])
def test_the_centerline_of_a_compact_ellipse_runs_straight_through_its_centre(vertices):
    polygon = compact_shapes.ellipse(vertices, 10.0, 6.0, (50.0, 20.0), 0.7)
    result = polygon_centerline(polygon)
    axis = LineString(compact_shapes.rectangle_ends(20.0, (50.0, 20.0), 0.7))
    vertices_off = [axis.distance(Point(xy)) for xy in result.line.coords]
    assert max(vertices_off) <= trace_tolerance(polygon)
    assert result.line.length >= axis.length - trace_tolerance(polygon)
    assert any("no dominant trunk" in note for note in result.notes)


@pytest.mark.parametrize("shape", ["square", "rectangle", "hexagon"])
def test_the_centerline_of_a_compact_shape_crosses_it_through_its_centre(shape):
    polygon = {
        "square": compact_shapes.rectangle(10.0, 10.0, (3.0, 4.0), 0.2),
        "rectangle": compact_shapes.rectangle(15.0, 10.0, (3.0, 4.0), 0.2),
        "hexagon": compact_shapes.regular_polygon(6, 10.0, (3.0, 4.0), 0.2),
    }[shape]
    result = polygon_centerline(polygon)
    line = result.line
    straight = LineString([line.coords[0], line.coords[-1]])
    assert line.distance(polygon.centroid) <= trace_tolerance(polygon)
    assert max(straight.distance(Point(xy)) for xy in line.coords) <= trace_tolerance(polygon)
    assert any("not elongated" in note and "no dominant trunk" in note for note in result.notes)


def star_cases():
    """(arms, inner radius, hole radius) of stars with tips at 10."""
    return [(arms, inner, hole) for arms in (3, 4, 5, 6, 7, 8) for inner in (2.5, 4.0) for hole in (0.0, 1.5)]


@pytest.mark.parametrize("centre, turn", PLACEMENTS)
@pytest.mark.parametrize("arms, inner, hole", star_cases())
def test_a_star_gets_the_tips_of_its_two_farthest_apart_arms(arms, inner, hole, centre, turn):
    polygon = compact_shapes.star(arms, 10.0, inner, centre, turn, hole)
    ends = find_ends(polygon)
    found = ends_array(ends)
    tips = compact_shapes.star_tips(arms, 10.0, centre, turn)
    tolerance = ROUNDING * size(polygon) + 1e-15 * np.abs(centre).max()
    assert ends.kind == STAR
    nearest = [np.hypot(*(tips - end).T).min() for end in found]
    assert max(nearest) <= tolerance
    # The farthest-apart pair: opposite tips (through the centre) with an even count, a chord of
    # (arms - 1) / arms half-turns with an odd one.
    farthest = 20.0 * math.sin(math.pi * (arms // 2) / arms)
    assert abs(np.hypot(*(found[0] - found[1])) - farthest) <= tolerance
    if arms % 2 == 0:
        assert LineString(found).distance(Point(centre)) <= tolerance


@pytest.mark.parametrize("arms", [3, 4, 5, 6])
def test_the_centerline_of_a_star_runs_from_tip_to_tip_through_its_centre(arms):
    polygon = compact_shapes.star(arms, 10.0, 3.0, (7.0, -2.0), 0.4)
    result = polygon_centerline(polygon)
    assert result.line.distance(Point(7.0, -2.0)) <= trace_tolerance(polygon)
    tips = compact_shapes.star_tips(arms, 10.0, (7.0, -2.0), 0.4)
    for end in (result.line.coords[0], result.line.coords[-1]):
        assert np.hypot(*(tips - end).T).min() <= ROUNDING * size(polygon)
    assert any("star-like" in note and "no dominant trunk" in note for note in result.notes)


def test_a_star_with_a_hole_gets_its_tips_and_a_line_around_the_hole():
    polygon = compact_shapes.star(5, 10.0, 4.0, hole=3.0)
    result = polygon_centerline(polygon)
    tips = compact_shapes.star_tips(5, 10.0)
    ends = np.array([result.line.coords[0], result.line.coords[-1]])
    assert np.hypot(*(ends[0] - ends[1])) >= 10.0
    assert max(np.hypot(*(tips - end).T).min() for end in ends) <= ROUNDING * size(polygon)
    assert result.line.is_simple and result.line.within(polygon.buffer(ROUNDING * size(polygon)))
    assert any("star-like" in note for note in result.notes)


def test_three_arms_with_a_short_third_keep_the_trunk_of_the_two_long_ones():
    # A dominant trunk (two long arms) with a stub: not star-like, the skeleton path's ends.
    arms = [
        LineString([(0.0, 0.0), tip]).buffer(1.0, cap_style="flat") for tip in [(-9.0, 0.0), (9.0, 0.0), (0.0, 3.5)]
    ]
    polygon = arms[0].union(arms[1]).union(arms[2]).union(Point(0.0, 0.0).buffer(1.6))
    ends = find_ends(polygon)
    assert ends.kind == ELONGATED
    assert pair_error(ends_array(ends), [(-9.0, 0.0), (9.0, 0.0)]) <= 0.01 * 2.0


def test_a_guide_keeps_the_ends_it_chooses_on_a_compact_shape():
    polygon = compact_shapes.rectangle(12.0, 10.0)
    guide = LineString([(0.0, -8.0), (0.0, 8.0)])
    ends = find_ends(polygon, guide=guide)
    assert ends.guided and ends.kind == ELONGATED


def test_compact_and_star_ends_are_the_same_in_a_batch():
    polygons = [
        compact_shapes.rectangle(10.0, 10.0, (5.0, 5.0), 0.1),
        box(0.0, 0.0, 100.0, 10.0),
        compact_shapes.star(5, 10.0, 4.0, (100.0, 0.0), 0.2, hole=1.0),
        compact_shapes.ellipse(10, 10.0, 7.0, (-40.0, 3.0), 1.0),
        compact_shapes.regular_polygon(7, 3.0, (9.0, 9.0), 0.5),
        compact_shapes.star(6, 10.0, 3.0, (0.0, 50.0)),
    ]
    together = find_ends_together(polygons)
    for polygon, batched in zip(polygons, together):
        alone = find_ends(polygon)
        tolerance = ROUNDING * size(polygon)
        assert batched.kind == alone.kind
        assert batched.start.distance(alone.start) <= tolerance
        assert batched.end.distance(alone.end) <= tolerance
    assert [result.kind for result in together] == [COMPACT, ELONGATED, STAR, COMPACT, COMPACT, STAR]
