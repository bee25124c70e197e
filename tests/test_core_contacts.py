"""The engine's kernels with hand-computed values: first contacts, event crossings, parabola stations, order.

Each expected value comes from elementary geometry written next to it (a disk on a normal touching a line
or a point, two radii equal, a parabola's chord), so a slip in a kernel fails here, not somewhere else as a
tolerance.
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from incircu_plugin.core import contacts
from incircu_plugin.core.contacts import (
    CLEAR,
    QUERY_GROUP,
    SKIPPED,
    AxisPoints,
    Boundary,
    Samples,
    _group_starts,
    _per_segment,
    first_contacts,
    solve,
    vertex_contact,
)
from incircu_plugin.core.lines import ORDER_RESOLUTION, _Blocks, _distinct, _first_of_each_centre, _ordered, _with_ends
from incircu_plugin.core.tracing import closed_form
from incircu_plugin.core.tracing.spans import EDGE, FAN


def contacts_of(sample, direction, segments, scale=1.0, slide=0.0):
    """``first_contacts`` of one sample against every segment of two chains built from ``segments``."""
    chains = [np.array(segments[0], dtype=float), np.array(segments[1], dtype=float)]
    boundary = Boundary(chains)
    count = boundary.segment_count
    segment = np.arange(count)
    ones = np.ones(count)
    t, along, site = first_contacts(
        sample[0] * ones,
        sample[1] * ones,
        direction[0] * ones,
        direction[1] * ones,
        scale * ones,
        slide * ones,
        boundary,
        segment,
    )
    return t, along, site, boundary


def test_first_contacts_without_along_give_the_same_contacts_and_sites():
    # A corner's disks (scale below 1) and an edge's against a zigzag: tangencies, start and end vertices.
    zigzag = [[(-6.0, 9.0), (-2.0, 12.0), (0.0, 8.0), (3.0, 11.0), (7.0, 6.0)], [(-6.0, -5.0), (7.0, -5.0)]]
    for scale, slide in ((1.0, 0.0), (0.8, 0.6)):
        t, _along, site, boundary = contacts_of((0.0, 0.0), (0.0, 1.0), zigzag, scale, slide)
        count = boundary.segment_count
        ones = np.ones(count)
        arguments = (0.0 * ones, 0.0 * ones, 0.0 * ones, ones, scale * ones, slide * ones, boundary, np.arange(count))
        t_only, none, site_only = first_contacts(*arguments, with_along=False)
        assert none is None and np.isfinite(t).sum() >= 4
        assert t_only.tobytes() == t.tobytes() and np.array_equal(site_only, site)
        assert len(set(site[np.isfinite(t)] >= count)) == 2  # vertices and interiors among the contacts


def test_the_last_segment_of_a_chain_answers_for_its_end_vertex():
    # Disks centred (0, t) with radius t reach the end (3, 9) of the segment from (8, 12) when 9 + (9 - t)^2 = t^2.
    t, along, site, _boundary = contacts_of((0.0, 0.0), (0.0, 1.0), [[(8.0, 12.0), (3.0, 9.0)], [(-6, -5), (7, -5)]])
    assert t[0] == pytest.approx(5.0, rel=1e-15) and along[0] == pytest.approx(np.hypot(5.0, 3.0), rel=1e-15)
    assert site[0] == 2 + 1  # two segments, then the vertices: the first chain's second vertex


def test_a_disk_on_a_normal_touches_a_parallel_line_halfway():
    # Disks centred (0, t) with radius t touch y = 10 when 10 - t = t: t = 5, at x = 0, 5 from (-5, 10).
    t, along, site, _boundary = contacts_of((0.0, 0.0), (0.0, 1.0), [[(-5, 10), (5, 10)], [(-5, -10), (5, -10)]])
    assert t[0] == pytest.approx(5.0, rel=1e-15)
    assert along[0] == pytest.approx(5.0, rel=1e-15)
    assert site[0] == 0  # the segment's interior
    assert t[1] == np.inf  # the line behind the sample is never touched


def test_a_disk_touches_a_segment_end_when_the_tangent_point_is_off_the_segment():
    # y = 4 would be touched at (0, 4) with t = 2, outside [3, 10]; the vertex (3, 4) is touched when
    # 3**2 + (4 - t)**2 = t**2: t = 25 / 8.
    t, along, site, boundary = contacts_of((0.0, 0.0), (0.0, 1.0), [[(3, 4), (10, 4)], [(-5, -10), (5, -10)]])
    assert t[0] == pytest.approx(25.0 / 8.0, rel=1e-15)
    assert along[0] == 0.0
    assert site[0] == boundary.segment_count + 0  # vertex 0: the start of the first chain


def test_a_convex_corner_disk_slides_on_the_bisector():
    # A right-angle corner at the origin, bisector (1, 1)/sqrt 2: radius t sin 45, centre t (1, 1)/sqrt 2.
    # The side x = 10 is touched when 10 - t/sqrt 2 = t/sqrt 2: t = 5 sqrt 2, centre (5, 5), radius 5.
    half = math.pi / 4.0
    t, along, _site, _ = contacts_of(
        (0.0, 0.0),
        (math.sqrt(0.5), math.sqrt(0.5)),
        [[(10, -5), (10, 20)], [(-5, -10), (5, -10)]],
        scale=math.sin(half),
        slide=math.cos(half),
    )
    assert t[0] == pytest.approx(5.0 * math.sqrt(2.0), rel=1e-14)
    assert along[0] == pytest.approx(10.0, rel=1e-14)  # (10, 5) is 10 from (10, -5)


def test_a_vertex_a_hair_from_the_sample_point_is_not_touched():
    # The vertex (1e-9, 1e-18) lies on the sample's tangent line up to 1e-18: the formula would touch it at
    # t = |d|**2 / (2 d.b) = 0.5, a contact made of rounding. The segment's own line (y = 1e-18) is touched
    # at x = 0, outside the segment.
    t, _, _, _ = contacts_of((0.0, 0.0), (0.0, 1.0), [[(1e-9, 1e-18), (1.0, 1e-18)], [(-5, -10), (5, -10)]])
    assert t[0] == np.inf


def test_a_segment_starts_at_its_start_vertex_on_every_chain():
    # Chains of 3, 1 and 4 segments: segment g of chain c is the (g - offset[c])-th edge of that chain.
    chains = [np.array([(0, 0), (1, 0), (2, 1), (3, 3)]), np.array([(5, 5), (6, 5)]), np.arange(10.0).reshape(5, 2)]
    boundary = Boundary([chain.astype(float) for chain in chains])
    segment = np.arange(boundary.segment_count)
    expected_start = np.concatenate([chain[:-1] for chain in chains])
    expected_end = np.concatenate([chain[1:] for chain in chains])
    assert np.array_equal(boundary.vertex[boundary.start_vertex(segment)], expected_start)
    assert np.array_equal(boundary.start, expected_start)
    assert np.array_equal(boundary.end(segment), expected_end)


def test_grouped_candidates_are_exactly_the_segments_whose_boxes_meet_each_box():
    # Two zigzag chains, the second running backwards, with a short last run of segments (the grid holds runs
    # of segments, queried with groups of consecutive boxes): every box gets exactly the segments whose
    # bounding box meets it, each once, a box's pairs together, whatever group it was queried in.
    rng = np.random.default_rng(7)
    size = 20_002
    x = np.arange(size, dtype=float)
    chains = [
        np.stack([x, rng.uniform(0.0, 3.0, size)], axis=1),
        np.stack([x[::-1], rng.uniform(6.0, 9.0, size)], axis=1),
    ]
    boundary = Boundary(chains)
    assert boundary.segment_count % contacts.INDEX_RUN
    # Overlapping boxes along the chains, then boxes far apart, then overlapping ones again (odd count).
    centre = np.concatenate([np.linspace(100.0, 130.0, 23), rng.uniform(0.0, size, 9), np.linspace(5000.0, 5040.0, 17)])
    centre = np.stack([centre, rng.uniform(0.0, 9.0, len(centre))], axis=1)
    reach = rng.uniform(2.0, 8.0, len(centre))[:, None]
    low, high = centre - reach, centre + reach
    box, segment = boundary.candidates(low, high, None)
    # Each box's pairs consecutive: as many runs of equal boxes as boxes.
    assert np.count_nonzero(np.diff(box)) + 1 == len(np.unique(box))
    for index in range(len(centre)):
        meets = (boundary.low_x <= high[index, 0]) & (boundary.high_x >= low[index, 0])
        meets &= (boundary.low_y <= high[index, 1]) & (boundary.high_y >= low[index, 1])
        alone = boundary.candidates(low[index : index + 1], high[index : index + 1], None)[1]
        assert np.array_equal(np.sort(alone), np.flatnonzero(meets))
        assert np.array_equal(np.sort(segment[box == index]), np.flatnonzero(meets))


def test_a_box_grid_lists_every_meeting_pair_once_whatever_the_boxes():
    # Boxes on integer corners whose largest sides (points, thin boxes, squares, four long ones) average 2: the
    # cells, of GRID_CELL_SIDE times that side or a power of two times it from the lowest corner 0, have
    # borders on integer coordinates, where many corners of boxes and query boxes lie.
    rng = np.random.default_rng(3)
    side = np.array([[0.0, 0.0]] * 100 + [[3.0, 0.0]] * 100 + [[2.0, 2.0]] * 96 + [[50, 1], [1, 40], [10, 10], [8, 0]])
    low = rng.integers(0, 40, (len(side), 2)).astype(float)
    low[0] = 0.0
    high = low + side
    grid = contacts.BoxGrid(low, high)
    assert np.array_equal(grid.origin, [0.0, 0.0]) and grid.size / (2.0 * contacts.GRID_CELL_SIDE) in (1, 2, 4)
    assert np.mean(low % grid.size == 0.0) > 0.1
    # Query boxes on integer corners (points among them), and a huge one, one across the grid, one outside it.
    query_low = rng.integers(-5, 95, (300, 2)).astype(float)
    query_high = query_low + rng.integers(0, 5, (300, 2))
    query_low = np.concatenate([query_low, [[-1e300, -1e300], [-50.0, 10.0], [200.0, 10.0]]])
    query_high = np.concatenate([query_high, [[1e300, 1e300], [500.0, 12.0], [220.0, 12.0]]])
    query, box = grid.query(query_low, query_high)
    assert np.all(np.diff(query) >= 0)
    meets = (low[:, 0] <= query_high[:, 0, None]) & (high[:, 0] >= query_low[:, 0, None])
    meets &= (low[:, 1] <= query_high[:, 1, None]) & (high[:, 1] >= query_low[:, 1, None])
    assert np.array_equal(np.sort(query * len(low) + box), np.flatnonzero(meets))
    assert np.all(meets[-3]) and np.any(meets[-2]) and not np.any(meets[-1])
    assert len(grid.query(query_low[:0], query_high[:0])[0]) == 0


def test_a_box_grid_of_no_boxes_or_of_one_point_finds_what_it_holds():
    empty = contacts.BoxGrid(np.zeros((0, 2)), np.zeros((0, 2)))
    assert [len(part) for part in empty.query(np.zeros((3, 2)), np.ones((3, 2)))] == [0, 0]
    point = contacts.BoxGrid(np.full((1, 2), 5.0), np.full((1, 2), 5.0))
    query, box = point.query(np.array([[0.0, 0.0], [6.0, 6.0]]), np.array([[5.0, 5.0], [7.0, 7.0]]))
    # A one-cell grid: both query boxes share its cell, only the first (with a corner on the point) meets it.
    assert query.tolist() == [0] and box.tolist() == [0]


def test_query_groups_are_runs_of_meeting_boxes_cut_every_query_group_boxes():
    # Ten unit boxes a half apart (each meets the one before), one far away, then three meeting again.
    x = np.concatenate([0.5 * np.arange(10), [100.0], 200.0 + 0.5 * np.arange(3)])
    low = np.stack([x, np.zeros(len(x))], axis=1)
    starts = _group_starts(low, low + 1.0)
    expected = sorted({*range(0, 10, QUERY_GROUP), 10, 11})
    assert starts.tolist() == expected


def test_the_corner_free_vertex_contact_equals_the_general_formula():
    # Without a convex corner (scale 1, slide 0) both factors of the discriminant are x, so t = |d|**2 / (2 x);
    # the general branch (forced by one corner sample) computes |d|**2 / (sqrt(x * x) + x): the same float.
    rng = np.random.default_rng(7)
    count = 2000
    offset, height = rng.normal(scale=50.0, size=(2, count))
    angle = rng.uniform(0.0, 2.0 * math.pi, count)
    b_along, b_across = np.cos(angle), np.sin(angle)
    fast = vertex_contact(offset, height, b_along, b_across, np.ones(count), np.zeros(count))
    scale, slide = np.ones(count + 1), np.zeros(count + 1)
    scale[-1], slide[-1] = math.sin(0.5), math.cos(0.5)
    general = vertex_contact(*(np.append(x, 1.0) for x in (offset, height, b_along, b_across)), scale, slide)
    assert np.isfinite(fast).sum() > count // 4
    assert np.array_equal(fast, general[:-1])


def crossing(kind, u0, u1, terms0, terms1):
    spans = SimpleNamespace(kind=np.array([kind]))
    intervals = SimpleNamespace(span=np.array([0]), u0=np.array([u0]), u1=np.array([u1]))
    as_arrays = [tuple(np.array([value], dtype=float) for value in terms) for terms in (terms0, terms1)]
    u, found, at_end = closed_form.crossing(spans, intervals, *as_arrays)
    return u[0], found[0], at_end[0]


def test_two_lines_cross_where_their_radii_are_equal_on_an_edge():
    # Along the x axis with normal (0, 1): the line x = 0 is touched at r = u, the line y = 10 at r = 5.
    u, found, _ = crossing(EDGE, 0.0, 20.0, (0.0, 1.0, 0.0), (5.0, 0.0, 0.0))
    assert found and u == pytest.approx(5.0, rel=1e-15)


def test_a_vertex_on_a_line_meets_it_in_a_double_root():
    # The line y = 2 is touched at r = 1; the vertex (3, 2) at r = ((u - 3)**2 + 4) / 4, equal only at u = 3
    # (the contact slides off the segment's end onto its vertex).
    u, found, _ = crossing(EDGE, 0.0, 10.0, (1.0, 0.0, 0.0), (13.0 / 4.0, -6.0 / 4.0, 1.0 / 4.0))
    assert found and u == pytest.approx(3.0, abs=1e-7)


def test_two_lines_cross_on_a_fan_at_the_bisecting_direction():
    # Lines at distance 2 in directions 0 and pi/2 from the fan's vertex: 1/r = (1 - cos u) / 2 and
    # (1 - sin u) / 2, equal at u = pi / 4.
    u, found, _ = crossing(FAN, 0.0, math.pi / 2.0, (0.5, -0.5, 0.0), (0.5, 0.0, -0.5))
    assert found and u == pytest.approx(math.pi / 4.0, rel=1e-14)


def test_a_crossing_at_an_end_is_reported_as_that_end():
    u, found, at_end = crossing(EDGE, 5.0, 20.0, (0.0, 1.0, 0.0), (5.0, 0.0, 0.0))
    assert not found and at_end == 0 and u == pytest.approx(12.5)


def test_parabola_stations_lie_on_the_parabola_with_chords_within_the_tolerance():
    # Focus (0, 1), directrix the x axis: y = (x**2 + 1) / 2. From x = -3 to x = 4, apex x = 0 included.
    tolerance = 1e-3
    ends = np.array([[[-3.0, 5.0], [4.0, 8.5]]])
    owner, centre, radius = closed_form.parabola_stations(
        np.array([[0.0, 1.0]]), np.array([[0.0, 0.0]]), np.array([[1.0, 0.0]]), ends, tolerance
    )
    assert np.all(owner == 0)
    x, y = centre.T
    assert np.abs(y - (x * x + 1.0) / 2.0).max() <= 1e-13
    assert np.abs(radius - y).max() <= 1e-13
    assert np.min(np.abs(x)) == 0.0
    stations = np.sort(np.concatenate([[-3.0, 4.0], x]))
    dense = np.linspace(-3.0, 4.0, 200_001)
    chord = np.interp(dense, stations, (stations**2 + 1.0) / 2.0)
    # The distance from the arc to a chord is the vertical gap times the cosine of the chord's slope.
    slope = np.interp(dense, stations[:-1], np.diff((stations**2 + 1.0) / 2.0) / np.diff(stations))
    assert np.max((chord - (dense**2 + 1.0) / 2.0) / np.sqrt(1.0 + slope**2)) <= tolerance * (1.0 + 1e-9)
    # Not wastefully many: uniform chords of the largest admissible length at the apex, 2 sqrt(2 tolerance),
    # would need 7 / (2 sqrt(2e-3)) ~ 78; the stations adapt to the flatter flanks.
    assert len(x) < 7.0 / (2.0 * math.sqrt(2.0 * tolerance))


def test_distinct_keeps_the_ends_and_drops_points_within_tolerance_of_their_predecessor():
    points = np.array([[0.0, 0.0], [0.0, 5e-10], [1.0, 0.0], [1.0, 5e-10]])
    # p1 is within 1e-9 of p0: dropped; p3 is the last point: kept, so p2 (within 1e-9 of it) is dropped.
    assert _distinct(points, 1e-9, _Blocks([4])).tolist() == [True, False, False, True]


def test_first_of_each_centre_keeps_a_junction_at_its_first_place():
    centres = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1e-15], [2.0, 0.0]])
    assert _first_of_each_centre(centres, np.arange(4), 1e-9, _Blocks([4])).tolist() == [0, 1, 3]
    # The cells sort otherwise than the indices (1, 3, then 0 and 2): the kept indices still ascend.
    centres = np.array([[5.0, 0.0], [1.0, 0.0], [5.0, 1e-15], [3.0, 0.0]])
    assert _first_of_each_centre(centres, np.arange(4), 1e-9, _Blocks([4])).tolist() == [0, 1, 3]


def test_first_of_each_centre_counts_places_in_the_order_and_leaves_the_centres_alone():
    centres = np.array([[5.0, 0.0], [1.0, 0.0], [5.0, 1e-15], [3.0, 0.0]])
    before = centres.copy()
    # In the order 3, 2, 1, 0 the junction (points 2 and 0) is first met at place 1.
    assert _first_of_each_centre(centres, np.array([3, 2, 1, 0]), 1e-9, _Blocks([4])).tolist() == [0, 1, 2]
    assert np.array_equal(centres, before)


def test_boundary_segments_start_and_end_at_their_chains_vertices():
    chains = [
        np.array([[0.0, 0.0], [1.0, 0.0], [3.0, 0.0]]),
        np.array([[0.0, 2.0], [2.0, 2.0], [2.0, 5.0], [1.0, 5.0]]),
    ]
    boundary = Boundary(chains)
    # The chains' vertex offsets are 0 and 3: segment 2, the second chain's first, runs from vertex 3 to vertex 4.
    assert _per_segment(np.arange(7), np.array([0, 3]), np.array([2, 3])).tolist() == [0, 1, 3, 4, 5]
    starts = np.concatenate([chain[:-1] for chain in chains])
    ends = np.concatenate([chain[1:] for chain in chains])
    assert np.array_equal(boundary.start, starts)
    assert np.array_equal(boundary.unit * boundary.length[:, None], ends - starts)
    assert boundary.segment_position.tolist() == [0.0, 1.0, 0.0, 2.0, 5.0]
    assert boundary.segment_end_position.tolist() == [1.0, 3.0, 2.0, 5.0, 6.0]
    assert boundary.start_site.tolist() == [5 + v for v in (0, 1, 3, 4, 5)]


def test_subset_by_a_mask_is_subset_by_its_indices():
    pairs, values = np.arange(20.0).reshape(10, 2), np.arange(10.0)
    points = AxisPoints(pairs, values, pairs + 100.0, pairs + 200.0, values + 10.0, values + 20.0)
    mask = np.arange(10) % 3 == 1
    by_mask, by_index = points.subset(mask), points.subset(np.flatnonzero(mask))
    for name in ("centre", "radius", "foot_a", "foot_b", "position_a", "position_b"):
        assert getattr(by_mask, name).tolist() == getattr(by_index, name).tolist()
        assert getattr(by_mask, name).shape == getattr(by_index, name).shape
    with pytest.raises(IndexError):
        points.subset(mask[:-1])


def test_with_ends_gathers_the_ordered_values_between_the_two_ends():
    order = np.array([2, 0, 1])
    centres = np.array([[0.0, 1.0], [2.0, 3.0], [4.0, 5.0]])
    ends = np.array([[-1.0, -1.0], [9.0, 9.0]])
    assert _with_ends(centres, order, [ends], _Blocks([5])).tolist() == [[-1, -1], [4, 5], [0, 1], [2, 3], [9, 9]]
    assert _with_ends(np.array([7.0, 8.0, 9.0]), order, [np.array([0.0, 1.0])], _Blocks([5])).tolist() == [
        0,
        9,
        7,
        8,
        1,
    ]


def test_order_along_the_axis_breaks_ties_of_the_feet_by_travel_then_radius():
    # Points whose feet lie at the same arc lengths (ties of the first key) must come in the order of the
    # full three-key sort: across the direction of travel, then by radius; drawn with many ties on purpose.
    rng = np.random.default_rng(7)
    count = 2000
    position_a = rng.integers(0, 40, count).astype(float)
    position_b = rng.integers(0, 3, count).astype(float)
    foot_a = np.stack([position_a, np.zeros(count)], axis=1)
    foot_b = np.stack([position_a, np.full(count, 2.0)], axis=1)
    centre = np.stack([position_a, rng.integers(0, 3, count).astype(float)], axis=1)
    radius = rng.integers(1, 4, count).astype(float)
    points = AxisPoints(centre, radius, foot_a, foot_b, position_a, position_b)
    lengths, side = (50.0, 50.0), 1.0
    order = _ordered(points, side, lengths, 1e-12, _Blocks([count]))
    # The three keys by their definitions: the feet's relative arc lengths, the centre's component along
    # the direction of travel side * (across_y, -across_x) with across = foot_b - foot_a = (0, 2), and the
    # radius, growing before the middle of the axis and shrinking after it.
    raw = position_a / lengths[0] + position_b / lengths[1]
    along = np.round(raw / ORDER_RESOLUTION)
    crossing = side * centre[:, 0] * 2.0
    growing = np.where(raw < 1.0, radius, -radius)
    assert order.tolist() == np.lexsort((growing, crossing, along)).tolist()
    assert sorted(order.tolist()) == list(range(count))


def straight_features(features, samples_each):
    """``samples_each`` samples spread along the lower bank of ``features`` straight channels (banks 4 apart, 10 units
    long, stacked 10 apart: pairs of chains ``2k``, ``2k + 1``), each sample's own segment its bank's only."""
    chains = []
    for k in range(features):
        chains += [
            np.array([[0.0, 10.0 * k], [10.0, 10.0 * k]]),
            np.array([[10.0, 10.0 * k + 4.0], [0.0, 10.0 * k + 4.0]]),
        ]
    along = np.tile(np.linspace(0.05, 9.95, samples_each), features)
    chain = np.repeat(2 * np.arange(features), samples_each)
    own = chain.copy()
    samples = Samples(
        chain,
        np.stack([along, 5.0 * chain], axis=1),
        np.tile([0.0, 1.0], (len(along), 1)),
        np.ones(len(along)),
        along,
        np.zeros(len(along)),
        own,
        own,
    )
    return samples, Boundary(chains)


@pytest.mark.parametrize(("features", "levels"), [(1, 3), (8, 1), (80, 1)])
def test_coarse_to_fine_levels_follow_the_samples_per_feature(monkeypatch, features, levels):
    # 800 samples in all: one feature gets three levels (strides 64, 8, 1), eight features of 100 samples and
    # eighty of 10 one; every level settles its samples exactly as one solve of all.
    samples, boundary = straight_features(features, 800 // features)
    index = np.arange(800)
    expected = solve(samples, index, boundary, np.full(800, 2.5), 30.0, 1e-9, points=True)
    calls = []
    solved = contacts.solve
    monkeypatch.setattr(
        contacts, "solve", lambda samples, index, *rest: calls.append(len(index)) or solved(samples, index, *rest)
    )
    result = contacts.solve_coarse_to_fine(samples, index, boundary, 2.5, 30.0, 1e-9, lambda done: None, points=True)
    assert len(calls) == levels and sum(calls) == 800
    assert np.all(result[0] == 2.0)
    for got, wanted in zip(result, expected, strict=True):
        assert np.array_equal(got, wanted)


def solved_on_straight_banks():
    """:func:`solve` of samples every half unit along a straight bank, facing a parallel bank 4 units away that
    runs backwards in unit segments; each disk touches the far bank at ``t = 2`` above its sample, at an
    integer x exactly where two segments meet (both report the same ``t``: an exact tie)."""
    x = np.arange(41.0)
    chains = [np.stack([x, np.zeros(41)], axis=1), np.stack([x[::-1], np.full(41, 4.0)], axis=1)]
    along = np.arange(1.0, 79.0) / 2.0
    count = len(along)
    # A sample at a vertex has both its segments as its own.
    last_own = np.minimum(np.floor(along), 39).astype(int)
    first_own = np.where(along == np.floor(along), last_own - 1, last_own)
    samples = Samples(
        np.zeros(count, dtype=int),
        np.stack([along, np.zeros(count)], axis=1),
        np.tile([0.0, 1.0], (count, 1)),
        np.ones(count),
        along,
        np.zeros(count),
        first_own,
        last_own,
    )
    return along, solve(samples, np.arange(count), Boundary(chains), np.ones(count), 10.0, 1e-9, points=True)


def test_ties_go_to_the_lowest_site_whatever_the_order_of_the_candidates(monkeypatch):
    along, expected = solved_on_straight_banks()
    contact_t, status, contact, position, site = expected
    assert np.all(contact_t == 2.0) and np.all(status == CLEAR)
    assert np.array_equal(contact, np.stack([along, np.full(len(along), 4.0)], axis=1))
    assert np.array_equal(position, 40.0 - along)
    # Far segment k (site 40 + k) runs from x = 40 - k to 39 - k: the lower of two sites at a tie.
    assert np.array_equal(site, 79 - np.floor(along).astype(int))
    listed = Boundary.candidates

    def reversed_candidates(boundary, low, high, chain=None):
        box, segment = listed(boundary, low, high)
        order = np.lexsort((-np.arange(len(box)), box))
        return box[order], segment[order]

    # The index of single segments, the index of runs, every pair tested, and each box's pairs reversed.
    for all_pairs, index_run, listing in (
        (0, 1, listed),
        (0, contacts.INDEX_RUN, listed),
        (1 << 62, contacts.INDEX_RUN, listed),
        (1 << 62, contacts.INDEX_RUN, reversed_candidates),
    ):
        monkeypatch.setattr(contacts, "ALL_PAIRS", all_pairs)
        monkeypatch.setattr(contacts, "INDEX_RUN", index_run)
        monkeypatch.setattr(Boundary, "candidates", listing)
        for result, wanted in zip(solved_on_straight_banks()[1], expected, strict=True):
            assert result.tobytes() == wanted.tobytes(), (all_pairs, index_run, listing.__name__)


def solved_alone(chain_a, chain_b, point, direction, own, scale=1.0, slide=0.0):
    """:func:`solve` of one sample of ``chain_a`` (a disk family from ``point`` along the unit ``direction``,
    own segments ``own``), trial radius 10 and a smallest contact of 1e-10: (t, status, contact, site)."""
    samples = Samples(
        np.zeros(1, dtype=int),
        np.array([point], dtype=float),
        np.array([direction], dtype=float),
        np.array([scale]),
        np.zeros(1),
        np.array([slide]),
        np.array([own[0]]),
        np.array([own[1]]),
    )
    boundary = Boundary([np.array(chain_a, dtype=float), np.array(chain_b, dtype=float)])
    contact_t, status, contact, _, site = solve(
        samples, np.arange(1), boundary, np.full(1, 10.0), 300.0, 1e-10, points=True
    )
    return contact_t[0], status[0], contact[0], site[0]


@pytest.mark.parametrize("hair", [0.0, 1e-13, 1e-12, 1e-11])
def test_own_segments_never_count_even_when_rounding_puts_the_sample_inside_one(hair):
    # A nearly straight reflex vertex at (50, 0): the next segment turns 0.003 rad away from the region. A
    # sample computed at the vertex with a rounding error ``hair`` towards the region lies on the region side
    # of that segment's line, so the segment itself would be touched at t = hair / (1 - cos 0.003), about
    # 2e-7 for hair = 1e-12: above the smallest contact, yet only rounding. It is the sample's own segment,
    # so the disk grows to the far bank 20 away.
    t, status, contact, _ = solved_alone(
        [[0.0, 0.0], [50.0, 0.0], [100.0, -0.15]], [[100.0, 20.0], [0.0, 20.0]], (50.0, hair), (0.0, 1.0), (0, 1)
    )
    assert status == CLEAR
    assert t == pytest.approx(10.0 - hair / 2.0, rel=1e-12)
    np.testing.assert_allclose(contact, [50.0, 20.0], atol=1e-9)


@pytest.mark.parametrize("offset", [0.0, 1e3, 1e4, 1e5])
def test_the_other_chains_copy_of_a_split_point_is_never_touched_from_the_own_end_segment(offset):
    # A channel 10 wide split at the middle (0, 5) of its straight left cap, turned by 0.3 rad and moved by
    # ``offset`` (a joint tracing's frame holds coordinates tens of extents from its origin). A sample ``hair``
    # below the split point on the cap (chain a's first segment) grows its disk into the channel: it first
    # touches the bottom bank, at t = 5 - hair. Chain b's copy of the split point lies on the sample's tangent
    # line (the cap), so its contact t = hair**2 / (2 x) has a height x made of the rounding of the coordinates:
    # at these offsets it came out anywhere from 1e-5 to 3, and a joint tracing lost features to it.
    turn = np.array([[math.cos(0.3), -math.sin(0.3)], [math.sin(0.3), math.cos(0.3)]])
    shift = offset * np.array([1.0, 0.7])
    chain_a = np.array([[0.0, 5.0], [0.0, 0.0], [100.0, 0.0], [100.0, 5.0]]) @ turn.T + shift
    chain_b = np.array([[0.0, 5.0], [0.0, 10.0], [100.0, 10.0], [100.0, 5.0]]) @ turn.T + shift
    direction = turn @ np.array([1.0, 0.0])
    cap = (chain_a[1] - chain_a[0]) / np.hypot(*(chain_a[1] - chain_a[0]))
    split_site = Boundary([chain_a, chain_b]).segment_count + len(chain_a)  # chain b's first vertex
    for hair in 10.0 ** np.arange(-12.0, -3.0, 0.25):
        t, _, _, site = solved_alone(chain_a, chain_b, chain_a[0] + hair * cap, direction, (0, 0))
        assert site != split_site, hair
        assert t == pytest.approx(5.0 - hair, rel=1e-9), hair


def test_a_convex_corners_disk_slides_past_the_far_end_of_a_short_own_segment():
    # A valley of half angle 75 degrees at the origin: the disk slides up the bisector with radius
    # t cos(15 deg), touching both edges t sin(15 deg) from the corner. The right edge is 1 long and is followed
    # by a horizontal segment, so the disk passes over that edge's far end at t = 1 / sin(15 deg) (a double
    # root: it touches there, never crosses) and first touches the far bank y = 20 at t = 20 / (1 + cos 15 deg).
    angle = math.radians(15.0)
    cos, sin = math.cos(angle), math.sin(angle)
    t, status, contact, site = solved_alone(
        [[-30.0 * cos, 30.0 * sin], [0.0, 0.0], [cos, sin], [30.0, sin]],
        [[30.0, 20.0], [-30.0, 20.0]],
        (0.0, 0.0),
        (0.0, 1.0),
        (0, 1),
        scale=cos,
        slide=sin,
    )
    assert status == CLEAR
    assert t == pytest.approx(20.0 / (1.0 + cos), rel=1e-12)
    np.testing.assert_allclose(contact, [0.0, 20.0], atol=1e-12)
    assert site == 3  # the far bank's only segment (segments 0-2 are the valley's)


@pytest.mark.parametrize("reverse", [False, True])
def test_a_disk_touching_its_own_chain_twice_at_once_reports_the_lower_site(monkeypatch, reverse):
    # A U of width 10: the disk from the middle of its floor (segment 1) touches both walls, segments 0 and 2,
    # at t = 5: the sample is skipped and its own-chain site is the lower one, whatever the listing order.
    listed = Boundary.candidates

    def reversed_candidates(boundary, low, high, chain=None):
        box, segment = listed(boundary, low, high)
        order = np.lexsort((-np.arange(len(box)), box))
        return box[order], segment[order]

    if reverse:
        monkeypatch.setattr(Boundary, "candidates", reversed_candidates)
    t, status, _, site = solved_alone(
        [[-5.0, 10.0], [-5.0, 0.0], [5.0, 0.0], [5.0, 10.0]],
        [[5.0, 40.0], [-5.0, 40.0]],
        (0.0, 0.0),
        (0.0, 1.0),
        (1, 1),
    )
    assert status == SKIPPED
    assert t == 5.0
    assert site == 0


def solved_between_dense_banks(small_trials=False):
    """``solve`` for samples at the inner vertices of the lower of two banks 20 apart with a vertex every 0.1:
    a disk of the trial radius 10 meets about 400 segments (with ``small_trials``, every third sample's trial
    radius is 1)."""
    x = np.linspace(0.0, 100.0, 1001)
    chains = [np.stack([x, np.zeros(1001)], axis=1), np.stack([x[::-1], np.full(1001, 20.0)], axis=1)]
    count = 999
    vertex = np.arange(1, 1000)
    samples = Samples(
        np.zeros(count, dtype=int),
        np.stack([x[vertex], np.zeros(count)], axis=1),
        np.tile([0.0, 1.0], (count, 1)),
        np.ones(count),
        x[vertex],
        np.zeros(count),
        vertex - 1,
        vertex,
    )
    trial = np.full(count, 10.0)
    if small_trials:
        trial[::3] = 1.0
    return solve(samples, np.arange(count), Boundary(chains), trial, 30.0, 1e-9, points=True)


def test_solve_blocks_hold_about_solve_pairs_pairs_and_change_no_result(monkeypatch):
    rounds = []
    solve_round = contacts._solve_round

    def recorded(samples, sample, *arguments):
        best, pairs = solve_round(samples, sample, *arguments)
        rounds.append((sample, pairs))
        return best, pairs

    monkeypatch.setattr(contacts, "_solve_round", recorded)
    contact_t, status, contact, position, _ = expected = solved_between_dense_banks()
    assert np.all(status == CLEAR) and np.allclose(contact_t, 10.0, rtol=1e-12)
    x = np.linspace(0.0, 100.0, 1001)[1:-1]
    np.testing.assert_allclose(contact, np.stack([x, np.full(999, 20.0)], axis=1), atol=1e-12)
    np.testing.assert_allclose(position, 100.0 - x, atol=1e-12)
    # About 400 pairs per sample: blocks of 4096 samples would hold 400,000 pairs.
    pairs_per_sample = max(pairs / len(sample) for sample, pairs in rounds)
    assert 300 < pairs_per_sample < 500
    assert max(pairs for _, pairs in rounds) <= 2 * contacts.SOLVE_PAIRS
    # From a trial ten times too small, every third sample takes four more rounds (radius 1, 2, 4, 8; 16 settles
    # it), shared with the fresh samples of the blocks after its own: only the last block's slow samples have
    # rounds of their own, and nothing else changes.
    rounds.clear()
    for result, wanted in zip(solved_between_dense_banks(small_trials=True), expected, strict=True):
        assert result.tobytes() == wanted.tobytes()
    assert sum(len(sample) for sample, _ in rounds) == 999 + 4 * 333
    assert len(rounds) > 8 and sum(np.all(sample % 3 == 0) for sample, _ in rounds) == 4
    for block, budget in ((1, 1 << 62), (7, 1 << 62), (1 << 20, 1 << 62), (4096, 1)):
        monkeypatch.setattr(contacts, "SOLVE_BLOCK", block)
        monkeypatch.setattr(contacts, "SOLVE_PAIRS", budget)
        for result, wanted in zip(solved_between_dense_banks(), expected, strict=True):
            assert result.tobytes() == wanted.tobytes(), (block, budget)


def test_without_points_the_solvers_keep_no_contact_point_and_the_same_contacts():
    # solve, solve_coarse_to_fine and solve_in_chunks: contact and position None, the rest as with the points.
    samples, boundary = straight_features(8, 100)
    index = np.arange(800)
    for solver, arguments in (
        (solve, (np.full(800, 2.5), 30.0, 1e-9)),
        (contacts.solve_coarse_to_fine, (2.5, 30.0, 1e-9, lambda done: None)),
        (contacts.solve_in_chunks, (2.5, 30.0, 1e-9, lambda done: None)),
    ):
        with_points = solver(samples, index, boundary, *arguments, points=True)
        without = solver(samples, index, boundary, *arguments)
        assert without[2] is None and without[3] is None, solver.__name__
        assert with_points[2].shape == (800, 2) and np.all(with_points[0] == 2.0)
        for kept in (0, 1, 4):
            assert without[kept].tobytes() == with_points[kept].tobytes(), (solver.__name__, kept)
        assert without[4].dtype == np.int32
