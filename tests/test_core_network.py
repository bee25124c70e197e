"""Networks between three or more ends (``incircu_plugin.core.network.polygon_network``).

Every case is checked by :func:`check_network` against independent exact computations: the chains are cut
from the polygon's ring here (shapely substrings), distances come from ``segment_distances`` and the medial
axis from the segment-Voronoi oracle. Tolerances: the engine's invariants hold to ``1e-9`` of the extent;
the oracle adds its own error bound; the covering test allows a hundredth of the narrowest arm's width
(chords of curved axis parts with the default spacing, a twentieth of the width, deviate by far less; a
missing branch would be a whole arm away).
"""

import numpy as np
import pytest
import shapely
import shapely.affinity
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import substring

from incircu_plugin.core import (
    Cancelled,
    IncirCuError,
    InvalidGeometryError,
    SplitPointError,
    multipolygon_networks,
    polygon_centerline,
    polygon_network,
)
from incircu_plugin.core import network as network_module
from tests.support import network_cases as cases
from tests.support.oracle import MedialOracle, segment_distances

RELATIVE = 1e-9


def ring_chains(polygon, network, attached=None):
    """The chains between the network's split points, cut from the polygon's ring (counter-clockwise).

    ``attached`` maps an island's index to the chain it belongs to; its ring is added to that chain's
    sites for the distance checks (not to the returned chains).
    """
    exterior = shapely.geometry.polygon.orient(polygon, 1.0).exterior
    line = LineString(exterior.coords)
    chains = []
    for start, end in network.chains:
        s0 = line.project(Point(network.split_points[start]))
        s1 = line.project(Point(network.split_points[end]))
        if s1 > s0:
            piece = shapely.get_coordinates(substring(line, s0, s1))
        else:
            head = shapely.get_coordinates(substring(line, s0, line.length))
            tail = shapely.get_coordinates(substring(line, 0.0, s1))
            piece = np.concatenate([head, tail[1:]])
        chains.append(piece)
    sites = [[chain] for chain in chains]
    for island, chain in (attached or {}).items():
        sites[chain].append(shapely.get_coordinates(polygon.interiors[island]))
    return chains, sites


def distance_to(points, site_list):
    """Exact distance from each point to the nearest of several polylines."""
    return np.min([segment_distances(points, site) for site in site_list], axis=0)


def branch_path(network, chain):
    """The branches along chain ``chain`` joined into one line from its first to its last split point."""
    start_point, end_point = network.chains[chain]
    incident = [b for b in network.branches if chain in (b.right_chain, b.left_chain)]
    leaf = next(b for b in incident if start_point in (b.start_point, b.end_point))
    coords = shapely.get_coordinates(leaf.result.line)
    here = tuple(coords[0] if leaf.start_point == start_point else coords[-1])
    path = [np.asarray(here)]
    while len(incident):
        for branch in incident:
            coords = shapely.get_coordinates(branch.result.line)
            for candidate in (coords, coords[::-1]):
                if tuple(candidate[0]) == here:
                    path.extend(candidate[1:])
                    incident.remove(branch)
                    here = tuple(candidate[-1])
                    break
            else:
                continue
            break
        else:
            raise AssertionError(f"the branches along chain {chain} do not join up from {start_point} to {end_point}")
    return np.array(path)


def check_topology(network, k):
    """A tree with ``k`` leaves at the split points (to the rounding of the engine's local frame), junctions
    exactly shared by their branches and of degree >= 3, one branch per pair of chains."""
    degree = {}
    tolerance = 1e-14 * float(np.max(np.abs(network.split_points)))
    for branch in network.branches:
        coords = shapely.get_coordinates(branch.result.line)
        for end, point in ((coords[0], branch.start_point), (coords[-1], branch.end_point)):
            degree[tuple(end)] = degree.get(tuple(end), 0) + 1
            if point is not None:
                assert np.hypot(*(end - network.split_points[point])) <= tolerance
        assert branch.result.line.is_simple
    leaves = {node for node, count in degree.items() if count == 1}
    assert len(leaves) == k
    assert all(count >= 3 for node, count in degree.items() if node not in leaves)
    assert len(network.branches) == len(degree) - 1
    pairs = [frozenset((b.right_chain, b.left_chain)) for b in network.branches]
    assert len(set(pairs)) == len(pairs), "two branches separate the same two chains"
    junctions = {node for node in degree if node not in leaves}
    assert junctions == {tuple(p) for p in network.junctions}
    return degree


