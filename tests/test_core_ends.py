"""Automatic ends (``incircu_plugin.core.ends.find_ends``): the tips a person would name, found exactly.

Every expected end is known by construction (the ends of the line that was buffered, the midpoints of the
cut caps, the split points of the analytic cases). Tolerances are fractions of the width of the known end,
the only length that sets how far a reasonable "end" can be from the true one.
"""

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, MultiPolygon, Point, Polygon, box
from shapely.geometry.polygon import orient
from shapely.ops import unary_union

from incircu_plugin.core import Cancelled, find_ends, polygon_centerline
from incircu_plugin.core import ends as ends_module
from incircu_plugin.core.ends import _last_trunk_positions
from incircu_plugin.core.errors import IncirCuError, InvalidGeometryError
from tests.support import geometry_cases

#: Fraction of the channel width within which a found end must match a flat cap's midpoint. A flat cap is
#: centred exactly by construction (midpoint between its two corners); what remains is the simplification
#: of the outline before the skeleton is built (its cap centring uses the exact outline) and rounding.
FLAT_CAP_TOLERANCE = 0.01

#: Fraction of the width within which a rounded cap's apex must be matched: the buffer approximates the
#: half circle by chords (8 per quarter), whose midpoint can miss the true apex by a chord's sagitta,
#: ``(1 - cos(pi / 16)) / 2`` of the width, about 0.0096.
ROUND_CAP_TOLERANCE = 0.02


def found_pair(polygon):
    """Return the two found ends as a (2, 2) array and the result."""
    ends = find_ends(polygon)
    return np.array([ends.start.coords[0], ends.end.coords[0]]), ends


def pair_error(found, expected):
    """Largest distance between two unordered pairs of points, CRS units."""
    expected = np.asarray(expected, dtype=float)
    straight = np.hypot(*(found - expected).T).max()
    swapped = np.hypot(*(found - expected[::-1]).T).max()
    return min(straight, swapped)


def channel(points, width, cap_style="flat"):
    """A channel of constant ``width`` around a polyline, with flat or round ends."""
    return LineString(points).buffer(width / 2.0, cap_style=cap_style, join_style="mitre")


@pytest.mark.parametrize("case", geometry_cases.analytic_cases(), ids=lambda case: case.name)
def test_analytic_cases_find_their_split_points(case):
    found, ends = found_pair(case.polygon)
    assert ends.elongated
    assert pair_error(found, case.split_points) <= FLAT_CAP_TOLERANCE * case.width


def test_rectangle_ends_are_the_short_side_midpoints_not_corners():
    found, _ = found_pair(box(0.0, 0.0, 120.0, 8.0))
    assert pair_error(found, [(0.0, 4.0), (120.0, 4.0)]) <= FLAT_CAP_TOLERANCE * 8.0


def test_u_shape_gets_its_two_tips_not_the_farthest_pair():
    width = 10.0
    polygon = channel([(0.0, 100.0), (0.0, 0.0), (60.0, 0.0), (60.0, 100.0)], width)
    found, ends = found_pair(polygon)
    assert ends.elongated
    assert pair_error(found, [(0.0, 100.0), (60.0, 100.0)]) <= FLAT_CAP_TOLERANCE * width


def test_flat_capped_s_meander_gets_the_middle_of_each_cap():
    width = 20.0
    x = np.linspace(0.0, 1200.0, 1201)
    axis = np.c_[x, 80.0 * np.sin(2.0 * math.pi * x / 600.0 + 0.4)]
    found, ends = found_pair(channel(axis, width))
    assert ends.elongated
    assert pair_error(found, [axis[0], axis[-1]]) <= FLAT_CAP_TOLERANCE * width


def test_round_capped_s_meander_gets_the_apex_of_each_cap():
    width = 20.0
    x = np.linspace(0.0, 1200.0, 1201)
    axis = np.c_[x, 80.0 * np.sin(2.0 * math.pi * x / 600.0 + 0.4)]
    found, _ = found_pair(channel(axis, width, cap_style="round"))
    apexes = []
    for tip, inner in ((axis[0], axis[1]), (axis[-1], axis[-2])):
        outward = (tip - inner) / np.hypot(*(tip - inner))
        apexes.append(tip + width / 2.0 * outward)
    assert pair_error(found, apexes) <= ROUND_CAP_TOLERANCE * width


