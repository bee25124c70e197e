"""The references themselves: the analytic shape builders and the pyvoronoi medial-axis oracle.

Before the oracle judges the engine it must agree with the axes known in closed form: the rectangle's and
the tapered channel's straight axes, the annulus sector's arc and the meander's sine. Tolerances are the
analytic cases' own polygonisation bound (``Case.axis_tolerance``) plus the oracle's error bound (grid
rounding and parabola chords), with a factor 4 on the latter for the amplification of the grid's rounding
by the bisector of two rounded segments (at most a factor sqrt(2) per coordinate, twice).
"""

import math

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString

from tests.support import geometry_cases
from tests.support.marks import case_params
from tests.support.oracle import MedialOracle, segment_distances

ANALYTIC = geometry_cases.analytic_cases()


def oracle_tolerance(case, oracle):
    """How far target and analytic axis may be apart, CRS units."""
    return case.axis_tolerance + 4.0 * oracle.error_bound


@pytest.mark.parametrize("case", ANALYTIC, ids=[c.name for c in ANALYTIC])
def test_builder_makes_a_valid_split_polygon(case):
    assert case.polygon.is_valid
    ring = case.ring
    assert np.array_equal(ring[0], ring[-1])
    assert np.array_equal(case.chain_a[0], case.chain_b[0])
    assert np.array_equal(case.chain_a[-1], case.chain_b[-1])
    assert tuple(case.chain_a[0]) == case.split_points[0]
    assert tuple(case.chain_a[-1]) == case.split_points[1]
    perimeter = LineString(case.chain_a).length + LineString(case.chain_b).length
    assert math.isclose(perimeter, case.polygon.exterior.length, rel_tol=1e-12)
    # The split points lie on the boundary, as ring vertices.
    assert shapely.distance(case.polygon.exterior, shapely.points(np.asarray(case.split_points))).max() == 0.0


@pytest.mark.parametrize("case", ANALYTIC, ids=[c.name for c in ANALYTIC])
def test_analytic_axis_lies_inside_and_spans_the_split_points(case):
    axis = np.asarray(case.axis_line.coords)
    assert np.hypot(*(axis[0] - case.split_points[0])) <= case.axis_tolerance
    assert np.hypot(*(axis[-1] - case.split_points[1])) <= case.axis_tolerance
    assert case.axis_distance(axis).max() <= case.axis_tolerance
    assert shapely.distance(case.polygon, shapely.points(axis)).max() <= case.axis_tolerance


@pytest.mark.parametrize("case", ANALYTIC, ids=[c.name for c in ANALYTIC])
def test_oracle_target_is_the_analytic_axis(case):
    oracle = MedialOracle(case.chain_a, case.chain_b)
    tolerance = oracle_tolerance(case, oracle)
    assert oracle.grid_error <= 1e-9 * case.extent
    assert oracle.discretisation_error <= 1e-9 * case.extent

    target = oracle.segments[~oracle.stub].reshape(-1, 2)
    target = target[case.away_from_ends(target)]
    assert len(target)
    assert case.axis_distance(target).max() <= tolerance

    axis = shapely.get_coordinates(shapely.segmentize(case.axis_line, case.extent / 500.0))
    axis = axis[case.away_from_ends(axis)]
    assert oracle.distance(axis).max() <= tolerance


@pytest.mark.parametrize("case", case_params(ANALYTIC))
def test_oracle_target_points_are_equidistant_from_both_chains(case):
    oracle = MedialOracle(case.chain_a, case.chain_b)
    points = oracle.segments.reshape(-1, 2)
    gap = np.abs(segment_distances(points, case.chain_a) - segment_distances(points, case.chain_b))
    assert gap.max() <= 4.0 * oracle.error_bound


def test_oracle_straight_target_has_the_stubs_to_the_split_points():
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=11)
    oracle = MedialOracle(case.chain_a, case.chain_b)
    # Points on the stub from (0, 5) to (5, 5) have the split point as nearest boundary point.
    assert oracle.distance(np.array([[1.0, 5.0], [50.0, 5.0], [99.0, 5.0]])).max() == 0.0
    assert oracle.stub.any()
    # Points off the axis or on a corner branch are not on the target.
    assert oracle.distance(np.array([[50.0, 4.0]]))[0] == pytest.approx(1.0)
    assert oracle.distance(np.array([[2.0, 2.0]]))[0] == pytest.approx(3.0)


def test_oracle_hausdorff_of_the_exact_axis_is_zero_and_of_a_shifted_one_is_the_shift():
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=11)
    oracle = MedialOracle(case.chain_a, case.chain_b)
    step = 1e-3 * case.width
    assert oracle.hausdorff_from_target(case.axis_line, step) <= step
    shifted = LineString([(0.0, 5.5), (100.0, 5.5)])
    assert oracle.hausdorff_from_target(shifted, step) == pytest.approx(0.5, abs=step)
    half = LineString([(0.0, 5.0), (50.0, 5.0)])
    assert oracle.hausdorff_from_target(half, step) == pytest.approx(50.0, abs=step)