def check_network(polygon, network, attached=None, coverage=None, sites=None, sides=True):
    """Assert every invariant of a network; return the worst vertex error, CRS units.

    Each vertex ``v`` (junctions included) of a branch with radius ``r`` lies at distance ``r`` from its right
    and left chains and no nearer to any other chain; each junction is equidistant from at least three
    chains (``sites`` replaces the chains cut here, e.g. by the core's chains with their island slits); with
    ``coverage`` (no islands), the branches along each chain ``i`` are the oracle's medial axis
    between ``C_i`` and the rest of the ring: every vertex on it and every point of it near them. ``sides``:
    also check that each foot lies on its side of the line (meaningless where a real outline's end cap turns
    the line within one vertex).
    """
    k = len(network.split_points)
    check_topology(network, k)
    chains, ring_sites = ring_chains(polygon, network, attached)
    sites = ring_sites if sites is None else sites
    extent = float(max(np.ptp(shapely.get_coordinates(polygon), axis=0)))
    tolerance = RELATIVE * extent
    worst = 0.0
    for branch in network.branches:
        vertices = shapely.get_coordinates(branch.result.line)
        radii = branch.result.radii
        distances = np.array([distance_to(vertices, site) for site in sites])
        for chain in (branch.right_chain, branch.left_chain):
            error = np.abs(distances[chain] - radii)
            worst = max(worst, float(error.max()))
            assert error.max() <= tolerance, f"chain {chain}: a vertex is {error.max():.3g} off its circle"
        assert np.all(distances.min(axis=0) >= radii - tolerance), "a circle holds another chain"
        # foot_a lies on the right chain, foot_b on the left one, each at the radius from its vertex, on its side.
        feet = (np.asarray(branch.result.foot_a), np.asarray(branch.result.foot_b))
        for foot, chain, side in ((feet[0], branch.right_chain, -1.0), (feet[1], branch.left_chain, 1.0)):
            assert distance_to(foot, sites[chain]).max() <= tolerance
            assert np.abs(np.hypot(*(foot - vertices).T) - radii).max() <= tolerance
            if not sides:
                continue
            direction = vertices[2:] - vertices[:-2]
            offset = foot[1:-1] - vertices[1:-1]
            cross = direction[:, 0] * offset[:, 1] - direction[:, 1] * offset[:, 0]
            # A foot at a split point lies on both chains: it has no side (the stub's disk touching a flat end).
            at_split = np.min(np.hypot(*(foot[1:-1, None, :] - network.split_points[None]).transpose(2, 0, 1)), axis=1)
            assert np.all((side * cross >= -tolerance * np.hypot(*direction.T)) | (at_split <= tolerance)), (
                f"a foot of chain {chain} is on the wrong side"
            )
        assert np.all(branch.result.widths == 2.0 * radii)
    for junction in network.junctions:
        distances = np.array([distance_to(junction[None], site)[0] for site in sites])
        assert np.sum(distances <= distances.min() + tolerance) >= 3, f"junction {junction} touches < 3 chains"
    if coverage is not None:
        for i in range(k):
            rest = np.concatenate([chains[(i - step) % k][::-1][(step > 1) :] for step in range(1, k)])
            oracle = MedialOracle(chains[i], rest)
            path = branch_path(network, i)
            assert oracle.distance(path).max() <= 4.0 * oracle.error_bound + tolerance
            assert farthest_target_point(oracle, path, coverage / 4.0) <= coverage * 3.0 / 4.0
    return worst


def farthest_target_point(oracle, path, step):
    """Largest distance from the oracle's target set, sampled every ``step`` or closer, to a path.

    The distance to a line is 1-Lipschitz, so the directed Hausdorff distance is at most this plus
    ``step / 2``.
    """
    start, end = oracle.segments[:, 0], oracle.segments[:, 1]
    counts = np.ceil(np.hypot(*(end - start).T) / step).astype(int) + 1
    segment = np.repeat(np.arange(len(counts)), counts)
    fraction = (np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)) / np.repeat(counts - 1, counts)
    points = start[segment] + fraction[:, None] * (end - start)[segment]
    return float(shapely.distance(LineString(path), shapely.points(points)).max())