def test_spiral_gets_its_inner_and_outer_tips():
    width = 6.0
    turns = np.linspace(0.0, 6.0 * math.pi, 900)
    radius = 10.0 + 5.0 * turns
    axis = np.c_[radius * np.cos(turns), radius * np.sin(turns)]
    found, ends = found_pair(channel(axis, width))
    assert ends.elongated
    assert pair_error(found, [axis[0], axis[-1]]) <= FLAT_CAP_TOLERANCE * width


def test_l_shape_gets_the_ends_of_both_legs():
    width = 10.0
    found, _ = found_pair(channel([(0.0, 100.0), (0.0, 0.0), (60.0, 0.0)], width))
    assert pair_error(found, [(0.0, 100.0), (60.0, 0.0)]) <= FLAT_CAP_TOLERANCE * width


def test_y_shape_picks_the_longest_pair_of_arms():
    width = 10.0
    tips = [(0.0, -100.0), (-50.0, 60.0), (55.0, 30.0)]
    polygon = unary_union([channel([(0.0, 0.0), tip], width) for tip in tips])
    lengths = [math.hypot(*tip) for tip in tips]
    longest_two = [tips[i] for i in np.argsort(lengths)[::-1][:2]]
    found, ends = found_pair(polygon)
    assert ends.elongated
    assert pair_error(found, longest_two) <= FLAT_CAP_TOLERANCE * width
    shortest = np.asarray(tips[int(np.argmin(lengths))])
    assert np.hypot(*(found - shortest).T).min() > 5.0 * width


def test_y_shape_follows_the_arms_when_the_lengths_change():
    width = 10.0
    tips = [(0.0, -60.0), (-50.0, 60.0), (70.0, 40.0)]
    polygon = unary_union([channel([(0.0, 0.0), tip], width) for tip in tips])
    found, _ = found_pair(polygon)
    assert pair_error(found, [tips[1], tips[2]]) <= FLAT_CAP_TOLERANCE * width


def test_near_circle_does_not_crash_and_is_not_elongated():
    rng = np.random.default_rng(7)
    angles = np.linspace(0.0, 2.0 * math.pi, 240, endpoint=False)
    radii = 10.0 * (1.0 + 0.02 * rng.standard_normal(len(angles)))
    polygon = Polygon(np.c_[radii * np.cos(angles), radii * np.sin(angles)])
    found, ends = found_pair(polygon)
    assert not ends.elongated
    assert polygon.exterior.distance(ends.start) <= 1e-9 * 20.0
    assert polygon.exterior.distance(ends.end) <= 1e-9 * 20.0
    assert np.hypot(*(found[0] - found[1])) > 0.0


def test_square_is_not_elongated_but_a_three_to_one_rectangle_is():
    assert not find_ends(box(0.0, 0.0, 10.0, 10.0)).elongated
    assert find_ends(box(0.0, 0.0, 30.0, 10.0)).elongated


def test_pointed_ends_are_the_points():
    found, _ = found_pair(Polygon([(0.0, 0.0), (50.0, 5.0), (100.0, 0.0), (50.0, -5.0)]))
    assert pair_error(found, [(0.0, 0.0), (100.0, 0.0)]) <= FLAT_CAP_TOLERANCE * 10.0


def test_oblique_cut_ends_are_the_middles_of_the_cuts():
    found, _ = found_pair(Polygon([(0.0, 0.0), (100.0, 0.0), (110.0, 10.0), (10.0, 10.0)]))
    cut = math.hypot(10.0, 10.0)
    assert pair_error(found, [(5.0, 5.0), (105.0, 5.0)]) <= FLAT_CAP_TOLERANCE * cut


