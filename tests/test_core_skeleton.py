"""Skeleton of the automatic ends (``incircu_plugin.core.skeleton``): what it takes from GEOS.

The triangle corners are identified by the sample index each point carries as z through GEOS's Delaunay
triangulation; these tests fail if a GEOS version drops or mixes up the z values.
"""

import numpy as np
import pytest
import shapely

from incircu_plugin.core import find_ends
from incircu_plugin.core import skeleton as skeleton_module
from incircu_plugin.core._arrays import ranges
from incircu_plugin.core.errors import InvalidGeometryError
from incircu_plugin.core.skeleton import _delaunay_all, joint_skeletons
from tests.support import geometry_cases


def triangle_areas(corners):
    """Areas of triangles given as corners of shape (t, 3, 2)."""
    first, second = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    return 0.5 * np.abs(first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0])


def test_triangle_corners_are_identified_by_the_ids_carried_through_geos():
    """Each polygon's triangles, read through their corner ids, tile exactly its points' convex hull and use
    every one of its points (random points: general position)."""
    rng = np.random.default_rng(3)
    samples = np.concatenate([rng.random((150, 2)), rng.random((120, 2)) * (2.0, 0.5) + (3.0, 0.0)])
    owner = np.repeat([0, 1], [150, 120])
    local = ranges(np.bincount(owner))[1]
    moved, corner_ids, triangle_owner, failed = _delaunay_all(samples, owner, local, np.array([1e-3, 1e-3]), 2)
    corners = moved[corner_ids]
    assert not np.any(failed)
    for polygon in (0, 1):
        own = triangle_owner == polygon
        points = np.flatnonzero(owner == polygon)
        assert np.all(owner[corner_ids[own]] == polygon)
        assert set(corner_ids[own].ravel().tolist()) == set(points.tolist())
        hull = shapely.MultiPoint(samples[points]).convex_hull.area
        assert abs(triangle_areas(corners[own]).sum() - hull) <= 1e-6 * hull


def test_lines_of_points_triangulate_as_multipoints_do_repeated_points_included():
    """The triangulation of the lines ``_point_runs`` builds (what ``_delaunay_all`` triangulates) equals that of
    multipoints of the same points, corners and their ids (z) included, also with repeated and collinear
    points (GEOS keeps one of the repeated points, the same for both)."""
    rng = np.random.default_rng(11)
    sizes = rng.integers(3, 40, size=60)
    points = rng.integers(0, 6, size=(int(sizes.sum()), 2)).astype(float)
    ids = np.arange(len(points))
    lines = skeleton_module._point_runs(points, ids, sizes)
    assert np.all(shapely.get_type_id(lines) == 1)
    firsts = np.append(0, np.cumsum(sizes))
    multipoints = [
        shapely.multipoints(np.column_stack([points, ids])[firsts[k] : firsts[k + 1]]) for k in range(len(sizes))
    ]
    expected = shapely.delaunay_triangles(np.array(multipoints, dtype=object))
    found = shapely.delaunay_triangles(lines)
    assert np.array_equal(shapely.get_num_geometries(found), shapely.get_num_geometries(expected))
    assert np.array_equal(
        shapely.get_coordinates(found, include_z=True), shapely.get_coordinates(expected, include_z=True)
    )


def test_joint_skeletons_keep_each_polygons_nodes_and_edges_to_itself():
    """Nodes come polygon after polygon, lie in their own polygon, and edges never join two polygons (the
    boxes overlap in x, so a mixed-up sample numbering would link them)."""
    polygons = [shapely.box(0.0, 0.0, 1.0, 0.1), shapely.box(-0.5, 0.2, 0.5, 0.3), shapely.box(0.2, -0.4, 0.3, 0.4)]
    skeleton = joint_skeletons(polygons)
    assert skeleton.errors == [None, None, None]
    assert np.all(np.diff(skeleton.owner) >= 0)
    for index, polygon in enumerate(polygons):
        nodes = skeleton.nodes[skeleton.owner == index]
        assert len(nodes) > 0
        assert np.all(shapely.covers(polygon.buffer(1e-9), shapely.points(nodes)))
    assert np.all(skeleton.owner[skeleton.edges[:, 0]] == skeleton.owner[skeleton.edges[:, 1]])


