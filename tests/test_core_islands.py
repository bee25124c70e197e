"""Islands (``incircu_plugin.core.islands.bridge_islands`` and ``polygon_centerline(islands=...)``).

A channel 200 long and 20 wide, split at the middles of its short sides: ``c1`` is the bottom bank (y = 0)
and ``c2`` the top bank (y = 20). Around an island the medial axis of the wide side is known exactly: the
line y = (island edge + bank) / 2 along a rectangular island, so the expected positions come from the
geometry. Tolerances: the engine's invariants hold to 1e-9 of the extent.
"""

import numpy as np
import pytest
import shapely
from shapely.geometry import LinearRing, LineString, Point, Polygon, box

from incircu_plugin.core import InvalidGeometryError, polygon_centerline, split_polygon
from incircu_plugin.core import islands as islands_module
from incircu_plugin.core.islands import bridge_islands

LENGTH = 200.0
WIDTH = 20.0
SPLIT_POINTS = ((0.0, WIDTH / 2.0), (LENGTH, WIDTH / 2.0))
EXTENT = float(np.hypot(LENGTH, WIDTH))
TOLERANCE = 1e-9 * EXTENT * 100.0
SPACING = WIDTH / 40.0


def channel_with(*islands):
    """The 200 x 20 channel with the given islands (polygons) as holes."""
    return Polygon(box(0.0, 0.0, LENGTH, WIDTH).exterior.coords, [island.exterior.coords for island in islands])


def centerline(polygon, **options):
    """Centerline of a channel between the middles of its short sides."""
    return polygon_centerline(polygon, SPLIT_POINTS, spacing=SPACING, **options)


def vertices_beside(result, island, margin):
    """Centerline vertices whose x lies over the island, ``margin`` inside its ends."""
    vertices = shapely.get_coordinates(result.line)
    x0, _, x1, _ = island.bounds
    return vertices[(vertices[:, 0] > x0 + margin) & (vertices[:, 0] < x1 - margin)]


def assert_valid_line(result, polygon):
    """One simple line, inside the region, crossing no island, with empty incircles."""
    line = result.line
    assert line.is_simple
    assert polygon.buffer(TOLERANCE).covers(line)
    for hole in polygon.interiors:
        assert not line.intersects(Polygon(hole).buffer(-TOLERANCE))
    vertices = shapely.get_coordinates(line)[1:-1]
    radii = result.radii[1:-1]
    clearance = shapely.distance(shapely.points(vertices), polygon.boundary)
    assert np.all(clearance >= radii - TOLERANCE)
    assert np.allclose(clearance, radii, atol=TOLERANCE)


def slit_width(*chains):
    """Width of the slits ``bridge_islands`` cuts (see its module), CRS units."""
    coordinates = np.concatenate([np.asarray(chain, dtype=float) for chain in chains])
    extent = float(np.hypot(*(coordinates.max(axis=0) - coordinates.min(axis=0))))
    largest = float(max(np.abs(coordinates).max(), 1.0))
    return max(islands_module.SLIT_WIDTH * extent, islands_module.SLIT_ULPS * float(np.spacing(largest)))


def ring_area(chain_a, chain_b):
    """Signed area of the ring chain a, then chain b backwards."""
    ring = np.concatenate([chain_a, chain_b[::-1]])
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def test_off_centre_island_line_passes_on_the_wide_side():
    island = box(80.0, 3.0, 120.0, 8.0)
    polygon = channel_with(island)
    result = centerline(polygon)
    assert_valid_line(result, polygon)
    beside = vertices_beside(result, island, margin=1.0)
    assert len(beside) > 10
    assert beside[:, 1] == pytest.approx((8.0 + WIDTH) / 2.0, abs=TOLERANCE)


def test_island_near_the_top_bank_puts_the_line_below_it():
    island = box(80.0, 13.0, 120.0, 18.0)
    polygon = channel_with(island)
    result = centerline(polygon)
    assert_valid_line(result, polygon)
    beside = vertices_beside(result, island, margin=1.0)
    assert beside[:, 1] == pytest.approx(13.0 / 2.0, abs=TOLERANCE)