def junction_errors(network, expected):
    """Distance from each expected junction to the nearest junction found."""
    return [float(np.min(np.hypot(*(network.junctions - point).T))) for point in expected]


def test_two_split_points_give_exactly_the_polygon_centerline():
    polygon, caps = cases.reservoir()
    for points in ([caps[0], caps[1]], [caps[1], caps[0]], [caps[2], caps[0]]):
        network = polygon_network(polygon, points)
        centerline = polygon_centerline(polygon, points)
        (branch,) = network.branches
        assert branch.result.line.equals_exact(centerline.line, 0.0)
        assert np.array_equal(branch.result.radii, centerline.radii)
        assert (branch.start_point, branch.end_point) == (0, 1)
        assert len(network.junctions) == 0


def test_two_split_points_with_islands_give_exactly_the_polygon_centerline():
    polygon, caps = cases.reservoir()
    holes = [Point(-3.0, 2.0).buffer(3.0), box(60.0, -14.0, 80.0, -8.0)]
    with_islands = Polygon(polygon.exterior.coords, [hole.exterior.coords for hole in holes])
    (branch,) = polygon_network(with_islands, caps[:2]).branches
    assert branch.result.line.equals_exact(polygon_centerline(with_islands, caps[:2]).line, 0.0)


def test_rectangle_split_at_its_corners_is_its_whole_medial_axis():
    # Chains are the four sides: the corner bisectors meet at (w/2, w/2) and (L - w/2, w/2), joined along
    # y = w/2 (a branch between the two long sides).
    network = polygon_network(box(0.0, 0.0, 100.0, 10.0), [(0, 0), (100, 0), (100, 10), (0, 10)], spacing=1.0)
    assert max(junction_errors(network, [np.array([5.0, 5.0]), np.array([95.0, 5.0])])) <= RELATIVE * 100.0
    (middle,) = [b for b in network.branches if b.start_point is None]
    assert {middle.right_chain, middle.left_chain} == {0, 2}
    assert np.all(shapely.get_coordinates(middle.result.line)[:, 1] == 5.0)
    assert middle.result.length == pytest.approx(90.0, abs=RELATIVE * 100.0)
    check_network(box(0.0, 0.0, 100.0, 10.0), network, coverage=10.0 / 100.0)


def test_six_arm_delta_is_a_tree_of_four_junctions_on_the_oracle_axis():
    polygon, caps = cases.delta()
    network = polygon_network(polygon, caps)
    assert len(network.junctions) == 4 and len(network.branches) == 9
    check_network(polygon, network, coverage=8.0 / 100.0)


def test_symmetric_y_meets_at_the_centre_of_its_three_reflex_corners():
    polygon, caps, expected, radius = cases.symmetric_y()
    network = polygon_network(polygon, caps)
    extent = 120.0
    assert len(network.junctions) == 1
    assert junction_errors(network, expected)[0] <= RELATIVE * extent
    assert len(network.branches) == 3
    for branch in network.branches:
        assert branch.result.radii[-1] == pytest.approx(radius, abs=RELATIVE * extent)
        assert branch.end_point is None and branch.start_point is not None
    check_network(polygon, network, coverage=10.0 / 100.0)


def test_skewed_y_meets_at_the_circumcentre_of_its_reflex_corners():
    polygon, caps, expected = cases.skewed_y()
    network = polygon_network(polygon, caps[::-1])
    assert junction_errors(network, expected)[0] <= RELATIVE * 120.0
    check_network(polygon, network, coverage=8.0 / 100.0)


def test_t_junction_centre_and_width_are_the_closed_form():
    polygon, caps, expected, radius = cases.t_junction()
    network = polygon_network(polygon, caps, spacing=0.25)
    assert junction_errors(network, expected)[0] <= RELATIVE * 100.0
    assert {round(float(b.result.radii[-1]), 9) for b in network.branches} == {round(radius, 9)}
    ends = {b.start_point for b in network.branches}
    assert ends == {0, 1, 2}
    check_network(polygon, network, coverage=6.0 / 100.0)


def test_right_angle_crossing_has_one_junction_of_degree_four():
    polygon, caps, expected = cases.crossing(90.0)
    network = polygon_network(polygon, caps)
    assert len(network.junctions) == 1
    assert junction_errors(network, expected)[0] <= RELATIVE * 100.0
    degree = check_topology(network, 4)
    assert degree[tuple(network.junctions[0])] == 4
    check_network(polygon, network, coverage=6.0 / 100.0)