def test_a_needle_is_too_thin_after_one_triangulation(monkeypatch):
    """A triangle whose long sides meet at 1e-11 radians has only slivers: it is not refined (splitting its
    sides would not converge; GEOS 3.11 took 48 s over the twelve rounds) and gets the "too thin" error, while a
    needle a thousand times wider still gets its ends."""
    calls = []

    def counted(*arguments):
        calls.append(len(arguments[0]))
        return _delaunay_all(*arguments)

    monkeypatch.setattr(skeleton_module, "_delaunay_all", counted)
    needle = shapely.Polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1e-11)])
    with pytest.raises(InvalidGeometryError, match="too thin"):
        find_ends(needle)
    assert len(calls) == 1
    wider = shapely.Polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1e-8)])
    ends = find_ends(wider)
    assert ends.start.x == pytest.approx(0.0, abs=1e-3) and ends.end.x == pytest.approx(1.0, abs=1e-3)


def test_reached_from_is_the_union_of_the_seeds_components(monkeypatch):
    """On random graphs (short and long paths between seeds and nodes), spreading from the seeds marks
    exactly the components that hold a seed, both by spreading alone (no labels) and by the component labels
    it falls back to."""
    labelled = skeleton_module.connected_labels

    def no_labels(*arguments):
        raise AssertionError("spreading fell back to labels")

    rng = np.random.default_rng(5)
    chain = np.arange(199)
    for first, second in [
        (rng.integers(0, 200, 150), rng.integers(0, 200, 150)),
        (chain, chain + 1),
    ]:
        seeds = np.zeros(200, dtype=bool)
        seeds[rng.integers(0, 200, 3)] = True
        labels = labelled(200, first, second)
        expected = np.isin(labels, labels[seeds])
        for rounds, labelling in ((0, labelled), (1000, no_labels)):
            monkeypatch.setattr(skeleton_module, "SPREAD_ROUNDS", rounds)
            monkeypatch.setattr(skeleton_module, "connected_labels", labelling)
            assert np.array_equal(skeleton_module.reached_from(seeds, first, second), expected)


def test_the_inside_found_by_labels_gives_the_same_skeleton(monkeypatch):
    """A river with an island (its water a ring of triangles far from the first seeds in the graph) gets the
    same skeleton whether its inside triangles are found by spreading or by component labels."""
    hole = shapely.box(2.0, 0.4, 8.0, 0.6)
    polygon = shapely.Polygon(shapely.box(0.0, 0.0, 10.0, 1.0).exterior, [hole.exterior.coords[::-1]])
    spread = joint_skeletons([polygon])
    monkeypatch.setattr(skeleton_module, "SPREAD_ROUNDS", 0)
    labelled = joint_skeletons([polygon])
    for name in ("nodes", "radii", "spans", "edges", "owner"):
        assert np.array_equal(getattr(spread, name), getattr(labelled, name))
    assert len(spread.nodes) > 0


def test_split_samples_keeps_the_flagged_polygons_and_inserts_midpoints_after_their_starts():
    """Three rings of three polygons: the middle polygon is dropped, and the midpoints of the flagged
    segments (one of them the closing segment of a ring) follow their starts, in ring order."""
    samples = np.arange(20.0).reshape(10, 2)
    ring = np.array([0, 0, 0, 1, 1, 1, 2, 2, 2, 2])
    owner = np.array([0, 0, 0, 1, 1, 1, 2, 2, 2, 2])
    following = skeleton_module._following(ring)
    keep = owner != 1
    split = np.zeros(10, dtype=bool)
    split[[0, 2, 7]] = True
    expected_samples, expected_ring = [], []
    for index in np.flatnonzero(keep).tolist():
        expected_samples.append(samples[index])
        expected_ring.append(ring[index])
        if split[index]:
            expected_samples.append((samples[index] + samples[following[index]]) / 2.0)
            expected_ring.append(ring[index])
    got_samples, got_ring, got_owner = skeleton_module._split_samples(samples, ring, owner, following, split, keep)
    assert np.array_equal(got_samples, np.array(expected_samples))
    assert got_ring.tolist() == expected_ring and got_owner.tolist() == expected_ring


