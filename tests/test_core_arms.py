"""Automatic networks: arm ends from the pruned skeleton (``incircu_plugin.core.arms``) and the networks built on them.

The shapes of ``tests/support/network_cases.py`` have flat-ended arms whose ends (the middles of the cut-off
ends) and junctions are known in closed form; every automatic network is also checked by the oracle
invariants of ``test_core_network.check_network`` (vertices and junctions on the exact axis within ``1e-9`` of
the extent, the branches along each chain covering the segment-Voronoi axis). Pruning is checked where its
rule decides: a side arm whose reach beyond the junction's circle is a known number of junction widths.
"""

import math

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Polygon, box
from shapely.ops import unary_union

from incircu_plugin.core import OptionError, find_ends, polygon_centerline, polygon_network
from incircu_plugin.core.arms import MIN_ARM_RATIO, find_arm_ends
from tests.support import network_cases as cases
from tests.support.real_rivers import real_rivers
from tests.test_core_network import RELATIVE, check_network, check_topology, junction_errors


def same_points(found, expected, tolerance):
    """Whether two point sets match one to one within ``tolerance``."""
    found, expected = np.asarray(found, dtype=float), np.asarray(expected, dtype=float)
    if found.shape != expected.shape:
        return False
    distances = np.hypot(*(found[:, None, :] - expected[None, :, :]).transpose(2, 0, 1))
    return bool(np.all(distances.min(axis=0) <= tolerance) and np.all(distances.min(axis=1) <= tolerance))


def extent_of(polygon):
    return float(max(np.ptp(shapely.get_coordinates(polygon), axis=0)))


@pytest.mark.parametrize(
    ("name", "coverage"),
    [("symmetric_y", 10.0), ("skewed_y", 8.0), ("t_junction", 6.0), ("reservoir", 7.0), ("delta", 8.0)],
)
def test_automatic_ends_are_the_middles_of_the_cut_off_ends_and_the_network_is_exact(name, coverage):
    polygon, caps, *_ = getattr(cases, name)()
    network = polygon_network(polygon)
    assert network.ends_from == "automatic" and set(network.end_sources) == {"automatic"}
    assert same_points(network.split_points, caps, RELATIVE * extent_of(polygon))
    check_network(polygon, network, coverage=coverage / 100.0)


def test_automatic_y_and_t_junctions_are_the_closed_form():
    polygon, _, expected, radius = cases.symmetric_y()
    network = polygon_network(polygon)
    assert junction_errors(network, expected)[0] <= RELATIVE * 120.0
    assert network.junction_radii[0] == pytest.approx(radius, abs=RELATIVE * 120.0)
    polygon, _, expected, radius = cases.t_junction()
    network = polygon_network(polygon)
    assert junction_errors(network, expected)[0] <= RELATIVE * 100.0
    assert network.junction_radii[0] == pytest.approx(radius, abs=RELATIVE * 100.0)


@pytest.mark.parametrize("angle", [90.0, 60.0])
def test_automatic_crossing_finds_its_four_arms(angle):
    polygon, caps, expected = cases.crossing(angle)
    network = polygon_network(polygon)
    assert same_points(network.split_points, caps, RELATIVE * 100.0)
    assert max(junction_errors(network, expected)) <= RELATIVE * 100.0
    check_topology(network, 4)
    check_network(polygon, network, coverage=6.0 / 100.0)


def test_a_road_comb_with_twelve_arms_is_found_whole_and_exact():
    polygon, caps = cases.fishbone()
    network = polygon_network(polygon)
    assert same_points(network.split_points, caps, RELATIVE * extent_of(polygon))
    degree = check_topology(network, 12)
    assert len(network.junctions) == 10 and max(degree.values()) == 3
    check_network(polygon, network)
    kinds = sorted(branch.kind for branch in network.branches)
    assert kinds == ["arm"] * 12 + ["inner"] * 9


def t_with_side_road(reach_in_widths, a=5.0, b=3.0):
    """A T whose side road reaches ``reach_in_widths`` junction widths beyond the junction's circle.

    The junction (see :func:`cases.t_junction`) is at ``(0, b**2 / (4 a))`` with radius ``a + b**2 / (4 a)``;
    the side road's end at ``y = L`` lies ``L - y0`` from it, so it reaches ``L - y0 - r`` beyond the circle.
    """
    y0 = b * b / (4.0 * a)
    radius = a + y0
    side = y0 + radius + reach_in_widths * 2.0 * radius
    polygon = unary_union([box(-60.0, -a, 60.0, a), box(-b, 0.0, b, side)])
    return polygon, (0.0, side), 2.0 * radius