def test_oracle_parabola_around_a_reflex_vertex_is_exact():
    # Chain a has a reflex vertex at (50, 3): the axis around it is the parabola with focus (50, 3) and
    # directrix y = 10 (the opposite straight side), y = 6.5 - (x - 50)**2 / 14.
    chain_a = np.array([[0.0, 5.0], [0.0, 0.0], [50.0, 3.0], [100.0, 0.0], [100.0, 5.0]])
    chain_b = np.array([[0.0, 5.0], [0.0, 10.0], [100.0, 10.0], [100.0, 5.0]])
    oracle = MedialOracle(chain_a, chain_b)
    # The vertex is the nearest boundary point only inside the wedge of its two edges' normals, which
    # lean by 3/50 per unit of height: at the parabola's height (about 3.5 above the vertex) |x - 50| < 0.21.
    x = np.linspace(49.8, 50.2, 41)
    parabola = np.stack([x, 6.5 - (x - 50.0) ** 2 / 14.0], axis=1)
    focus_distance = np.hypot(parabola[:, 0] - 50.0, parabola[:, 1] - 3.0)
    assert np.allclose(focus_distance, 10.0 - parabola[:, 1])
    assert np.all(np.abs(parabola[:, 0] - 50.0) < 3.0 / 50.0 * (parabola[:, 1] - 3.0))
    assert oracle.distance(parabola).max() <= 4.0 * oracle.error_bound + 1e-9 * oracle.extent


def test_gambia_fixture_is_the_natural_earth_outline():
    lonlat = geometry_cases.load_gambia(projected=False)
    projected = geometry_cases.load_gambia(projected=True)
    assert lonlat.is_valid and projected.is_valid
    assert len(lonlat.exterior.coords) == len(projected.exterior.coords) == 402
    west, south, east, north = lonlat.bounds
    # The Gambia lies between 16.9 W and 13.7 W, 13.0 N and 13.9 N.
    assert -16.9 < west < east < -13.7 and 13.0 < south < north < 13.9
    # About 11,000 km2 (Natural Earth's outline of a 10,690 km2 country, rivers included).
    assert 1.0e10 < projected.area < 1.2e10
    case = geometry_cases.gambia()
    assert case.polygon.is_valid
    assert np.array_equal(case.chain_a[0], case.chain_b[0]) and np.array_equal(case.chain_a[-1], case.chain_b[-1])
    assert len(case.chain_a) + len(case.chain_b) - 2 == case.vertex_count


def test_meander_is_the_buffer_of_its_sine_curve():
    case = geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0, n=(301, 287))
    x = np.linspace(0.0, 800.0, 40_001)
    sine = LineString(np.stack([x, 40.0 * np.sin(2.0 * math.pi * x / 400.0)], axis=1))
    buffered = sine.buffer(10.0, cap_style="flat", quad_segs=64)
    # The two differ by the bank chords (sagitta <= axis_tolerance) along both banks.
    difference = case.polygon.symmetric_difference(buffered).area
    assert difference <= 2.0 * (2.0 * case.axis_tolerance + 1e-6) * sine.length
    counted = geometry_cases.meander_with_vertex_count(2333)
    assert counted.vertex_count == 2333 and counted.polygon.is_valid


@pytest.mark.parametrize("n_samples", [1_000, 10_000])
def test_synthetic_river_has_the_requested_size_and_is_valid(n_samples):
    case = geometry_cases.synthetic_river(n_samples, seed=1, validate=True)
    assert case.vertex_count == n_samples + 2
    assert case.polygon.is_valid
    mean_width = case.polygon.area / ((LineString(case.bank_a).length + LineString(case.bank_b).length) / 2)
    assert 0.8 * case.width < mean_width < 1.2 * case.width


def test_placements_round_trip():
    points = np.array([[0.0, 0.0], [100.0, 10.0], [-3.0, 7.5]])
    for placement in geometry_cases.PLACEMENTS.values():
        back = placement.invert(placement.apply(points))
        assert np.abs(back - points).max() <= 1e-9 * 100.0


@pytest.mark.parametrize(
    "case",
    [geometry_cases.rectangle(n=(7, 13), jitter=0.4, seed=3), geometry_cases.tapered_channel()],
    ids=["rectangle", "tapered"],
)
def test_oracle_open_mode_target_is_the_whole_axis_between_the_gaps(case):
    # Two banks without caps: the medial axis between them runs from one end gap to the other, crossing the
    # gaps (which are not boundary), so the oracle must close the diagram and clip at the gaps.
    region = geometry_cases.channel_case("region", case.bank_a, case.bank_b, case.width).polygon
    oracle = MedialOracle(case.bank_a, case.bank_b, region=region)
    assert not oracle.closed
    tolerance = 4.0 * oracle.error_bound + 1e-12 * case.extent
    axis = shapely.get_coordinates(shapely.segmentize(case.axis_line, case.extent / 500.0))
    assert oracle.distance(axis).max() <= tolerance
    assert case.axis_distance(oracle.segments.reshape(-1, 2)).max() <= tolerance
    assert oracle.length == pytest.approx(case.axis_line.length, abs=tolerance * len(oracle.segments))