def test_sides_run_from_each_corner_to_the_next():
    start, end = skeleton_module._sides(np.array([[3, 4, 5], [9, 7, 8]]))
    assert start.tolist() == [3, 4, 5, 9, 7, 8] and end.tolist() == [4, 5, 3, 7, 8, 9]


def u_with_island():
    """A U-shaped channel about 1 across with an island in its bend (hole clockwise), near the origin."""
    outline = shapely.Polygon(
        [(-0.5, -0.4), (0.5, -0.4), (0.5, 0.4), (0.3, 0.4), (0.3, -0.2), (-0.3, -0.2)] + [(-0.3, 0.4), (-0.5, 0.4)]
    )
    return outline.difference(shapely.box(-0.05, -0.35, 0.05, -0.25))


def test_clearly_outside_triangles_lie_outside_and_are_most_of_the_outside():
    """On a conforming triangulation of a U-shaped channel with an island, every triangle flagged outside has
    its centroid outside the polygon, and the flagged ones are nearly all of those outside (the bend's
    pocket, the island) but slivers of nearly collinear samples along the straight banks."""
    polygon = u_with_island()
    samples, ring, owner, steps = skeleton_module._boundary_sample_arrays([polygon])
    following = skeleton_module._following(ring)
    moved, corner_ids, _, failed = _delaunay_all(samples, owner, np.arange(len(samples)), steps, 1)
    start, end = skeleton_module._sides(corner_ids)
    edges = set(zip(start.tolist(), end.tolist())) | set(zip(end.tolist(), start.tolist()))
    assert not failed[0] and all((k, int(following[k])) in edges for k in range(len(samples)))
    outside = skeleton_module._clearly_outside(moved, corner_ids, following)
    inside = shapely.within(shapely.points(moved[corner_ids].mean(axis=1)), polygon)
    solid = skeleton_module._triangle_shapes(moved[corner_ids])[2]
    assert not np.any(outside & inside)
    assert np.count_nonzero(outside) >= 0.95 * np.count_nonzero(~inside & solid) > 0


def test_dropping_the_outside_triangles_changes_no_skeleton(monkeypatch):
    """The skeletons of a U-shaped channel with an island, a meander (refined over several rounds) and a
    needle too thin to conform are the same whether the outside triangles are dropped early or not."""
    meander = geometry_cases.meander().polygon
    meander = shapely.transform(meander, lambda xy: (xy - meander.centroid.coords[0]) / 2000.0)
    needle = shapely.Polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1e-7)])
    polygons = [u_with_island(), meander, needle]
    dropped = joint_skeletons(polygons)
    monkeypatch.setattr(
        skeleton_module, "_clearly_outside", lambda points, corner_ids, following: np.zeros(len(corner_ids), dtype=bool)
    )
    kept = joint_skeletons(polygons)
    for name in ("nodes", "radii", "spans", "edges", "owner", "steps"):
        assert np.array_equal(getattr(dropped, name), getattr(kept, name))
    assert [error is None for error in dropped.errors] == [error is None for error in kept.errors]
    assert len(np.unique(dropped.owner)) == 3