def test_several_islands_in_a_row_each_on_its_wide_side():
    islands = [box(30.0, 2.0, 50.0, 7.0), box(70.0, 13.0, 90.0, 18.0), box(110.0, 3.0, 130.0, 9.0)]
    islands.append(box(150.0, 12.0, 170.0, 16.5))
    polygon = channel_with(*islands)
    result = centerline(polygon)
    assert_valid_line(result, polygon)
    for island in islands:
        _, bottom, _, top = island.bounds
        near_bottom = bottom < WIDTH - top
        expected = (top + WIDTH) / 2.0 if near_bottom else bottom / 2.0
        beside = vertices_beside(result, island, margin=1.0)
        assert len(beside) > 5
        assert beside[:, 1] == pytest.approx(expected, abs=TOLERANCE)


def test_island_exactly_in_the_middle_joins_c1_and_the_line_passes_by_c2():
    island = box(90.0, 7.0, 110.0, 13.0)
    polygon = channel_with(island)
    first = centerline(polygon)
    second = centerline(polygon)
    assert first.line.equals_exact(second.line, 0.0)
    assert_valid_line(first, polygon)
    c1, _ = split_polygon(polygon, SPLIT_POINTS)
    assert np.all(c1[1:-1, 1] == 0.0)
    beside = vertices_beside(first, island, margin=1.0)
    assert beside[:, 1] == pytest.approx((13.0 + WIDTH) / 2.0, abs=TOLERANCE)


def test_tiny_island_only_bends_the_line_where_the_geometry_requires():
    centre, radius = (100.0, 12.0), 0.05
    island = Point(centre).buffer(radius, quad_segs=4)
    polygon = channel_with(island)
    result = centerline(polygon)
    assert_valid_line(result, polygon)
    vertices = shapely.get_coordinates(result.line)
    # The island (nearer the top) joins the top bank; at y = 10 it is nearer than the top bank only within
    # |x - 100| < sqrt((10 + radius)^2 - 2^2); everywhere else the line must stay on the axis y = 10.
    reach = np.sqrt((WIDTH / 2.0 + radius) ** 2 - (centre[1] - WIDTH / 2.0) ** 2)
    away = np.abs(vertices[:, 0] - centre[0]) > reach + SPACING
    assert vertices[away, 1] == pytest.approx(WIDTH / 2.0, abs=TOLERANCE)
    # Over the island the line is midway between the bottom bank and the island's lowest point.
    lowest = island.bounds[1]
    assert vertices[:, 1].min() >= lowest / 2.0 - TOLERANCE
    assert vertices[:, 1].min() <= lowest / 2.0 + SPACING


def test_ignoring_islands_lets_the_line_run_straight_through():
    island = box(80.0, 3.0, 120.0, 8.0)
    result = centerline(channel_with(island), islands="ignore")
    assert shapely.get_coordinates(result.line)[:, 1] == pytest.approx(WIDTH / 2.0, abs=TOLERANCE)


def test_island_behind_another_joins_through_it_and_the_line_keeps_the_wide_side():
    lower, upper = box(90.0, 2.0, 110.0, 6.0), box(95.0, 7.0, 105.0, 8.0)
    polygon = channel_with(lower, upper)
    result = centerline(polygon, islands="main_channel")
    assert_valid_line(result, polygon)
    beside = vertices_beside(result, upper, margin=1.0)
    assert beside[:, 1] == pytest.approx((8.0 + WIDTH) / 2.0, abs=TOLERANCE)