@pytest.mark.parametrize(("reach", "kept"), [(0.5, False), (0.75, False), (1.25, True), (2.0, True)])
def test_a_side_arm_is_kept_when_it_reaches_one_junction_width_beyond_the_junctions_circle(reach, kept):
    polygon, tip, _ = t_with_side_road(reach)
    ends = find_arm_ends(polygon)
    assert len(ends.points) == (3 if kept else 2)
    assert (min(np.hypot(*(ends.points - tip).T)) <= 1e-9 * 120.0) == kept
    if kept:
        (side,) = ends.reaches[np.hypot(*(ends.points - tip).T) <= 1e-9 * 120.0]
        # The skeleton's reach is within about a sampling step (a third of the typical width, here 0.2 junction
        # widths) of the closed form: its junction node is a triangle's circumcentre, not the exact junction.
        assert side == pytest.approx(reach, abs=0.2)


def test_the_arm_options_move_the_threshold():
    polygon, _, width = t_with_side_road(0.6)
    assert len(find_arm_ends(polygon, min_arm_ratio=0.4).points) == 3
    polygon, _, width = t_with_side_road(2.0)
    assert len(find_arm_ends(polygon, min_arm_length=2.5 * width).points) == 2
    assert len(find_arm_ends(polygon, min_arm_length=1.5 * width).points) == 3
    assert MIN_ARM_RATIO == 1.0
    with pytest.raises(OptionError, match="min_arm_ratio"):
        find_arm_ends(polygon, min_arm_ratio=-1.0)
    with pytest.raises(OptionError, match="min_arm_length"):
        find_arm_ends(polygon, min_arm_length=float("nan"))


@pytest.mark.parametrize("seed", [1, 2, 3])
@pytest.mark.parametrize("name", ["symmetric_y", "t_junction", "delta"])
def test_bank_noise_at_five_percent_of_the_width_never_adds_a_branch(name, seed):
    polygon, caps, *_ = getattr(cases, name)()
    width = 6.0 if name == "t_junction" else 8.0
    rough = cases.noisy(polygon, width, seed)
    assert rough.geom_type == "Polygon" and not rough.equals(polygon)
    network = polygon_network(rough)
    assert len(network.split_points) == len(caps)
    # Each end within a tenth of the narrowest arm's width of the clean cap's middle.
    assert same_points(network.split_points, caps, 0.1 * width)
    check_topology(network, len(caps))


def test_a_small_bay_makes_no_branch_and_a_tributary_does():
    polygon, _, _, _ = cases.t_junction()
    bay = box(20.0, -5.0, 24.0, -2.0)  # 4 wide, 3 deep into a road 10 wide
    network = polygon_network(polygon.difference(bay))
    assert len(network.split_points) == 3
    notch = box(20.0, -5.0 - 18.0, 24.0, -4.0)  # a tributary 4 wide, 18 long
    network = polygon_network(unary_union([polygon, notch]))
    assert len(network.split_points) == 4
    assert min(np.hypot(*(network.split_points - (22.0, -23.0)).T)) <= RELATIVE * 100.0


