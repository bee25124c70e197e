"""The centerline lies on the medial axis between the chains: the oracle and the analytic axes say where.

- Every interior vertex is on the oracle's target set (the pyvoronoi medial axis between the two chains)
  within ``1e-7`` of the extent, plus the oracle's own error bound.
- Every interior vertex is on the analytic axis within the shape's polygonisation bound, away from the caps
  (``Case.away_from_ends``).
- The Hausdorff distance from the target set to the line shrinks as the spacing shrinks, and the default
  spacing keeps the mean deviation from the target below ``1e-3`` of the width (the documented rule).
- More samples per chain bring the line closer to the medial axis (the paper's Fig. 4).
"""

import numpy as np
import pytest
import shapely

from incircu_plugin.core import polygon_centerline
from tests.support import geometry_cases
from tests.support.marks import case_params
from tests.support.oracle import MedialOracle

ANALYTIC = geometry_cases.analytic_cases()
WAVY = [
    geometry_cases.wavy_channel(seed=11),
    geometry_cases.wavy_channel(seed=12, n=(31, 70), split_fractions=(0.3, 0.6)),
    geometry_cases.wavy_channel(
        seed=13,
        length=300.0,
        mean_width=12.0,
        n=(150, 140),
        harmonics=((20.0, 150.0, 1.0), (4.0, 37.0, 0.0)),
        placement=geometry_cases.PLACEMENTS["projected"],
    ),
]
GAMBIA = geometry_cases.gambia()
CASES = ANALYTIC + WAVY + [GAMBIA]


_ORACLES = {}


def oracle_for(case):
    """One oracle per case for the whole module (building it costs up to a second)."""
    if case.name not in _ORACLES:
        _ORACLES[case.name] = MedialOracle(case.chain_a, case.chain_b, region=case.polygon)
    return _ORACLES[case.name]


def interior_vertices(result):
    return np.asarray(result.line.coords)[1:-1, :2]


def position_tolerance(case, radii):
    """How precisely floating point can place a vertex of radius ``r`` on an analytic axis, CRS units.

    Distances are exact to ``eps`` = 16 units in the last place of the extent (the engine works in
    coordinates relative to the data's centre). Along a straight stretch that places a vertex to ``eps``,
    but where the incircle also touches a point (a split point, a reflex vertex) the distance to that point
    grows only quadratically off the axis, ``delta**2 / (2 r)``, so the vertex is placed to
    ``sqrt(2 r eps)`` there. Translating back to the data's coordinates adds their rounding.
    """
    eps = 16.0 * float(np.spacing(case.extent))
    return np.sqrt(2.0 * np.asarray(radii) * eps) + eps + 16.0 * case.coordinate_ulp


@pytest.mark.parametrize("fraction", [0.5, 0.1, 0.02], ids=["w/2", "w/10", "w/50"])
@pytest.mark.parametrize("case", case_params(CASES))
def test_every_vertex_lies_on_the_medial_axis_between_the_chains(case, fraction):
    oracle = oracle_for(case)
    result = polygon_centerline(case.polygon, case.split_points, spacing=fraction * case.width)
    vertices = interior_vertices(result)
    distance = oracle.distance(vertices)
    tolerance = 1e-7 * case.extent + 4.0 * oracle.error_bound
    worst = int(np.argmax(distance))
    assert distance[worst] <= tolerance, (
        f"vertex {worst + 1} = {vertices[worst].tolist()} is {distance[worst]:.3g} off the medial axis (tolerance {tolerance:.3g})"
    )


@pytest.mark.parametrize("case", ANALYTIC, ids=[c.name for c in ANALYTIC])
def test_every_vertex_lies_on_the_analytic_axis(case):
    result = polygon_centerline(case.polygon, case.split_points, spacing=0.1 * case.width)
    vertices = interior_vertices(result)
    away = case.away_from_ends(vertices)
    assert away.sum() >= 10
    tolerance = case.axis_tolerance + 1e-9 * case.extent + position_tolerance(case, result.radii[1:-1][away])
    excess = case.axis_distance(vertices[away]) - tolerance
    worst = int(np.argmax(excess))
    assert excess[worst] <= 0.0, (
        f"vertex {vertices[away][worst].tolist()} is {excess[worst] + tolerance[worst]:.3g} off the axis, tolerance {tolerance[worst]:.3g}"
    )


@pytest.mark.parametrize("case", ANALYTIC[:4], ids=[c.name for c in ANALYTIC[:4]])
def test_straight_axes_are_reproduced_exactly(case):
    # Rectangle and tapered channel: the whole line, chords included, is the straight axis.
    result = polygon_centerline(case.polygon, case.split_points, spacing=0.1 * case.width)
    tolerance = 1e-9 * case.extent + position_tolerance(case, result.radii)
    assert np.all(case.axis_distance(np.asarray(result.line.coords)) <= tolerance)
    assert result.line.length == pytest.approx(case.axis_line.length, abs=float(tolerance.sum()))