def test_bridged_chains_enclose_the_region_without_its_islands():
    islands = [box(30.0, 2.0, 50.0, 7.0), box(70.0, 13.0, 90.0, 18.0), Point(120.0, 10.5).buffer(1.5)]
    polygon = channel_with(*islands)
    c1, c2 = split_polygon(polygon, SPLIT_POINTS)
    bridged_a, bridged_b = bridge_islands(c1, c2, list(polygon.interiors))
    # Each slit is a corridor of negligible width, no longer than the channel is wide.
    assert ring_area(bridged_a, bridged_b) == pytest.approx(polygon.area, abs=slit_width(c1, c2) * WIDTH * len(islands))
    for chain, original in ((bridged_a, c1), (bridged_b, c2)):
        assert np.array_equal(chain[0], original[0]) and np.array_equal(chain[-1], original[-1])
        assert np.all(np.hypot(*np.diff(chain, axis=0).T) > 0.0)
        for island in islands:
            assert not LineString(chain).intersects(island.buffer(-TOLERANCE))


def test_each_island_joins_the_nearer_chain_and_ties_go_to_c1():
    c1 = np.array([[0.0, 10.0], [0.0, 0.0], [200.0, 0.0], [200.0, 10.0]])
    c2 = np.array([[0.0, 10.0], [0.0, 20.0], [200.0, 20.0], [200.0, 10.0]])
    near_a = np.array(box(20.0, 2.0, 30.0, 4.0).exterior.coords)
    near_b = np.array(box(60.0, 15.0, 70.0, 17.0).exterior.coords)
    middle = np.array(box(120.0, 8.0, 130.0, 12.0).exterior.coords)
    bridged_a, bridged_b = bridge_islands(c1, c2, [near_a, near_b, middle])
    lines = LineString(bridged_a), LineString(bridged_b)
    tolerance = slit_width(c1, c2)
    for ring, joined, other in ((near_a, 0, 1), (near_b, 1, 0), (middle, 0, 1)):
        corners = shapely.points(ring[:-1])
        assert np.all(shapely.distance(corners, lines[joined]) <= tolerance)
        assert np.all(shapely.distance(corners, lines[other]) >= 1.0)


def test_islands_are_spliced_in_chain_order():
    c1 = np.array([[0.0, 10.0], [0.0, 0.0], [200.0, 0.0], [200.0, 10.0]])
    c2 = np.array([[0.0, 10.0], [0.0, 20.0], [200.0, 20.0], [200.0, 10.0]])
    islands = [box(x, 2.0, x + 10.0, 4.0) for x in (150.0, 30.0, 90.0)]
    bridged_a, _ = bridge_islands(c1, c2, islands)
    first_visit = []
    for island in islands:
        corner = np.asarray(island.exterior.coords[1])
        first_visit.append(int(np.argmin(np.hypot(*(bridged_a - corner).T))))
    assert np.argsort(first_visit).tolist() == [1, 2, 0]
    assert np.all(np.diff(bridged_a[bridged_a[:, 1] == 0.0][:, 0]) >= 0.0)


def test_slit_goes_around_an_island_in_the_way():
    c1 = np.array([[0.0, 10.0], [0.0, 0.0], [200.0, 0.0], [200.0, 10.0]])
    c2 = np.array([[0.0, 10.0], [0.0, 40.0], [200.0, 40.0], [200.0, 10.0]])
    blocker = box(60.0, 2.0, 140.0, 6.0)
    hidden = box(95.0, 7.0, 105.0, 8.0)
    bridged_a, bridged_b = bridge_islands(c1, c2, [blocker, hidden])
    assert np.array_equal(bridged_b, c2)
    for island in (blocker, hidden):
        assert not LineString(bridged_a).intersects(island.buffer(-TOLERANCE))
        corners = shapely.points(np.asarray(island.exterior.coords))
        assert np.all(shapely.distance(corners, LineString(bridged_a)) <= slit_width(c1, c2))