def test_oblique_crossing_has_two_junctions_joined_by_a_short_branch():
    polygon, caps, expected = cases.crossing(60.0)
    network = polygon_network(polygon, caps)
    assert len(network.junctions) == 2
    assert max(junction_errors(network, expected)) <= RELATIVE * 100.0
    (middle,) = [b for b in network.branches if b.start_point is None and b.end_point is None]
    assert middle.result.length >= np.hypot(*(expected[0] - expected[1])) - RELATIVE * 100.0
    check_network(polygon, network, coverage=6.0 / 100.0)


def test_three_arm_reservoir_is_the_oracle_axis():
    polygon, caps = cases.reservoir()
    network = polygon_network(polygon, caps)
    assert len(network.junctions) == 1
    # The branches' tolerance is 0.058 (typical width 11.65 / 200), and the line may use all of it (the tracer's
    # chords settle within half of it, the simplification takes the other half): the coverage's bound on the
    # distance from the axis to the line, 7/8 of it, is 0.061.
    check_network(polygon, network, coverage=7.0 / 100.0)


def test_confluence_with_an_island_passes_it_on_the_wide_side():
    polygon, caps, _, _ = cases.symmetric_y(half_width=8.0)
    island = box(-2.0, 30.0, 4.0, 45.0)
    with_island = Polygon(polygon.exterior.coords, [island.exterior.coords])
    network = polygon_network(with_island, caps)
    assert all(not b.result.line.intersects(island) for b in network.branches)
    # The island is nearer the arm's right bank (x = 8, 4 away; the left bank is 6 away): it belongs to the
    # chain holding that bank and the branch runs down the middle of the left channel, x = -5.
    bank = int(np.argmin([Point(8.0, 40.0).distance(LineString(c)) for c in ring_chains(with_island, network)[0]]))
    check_network(with_island, network, attached={0: bank})
    upper = [b for b in network.branches if 0 in (b.start_point, b.end_point)]
    (arm,) = upper
    beside = shapely.get_coordinates(arm.result.line)
    beside = beside[(beside[:, 1] > 31.0) & (beside[:, 1] < 44.0)]
    assert np.allclose(beside[:, 0], (-8.0 + -2.0) / 2.0, atol=RELATIVE * 120.0)


def test_island_ignored_gives_the_network_without_it():
    polygon, caps, _, _ = cases.symmetric_y(half_width=8.0)
    with_island = Polygon(polygon.exterior.coords, [box(-2.0, 30.0, 4.0, 45.0).exterior.coords])
    ignored = polygon_network(with_island, caps, islands="ignore")
    plain = polygon_network(polygon, caps)
    assert [b.result.line.wkb for b in ignored.branches] == [b.result.line.wkb for b in plain.branches]


def test_split_point_order_only_renames_the_ends():
    polygon, caps, _, _ = cases.t_junction()
    forward = polygon_network(polygon, caps)
    backward = polygon_network(polygon, caps[::-1])
    assert np.allclose(forward.junctions, backward.junctions, rtol=0.0, atol=RELATIVE * 100.0)
    # Other runs sample the corners' parabolic arcs elsewhere: the chords differ by far less than the width.
    lines = [shapely.MultiLineString([b.result.line for b in n.branches]) for n in (forward, backward)]
    assert shapely.hausdorff_distance(*lines) <= 6.0 / 100.0
    assert {(b.start_point, b.end_point) for b in forward.branches} == {
        (2 - b.start_point, None) for b in backward.branches
    }


def test_bad_split_points_are_typed_errors():
    polygon, caps, _, _ = cases.t_junction()
    with pytest.raises(SplitPointError, match="away from"):
        polygon_network(polygon, [*caps[:2], (0.0, 0.0)])
    with pytest.raises(SplitPointError, match="same place"):
        polygon_network(polygon, [*caps, caps[0]])
    with pytest.raises(IncirCuError, match="island mode"):
        polygon_network(polygon, caps, islands="drop")