@pytest.mark.parametrize("reflex", [False, True])
def test_clearly_outside_is_the_outer_angle_at_the_first_corner(reflex):
    """At a corner of the boundary (next sample along x, previous along y: a right angle inside; the other
    way round: three right angles inside), a triangle with that first corner is outside when it lies in the
    outer angle, and not when it lies inside or only about 1e-12 radians off the boundary."""
    after, before = ((0.0, 1.0), (1.0, 0.0)) if reflex else ((1.0, 0.0), (0.0, 1.0))
    directions = np.array([20.0, 70.0, 110.0, 160.0, 200.0, 250.0, 290.0, 340.0])
    unit = np.stack([np.cos(np.radians(directions)), np.sin(np.radians(directions))], axis=1)
    near = np.array([[1.0, 1e-12], [1.0, -1e-12], [1e-12, 1.0], [-1e-12, 1.0]])
    # Each triangle's other corners: two points 10 degrees apart around its direction.
    spread = np.radians(5.0)
    turn = np.array([[np.cos(spread), -np.sin(spread)], [np.sin(spread), np.cos(spread)]])
    others = np.concatenate([unit @ turn.T, unit @ turn, near, near * 0.5])
    points = np.concatenate([[(0.0, 0.0), after, before], others * 0.5])
    following = np.concatenate([[1, 2, 0], np.arange(4, len(points)), [3]])
    count = len(directions) + len(near)
    first = 3 + np.arange(len(directions))
    second = 3 + len(directions) + np.arange(len(directions))
    near_first = 3 + 2 * len(directions) + np.arange(len(near))
    corner_ids = np.stack(
        [np.zeros(count, np.int64), np.concatenate([first, near_first]), np.concatenate([second, near_first + 4])],
        axis=1,
    )
    outer = (directions > 90.0) if not reflex else (directions < 90.0)
    expected = np.concatenate([outer, np.zeros(len(near), dtype=bool)])
    assert skeleton_module._clearly_outside(points, corner_ids, following).tolist() == expected.tolist()


def test_kept_triangles_drop_the_clearly_outside_ones_of_finished_conforming_polygons_only():
    """Of two copies of the U-shaped channel's triangulation, a finished conforming one keeps the triangles not
    clearly outside, a finished one that does not conform keeps them all, and an unfinished one none."""
    polygon = u_with_island()
    samples, ring, owner, steps = skeleton_module._boundary_sample_arrays([polygon])
    following = skeleton_module._following(ring)
    moved, corner_ids, _, _ = _delaunay_all(samples, owner, np.arange(len(samples)), steps, 1)
    outside = skeleton_module._clearly_outside(moved, corner_ids, following)
    assert np.any(outside)
    count = len(corner_ids)
    points = np.concatenate([moved, moved])
    both_ids = np.concatenate([corner_ids, corner_ids + len(moved)])
    both_following = np.concatenate([following, following + len(moved)])
    triangle_owner = np.repeat([0, 1], count)

    def kept(done, conforming):
        return skeleton_module._kept_triangles(
            points, both_ids, both_following, triangle_owner, np.array(done), np.array(conforming)
        ).tolist()

    walled = np.flatnonzero(~outside).tolist()
    assert kept([True, True], [True, False]) == walled + list(range(count, 2 * count))
    assert kept([True, True], [False, True]) == list(range(count)) + [count + k for k in walled]
    assert kept([False, True], [True, False]) == list(range(count, 2 * count))
    assert kept([True, False], [True, True]) == walled
    assert kept([False, False], [True, True]) == []


def test_densified_rings_are_those_of_shapely_segmentize():
    """An uneven polygon with a hole, its rings split with a different step each (segments from under one step
    to nineteen steps long, and one of no length): the same points as ``shapely.segmentize`` gives, in the
    same order, each ring without its closing point."""
    rng = np.random.default_rng(3)
    angles = np.sort(rng.random(40)) * 2.0 * np.pi
    radii = 1.0 + 0.4 * rng.random(40)
    outer = np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=1)
    outer = np.insert(outer, 5, outer[5], axis=0)
    hole = np.array([(0.1, 0.1), (0.3, 0.1), (0.3, 0.25), (0.1, 0.3)])[::-1]
    polygon = shapely.Polygon(outer, [hole])
    steps = np.array([0.037, 0.011])
    rings = shapely.get_rings(polygon)
    samples, ring = skeleton_module._densified(*shapely.get_coordinates(rings, return_index=True), steps)
    for number, step in enumerate(steps):
        expected = shapely.get_coordinates(shapely.segmentize(rings[number], step))[:-1]
        expected = expected[np.append(True, np.any(expected[1:] != expected[:-1], axis=1))]
        assert np.allclose(samples[ring == number], expected, rtol=0.0, atol=1e-15)