def test_accepts_rings_polygons_and_linestring_chains():
    c1 = LineString([(0.0, 10.0), (0.0, 0.0), (200.0, 0.0), (200.0, 10.0)])
    c2 = LineString([(0.0, 10.0), (0.0, 20.0), (200.0, 20.0), (200.0, 10.0)])
    as_ring = LinearRing([(20.0, 2.0), (30.0, 2.0), (30.0, 4.0)])
    as_polygon = box(60.0, 2.0, 70.0, 4.0)
    bridged_a, bridged_b = bridge_islands(c1, c2, [as_ring, as_polygon])
    assert bridged_a.shape[1] == 2 and bridged_b.shape[1] == 2
    # Each island adds its foot twice and its closed walk from the slit's end (a corner here).
    assert len(bridged_a) == 4 + (2 + 3 + 1) + (2 + 4 + 1)
    assert bridge_islands(c1, c2, [])[0].tolist() == np.asarray(c1.coords).tolist()


@pytest.mark.parametrize("ring", [[(1.0, 1.0), (2.0, 2.0)], [(1.0, 1.0), (float("nan"), 2.0), (3.0, 1.0)], []])
def test_bad_island_is_a_typed_error(ring):
    c1 = np.array([[0.0, 10.0], [0.0, 0.0], [200.0, 0.0], [200.0, 10.0]])
    c2 = np.array([[0.0, 10.0], [0.0, 20.0], [200.0, 20.0], [200.0, 10.0]])
    with pytest.raises(InvalidGeometryError):
        bridge_islands(c1, c2, [np.array(ring, dtype=float).reshape(-1, 2)])


@pytest.mark.parametrize("offset", [(0.0, 0.0), (5.0e6, 5.2e6), (-3.0e5, 1.0e7)])
def test_islands_far_from_the_origin_keep_the_line_simple_and_on_the_wide_side(offset):
    shift = np.asarray(offset)
    islands = [box(60.0, 3.0, 90.0, 8.0), box(120.0, 12.0, 150.0, 17.0)]
    moved = [shapely.transform(island, lambda xy: xy + shift) for island in islands]
    polygon = shapely.transform(channel_with(*islands), lambda xy: xy + shift)
    split_points = [tuple(np.asarray(point) + shift) for point in SPLIT_POINTS]
    result = polygon_centerline(polygon, split_points, spacing=SPACING)
    assert result.line.is_simple
    rounding = 64.0 * float(np.spacing(np.abs(shapely.get_coordinates(polygon)).max()))
    for island, expected in zip(moved, [(8.0 + WIDTH) / 2.0, 12.0 / 2.0]):
        assert not result.line.intersects(island.buffer(-TOLERANCE - rounding))
        beside = vertices_beside(result, island, margin=1.0)
        assert beside[:, 1] - offset[1] == pytest.approx(expected, abs=TOLERANCE + rounding)


def test_braided_channel_with_many_islands_gives_one_simple_line():
    rng = np.random.default_rng(1)
    length, width = 1000.0, 50.0
    blobs = [
        Point(rng.uniform(10.0, length - 10.0), rng.uniform(5.0, width - 5.0)).buffer(
            rng.uniform(0.5, 2.5), quad_segs=4
        )
        for _ in range(40)
    ]
    merged = shapely.union_all(blobs)
    islands = list(getattr(merged, "geoms", [merged]))
    polygon = Polygon(box(0.0, 0.0, length, width).exterior.coords, [island.exterior.coords for island in islands])
    result = polygon_centerline(polygon, [(0.0, width / 2.0), (length, width / 2.0)], spacing=0.5)
    line = result.line
    assert line.is_simple
    tolerance = 1e-9 * float(np.hypot(length, width)) * 100.0
    assert polygon.buffer(tolerance).covers(line)
    for island in islands:
        assert not line.intersects(island.buffer(-tolerance))
    clearance = shapely.distance(shapely.points(shapely.get_coordinates(line)[1:-1]), polygon.boundary)
    assert np.all(clearance >= result.radii[1:-1] - tolerance)