def test_the_skeleton_path_goes_around_an_island():
    island = box(30.0, 4.0, 70.0, 16.0)
    polygon = Polygon(box(0.0, 0.0, 100.0, 20.0).exterior.coords, [island.exterior.coords])
    found, ends = found_pair(polygon)
    assert pair_error(found, [(0.0, 10.0), (100.0, 10.0)]) <= FLAT_CAP_TOLERANCE * 20.0
    assert not ends.trunk.intersects(island.buffer(-1e-6))
    assert polygon.buffer(1e-9).covers(ends.trunk)


@pytest.mark.parametrize(
    "island",
    [
        Point(2780.0, -120.0).buffer(8.0, 4),
        Point(2700.0, -125.0).buffer(10.0, 4),
        Point(2850.0, 120.0).buffer(8.0, 4),
        Point(200.0, 100.0).buffer(12.0, 4),
        box(1000.0, -60.0, 2000.0, 60.0),
    ],
    ids=["small, near a bank near the end", "larger, nearer the bank", "near the other bank", "near the start", "big"],
)
def test_islands_do_not_move_the_ends(island):
    """A straight channel 3,000 x 300 with one island: the ends are the middles of its flat caps, as without the
    island. (A small island beside a bank near an end used to pull the path through the gap between them and
    the end to a corner of the cap, 150 away: islands smaller than the typical width are left out of the
    skeleton; the big one is kept, and the path goes around it.)"""
    outline = box(0.0, -150.0, 3000.0, 150.0)
    found, ends = found_pair(Polygon(outline.exterior.coords, [island.exterior.coords]))
    assert pair_error(found, [(0.0, 0.0), (3000.0, 0.0)]) <= FLAT_CAP_TOLERANCE * 300.0
    assert ends.elongated


def test_ignored_islands_do_not_move_the_automatic_ends():
    """With the islands ignored the ends are those of the outline, even beside an island wider than the
    channel's typical width near an end (which, kept, may pull that end to a corner of the cap)."""
    outline = box(0.0, -150.0, 3000.0, 150.0)
    polygon = Polygon(outline.exterior.coords, [box(2600.0, -140.0, 2900.0, -20.0).exterior.coords])
    line = polygon_centerline(polygon, islands="ignore").line
    found = np.array([line.coords[0], line.coords[-1]])
    assert pair_error(found, [(0.0, 0.0), (3000.0, 0.0)]) <= FLAT_CAP_TOLERANCE * 300.0


@pytest.mark.slow
def test_ends_with_islands_are_those_of_the_outline():
    """A meandering river 5 km long and 300 wide strewn with 300 small islands gets the ends of its outline
    alone (which lie on the middles of its flat caps), so ignoring the islands or going around them starts
    from the same ends."""
    along = np.linspace(0.0, 5000.0, 400)
    river = LineString(np.c_[along, 200.0 * np.sin(along / 500.0)]).buffer(150.0, cap_style="flat")
    rng = np.random.default_rng(3)
    islands = []
    while len(islands) < 300:
        island = Point(rng.uniform(0.0, 5000.0), rng.uniform(-350.0, 350.0)).buffer(rng.uniform(2.0, 12.0), 4)
        if river.buffer(-3.0).contains(island) and all(island.distance(other) > 3.0 for other in islands):
            islands.append(island)
    polygon = Polygon(river.exterior.coords, [island.exterior.coords for island in islands])
    outline_ends, _ = found_pair(Polygon(river.exterior.coords))
    found, _ = found_pair(polygon)
    assert np.array_equal(found, outline_ends)
    assert pair_error(found, [(0.0, 0.0), (5000.0, 200.0 * np.sin(10.0))]) <= FLAT_CAP_TOLERANCE * 300.0
    for islands_mode in ("main_channel", "ignore"):
        line = polygon_centerline(polygon, islands=islands_mode).line
        assert pair_error(np.array([line.coords[0], line.coords[-1]]), found) <= 1e-9 * 5000.0