def test_multipart_networks_number_split_points_among_all_candidates():
    y_polygon, y_caps, _, _ = cases.symmetric_y()
    t_polygon, t_caps, _, _ = cases.t_junction()
    t_polygon = shapely.affinity.translate(t_polygon, 200.0, 0.0)
    t_caps = [(x + 200.0, y) for x, y in t_caps]
    candidates = [t_caps[0], *y_caps, *t_caps[1:], (500.0, 500.0)]
    outcomes = multipolygon_networks(shapely.MultiPolygon([y_polygon, t_polygon, box(400, 0, 450, 10)]), candidates)
    assert [o.error is None for o in outcomes] == [True, True, True]
    # The part without split points gets its two ends automatically, numbered None (no candidate).
    (lone,) = outcomes[2].result.branches
    assert outcomes[2].result.point_indices == (None, None) and (lone.start_point, lone.end_point) == (None, None)
    assert sorted(np.round(shapely.get_coordinates(lone.result.line)[[0, -1], 0], 9)) == [400.0, 450.0]
    for outcome, expected in zip(outcomes, ({1, 2, 3}, {0, 4, 5})):
        network = outcome.result
        assert {b.start_point for b in network.branches} == expected
        assert set(network.point_indices) == expected
        for branch in network.branches:
            start = shapely.get_coordinates(branch.result.line)[0]
            assert np.hypot(*(start - np.asarray(candidates[branch.start_point]))) <= 1e-12


def test_an_invalid_part_is_named_invalid_before_its_split_points_are_counted():
    """A bow-tie with one split point: its error is what is wrong with it (it crosses itself), as a centerline
    says, not that it lacks a split point."""
    bow_tie = Polygon([(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)])
    (outcome,) = multipolygon_networks(bow_tie, [(0.0, 5.0)])
    assert isinstance(outcome.error, InvalidGeometryError) and "Self-intersection" in str(outcome.error), outcome.error


def test_a_branch_shorter_than_the_sampling_is_recovered_between_two_junctions():
    # A run whose vertices jump from the left side's label straight to the right side's (no vertex on the
    # middle branch along the top): the point equidistant from the bottom, left and right sides, (50, 50),
    # has the top side inside its circle, so the change splits into the junctions (5, 5) and (95, 5).
    chains = [np.array(c, dtype=float) for c in ([(0, 0), (100, 0)], [(100, 0), (100, 10)], [(100, 10), (0, 10)])]
    chains.append(np.array([(0, 10), (0, 0)], dtype=float))
    junctions = network_module._Junctions(network_module._Boundary(chains, float(np.hypot(100.0, 10.0))))
    found = junctions.between(0, 3, 1, np.array([3.0, 3.0]), np.array([97.0, 3.0]))
    assert [key for key, _, _ in found] == [(0, 2, 3), (0, 1, 2)]
    assert np.allclose([centre for _, centre, _ in found], [(5.0, 5.0), (95.0, 5.0)], rtol=0.0, atol=1e-12)
    assert [radius for _, _, radius in found] == pytest.approx([5.0, 5.0], abs=1e-12)


def test_island_in_the_confluence_basin_is_passed_on_the_far_side_of_its_slit():
    # The island is nearest chain 1 (the west bank) and joins it through a slit: for the core the slit is
    # part of that chain, and a branch may touch it (as the polygon centerline may), so the branches are
    # checked against the core's bridged chains; that no circle holds any of the island is checked apart.
    polygon, caps = cases.reservoir()
    island = Point(-3.0, 2.0).buffer(3.0)
    with_island = Polygon(polygon.exterior.coords, [island.exterior.coords])
    network = polygon_network(with_island, caps)
    order = network_module._ring_order(with_island, caps, None)
    bridged = network_module._bridged_chains(with_island, [np.asarray(caps[i]) for i in order], None, "main_channel")
    check_network(with_island, network, sites=[[chain] for chain in bridged])
    for branch in network.branches:
        assert not branch.result.line.intersects(island)
        vertices = shapely.get_coordinates(branch.result.line)
        ring = shapely.get_coordinates(island.exterior)
        assert np.all(segment_distances(vertices, ring) >= branch.result.radii - RELATIVE * 300.0)


def test_progress_runs_from_zero_to_one_and_cancel_stops():
    polygon, caps = cases.delta()
    fractions = []
    polygon_network(polygon, caps, progress=lambda fraction: fractions.append(fraction) or True)
    assert fractions and 0.0 <= min(fractions) and max(fractions) <= 1.0
    assert max(fractions) >= 0.99
    assert np.all(np.diff(fractions) >= 0.0)
    with pytest.raises(Cancelled):
        polygon_network(polygon, caps, progress=lambda fraction: fraction < 0.5)