def test_automatic_ends_and_islands_together():
    x = np.linspace(0.0, 1200.0, 1201)
    axis = np.c_[x, 80.0 * np.sin(2.0 * np.pi * x / 600.0)]
    half_width = 15.0
    river = LineString(axis).buffer(half_width, cap_style="flat")
    islands = [Point(axis[i] + (0.0, 5.0)).buffer(3.0) for i in (200, 500, 800)]
    polygon = Polygon(river.exterior.coords, [island.exterior.coords for island in islands])
    result = polygon_centerline(polygon, spacing=half_width / 10.0)
    assert result.ends_found
    ends = np.array([result.line.coords[0], result.line.coords[-1]])
    expected = np.array([axis[0], axis[-1]])
    assert np.hypot(*(ends - expected).T).max() <= 0.01 * 2.0 * half_width
    assert result.line.is_simple
    for island in islands:
        assert not result.line.intersects(island.buffer(-TOLERANCE))


def test_a_blocked_shortest_slit_gives_way_to_the_next_shortest(monkeypatch):
    """When the shortest slit, tried alone first, is blocked, the next shortest free candidate is taken.

    A round island (radius 2 around (100, 6)) has one shortest slit, straight down to the bank (length 4); it
    is refused here, so the slit must start one candidate step beside it: longer than 4 by less than the
    sagitta of that step.
    """
    free_candidates = islands_module._free_candidates
    refused = []

    def refuse_the_first_tried_alone(search, islands, starts, feet, lengths):
        if len(starts) == 1 and not refused:
            refused.append(float(lengths[0]))
            return np.zeros(0, dtype=np.int64)
        return free_candidates(search, islands, starts, feet, lengths)

    monkeypatch.setattr(islands_module, "_free_candidates", refuse_the_first_tried_alone)
    radius, centre = 2.0, (100.0, 6.0)
    island = Point(centre).buffer(radius, quad_segs=64)
    polygon = channel_with(island)
    c1, c2 = split_polygon(polygon, SPLIT_POINTS)
    bridged_a, _ = bridge_islands(c1, c2, [island])
    assert refused == [pytest.approx(centre[1] - radius, abs=1e-9)]
    leaves = np.flatnonzero((bridged_a[:-1, 1] == 0.0) & (bridged_a[1:, 1] > 0.0))
    foot, top = bridged_a[leaves[0]], bridged_a[leaves[0] + 1]
    step = 2.0 * np.pi / islands_module.SLIT_CANDIDATES
    slit = float(np.hypot(*(top - foot)))
    assert refused[0] < slit <= refused[0] + radius * (1.0 - np.cos(step)) + 1e-9
    assert 0.0 < abs(foot[0] - centre[0]) <= radius * np.sin(step) + 1e-6
    assert not LineString(bridged_a).intersects(island.buffer(-TOLERANCE))


def test_the_gap_to_the_host_bounds_the_shortest_slit(monkeypatch):
    """The island's gap to its host plus half a candidate spacing bounds its shortest candidate slit, so the
    nearest-candidate search never falls back to probing (the same slit either way, only slower).

    The bank rises to a peak 0.5 under the middle of the lower island's bottom edge, between two candidates;
    the upper island joins the lower one.
    """

    def refuse_to_probe(*args):
        raise AssertionError("closest fell back to probing: the hint was below the shortest candidate")

    monkeypatch.setattr(islands_module.IndexedPolyline, "_may_be_closest", refuse_to_probe)
    c1 = np.array([[0.0, 10.0], [0.0, 0.0], [50.37, 1.5], [200.0, 0.0], [200.0, 10.0]])
    c2 = np.array([[0.0, 10.0], [0.0, 20.0], [200.0, 20.0], [200.0, 10.0]])
    lower, upper = box(40.0, 2.0, 60.0, 4.0), box(45.0, 4.5, 55.0, 5.0)
    bridged_a, bridged_b = bridge_islands(c1, c2, [lower, upper])
    assert len(bridged_b) == len(c2)
    assert np.isclose(bridged_a[:, 1], 2.0).any() and np.isclose(bridged_a[:, 1], 5.0).any()