@pytest.mark.parametrize("name", sorted(geometry_cases.PLACEMENTS))
def test_result_does_not_depend_on_ring_start_or_orientation(name):
    placement = geometry_cases.PLACEMENTS[name]
    case = geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0, placement=placement)
    reference, _ = found_pair(case.polygon)
    ring = np.asarray(case.polygon.exterior.coords)[:-1]
    for variant in (
        Polygon(np.roll(ring, 137, axis=0)),
        orient(case.polygon, -1.0),
        Polygon(np.roll(ring[::-1], 41, axis=0)),
    ):
        found, _ = found_pair(variant)
        assert pair_error(found, reference) <= FLAT_CAP_TOLERANCE * case.width


@pytest.mark.parametrize(
    ("origin", "width", "height"),
    [
        ((0.0, 0.0), 1.0, 10.0),
        ((0.3, -3.3), 1.0, 37.5),
        ((12345.678, 1e5), 1.0, 1000.0),
        # Boxes of centimetres to metres far from the origin: adding the origin rounds x by more than SAME_X of
        # their size.
        ((8892296.71, 16766275.72), 0.0129, 0.072),
        ((17290681.26, 1638125.93), 0.7305, 3.09),
    ],
)
def test_a_north_south_box_starts_at_its_south_end_whatever_its_ring(origin, width, height):
    """Both ends of a north-south box have the same x up to rounding: the start is the south one, for every
    ring start and orientation (rounding alone used to decide the order)."""
    x, y = origin
    corners = np.asarray(box(x, y, x + width, y + height).exterior.coords)[:-1]
    for shift in range(4):
        for ring in (np.roll(corners, shift, axis=0), np.roll(corners[::-1], shift, axis=0)):
            ends = find_ends(Polygon(ring))
            assert ends.start.y < ends.end.y
            assert math.dist(ends.start.coords[0], (x + width / 2.0, y)) <= FLAT_CAP_TOLERANCE * width


def test_an_end_slightly_west_of_the_other_is_the_start():
    """Beyond rounding, the smaller x decides even when the y order is the other way."""
    tilted = shapely.affinity.rotate(box(0.0, 0.0, 1.0, 100.0), 0.01, origin=(0.5, 50.0))
    ends = find_ends(tilted)
    assert ends.start.x < ends.end.x
    assert ends.start.y > ends.end.y


def test_same_input_gives_the_same_answer():
    polygon = channel([(0.0, 0.0), (40.0, 30.0), (90.0, 10.0)], 8.0)
    first, _ = found_pair(polygon)
    second, _ = found_pair(polygon)
    assert np.array_equal(first, second)


def test_ends_lie_on_the_exterior_ring():
    case = geometry_cases.gambia()
    ends = find_ends(case.polygon)
    tolerance = 1e-9 * case.extent
    assert case.polygon.exterior.distance(ends.start) <= tolerance
    assert case.polygon.exterior.distance(ends.end) <= tolerance
    assert ends.start.distance(ends.end) > 0.5 * case.extent


