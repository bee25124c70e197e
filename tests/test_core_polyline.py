"""Direct tests of the shared polyline helpers (incircu_plugin/core/polyline.py), hand-computed values."""

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString

from incircu_plugin.core import polyline as polyline_module
from incircu_plugin.core.errors import InvalidGeometryError
from incircu_plugin.core.polyline import (
    CLUSTER_POINTS,
    IndexedPolyline,
    as_coordinates,
    cumulative_lengths,
    local_origin,
    nearest_entries,
    nearest_on_polyline,
    points_at,
    turn_angles,
    typical_width,
)

# An L: 3-4-5 segment, then 12 units straight up.
L_PATH = np.array([[0.0, 0.0], [3.0, 4.0], [3.0, 16.0]])


def test_cumulative_lengths_of_an_l():
    assert cumulative_lengths(L_PATH).tolist() == [0.0, 5.0, 17.0]


def test_points_at_interpolates_inside_segments_and_clips_outside():
    cumulative = cumulative_lengths(L_PATH)
    points = points_at(L_PATH, cumulative, np.array([-1.0, 2.5, 5.0, 11.0, 40.0]))
    np.testing.assert_allclose(points, [[0, 0], [1.5, 2.0], [3, 4], [3, 10], [3, 16]], atol=1e-15)


def test_points_at_interpolates_extra_columns_the_same_way():
    values = np.column_stack([L_PATH, [0.0, 10.0, 22.0]])
    point = points_at(values, cumulative_lengths(L_PATH), 11.0)
    np.testing.assert_allclose(point, [3.0, 10.0, 16.0])


def test_points_at_skips_zero_length_segments():
    path = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 0.0], [2.0, 2.0]])
    np.testing.assert_allclose(points_at(path, cumulative_lengths(path), [2.0, 3.0]), [[2, 0], [2, 1]])


def test_nearest_on_polyline_hand_computed():
    distance, arc_length, foot = nearest_on_polyline(L_PATH, np.array([[3.0, 0.0], [5.0, 12.0], [0.0, 20.0]]))
    # (3, 0) projects onto the 3-4-5 segment at 9/25 of it: foot (1.08, 1.44), distance 12/5.
    np.testing.assert_allclose(foot, [[1.08, 1.44], [3.0, 12.0], [3.0, 16.0]], atol=1e-12)
    np.testing.assert_allclose(distance, [2.4, 2.0, 5.0], atol=1e-12)
    np.testing.assert_allclose(arc_length, [1.8, 13.0, 17.0], atol=1e-12)