@pytest.mark.parametrize("case", ANALYTIC[:4], ids=[c.name for c in ANALYTIC[:4]])
def test_straight_axes_have_the_exact_widths(case):
    # The incircle of a point of the axis of a rectangle or a symmetric trapezoid touches both long sides.
    result = polygon_centerline(case.polygon, case.split_points, spacing=0.1 * case.width)
    vertices = interior_vertices(result)
    half_width = np.minimum(
        shapely.distance(shapely.LineString(case.bank_a), shapely.points(vertices)),
        shapely.distance(shapely.LineString(case.bank_b), shapely.points(vertices)),
    )
    tolerance = 1e-9 * case.extent + 16.0 * case.coordinate_ulp
    assert np.abs(result.radii[1:-1] - half_width).max() <= tolerance


#: Spacings, as fractions of the width, over which the Hausdorff distance must shrink.
HAUSDORFF_FRACTIONS = [0.4, 0.2, 0.1, 0.05, 0.025]
HAUSDORFF_CASES = [ANALYTIC[3], ANALYTIC[4], ANALYTIC[6]] + WAVY[:2] + [GAMBIA]


@pytest.mark.slow
@pytest.mark.parametrize("case", HAUSDORFF_CASES, ids=[c.name for c in HAUSDORFF_CASES])
def test_hausdorff_distance_to_the_medial_axis_shrinks_with_the_spacing(case):
    oracle = oracle_for(case)
    # Each measurement is exact to `step`: 1e-4 of the width, below the chord errors being compared.
    step = 1e-4 * case.width
    distances = []
    for fraction in HAUSDORFF_FRACTIONS:
        result = polygon_centerline(case.polygon, case.split_points, spacing=fraction * case.width)
        distances.append(oracle.hausdorff_from_target(result.line, step))
    report = ", ".join(f"w*{f:g}: {d:.3g}" for f, d in zip(HAUSDORFF_FRACTIONS, distances))
    # Never worse with a finer spacing (to the measurement's resolution) ...
    assert all(later <= earlier + step for earlier, later in zip(distances, distances[1:])), report
    # ... and 16 times finer sampling at least halves it: chords converge quadratically on smooth stretches
    # of the axis and linearly at its corners, so a factor 2 is the least a correct method achieves.
    assert distances[-1] <= 0.5 * distances[0] + step, report


@pytest.mark.parametrize("case", HAUSDORFF_CASES, ids=[c.name for c in HAUSDORFF_CASES])
def test_default_spacing_keeps_the_mean_deviation_below_a_thousandth_of_the_width(case):
    oracle = oracle_for(case)
    result = polygon_centerline(case.polygon, case.split_points)
    # Mean over the line's length: sample it at equal arc-length steps.
    stations = np.linspace(0.0, result.line.length, 20_001)
    points = shapely.get_coordinates(shapely.line_interpolate_point(result.line, stations))
    mean_deviation = float(np.mean(oracle.distance(points)))
    assert mean_deviation <= 1e-3 * case.width, f"mean deviation {mean_deviation:.3g}, width {case.width:.3g}"


@pytest.mark.slow
def test_more_samples_per_chain_bring_the_line_closer_to_the_medial_axis():
    # The paper's Fig. 4: average distance to the medial axis against the number of points per chain.
    case = WAVY[0]
    oracle = oracle_for(case)
    counts = [10, 20, 40, 80, 160, 320]
    means = []
    for count in counts:
        result = polygon_centerline(case.polygon, case.split_points, samples_per_chain=count)
        stations = np.linspace(0.0, result.line.length, 20_001)
        points = shapely.get_coordinates(shapely.line_interpolate_point(result.line, stations))
        means.append(float(np.mean(oracle.distance(points))))
    report = ", ".join(f"{n}: {m:.3g}" for n, m in zip(counts, means))
    assert means[-1] < means[0] / 4.0, report
    assert means[-1] <= 1e-3 * case.width, report


@pytest.mark.slow
def test_the_fan_at_a_reflex_corner_traces_the_parabolic_arcs():
    # An L-shaped channel of width 10: around the inner corner (50, 10), a reflex vertex with a 90 degree
    # turn, the medial axis is two parabolic arcs (focus (50, 10), directrices y = 0 and x = 60) meeting at
    # the outer corner's bisector, J = (60 - d, d) with d = 10 / (1 + 1/sqrt(2)). A single normal per
    # vertex would cut those arcs by up to r (1 - cos 45 deg) ~ 0.3 r; the fan's parabola stations keep every
    # chord within the tolerance (here 1e-3 of the width), and the junction is an exact vertex.
    polygon = shapely.Polygon([(0, 0), (60, 0), (60, 60), (50, 60), (50, 10), (0, 10)])
    ends = [(0.0, 5.0), (55.0, 60.0)]
    chain_a = np.array([ends[0], (0, 0), (60, 0), (60, 60), ends[1]], dtype=float)
    chain_b = np.array([ends[0], (0, 10), (50, 10), (50, 60), ends[1]], dtype=float)
    oracle = MedialOracle(chain_a, chain_b, region=polygon)
    tolerance = 1e-3 * 10.0
    result = polygon_centerline(polygon, ends, tolerance=tolerance)
    d = 10.0 / (1.0 + 1.0 / np.sqrt(2.0))
    junction = np.array([60.0 - d, d])
    assert oracle.distance(junction[None])[0] <= 4.0 * oracle.error_bound
    assert np.hypot(*(np.asarray(result.line.coords) - junction).T).min() <= 1e-9 * 60.0
    assert oracle.hausdorff_from_target(result.line, 1e-5 * 10.0) <= tolerance + 1e-5 * 10.0