def polygon_with_nan():
    """A triangle with a NaN coordinate (shapely warns while building it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return Polygon([(0.0, 0.0), (float("nan"), 0.0), (1.0, 1.0)])


BAD_INPUTS = {
    "empty": Polygon,
    "multipolygon": lambda: MultiPolygon([box(0, 0, 10, 1), box(0, 5, 10, 6)]),
    "bowtie": lambda: Polygon([(0, 0), (10, 10), (10, 0), (0, 10)]),
    "nan": polygon_with_nan,
    "null": lambda: None,
}


@pytest.mark.parametrize("name", sorted(BAD_INPUTS))
def test_bad_input_gets_a_typed_error(name):
    with pytest.raises(InvalidGeometryError):
        find_ends(BAD_INPUTS[name]())


def test_trunk_is_longer_than_the_straight_distance_in_a_u_shape():
    polygon = channel([(0.0, 100.0), (0.0, 0.0), (60.0, 0.0), (60.0, 100.0)], 10.0)
    ends = find_ends(polygon)
    assert ends.trunk.length > 2.0 * shapely.distance(ends.start, ends.end)
    assert isinstance(ends.start, Point) and isinstance(ends.end, Point)


def test_polygon_centerline_without_split_points_runs_tip_to_tip():
    width = 10.0
    polygon = channel([(0.0, 100.0), (0.0, 0.0), (60.0, 0.0), (60.0, 100.0)], width)
    result = polygon_centerline(polygon, spacing=width / 10.0)
    assert result.ends_found
    line_ends = np.array([result.line.coords[0], result.line.coords[-1]])
    assert pair_error(line_ends, [(0.0, 100.0), (60.0, 100.0)]) <= FLAT_CAP_TOLERANCE * width
    assert result.line.is_simple


def test_polygon_centerline_warns_when_the_shape_is_not_elongated():
    result = polygon_centerline(Point(0.0, 0.0).buffer(10.0), spacing=0.5)
    assert result.ends_found
    assert any("not elongated" in note for note in result.notes)


@pytest.mark.parametrize("height", [1e-3, 1e-4, 1e-5])
def test_thin_boxes_get_the_middles_of_their_short_sides(height):
    found, ends = found_pair(box(0.0, 0.0, 1.0, height))
    assert ends.elongated
    assert pair_error(found, [(0.0, height / 2.0), (1.0, height / 2.0)]) <= FLAT_CAP_TOLERANCE * height


@pytest.mark.parametrize("scale", [1e-45, 1e-30, 1e30, 1e45])
def test_the_answer_scales_with_the_coordinates(scale):
    found, _ = found_pair(box(0.0, 0.0, 10.0 * scale, scale))
    assert pair_error(found, [(0.0, scale / 2.0), (10.0 * scale, scale / 2.0)]) <= FLAT_CAP_TOLERANCE * scale


@pytest.mark.parametrize(("scale", "words"), [(1e-170, "Scale the data up"), (1e155, "scale the data down")])
def test_coordinates_beyond_the_supported_range_get_a_typed_error(scale, words):
    with pytest.raises(InvalidGeometryError, match=words):
        find_ends(box(0.0, 0.0, 10.0 * scale, scale))


def test_absurd_extent_gets_a_typed_error():
    with pytest.raises(InvalidGeometryError):
        find_ends(box(0.0, 0.0, 1e301, 1e300))


def test_unknown_rule_gets_a_typed_error():
    with pytest.raises(IncirCuError):
        find_ends(box(0.0, 0.0, 10.0, 1.0), rule="shortest")


def test_the_ends_of_compact_shapes_are_distinct():
    square = shapely.segmentize(
        box(499.04325887565847, 203.26611626641056, 500.04325887565847, 204.26611626641056), 1.0 / 14.0
    )
    polygons = [square] + [Point(0.0, 0.0).buffer(1.0, quad_segs=k) for k in (1, 2, 3)]
    for sides in range(3, 14):
        angles = np.linspace(0.0, 2.0 * math.pi, sides, endpoint=False)
        polygons.append(Polygon(np.c_[np.cos(angles), np.sin(angles)]))
    for polygon in polygons:
        ends = find_ends(polygon)
        size = math.sqrt(polygon.area)
        assert ends.start.distance(ends.end) > 0.1 * size
        assert polygon.exterior.distance(ends.start) <= 1e-9 * size
        assert polygon.exterior.distance(ends.end) <= 1e-9 * size


def test_progress_reports_fractions_and_cancel_stops():
    polygon = channel([(0.0, 0.0), (400.0, 0.0), (400.0, 300.0)], 4.0)
    fractions = []
    find_ends(polygon, progress=lambda fraction: fractions.append(fraction) or True)
    assert fractions and fractions == sorted(fractions)
    assert 0.0 <= fractions[0] and fractions[-1] <= 1.0
    calls = []
    with pytest.raises(Cancelled):
        find_ends(polygon, progress=lambda fraction: calls.append(fraction) or False)
    assert len(calls) == 1


def tiny_heptagon(size, centre=(727280.18049115, 962390.08013269)):
    angles = np.linspace(0.0, 2.0 * math.pi, 7, endpoint=False)
    return Polygon(np.c_[centre[0] + size * np.cos(angles), centre[1] + size * np.sin(angles)])


def test_a_tiny_polygon_far_from_the_origin_gets_ends_on_its_ring():
    # 2e-3 across at 1e6 from the origin: coordinates are rounded to about 1e-10, 1e-7 of its size.
    size = 1.0e-3
    polygon = tiny_heptagon(size)
    ends = find_ends(polygon)
    for end in (ends.start, ends.end):
        assert polygon.exterior.distance(end) <= 1e-7 * 2.0 * size
    assert polygon_centerline(polygon).line.length > 0.0


def test_a_polygon_too_small_for_its_distance_from_the_origin_gets_a_typed_error():
    # 2.8e-5 across at 1e6: under the 1e-9 of the coordinates' magnitude float64 resolves reliably.
    with pytest.raises(InvalidGeometryError, match="Shift the data nearer the origin"):
        find_ends(tiny_heptagon(1.4030173759013428e-05))


def test_the_last_trunk_point_is_the_first_widest_junction_near_the_tip_else_where_the_banks_open():
    """``_last_trunk_positions`` on three hand-made ends (arc lengths ``along`` from the tip, radii, junction
    flags): two equally wide junctions near the tip and a wider one past half the path; no junction with
    radius 1 (the trunk point is where the distance from the tip, ``r_tip + along``, first exceeds
    ``CAP_REACH * r``: at ``CAP_REACH - 1``, between the first two points); no junction with radius 10 (that
    distance stays below ``CAP_REACH * r`` up to half the path, so half the path)."""
    along = np.tile([0.0, 1.0, 2.0, 3.0, 6.0, 10.0], 3)
    radii = np.array([2.0, 2.0, 2.0, 2.0, 5.0, 2.0] + [1.0] * 6 + [10.0] * 6)
    junction = np.zeros(18, dtype=bool)
    junction[[1, 3, 4]] = True
    tips = SimpleNamespace(
        along=along,
        radii=radii,
        junction=junction,
        starts=np.array([0, 6, 12]),
        lengths=np.array([6, 6, 6]),
        group=np.repeat(np.arange(3), 6),
    )
    position = _last_trunk_positions(tips)
    np.testing.assert_allclose(position, [1.0, ends_module.CAP_REACH - 1.0, 5.0], rtol=1e-12)


def test_arc_vertices_hold_every_vertex_strictly_within_each_arc():
    """Arcs on three rings (a star, a finely and unevenly digitised circle, a box), some wrapping past the
    ring's start, some starting at zero or on a vertex, one a whole turn: each arc's vertices include every
    vertex strictly within it, and their turns are those of the ring's neighbours."""
    rng = np.random.default_rng(5)
    angles = np.sort(rng.random(400)) * 2.0 * np.pi
    star = Polygon(
        [
            (np.cos(a) * (1.0 + 0.3 * (k % 2)), np.sin(a) * (1.0 + 0.3 * (k % 2)))
            for k, a in enumerate(np.linspace(0, 6, 12))
        ]
    )
    circle = Polygon(np.stack([np.cos(angles), np.sin(angles)], axis=1) * 0.4)
    exteriors = shapely.get_exterior_ring(np.array([orient(star), orient(circle), orient(box(0, 0, 0.6, 0.1))]))
    rings = ends_module._Rings(exteriors)
    ring = np.repeat(np.arange(3), 40)
    perimeter = rings.perimeters[ring]
    start = rng.random(len(ring)) * perimeter
    start[::10] = 0.0
    on_vertex = np.arange(5, len(ring), 10)
    start[on_vertex] = rings.positions[rings.starts[ring[on_vertex]] + 1]
    length = rng.random(len(ring)) * perimeter
    length[::7] = perimeter[::7]
    vertex, arc = rings.arc_vertices(ring, start, length)
    for number in range(len(ring)):
        own = slice(rings.starts[ring[number]], rings.starts[ring[number]] + rings.lengths[ring[number]])
        offset = (rings.positions[own] - start[number]) % perimeter[number]
        inside = np.flatnonzero((offset > 0.0) & (offset < length[number])) + own.start
        assert set(inside.tolist()) <= set(vertex[arc == number].tolist())
    coordinates = shapely.get_coordinates(exteriors[1])[:-1]
    incoming = coordinates - np.roll(coordinates, 1, axis=0)
    outgoing = np.roll(coordinates, -1, axis=0) - coordinates
    cross = incoming[:, 0] * outgoing[:, 1] - incoming[:, 1] * outgoing[:, 0]
    expected = np.arctan2(cross, np.sum(incoming * outgoing, axis=1))
    own = rings.starts[1] + np.arange(rings.lengths[1])
    assert np.allclose(rings.turns(own), expected, rtol=0.0, atol=1e-12)