def test_nearest_on_polyline_agrees_with_geos_on_a_random_zigzag():
    rng = np.random.default_rng(7)
    path = np.cumsum(rng.normal(size=(200, 2)), axis=0)
    points = rng.uniform(path.min(axis=0), path.max(axis=0), size=(500, 2))
    distance, arc_length, foot = nearest_on_polyline(path, points)
    line = LineString(path)
    np.testing.assert_allclose(distance, shapely.distance(shapely.points(points), line), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(np.hypot(*(foot - points).T), distance, rtol=1e-12)
    np.testing.assert_allclose(
        shapely.get_coordinates(shapely.line_interpolate_point(line, arc_length)), foot, atol=1e-9
    )


@pytest.mark.parametrize("spread", [0.01, 1.0, 5.0])
def test_a_cluster_of_points_gets_the_same_nearest_points_as_one_by_one(spread):
    # Clusters are answered from the segments near them (one index query); the answer is GEOS's distance.
    rng = np.random.default_rng(11)
    path = np.cumsum(rng.normal(size=(400, 2)), axis=0)
    polyline = IndexedPolyline(path)
    line = LineString(path)
    for centre in path[rng.integers(0, len(path), 8)] + rng.normal(size=(8, 2)):
        points = centre + rng.normal(size=(4 * CLUSTER_POINTS, 2)) * spread
        assert polyline._segments_near(points) is not None
        distance, arc_length, foot = polyline.nearest(points)
        expected = shapely.distance(shapely.points(points), line)
        np.testing.assert_allclose(distance, expected, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(np.hypot(*(foot - points).T), distance, rtol=1e-12)
        along = shapely.get_coordinates(shapely.line_interpolate_point(line, arc_length))
        np.testing.assert_allclose(along, foot, atol=1e-9)


@pytest.mark.parametrize("spread", [0.01, 1.0, 5.0, 50.0])
def test_closest_is_the_first_smallest_distance_of_nearest(spread):
    # closest measures only the points a probe's bound lets come near; its answer must be nearest's, bit for bit.
    rng = np.random.default_rng(5)
    path = np.cumsum(rng.normal(size=(300, 2)), axis=0)
    polyline = IndexedPolyline(path)
    for count in (3, CLUSTER_POINTS, 5 * CLUSTER_POINTS + 3):
        for centre in path[rng.integers(0, len(path), 6)] + rng.normal(size=(6, 2)):
            # Points along a closed curve, as the slit candidates along an island's outline.
            angle = np.sort(rng.uniform(0.0, 2.0 * np.pi, count))
            points = centre + spread * np.column_stack([np.cos(angle), 0.4 * np.sin(angle)])
            distance, arc_length, foot = polyline.nearest(points)
            index, closest_distance, closest_arc_length, closest_foot = polyline.closest(points)
            assert index == int(np.argmin(distance))
            assert (closest_distance, closest_arc_length) == (distance[index], arc_length[index])
            assert closest_foot.tolist() == foot[index].tolist()


def test_closest_without_a_cluster_and_on_one_vertex(monkeypatch):
    # Too many (point, segment) pairs for a cluster: every point is measured through the index.
    monkeypatch.setattr(polyline_module, "CLUSTER_PAIRS", 1)
    rng = np.random.default_rng(8)
    path = np.cumsum(rng.normal(size=(50, 2)), axis=0)
    polyline = IndexedPolyline(path)
    points = rng.normal(size=(2 * CLUSTER_POINTS, 2)) * 5.0
    assert polyline._segments_near(points) is None
    distance, arc_length, foot = polyline.nearest(points)
    np.testing.assert_allclose(distance, shapely.distance(shapely.points(points), LineString(path)), rtol=1e-12)
    index, closest_distance, closest_arc_length, closest_foot = polyline.closest(points)
    assert (index, closest_distance, closest_arc_length) == (
        int(np.argmin(distance)),
        distance.min(),
        arc_length[index],
    )
    assert closest_foot.tolist() == foot[index].tolist()
    # A polyline of one vertex: its vertex is every point's foot.
    point_line = IndexedPolyline(np.array([[1.0, 2.0]]))
    index, closest_distance, closest_arc_length, closest_foot = point_line.closest(points)
    assert index == int(np.argmin(np.hypot(*(points - [1.0, 2.0]).T)))
    assert closest_arc_length == 0.0 and closest_foot.tolist() == [1.0, 2.0]


def test_nearest_on_a_single_point():
    distance, arc_length, foot = nearest_on_polyline(np.array([[1.0, 1.0]]), np.array([[4.0, 5.0]]))
    assert distance.tolist() == [5.0] and arc_length.tolist() == [0.0] and foot.tolist() == [[1.0, 1.0]]


def test_turn_angles_signs_and_ring():
    zigzag = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 1.0]])
    np.testing.assert_allclose(np.degrees(turn_angles(zigzag)), [90.0, -90.0])
    triangle = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])
    np.testing.assert_allclose(np.degrees(turn_angles(triangle, closed=True)), [90.0, 135.0, 135.0])
    assert turn_angles(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]])).tolist() == [0.0]


def test_local_origin_is_the_bounding_box_centre():
    assert local_origin(np.array([[10.0, -4.0]]), np.array([[20.0, 6.0], [12.0, 0.0]])).tolist() == [15.0, 1.0]


def test_typical_width_of_banks_and_of_a_polygon():
    assert typical_width(8.0 * 100.0, 100.0) == 8.0
    assert typical_width(1.0, 0.0) == 0.0
    # Rectangle 90 x 10: area 900, half perimeter 100.
    assert typical_width(900.0, 100.0) == 9.0


def test_as_coordinates_messages():
    with pytest.raises(InvalidGeometryError, match=r"^The bank is empty\.$"):
        as_coordinates(LineString(), "bank")
    with pytest.raises(InvalidGeometryError, match=r"^The bank must be a single line, not a Point\.$"):
        as_coordinates(shapely.Point(0, 0), "bank")
    with pytest.raises(InvalidGeometryError, match=r"^The bank must be an \(n, 2\) coordinate array\.$"):
        as_coordinates([1.0, 2.0], "bank")
    source = np.array([[0.0, 0.0, 1.0], [1.0, 1.0, 1.0]])
    coordinates = as_coordinates(source)
    coordinates[0, 0] = 9.0
    assert source[0, 0] == 0.0 and coordinates.shape == (2, 2)