def test_ring_start_and_orientation_do_not_change_the_network():
    polygon, _ = cases.delta()
    ring = shapely.get_coordinates(polygon.exterior)[:-1]
    reference = polygon_network(polygon)
    tolerance = RELATIVE * extent_of(polygon)
    for shift in (1, 7, len(ring) // 2):
        for coordinates in (np.roll(ring, shift, axis=0), np.roll(ring, shift, axis=0)[::-1]):
            other = polygon_network(Polygon(coordinates))
            assert same_points(other.split_points, reference.split_points, tolerance)
            assert same_points(other.junctions, reference.junctions, tolerance)
            assert len(other.branches) == len(reference.branches)


def test_one_given_split_point_replaces_the_automatic_end_of_its_arm():
    polygon, caps, _, _ = cases.t_junction()
    given = (-50.0, 3.0)  # across the west end, off its middle
    network = polygon_network(polygon, [given])
    assert network.ends_from == "split_points_and_automatic" and network.end_sources == (
        "split_point",
        "automatic",
        "automatic",
    )
    assert tuple(network.split_points[0]) == given
    assert same_points(network.split_points[1:], caps[1:], RELATIVE * 100.0)
    check_network(polygon, network)


def test_a_centerline_with_one_split_point_ends_at_the_far_end_of_the_main_stem():
    polygon, _ = cases.reservoir()
    main = find_ends(polygon)
    for given, far in ((main.start, main.end), (main.end, main.start)):
        result = polygon_centerline(polygon, [given])
        assert result.ends_from == "split_points_and_automatic"
        assert np.hypot(*(np.asarray(result.line.coords[0]) - given.coords[0])) <= RELATIVE * 300.0
        assert np.hypot(*(np.asarray(result.line.coords[-1]) - far.coords[0])) <= RELATIVE * 300.0


def test_a_shape_without_arms_gets_the_ends_of_its_centerline():
    network = polygon_network(box(0.0, 0.0, 100.0, 10.0))
    assert same_points(network.split_points, [(0.0, 5.0), (100.0, 5.0)], RELATIVE * 100.0)
    (branch,) = network.branches
    assert branch.kind == "arm" and {branch.start_node, branch.end_node} == {0, 1}
    # A ring around an island has no leaf at all: the main stem's ends (find_ends) are its ends.
    ring = box(0.0, 0.0, 100.0, 100.0).difference(box(10.0, 10.0, 90.0, 90.0))
    main = find_ends(ring)
    network = polygon_network(ring)
    assert same_points(network.split_points, [main.start.coords[0], main.end.coords[0]], RELATIVE * 100.0)


@pytest.fixture(scope="module")
def reservoirs():
    return real_rivers()


@pytest.mark.slow
def test_every_real_reservoir_gets_an_exact_network_through_its_main_stem_ends(reservoirs):
    for river in reservoirs:
        polygon = river.polygon
        arms = find_arm_ends(polygon)
        network = polygon_network(polygon)
        check_topology(network, len(arms.points))
        assert len(network.split_points) >= 2
        # find_ends' two ends (the main stem) are arm ends: within the arm's width.
        main = find_ends(polygon)
        for end in (main.start, main.end):
            distance = np.hypot(*(arms.points - end.coords[0]).T)
            assert np.any(distance <= arms.widths), river.name
        # Every kept arm reaches at least one junction width beyond its junction's circle.
        assert np.all(arms.reaches >= MIN_ARM_RATIO), river.name
        extent = extent_of(polygon)
        radii = network.junction_radii
        for junction, radius in zip(network.junctions, radii):
            assert shapely.distance(polygon.boundary, shapely.Point(junction)) == pytest.approx(
                radius, abs=RELATIVE * extent
            )


def test_a_real_reservoir_with_arms_is_checked_by_the_oracle(reservoirs):
    (river,) = [river for river in reservoirs if river.name.startswith("Cahora Bassa")]
    network = polygon_network(river.polygon)
    assert len(network.split_points) >= 3
    check_network(river.polygon, network, sides=False)


def test_arm_ends_of_a_long_pointed_arm_are_its_tip():
    arm = LineString([(0.0, 0.0), (100.0, 0.0)]).buffer(5.0, cap_style="flat")
    spike = Polygon([(40.0, 4.0), (60.0, 4.0), (50.0, 4.0 + 40.0 * math.sqrt(3.0))])
    polygon = unary_union([arm, spike])
    ends = find_arm_ends(polygon)
    assert len(ends.points) == 3
    assert min(np.hypot(*(ends.points - (50.0, 4.0 + 40.0 * math.sqrt(3.0))).T)) <= 1e-9 * 100.0


def check_loops(polygon, network, islands):
    """Every vertex of every branch lies at its radius from its two chains (an island's ring for a channel
    island's chain) and no nearer to any other; every junction is equidistant from three of them."""
    from tests.test_core_network import distance_to, ring_chains

    _, sites = ring_chains(polygon, network)
    sites = sites + [[np.asarray(ring)] for ring in islands]
    tolerance = RELATIVE * extent_of(polygon)
    for branch in network.branches:
        vertices = shapely.get_coordinates(branch.result.line)
        distances = np.array([distance_to(vertices, site) for site in sites])
        for chain in (branch.right_chain, branch.left_chain):
            assert np.abs(distances[chain] - branch.result.radii).max() <= tolerance
        assert np.all(distances.min(axis=0) >= branch.result.radii - tolerance)
    for junction, radius in zip(network.junctions, network.junction_radii):
        distances = np.array([distance_to(junction[None], site)[0] for site in sites])
        assert np.sum(np.abs(distances - radius) <= tolerance) >= 3
        assert distances.min() >= radius - tolerance


def braided_reach():
    """A reach 600 long and 60 wide with three islands in a row, 20 and 10 wide: closed-form junctions."""
    islands = [box(100.0, 20.0, 180.0, 40.0), box(260.0, 25.0, 340.0, 35.0), box(420.0, 15.0, 520.0, 35.0)]
    polygon = Polygon(box(0.0, 0.0, 600.0, 60.0).exterior.coords, [island.exterior.coords for island in islands])
    return polygon, islands


def test_a_braided_reach_with_three_islands_has_a_loop_around_each():
    polygon, islands = braided_reach()
    network = polygon_network(polygon, islands="channels")
    assert same_points(network.split_points, [(0.0, 30.0), (600.0, 30.0)], RELATIVE * 600.0)
    assert len(network.junctions) == 6
    # Up- and downstream of each island the circle touches both banks (radius 30, centre y = 30) and the
    # island's end face: its centre lies 30 before or after it (the islands' end faces are straight).
    expected = [(x, 30.0) for island in islands for x in (island.bounds[0] - 30.0, island.bounds[2] + 30.0)]
    assert same_points(network.junctions, expected, RELATIVE * 600.0)
    assert np.allclose(network.junction_radii, 30.0, atol=RELATIVE * 600.0)
    kinds = sorted(branch.kind for branch in network.branches)
    assert kinds == ["arm"] * 2 + ["inner"] * 2 + ["loop"] * 6
    degrees = network.node_degrees
    assert list(degrees[:2]) == [1, 1] and set(degrees[2:]) == {3}
    check_loops(polygon, network, [shapely.get_coordinates(island.exterior) for island in islands])


@pytest.mark.parametrize(("columns", "rows"), [(1, 1), (2, 1), (2, 2), (4, 2), (5, 5)])
def test_a_road_grid_with_blocks_as_holes_gives_its_street_network(columns, rows):
    # Streets 10 wide around 40 x 40 blocks (holes), each street leaving by a stub: one branch per street
    # segment between two crossings (including those between two blocks) and one per stub; every crossing a
    # junction of degree four at its closed-form centre, found with automatic ends as with the given ones.
    polygon, caps, crossings, radius = cases.road_grid(columns, rows)
    tolerance = RELATIVE * extent_of(polygon)
    segments = columns * (rows + 1) + rows * (columns + 1)
    for network in (polygon_network(polygon, islands="channels"), polygon_network(polygon, caps, islands="channels")):
        assert same_points(network.split_points, caps, tolerance)
        assert same_points(network.junctions, crossings, tolerance)
        assert np.allclose(network.junction_radii, radius, rtol=0.0, atol=tolerance)
        assert len(network.branches) == len(caps) + segments
        assert list(network.node_degrees[len(caps) :]) == [4] * len(crossings)
        between_blocks = [b for b in network.branches if min(b.right_chain, b.left_chain) >= len(caps)]
        assert len(between_blocks) == (columns - 1) * rows + (rows - 1) * columns
        for branch in network.branches:  # each street segment is straight, from crossing to crossing or cap
            ends = network.nodes[[branch.start_node, branch.end_node]]
            assert branch.result.length == pytest.approx(float(np.hypot(*(ends[1] - ends[0]))), abs=tolerance)
        check_loops(polygon, network, [shapely.get_coordinates(ring) for ring in polygon.interiors])


def test_small_islands_keep_the_main_channel_rule_among_channels():
    polygon, _ = braided_reach()
    pebble = box(40.0, 10.0, 42.0, 12.0)
    with_pebble = Polygon(
        polygon.exterior.coords, [*[ring.coords for ring in polygon.interiors], pebble.exterior.coords]
    )
    network = polygon_network(with_pebble, islands="channels")
    assert len(network.junctions) == 6
    for branch in network.branches:
        assert not branch.result.line.intersects(pebble)
    # The other modes keep their meaning: one line past every island.
    (branch,) = polygon_network(polygon, islands="main_channel").branches
    assert branch.kind == "arm"
    with pytest.raises(Exception, match="island mode"):
        polygon_network(polygon, islands="braided")