def test_first_crossings_find_the_nearest_crossing_of_each_ray_as_shapely_does():
    """Rays from inside and outside a star, a box and an L (through a vertex, along a side, from a point on the
    ring, missing it, crossing it several times): each first crossing is the nearest point of
    ``shapely.intersection`` along the ray, and its arc length is where ``line_locate_point`` puts it."""
    star = Polygon(
        [
            (np.cos(a) * (1.0 + 0.5 * (k % 2)), np.sin(a) * (1.0 + 0.5 * (k % 2)))
            for k, a in enumerate(np.linspace(0.0, 2.0 * np.pi, 10, endpoint=False))
        ]
    )
    ell = Polygon([(0, 0), (2, 0), (2, 0.5), (0.5, 0.5), (0.5, 2), (0, 2)])
    exteriors = shapely.get_exterior_ring(np.array([orient(star), orient(box(0, 0, 1, 0.5)), orient(ell)]))
    rings = ends_module._Rings(exteriors)
    rng = np.random.default_rng(11)
    ring = np.concatenate([np.repeat([0, 1, 2], 30), [1, 1, 1, 2, 2, 0]])
    origin = rng.uniform(-0.5, 1.0, (len(ring), 2))
    direction = rng.normal(size=(len(ring), 2)) * 2.0
    special = np.array(
        [
            [(0.5, 0.25), (0.5, 0.25)],  # box: through the corner (1, 0.5)
            [(0.0, 0.0), (0.25, 0.0)],  # box: from a corner along its bottom side
            [(-0.5, 0.25), (-0.5, 0.0)],  # box: outside, missing it
            [(0.25, 1.0), (0.5, -1.0)],  # L: through its inner corner (0.5, 0.5), on to the bottom
            [(3.0, 0.25), (-4.0, 0.0)],  # L: from outside, across both its arms' ends
            [(0.0, 0.0), (2.0, 0.0)],  # star: from its centre through its vertex (1, 0)
        ]
    )
    origin[-6:], direction[-6:] = special[:, 0], special[:, 1]
    points, positions, found = rings.first_crossings(ring, origin, direction)
    rays = shapely.linestrings(np.stack([origin, origin + direction], axis=1))
    for number in range(len(ring)):
        with warnings.catch_warnings():
            # GEOS 3.11 returns a missing ray's intersection as an empty line with z, and numpy warns about it.
            warnings.simplefilter("ignore", RuntimeWarning)
            hits = shapely.get_coordinates(shapely.intersection(rays[number], exteriors[ring[number]]))
        assert found[number] == (len(hits) > 0)
        if not len(hits):
            assert np.array_equal(points[number], origin[number])
            continue
        expected = hits[np.argmin(np.hypot(*(hits - origin[number]).T))]
        assert np.allclose(points[number], expected, rtol=0.0, atol=1e-12)
        located = shapely.line_locate_point(exteriors[ring[number]], shapely.Point(points[number]))
        perimeter = rings.perimeters[ring[number]]
        gap = abs(positions[number] - located)
        assert min(gap, perimeter - gap) <= 1e-12
    expected = [(1.0, 0.5), (0.0, 0.0), (-0.5, 0.25), (0.5, 0.5), (2.0, 0.25), (1.0, 0.0)]
    assert np.allclose(points[-6:], expected, rtol=0.0, atol=1e-12)
    assert found[-6:].tolist() == [True, True, False, True, True, True]