def test_counterclockwise_without_orient_polygons_equals_shapely_2_1(monkeypatch):
    # Shapely 2.0 has no orient_polygons: the per-polygon fallback must give the same polygons (on Shapely 2.1
    # and later, orient itself calls orient_polygons, so only the choice is switched here).
    rng = np.random.default_rng(3)
    polygons = np.empty(30, dtype=object)
    for number in range(30):
        outline = shapely.Point(rng.normal(size=2) * 100).buffer(10.0 + number, quad_segs=3)
        hole = shapely.Point(outline.centroid).buffer(2.0, quad_segs=2)
        polygon = outline.difference(hole) if number % 2 else outline
        polygons[number] = shapely.reverse(polygon) if number % 3 else polygon
    expected = shapely.orient_polygons(polygons, exterior_cw=False)
    monkeypatch.setattr(polyline_module, "HAS_ORIENT_POLYGONS", False)
    fallback = polyline_module.counterclockwise(polygons)
    assert all(shapely.equals_exact(a, b, tolerance=0.0) for a, b in zip(fallback, expected))
    assert all(polygon.exterior.is_ccw for polygon in fallback)
    assert all(not ring.is_ccw for polygon in fallback for ring in polygon.interiors)


def test_nearest_entries_are_those_of_the_broadcast_argmin_with_ties_to_the_first():
    ascending = np.array([0.0, 1.0, 3.0, 3.5, 10.0])
    # Below the first, on an entry, halfway (a tie: the first), nearer the next, beyond the last.
    values = np.array([-2.0, 3.0, 2.0, 2.9, 3.25, 6.0, 7.0, 12.0])
    expected = np.abs(ascending[:, None] - values).argmin(axis=0)
    assert expected.tolist() == [0, 2, 1, 2, 2, 3, 4, 4]
    assert nearest_entries(ascending, values).tolist() == expected.tolist()


@pytest.mark.parametrize("hint_scale", [0.0, 0.5, 1.0, 1.5, 1e6])
def test_closest_within_a_hint_is_the_first_smallest_distance_of_nearest(hint_scale, monkeypatch):
    # A hint at or above the smallest distance is answered from the segments within it; a hint below it (or 0)
    # finds no point that near, and closest answers without it: nearest's answer, bit for bit, either way.
    rng = np.random.default_rng(13)
    path = np.cumsum(rng.normal(size=(300, 2)), axis=0)
    polyline = IndexedPolyline(path)
    probed = []
    monkeypatch.setattr(
        IndexedPolyline, "_may_be_closest", lambda self, *args: probed.append(1) or np.arange(len(args[0]))
    )
    for centre in path[rng.integers(0, len(path), 12)] + rng.normal(size=(12, 2)) * 3.0:
        angle = np.linspace(0.0, 2.0 * np.pi, 4 * CLUSTER_POINTS, endpoint=False)
        points = centre + 4.0 * np.column_stack([np.cos(angle), 0.3 * np.sin(angle)])
        distance, arc_length, foot = polyline.nearest(points)
        index, closest_distance, closest_arc_length, closest_foot = polyline.closest(
            points, within=hint_scale * distance.min()
        )
        assert index == int(np.argmin(distance))
        assert (closest_distance, closest_arc_length) == (distance[index], arc_length[index])
        assert closest_foot.tolist() == foot[index].tolist()
    # Only the hints below the smallest distance fall back to probing.
    assert bool(probed) == (hint_scale < 1.0)


def test_segments_within_are_those_whose_boxes_come_that_near():
    rng = np.random.default_rng(17)
    path = np.cumsum(rng.normal(size=(200, 2)), axis=0)
    polyline = IndexedPolyline(path)
    starts, ends = path[:-1], path[1:]
    low, high = np.minimum(starts, ends), np.maximum(starts, ends)
    for centre in path[rng.integers(0, len(path), 10)]:
        points = centre + rng.normal(size=(20, 2))
        for reach in (0.0, 0.7, 3.0):
            near = polyline._segments_within(points, reach)
            apart = np.maximum(points.min(axis=0) - high, low - points.max(axis=0)).max(axis=1)
            assert near.tolist() == np.flatnonzero(apart <= reach).tolist()


def test_closest_within_a_hint_too_small_ignores_segments_that_only_touch_the_box():
    # A circle of radius 1 at the origin; a bank 0.2 above it, and a last segment ending in the corner of the
    # circle's box, 0.4 from it. A hint of 0.1 keeps only that last segment, which must not give the answer.
    angle = np.linspace(0.0, 2.0 * np.pi, 2 * CLUSTER_POINTS, endpoint=False)
    points = np.column_stack([np.cos(angle), np.sin(angle)])
    polyline = IndexedPolyline(np.array([[-10.0, 1.2], [10.0, 1.2], [10.0, -5.0], [0.99, -0.99]]))
    assert polyline._segments_within(points, 0.1).tolist() == [2]
    index, distance, arc_length, foot = polyline.closest(points, within=0.1)
    assert angle[index] == np.pi / 2 and foot.tolist() == [0.0, 1.2]
    assert (distance, arc_length) == (pytest.approx(0.2), 10.0)
