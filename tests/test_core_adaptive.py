"""The adaptive sampling (the default): within ``tolerance`` of the exact medial axis, few vertices, all exact.

Against the segment-Voronoi oracle (``tests/oracle.py``, no code shared with the engine), on every shape of
the suite and on random compact shapes and near-end configurations:

- every interior vertex lies on the medial axis between the chains (``1e-7`` of the extent plus the
  oracle's own error bound), the invariants of :func:`oracle.check_centerline` hold (ends exact, one simple
  line, equidistant empty incircles);
- the Hausdorff distance between the line and the oracle's target set is at most the tolerance (plus the
  measurement's resolution): from the target to the line by the oracle's refinement, from the line to the
  target on the line densified to a tenth of the tolerance;
- the line has at most 1.5 times as many vertices as the two chains together.

The tolerances are the documented rule (typical width / 200) or a tighter one given explicitly; nothing is
copied from a previous run.
"""

import json
import math

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Polygon, box

from incircu_plugin.core import (
    IncirCuError,
    centerline_from_chains,
    default_tolerance,
    lines,
    lines_centerline,
    polygon_centerline,
    split_polygon,
)
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core._steps import TraceRequest
from incircu_plugin.core.api import _polygon_centerline_steps
from incircu_plugin.core.contacts import Boundary
from incircu_plugin.core.errors import OptionError
from incircu_plugin.core.tracing import SETTLED_CHORD, TraceOptions, Tracer, TraceStats, observed
from incircu_plugin.core.tracing.initial import initial_samples, intervals_between
from incircu_plugin.core.tracing.intervals import Intervals, split_at_nodes
from incircu_plugin.core.tracing.settling import sag_bound
from incircu_plugin.core.tracing.sites import radius_at
from incircu_plugin.core.tracing.spans import FAN
from tests.support import geometry_cases
from tests.support.marks import case_params
from tests.support.oracle import MedialOracle, assert_within_tolerance, check_centerline

ANALYTIC = geometry_cases.analytic_cases()
WAVY = [
    geometry_cases.wavy_channel(seed=31),
    geometry_cases.wavy_channel(seed=32, n=(25, 80), split_fractions=(0.15, 0.9), teeth=0.05),
    geometry_cases.wavy_channel(
        seed=33,
        length=250.0,
        mean_width=15.0,
        n=(120, 160),
        harmonics=((15.0, 120.0, 0.5), (3.0, 41.0, 1.0)),
        placement=geometry_cases.PLACEMENTS["projected"],
    ),
]
GAMBIA = geometry_cases.gambia()
CASES = ANALYTIC + WAVY + [GAMBIA]


#: Largest ratio of output vertices to the vertices of both chains at the default tolerance.
VERTEX_RATIO = 1.5


@pytest.mark.parametrize("case", case_params(CASES, other_placements=True))
def test_default_tolerance_bounds_the_distance_to_the_medial_axis(case):
    result = polygon_centerline(case.polygon, case.split_points)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)
    tolerance = default_tolerance(case.chain_a, case.chain_b)
    assert_within_tolerance(result, case.chain_a, case.chain_b, case.polygon, tolerance)
    assert len(result.line.coords) <= VERTEX_RATIO * (len(case.chain_a) + len(case.chain_b))


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_a_tight_tolerance_bounds_the_distance_to_the_medial_axis(case):
    tolerance = case.width / 2000.0
    result = polygon_centerline(case.polygon, case.split_points, tolerance=tolerance)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)
    assert_within_tolerance(result, case.chain_a, case.chain_b, case.polygon, tolerance)


@pytest.mark.slow
@pytest.mark.parametrize("piece", [2, 5, 16])
def test_a_line_simplified_in_pieces_stays_within_the_tolerance(monkeypatch, piece):
    # Long lines are simplified in pieces that share their end vertices (SIMPLIFY_PIECE points each).
    case = geometry_cases.meander()
    monkeypatch.setattr(lines, "SIMPLIFY_PIECE", piece)
    result = polygon_centerline(case.polygon, case.split_points)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)
    tolerance = default_tolerance(case.chain_a, case.chain_b)
    assert_within_tolerance(result, case.chain_a, case.chain_b, case.polygon, tolerance)


@pytest.mark.parametrize("piece", [3, 40, 10_000])
def test_pieces_keep_their_ends_and_every_dropped_vertex_near_its_chord(monkeypatch, piece):
    rng = np.random.default_rng(7)
    # Increasing x: neither the line nor any subset of its vertices crosses itself (no topology fallback).
    points = np.cumsum(
        np.abs(rng.normal(size=(1_000, 2))) * [1.0, 0.0] + rng.normal(size=(1_000, 2)) * [0.0, 1.0], axis=0
    )
    tolerance = 0.5
    monkeypatch.setattr(lines, "SIMPLIFY_PIECE", piece)
    keep = lines._fewest_vertices(points, tolerance)
    assert keep[::piece].all() and keep[-1]
    kept = np.flatnonzero(keep)
    chords = shapely.linestrings(np.stack([points[kept[:-1]], points[kept[1:]]], axis=1))
    owner = np.searchsorted(kept, np.arange(len(points)), side="right") - 1
    dropped = np.flatnonzero(~keep)
    distance = shapely.distance(chords[owner[dropped]], shapely.points(points[dropped]))
    assert distance.max() <= tolerance * (1.0 + 1e-12)
    if piece >= len(points):
        plain = shapely.simplify(shapely.LineString(points), tolerance, preserve_topology=False)
        assert np.array_equal(points[keep], shapely.get_coordinates(plain))


def test_the_pieces_are_the_same_in_any_batches(monkeypatch):
    rng = np.random.default_rng(11)
    points = np.cumsum(
        np.abs(rng.normal(size=(1_001, 2))) * [1.0, 0.0] + rng.normal(size=(1_001, 2)) * [0.0, 1.0], axis=0
    )
    monkeypatch.setattr(lines, "SIMPLIFY_PIECE", 40)
    masks = []
    for batch in (1, 3, 100):
        monkeypatch.setattr(lines, "SIMPLIFY_BATCH", batch)
        masks.append(lines._fewest_vertices(points, 0.5))
    # 1000 segments: 25 pieces, in batches of 1, 3 (the last one shorter) or all at once.
    assert masks[0][::40].all() and masks[0][-1]
    assert np.array_equal(masks[0], masks[1]) and np.array_equal(masks[0], masks[2])


def test_a_tighter_tolerance_gives_more_vertices_on_a_curved_axis():
    case = geometry_cases.annulus_sector(n=61)
    counts = [
        len(polygon_centerline(case.polygon, case.split_points, tolerance=t).line.coords) for t in (1.0, 0.1, 0.01)
    ]
    assert counts[0] < counts[1] < counts[2]


def test_a_straight_channel_is_its_ends_and_the_two_ends_of_its_axis():
    # The axis of a rectangle split at the middles of its short sides is the whole mid-line: the stubs from
    # the split points (radius 0) meet the two long sides' bisector at (5, 5) and (95, 5) (radius 5, the
    # half width, which the width statistics need); nothing else, whatever the number of boundary vertices.
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=50)
    result = polygon_centerline(case.polygon, case.split_points)
    assert [tuple(p) for p in result.line.coords] == [(0.0, 5.0), (5.0, 5.0), (95.0, 5.0), (100.0, 5.0)]
    assert result.radii.tolist() == [0.0, 5.0, 5.0, 0.0]


NORWAY_FILE = geometry_cases.DATA_FOLDER / "norway_ne10m_aeqd.geojson"


@pytest.mark.slow
def test_an_event_between_two_nearly_collinear_segments_at_a_split_point_is_on_the_axis():
    # Norway's north-eastern split point is a vertex turning by about 3e-7 rad. Next to it the closed-form
    # event between the two segments meeting there is ill-conditioned: a probe 0.62 m beside the true junction
    # touched both to 5e-9 of its radius (within the event tolerance) and became a vertex 4e-7 x extent off
    # the axis. The vertices must be on the oracle's axis to its own resolution.
    feature = json.loads(NORWAY_FILE.read_text())["features"][0]
    polygon = Polygon(feature["geometry"]["coordinates"][0])
    split_points = [tuple(point) for point in feature["properties"]["split_points"]]
    result = polygon_centerline(polygon, split_points)
    oracle = MedialOracle(*split_polygon(polygon, split_points), region=polygon)
    distance = oracle.distance(np.asarray(result.line.coords)[1:-1, :2])
    assert distance.max() <= 1e-9 * oracle.extent + 4.0 * oracle.error_bound


OPEN = [c for c in ANALYTIC if not c.name.startswith("annulus sector r=30")] + WAVY[:2]


@pytest.mark.parametrize("case", case_params(OPEN, other_placements=True))
def test_open_mode_is_within_the_tolerance_away_from_the_end_gaps(case):
    line_a, line_b = geometry_cases.bank_pair(case, False, True)
    region = geometry_cases.channel_case("region", case.bank_a, case.bank_b, case.width).polygon
    ends = [0.5 * (case.bank_a[i] + case.bank_b[i]) for i in (0, -1)]
    result = lines_centerline(line_a, line_b)
    check_centerline(result, case.bank_a, case.bank_b, region, [tuple(end) for end in ends])
    gap = max(np.hypot(*(case.bank_a[i] - case.bank_b[i])) for i in (0, -1))
    tolerance = default_tolerance(case.bank_a, case.bank_b)
    assert_within_tolerance(result, case.bank_a, case.bank_b, region, tolerance, near_ends=(ends, gap))


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -1.0, "0.5", True, [1.0]])
def test_a_tolerance_that_is_not_a_positive_length_is_an_option_error(bad):
    case = geometry_cases.rectangle()
    with pytest.raises(OptionError, match="tolerance"):
        polygon_centerline(case.polygon, case.split_points, tolerance=bad)
    assert issubclass(OptionError, IncirCuError)


def test_a_tolerance_below_what_float64_resolves_is_an_option_error():
    case = geometry_cases.rectangle()
    extent = float(np.ptp(np.asarray(case.polygon.exterior.coords), axis=0).max())
    with pytest.raises(OptionError, match="below 1e-09 of the shape's extent"):
        polygon_centerline(case.polygon, case.split_points, tolerance=1e-300)
    assert polygon_centerline(case.polygon, case.split_points, tolerance=2e-9 * extent).line.is_simple


def test_a_tolerance_with_a_spacing_is_an_option_error():
    case = geometry_cases.rectangle()
    with pytest.raises(OptionError, match="either a tolerance"):
        centerline_from_chains(case.chain_a, case.chain_b, 1.0, tolerance=0.1)


@pytest.mark.parametrize("tolerance", [None, 0, 0.0])
def test_no_tolerance_and_zero_mean_the_documented_default(tolerance):
    case = geometry_cases.wavy_channel(seed=5)
    expected = polygon_centerline(
        case.polygon, case.split_points, tolerance=default_tolerance(case.chain_a, case.chain_b)
    )
    result = polygon_centerline(case.polygon, case.split_points, tolerance=tolerance)
    assert result.line.equals_exact(expected.line, 0.0)


# Property tests: compact shapes (regular polygons, stars, squares) and split points near corners and ends.

PROPERTY_SETTINGS = settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True, database=None
)


def regular_polygon(corners, phase, radius=1.0):
    angles = phase + 2.0 * np.pi * np.arange(corners) / corners
    return Polygon(np.stack([radius * np.cos(angles), radius * np.sin(angles)], axis=1))


def star(tips, inner, phase):
    angles = phase + np.pi * np.arange(2 * tips) / tips
    radius = np.where(np.arange(2 * tips) % 2 == 0, 1.0, inner)
    return Polygon(np.stack([radius * np.cos(angles), radius * np.sin(angles)], axis=1))


def on_edge(ring, edge, fraction):
    """The point ``fraction`` of the way along edge ``edge`` of a closed ring's vertex array."""
    start, end = ring[edge % len(ring)], ring[(edge + 1) % len(ring)]
    return tuple(start + fraction * (end - start))


def assert_adaptive_properties(polygon, split_points):
    result = polygon_centerline(polygon, split_points)
    chain_a, chain_b = split_polygon(polygon, split_points)
    check_centerline(result, chain_a, chain_b, polygon, [tuple(chain_a[0]), tuple(chain_a[-1])])
    assert_within_tolerance(result, chain_a, chain_b, polygon, default_tolerance(chain_a, chain_b))
    assert len(result.line.coords) <= VERTEX_RATIO * (len(chain_a) + len(chain_b))
    return result


@st.composite
def compact_shapes(draw):
    """A regular polygon or a star (split at two tips or inside two edges), or a square split on two sides."""
    kind = draw(st.sampled_from(["regular", "star", "square"]))
    phase = draw(st.floats(0.0, 2.0 * math.pi))
    if kind == "regular":
        corners = draw(st.integers(3, 12))
        polygon = regular_polygon(corners, phase)
        ring = np.asarray(polygon.exterior.coords)[:-1]
        second = draw(st.integers(1, corners - 1))
        fractions = draw(st.tuples(st.floats(0.0, 0.99), st.floats(0.0, 0.99)))
        return polygon, [on_edge(ring, 0, fractions[0]), on_edge(ring, second, fractions[1])]
    if kind == "star":
        tips = draw(st.integers(3, 9))
        polygon = star(tips, draw(st.floats(0.3, 0.8)), phase)
        ring = np.asarray(polygon.exterior.coords)[:-1]
        second = 2 * draw(st.integers(1, tips - 1))
        if draw(st.booleans()):
            return polygon, [tuple(ring[0]), tuple(ring[second])]
        return polygon, [on_edge(ring, 0, 0.5), on_edge(ring, second, 0.5)]
    side = draw(st.floats(0.1, 10.0))
    polygon = shapely.segmentize(box(0.0, 0.0, side, side), side / draw(st.integers(1, 20)))
    fractions = draw(st.tuples(st.floats(0.0, 1.0), st.floats(0.0, 1.0)))
    return polygon, [(0.0, fractions[0] * side), (side, fractions[1] * side)]


@pytest.mark.slow
@PROPERTY_SETTINGS
@given(compact_shapes())
def test_compact_shapes_give_one_simple_line_within_the_tolerance(drawn):
    polygon, split_points = drawn
    assert_adaptive_properties(polygon, split_points)


@st.composite
def near_end_channels(draw):
    """A rectangle or a wavy channel with its split points anywhere on its caps, corners included."""
    if draw(st.booleans()):
        length = draw(st.floats(1.0, 30.0))
        polygon = shapely.segmentize(box(0.0, 0.0, length, 1.0), length / draw(st.integers(1, 30)))
        heights = draw(st.tuples(st.floats(0.0, 1.0), st.floats(0.0, 1.0)))
        return polygon, [(0.0, heights[0]), (length, heights[1])]
    case = geometry_cases.wavy_channel(
        seed=draw(st.integers(0, 2**31)),
        jitter=draw(st.floats(0.0, 0.45)),
        split_fractions=(draw(st.floats(0.0, 1.0)), draw(st.floats(0.0, 1.0))),
        teeth=draw(st.sampled_from([0.0, 0.05, 0.2])),
    )
    return case.polygon, case.split_points


@pytest.mark.slow
@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True, database=None)
@given(near_end_channels())
def test_split_points_near_corners_give_one_simple_line_within_the_tolerance(drawn):
    polygon, split_points = drawn
    assert_adaptive_properties(polygon, split_points)


def toothed_channel(length, width, bottom_step, tooth, depth, spike=None):
    """A channel whose bottom bank has a vertex every ``bottom_step`` (long edges: their samples touch sites of
    the top bank several sites apart) and whose top bank has teeth pointing into the region every ``tooth``
    (``depth`` deep: reflex tips, convex valleys); ``spike`` = (x, height) adds a thin spike to the bottom bank.
    Returns the polygon and its split points (the middles of the two ends)."""
    xs = np.arange(0.0, length + 0.5 * bottom_step, bottom_step)
    bottom = [(x, 0.0) for x in xs]
    if spike is not None:
        x, height = spike
        bottom = [p for p in bottom if p[0] < x - 0.2] + [(x - 0.2, 0.0), (x, height), (x + 0.2, 0.0)]
        bottom += [p for p in [(x_, 0.0) for x_ in xs] if p[0] > x + 0.2]
    tips = np.arange(tooth, length - 0.5 * tooth, tooth)
    top = [(length, width)]
    for tip in tips[::-1]:
        top += (
            [(tip + 0.5 * tooth, width), (tip, width - depth)] if tip + 0.5 * tooth < length else [(tip, width - depth)]
        )
    top += [(0.0, width)]
    return Polygon(bottom + top), [(0.0, 0.5 * width), (length, 0.5 * width)]


@pytest.fixture
def trace_stats():
    """What the tracings of a test did (:class:`TraceStats`), every rule on (the cases below must exercise the
    rule they test)."""
    with observed() as stats:
        yield stats


def test_a_walk_over_reflex_teeth_of_the_other_bank_stays_on_the_axis(trace_stats):
    # Each long bottom edge faces several teeth: its contact walks segment, reflex tip, segment, ... (the
    # convex valleys are no sites), and the events between them are predicted in one round.
    polygon, split_points = toothed_channel(40.0, 10.0, 4.0, 1.0, 0.4)
    assert_adaptive_properties(polygon, split_points)
    assert trace_stats.predicted_events > 0


def test_a_walk_interrupted_by_a_spike_of_the_own_bank_stays_on_the_axis(trace_stats):
    # A thin spike of the bottom bank reaches to 2 of the top teeth: between two top sites the disks of the
    # bottom edges beside it touch its tip first, so predicted events between top sites there are wrong.
    polygon, split_points = toothed_channel(40.0, 10.0, 4.0, 1.0, 0.4, spike=(21.0, 7.6))
    assert_adaptive_properties(polygon, split_points)
    assert trace_stats.predicted_events > 0


def test_a_walk_past_a_narrow_bay_of_the_other_bank_stays_on_the_axis(trace_stats):
    # A bay of the top bank behind a narrow mouth: its sites lie between the mouth's in the top bank's order,
    # but no disk of the bottom bank reaches them (the contact jumps across the mouth).
    polygon, split_points = toothed_channel(40.0, 10.0, 4.0, 1.0, 0.4)
    ring = list(polygon.exterior.coords)[:-1]
    mouth = next(i for i, (x, y) in enumerate(ring) if y == 10.0 and 18.0 < x < 22.0)
    x = ring[mouth][0]
    bay = [(x + 0.1, 10.0), (x + 0.1, 10.5), (x + 3.0, 10.5), (x + 3.0, 14.0), (x - 3.0, 14.0), (x - 3.0, 10.5)]
    bay += [(x - 0.1, 10.5), (x - 0.1, 10.0)]
    polygon = Polygon(ring[:mouth] + bay + ring[mouth + 1 :])
    assert polygon.is_valid
    assert_adaptive_properties(polygon, split_points)
    assert trace_stats.predicted_events > 0


@pytest.mark.slow
@pytest.mark.parametrize("widths", [None, 1.0 / 2000.0], ids=["default", "tight"])
def test_a_contact_walking_along_its_own_chain_before_the_other_takes_over_stays_on_the_axis(trace_stats, widths):
    # Near the meander's split points an interval's disks first touch the other chain at one end and the own
    # chain's bank at the other; its two sites' radii do not cross inside it: the own contact walks on along
    # the bank first (predicted and probed in one round).
    case = next(c for c in ANALYTIC if c.name == "meander L=800 W=20 A=40 lambda=400 n=(301, 287) unit")
    tolerance = None if widths is None else widths * case.width
    result = polygon_centerline(case.polygon, case.split_points, tolerance=tolerance)
    check_centerline(result, case.chain_a, case.chain_b, case.polygon, case.split_points)
    tolerance = default_tolerance(case.chain_a, case.chain_b) if tolerance is None else tolerance
    assert_within_tolerance(result, case.chain_a, case.chain_b, case.polygon, tolerance)
    assert trace_stats.approach_sites > 0


def test_predicted_walks_save_the_meanders_rounds():
    # On the meander, intervals at the chain starts see the own contact walk across several own sites before
    # the other bank takes over: predicted, the walk is probed in one round; halved, one site per round.
    case = geometry_cases.meander_with_vertex_count(2333)
    with observed() as walking:
        predicted = polygon_centerline(case.polygon, case.split_points)
    with observed(TraceStats(predict_approaches=False)) as halving:
        halved = polygon_centerline(case.polygon, case.split_points)
    assert walking.approach_sites > 0 and halving.approach_sites == 0
    assert walking.rounds < halving.rounds
    tolerance = default_tolerance(case.chain_a, case.chain_b)
    assert predicted.line.hausdorff_distance(halved.line) <= 2.0 * tolerance
    check_centerline(predicted, case.chain_a, case.chain_b, case.polygon, case.split_points)


BENT_CHANNEL = Polygon([(0.0, 0.0), (50.0, 0.0), (100.0, 20.0), (100.0, 30.0), (45.0, 10.0), (0.0, 10.0)])
#: A reflex corner of the bottom bank next to the left cap: the disks of its fan touch the cap.
NOTCHED_CHANNEL = Polygon([(0.0, 0.0), (2.0, 0.0), (4.0, -2.0), (100.0, -2.0), (100.0, 8.0), (0.0, 10.0)])


@pytest.mark.parametrize(
    "polygon, split_points",
    [
        (BENT_CHANNEL, [(0.0, 3.0), (100.0, 27.0)]),
        (BENT_CHANNEL, [(0.0, 8.5), (100.0, 21.0)]),
        pytest.param(NOTCHED_CHANNEL, [(0.0, 3.0), (100.0, 3.0)], marks=pytest.mark.slow),
        pytest.param(NOTCHED_CHANNEL, [(0.0, 2.5), (100.0, 5.0)], marks=pytest.mark.slow),
    ],
    ids=["bent low", "bent high", "notched fan", "notched fan, other end"],
)
def test_the_contact_crossing_a_straight_split_point_is_found_in_closed_form(polygon, split_points):
    # Split off the middle of its straight caps, a channel's disks near a cap touch the cap on the own chain's
    # side of the split point, then on the other's: one line, so the two sites' radii never cross. The contact
    # passes where the disk is tangent at the split point, in closed form (on an edge, and on a reflex corner's
    # fan); halving the interval instead takes a round per halving, down to the chord that settles it.
    with observed() as in_closed_form:
        closed_form = assert_adaptive_properties(polygon, split_points)
    with observed(TraceStats(cross_split_points=False)) as halving:
        halved = polygon_centerline(polygon, split_points)
    chain_a, chain_b = split_polygon(polygon, split_points)
    tolerance = default_tolerance(chain_a, chain_b)
    # The halvings of an interval half the width (10) long down to the chord that settles it.
    halvings = math.log2(5.0 / (SETTLED_CHORD * tolerance))
    assert in_closed_form.rounds < halvings / 2.0 < halving.rounds
    assert closed_form.line.hausdorff_distance(halved.line) <= 2.0 * tolerance


def test_convex_corners_whose_junction_lies_beyond_an_edge_stay_on_the_axis(trace_stats):
    # A bottom bank bulging out of the region (convex corners), its edges alternately long and very short: a
    # corner's bisector disk touches the short edge beyond its end (left to the rounds), a long one inside it.
    steps = np.cumsum(np.tile([3.0, 0.05], 10))
    xs = np.concatenate([[0.0], 40.0 * steps / steps[-1]])
    bottom = [(x, -3.0 * np.sin(np.pi * x / 40.0)) for x in xs]
    polygon = Polygon(bottom + [(40.0, 10.0), (0.0, 10.0)])
    assert_adaptive_properties(polygon, [(0.0, 5.0), (40.0, 5.0)])
    assert trace_stats.corner_samples > 0


def test_the_ends_middles_and_corners_of_the_edges_are_solved_in_one_pass_along_the_chains():
    # The bulging bank of convex corners: every edge between two corners also has its middle solved first, and
    # every corner its bisector's sample; both go into the one coarse-to-fine solution of the edges' ends, in
    # the order of their points, and nothing else is solved before the rounds.
    xs = np.linspace(0.0, 40.0, 21)
    polygon = Polygon([(x, -3.0 * np.sin(np.pi * x / 40.0)) for x in xs] + [(40.0, 10.0), (0.0, 10.0)])
    with observed(TraceStats(record_solutions=True)) as stats:
        assert_adaptive_properties(polygon, [(0.0, 5.0), (40.0, 5.0)])
    initial = [solution for solution in stats.solutions if solution.stage == "initial"]
    probes = [solution for solution in stats.solutions if solution.stage == "probes"]
    # One tracing; every one of the 19 corners in its one initial solution, none among the rounds' probes.
    assert stats.tracings == 1 and len(initial) == 1 and initial[0].corners == 19
    assert len(probes) == stats.rounds and not any(solution.corners for solution in probes)
    chain, position = initial[0].chain, initial[0].position
    assert np.all((chain[1:] > chain[:-1]) | ((chain[1:] == chain[:-1]) & (position[1:] >= position[:-1])))


def test_trace_options_hold_each_requests_values_for_both_its_chains_and_stats_only_count_inside_the_block():
    chains = [np.array([(0.0, 0.0), (10.0, 0.0)]), np.array([(10.0, 2.0), (0.0, 2.0)])]
    values = [(True, 0.01, 2.0, 50.0, 0.0, (1.0, -1.0)), (False, 0.5, 3.0, 60.0, 1e-9, (-1.0, 1.0))]
    requests = [
        TraceRequest(chains, sides, closed, tolerance, width, max_t, min_t, None)
        for closed, tolerance, width, max_t, min_t, sides in values
    ]
    options = TraceOptions.from_requests(requests)
    assert options.sides.tolist() == [1.0, -1.0, -1.0, 1.0]
    assert options.closed.tolist() == [True, True, False, False]
    assert options.tolerance.tolist() == [0.01, 0.01, 0.5, 0.5]
    assert options.min_t.tolist() == [0.0, 0.0, 1e-9, 1e-9]
    alone = TraceOptions.from_request(requests[1])
    assert alone.width.tolist() == [3.0, 3.0] and alone.max_t.tolist() == [60.0, 60.0]
    polygon = box(0.0, 0.0, 10.0, 2.0)
    with observed() as stats:
        polygon_centerline(polygon, [(0.0, 1.0), (10.0, 1.0)])
        inside = (stats.tracings, stats.rounds)
    polygon_centerline(polygon, [(0.0, 1.0), (10.0, 1.0)])
    assert inside[0] == 1 and (stats.tracings, stats.rounds) == inside


def make_tracer(bank_a, bank_b, sides, closed):
    """A :class:`Tracer` of two banks (tolerance 0.01, width 6, largest disk 50, smallest contact 0)."""
    options = TraceOptions(np.asarray(sides, dtype=float), *(np.full(2, value) for value in (closed, 0.01, 6, 50, 0)))
    return Tracer(Boundary([bank_a, bank_b]), options)


def test_the_initial_intervals_run_between_the_initial_samples_along_every_span():
    # A zigzag bank (reflex vertices: fans; convex ones: edges between two corners have a middle sample).
    bank_a = np.array([(0.0, 0.0), (2.0, 1.0), (4.0, -0.5), (6.0, 1.5), (7.0, 0.5), (9.0, 0.0)])
    bank_b = np.array([(9.0, 6.0), (0.0, 6.5)])
    tracer = make_tracer(bank_a, bank_b, [1, -1], True)
    spans = tracer.spans
    edge, given_site, _, _ = initial_samples(spans, tracer.sites, tracer.options.closed, tracer.traced, tracer.boundary)
    between_corners = (given_site[0::2] >= 0) & (given_site[1::2] >= 0)
    assert between_corners.any() and np.any(spans.kind == FAN)
    intervals = intervals_between(spans, edge, between_corners)
    # The samples: both ends of every edge, then the middles.
    middle = np.flatnonzero(between_corners)
    sample_span = np.concatenate([np.repeat(np.arange(len(edge)), 2), middle])
    sample_u = np.concatenate([np.stack([0.0 * edge, spans.length[: len(edge)]], 1).ravel(), spans.length[middle] / 2])
    order = np.lexsort((intervals.u0, intervals.span))
    span, u0, u1 = intervals.span[order], intervals.u0[order], intervals.u1[order]
    # Every span from 0 to its length, in pieces that meet.
    assert np.array_equal(np.unique(span), np.arange(len(spans.kind)))
    starts = np.ones(len(span), dtype=bool)
    starts[1:] = span[1:] != span[:-1]
    ends = np.append(starts[1:], True)
    assert np.all(u0[starts] == 0.0) and np.all(u1[ends] == spans.length[span[ends]])
    assert np.array_equal(u0[~starts], u1[~ends])
    # Each end's sample lies where the interval ends (a fan's ends at the vertex, its edges' samples).
    for end, u in ((intervals.left[order], u0), (intervals.right[order], u1)):
        on_edge = spans.kind[span] != FAN
        assert np.array_equal(sample_span[end[on_edge]], span[on_edge])
        assert np.array_equal(sample_u[end[on_edge]], u[on_edge])
        point, _ = spans.points(sample_span[end], sample_u[end])
        assert np.allclose(point, spans.points(span, u)[0], rtol=0.0, atol=1e-12)
    assert np.all(intervals.site0 == -1) and np.all(intervals.site1 == -1)


def test_intervals_are_cut_at_their_nodes_in_order_of_parameter():
    # Three intervals; the third gets two nodes given out of order, the second none.
    intervals = Intervals(
        span=[0, 1, 2],
        u0=np.zeros(3),
        u1=np.array([1.0, 2.0, 3.0]),
        left=[0, 2, 4],
        right=[1, 3, 5],
        site0=[10, 11, 12],
        site1=[20, 21, 22],
        verified=np.zeros(3, dtype=bool),
    )
    owner, u, index = np.array([2, 0, 2]), np.array([2.0, 0.5, 1.0]), np.array([6, 7, 8])
    pieces = split_at_nodes(intervals, owner, u, index, np.array([30, 31, 32]), np.array([40, 41, 42]), True)
    assert pieces.span.tolist() == [0, 0, 1, 2, 2, 2]
    assert pieces.u0.tolist() == [0.0, 0.5, 0.0, 0.0, 1.0, 2.0]
    assert pieces.u1.tolist() == [0.5, 1.0, 2.0, 1.0, 2.0, 3.0]
    assert pieces.left.tolist() == [0, 7, 2, 4, 8, 6]
    assert pieces.right.tolist() == [7, 1, 3, 8, 6, 5]
    # A node's site before it ends the piece on its left, its site after starts the piece on its right.
    assert pieces.site0.tolist() == [10, 41, 11, 12, 42, 40]
    assert pieces.site1.tolist() == [31, 20, 21, 32, 30, 22]
    assert pieces.verified.all() and pieces.left.dtype == np.int32


@pytest.mark.parametrize("same_direction", [False, True])
def test_radius_terms_give_disks_that_touch_their_site(same_direction):
    """Disks of the closed-form radii touch their site, with the upper bank running either way: running like
    the lower one (as chains do), the samples lie on the negative side of its segments' lines."""
    # A zigzag bank (its reflex vertices are fans) under a bank with vertices and segments of every slope.
    bank_a = np.array([(0.0, 0.0), (2.0, 1.0), (4.0, -0.5), (6.0, 1.5), (9.0, 0.0)])
    bank_b = np.array([(9.0, 6.0), (7.0, 5.0), (5.0, 7.5), (3.0, 5.5), (0.0, 6.5)])
    sides = [1, 1]
    if same_direction:
        bank_b, sides = bank_b[::-1], [1, -1]
    tracer = make_tracer(bank_a, bank_b, sides, False)
    spans, boundary = tracer.spans, tracer.boundary
    other = np.arange(4, 8)
    site = np.concatenate([other, boundary.segment_count + 5 + np.arange(5)])
    span, site = (grid.ravel() for grid in np.meshgrid(np.arange(len(spans.kind)), site, indexing="ij"))
    u = 0.37 * spans.length[span]
    assert np.any(spans.kind == 1) and np.any(spans.kind == 0)
    radius = radius_at(spans, span, tracer.sites.radius_terms(spans, span, site), u)
    point, _ = spans.points(span, u)
    centre = point + radius[:, None] * spans.directions(span, u)
    on_segment = site < boundary.segment_count
    segment = np.minimum(site, boundary.segment_count - 1)
    across = np.stack([-boundary.unit[segment, 1], boundary.unit[segment, 0]], axis=1)
    line_distance = np.abs(np.einsum("ij,ij->i", centre - boundary.start[segment], across))
    vertex = boundary.vertex[np.maximum(site - boundary.segment_count, 0)]
    distance = np.where(on_segment, line_distance, np.hypot(*(centre - vertex).T))
    touched = np.isfinite(radius)
    assert touched.mean() > 0.5 and touched[spans.kind[span] == 1].any()
    assert np.allclose(distance[touched], radius[touched], rtol=1e-9, atol=1e-9)
    height = np.einsum("ij,ij->i", point - boundary.start[segment], across)
    assert np.all((height[on_segment] < 0.0) == same_direction)
    # Every segment's line is touched from the samples' side (a wrong side leaves the disks untouched: inf).
    assert np.all(np.isfinite(radius[on_segment]) & (radius[on_segment] > 0.0))


def test_intervals_touching_the_own_chain_on_one_side_of_their_span_are_settled_without_changing_the_line():
    # Ragged banks (a real outline, random-walk rivers) put many samples on side branches: an interval whose two
    # ends touch the own bank on the same side of its span holds no point of the axis, so settling it without
    # probes must give the very same line as probing it.
    from benchmarks.rivers import river_layer

    shapes = [(GAMBIA.polygon, GAMBIA.split_points)] + [(river.polygon, river.ends) for river in river_layer(6, 7)]
    for polygon, split_points in shapes:
        with observed() as settling:
            line = np.asarray(polygon_centerline(polygon, split_points).line.coords)
        with observed(TraceStats(settle_off_axis=False)) as probing:
            probed = np.asarray(polygon_centerline(polygon, split_points).line.coords)
        assert settling.off_the_axis > 0 and probing.off_the_axis == 0
        np.testing.assert_array_equal(line, probed)


@pytest.mark.parametrize(
    "spike",
    [(30.0, 9.0), pytest.param((50.0, 9.5), marks=pytest.mark.slow), pytest.param((71.0, 8.5), marks=pytest.mark.slow)],
)
def test_a_spike_of_the_other_bank_between_two_samples_is_not_settled_over(spike):
    # The top bank is two slightly different lines with a thin spike pointing down between them: the bottom
    # edge's samples beside it touch the two lines, whose event lies between them, but the axis dips under the
    # spike: its sites lie between the two lines', so the interval is not settled at the lines' event.
    x, tip = spike
    ring = [(0.0, 0.0), (100.0, 0.0), (100.0, 10.5), (x + 0.2, 10.0), (x, tip), (x - 0.2, 10.0), (0.0, 10.0)]
    assert_adaptive_properties(Polygon(ring), [(0.0, 5.0), (100.0, 5.0)])


@pytest.mark.parametrize("half_width", [5e-4, pytest.param(1e-6, marks=pytest.mark.slow)])
@pytest.mark.parametrize("spike", [False, True])
@pytest.mark.parametrize("x", [2.3, pytest.param(8.42, marks=pytest.mark.slow)])
def test_the_axis_passes_under_a_needle_on_its_tips_parabola(half_width, spike, x):
    # A needle (two nearly parallel edges, a digitising spike) reaches three quarters across a channel 1 wide.
    # Each edge's line, extended, runs on past the tip, so a bottom sample on the far side of it lies on the
    # needle's inner side of that line: a disk there never touches the edge. The events through the tip must be
    # predicted on the region's side of the lines, else the walk from one edge to the other through the tip
    # fails, the edges' own event is probed at the tip and its pieces take the wrong edge for the parabola.
    needle = [(x + half_width, 1.0), (x, 0.25), (x - half_width, 1.0)]
    end = [(10.0, 1.0), (9.077, 0.146), (9.035, 1.0)] if spike else [(10.0, 1.0)]
    polygon = Polygon([(0.0, 0.0), (10.0, 0.0), *end, *needle, (0.0, 1.0)])
    result = polygon_centerline(polygon, [(0.0, 0.5), (10.0, 0.5)])
    chain_a, chain_b = split_polygon(polygon, [(0.0, 0.5), (10.0, 0.5)])
    check_centerline(result, chain_a, chain_b, polygon, [tuple(chain_a[0]), tuple(chain_a[-1])])
    tolerance = default_tolerance(chain_a, chain_b)
    assert_within_tolerance(result, chain_a, chain_b, polygon, tolerance)
    # Under the tip the axis is the tip's parabola, at half the tip's height above the bottom.
    under_the_tip = shapely.intersection(result.line, LineString([(x, 0.0), (x, 0.25)]))
    assert abs(under_the_tip.y - 0.125) <= tolerance


@pytest.mark.parametrize("reverse", [False, True])
def test_a_split_point_in_a_concave_corner_traces_no_parabola_round_it(reverse):
    # A channel 1 wide whose left end is a notch: its apex (a reflex vertex) is a split point, so it lies on
    # both chains. The disks touching it there touch both chains only through it: no parabola round the apex
    # is traced (it was, for the chain sampled first, dipping 0.14 below the axis), and the line runs straight
    # from the apex along the axis y = 0.5, whichever split point comes first.
    apex = (0.3, 0.5)
    polygon = Polygon([(0.0, 0.0), (10.0, 0.0), (10.0, 1.0), (0.0, 1.0), apex])
    split_points = [apex, (10.0, 0.5)][:: -1 if reverse else 1]
    result = polygon_centerline(polygon, split_points)
    coordinates = np.asarray(result.line.coords)
    assert np.allclose(coordinates[[0, -1]], split_points, rtol=0, atol=1e-12)
    assert np.abs(coordinates[:, 1] - 0.5).max() <= 1e-9
    # The axis proper starts where the disk touching both banks reaches the apex: x = 0.3 + 0.5.
    assert np.isclose(np.sort(coordinates[:, 0])[1], 0.8, rtol=0, atol=1e-9)


def _spiked_channel():
    """A channel 1 wide split at its ends' middles, with a spike from the top bank down to 0.1 above the
    bottom: the axis dips under the tip to 0.05, 0.45 below its straight course. Returns the polygon, the
    split points and the width."""
    polygon = Polygon([(0.0, 0.0), (10.0, 0.0), (10.0, 1.0), (5.01, 1.0), (5.0, 0.1), (4.99, 1.0), (0.0, 1.0)])
    return polygon, [(0.0, 0.5), (10.0, 0.5)], 1.0


def _u_bend():
    """The annulus sector r = 40..60, 20 wide, whose axis is the half circle of radius 50."""
    case = geometry_cases.annulus_sector()
    return case.polygon, case.split_points, case.width


@pytest.mark.parametrize(
    "shape, widths",
    # Tolerances in widths: their simplification share (half) exceeds the spike's dip (0.45 widths), and the
    # sag of a quarter circle of radius 50 (14.6) exceeds the clearance to the inner bank (10, half a width).
    [(_spiked_channel, [0.95, 1.5, 4.0]), (_u_bend, [1.5, 3.0, 10.0])],
    ids=["spike", "u-bend"],
)
def test_a_tolerance_wider_than_the_channel_keeps_the_line_inside(shape, widths):
    # A chord of the simplified line that would cut across the boundary (a bend's inner bank, a spike's tip)
    # gets back the points it replaced, as few as keep it inside.
    polygon, split_points, width = shape()
    chain_a, chain_b = split_polygon(polygon, split_points)
    oracle = MedialOracle(chain_a, chain_b, region=polygon)
    default_count = len(polygon_centerline(polygon, split_points).line.coords)
    for tolerance in np.array(widths) * width:
        result = polygon_centerline(polygon, split_points, tolerance=tolerance)
        outside = shapely.difference(result.line, polygon).length
        assert outside <= 1e-9 * oracle.extent, f"tolerance {tolerance:g}: {outside:.3g} of the line outside"
        assert_within_tolerance(result, chain_a, chain_b, polygon, tolerance, oracle=oracle)
        assert len(result.line.coords) < default_count


def test_a_leaving_chord_is_split_at_the_point_it_replaced_farthest_from_it(monkeypatch):
    # An L-shaped corridor 2 wide; its axis points run along y = 1, then up x = 9. Kept: the two ends and their
    # neighbours, so one chord from (1, 1) to (9, 9) cuts across the inner corner (8, 2). It is split at the
    # corner point (9, 1), the replaced point farthest from it, and both halves stay inside.
    region = shapely.union(box(0.0, 0.0, 10.0, 2.0), box(8.0, 0.0, 10.0, 10.0))
    centre = np.array([(x, 1.0) for x in range(10)] + [(9.0, y) for y in range(2, 11)], dtype=float)
    distinct = np.ones(len(centre), dtype=bool)
    keep = np.zeros(len(centre), dtype=bool)
    keep[[0, 1, -2, -1]] = True
    restored = lines._restore_leaving_chords(centre, distinct, keep, region, np.zeros(2))
    assert np.flatnonzero(restored).tolist() == [0, 1, 9, len(centre) - 2, len(centre) - 1]
    assert region.covers(LineString(centre[restored]))
    assert keep.sum() == 4
    # Should the points put back make the line cross itself, every distinct point is kept.
    monkeypatch.setattr(shapely, "is_simple", lambda line: False)
    assert lines._restore_leaving_chords(centre, distinct, keep, region, np.zeros(2)).all()


@pytest.mark.parametrize("tolerance", [30.0, 200.0])
def test_two_bank_lines_keep_the_line_between_them_at_a_wide_tolerance(tolerance):
    # A U-bend's banks (half circles of radii 40 and 60) as two lines (open mode): the chords are kept in the
    # region between them.
    angle = np.linspace(0.0, math.pi, 61)
    inner, outer = (radius * np.stack([np.cos(angle), np.sin(angle)], axis=1) for radius in (40.0, 60.0))
    result = lines_centerline(inner, outer, tolerance=tolerance)
    between = Polygon(np.concatenate([inner, outer[::-1]]))
    assert shapely.difference(result.line, between).length <= 1e-9 * 120.0
    assert_within_tolerance(result, inner, outer, between, tolerance, near_ends=(inner[[0, -1]], 20.0))


def test_a_gentle_convex_corner_opposite_one_long_edge_needs_no_probe_along_it():
    # The top bank turns by 0.1 degrees over the long bottom edge: the axis there bends by less than the
    # tolerance, which the event proves: no probe along the edge's middle (without it, the event is probed).
    polygon = Polygon([(0.0, 0.0), (100.0, 0.0), (100.0, 10.0), (30.0, 10.03), (0.0, 10.0)])
    middle, settled = [], []
    for settling in (True, False):
        with observed(TraceStats(settle_at_event=settling, record_solutions=True)) as stats:
            assert_adaptive_properties(polygon, [(0.0, 5.0), (100.0, 5.0)])
        # The probes along the middle of the long edge (the only span 100 long).
        probes = [solution for solution in stats.solutions if solution.stage == "probes"]
        middle.append(sum(int(np.sum((p.length > 99.0) & (p.u > 10.0) & (p.u < 90.0))) for p in probes))
        settled.append(stats.settled_at_event)
    assert settled[0] > 0 and settled[1] == 0
    assert middle[0] == 0 and middle[1] >= 1


@pytest.fixture
def settled_intervals_checked():
    """Probes every interval settled at its event at 15 places inside (:attr:`TraceStats.check_settled`): the
    stats count the intervals checked and keep the worst excess of a probe's disk centre over the tracer's
    tolerance from the chord of the interval's end centres (-inf when none)."""
    with observed(TraceStats(check_settled=True)) as stats:
        yield stats


@pytest.mark.parametrize("case", WAVY + [GAMBIA], ids=lambda case: case.name)
def test_intervals_settled_at_their_event_hold_the_axis(settled_intervals_checked, case):
    polygon_centerline(case.polygon, case.split_points)
    assert settled_intervals_checked.settled_checked > 0
    assert settled_intervals_checked.settled_worst <= 0.0


def test_two_bank_lines_settle_no_interval_next_to_a_free_end(settled_intervals_checked):
    # Two bank lines are joined nowhere: between two consecutive sites of bank b the contact can pass round
    # b's free end to the back of a thin wall of b (seen from both sides), which the
    # argument for settling at the event excludes only where the chains share their ends. Found by an
    # adversarial campaign: the axis there lay 17.8 tolerances off the chord.
    ring = [(0.0, 1.0), (10.0, 1.0), (10.0, 0.0), (8.087, 0.0), (8.0197, 0.6949), (7.9524, 0.0), (3.3516, 0.0)]
    ring += [(3.3199, 0.9651), (3.1337, 0.9651), (3.102, 0.0), (0.9036, 0.0), (0.8649, 0.2791), (0.8262, 0.0)]
    bank_a, bank_b = ring[:7], ring[7:] + [(0.0, 0.0)]
    try:
        lines_centerline(bank_a, bank_b, tolerance=0.05)
    except IncirCuError:
        pass
    assert settled_intervals_checked.settled_worst <= 0.0


def test_the_sag_bounds_the_arcs_of_the_axis_beside_an_event():
    """The axis touching one site between two parameters of a span (a parabola for an edge and a vertex or a
    fan and a segment, else straight) lies within the sag of its chord, and the sag is not far above it (away
    from the parabola's apex the bound's curvature 1 / h is several times the actual one)."""
    bank_a = np.array([(0.0, 0.0), (2.0, 1.0), (4.0, -0.5), (6.0, 1.5), (9.0, 0.0)])
    bank_b = np.array([(9.0, 6.0), (7.0, 5.0), (5.0, 7.5), (3.0, 5.5), (0.0, 6.5)])
    tracer = make_tracer(bank_a, bank_b, [1, 1], False)
    spans, boundary = tracer.spans, tracer.boundary
    site = np.concatenate([np.arange(4, 8), boundary.segment_count + 5 + np.arange(1, 4)])
    span, site = (grid.ravel() for grid in np.meshgrid(np.arange(len(spans.kind)), site, indexing="ij"))
    share = np.linspace(0.1, 0.9, 81)
    u = share[:, None] * spans.length[span]
    centres = []
    for row in u:
        radius = radius_at(spans, span, tracer.sites.radius_terms(spans, span, site), row)
        centres.append(spans.points(span, row)[0] + radius[:, None] * spans.directions(span, row))
    centres = np.array(centres)
    start, end = centres[0], centres[-1]
    chord = end - start
    along = np.clip(np.einsum("kij,ij->ki", centres - start, chord) / np.einsum("ij,ij->i", chord, chord), 0, 1)
    deviation = np.hypot(*(centres - start - along[..., None] * chord).transpose(2, 0, 1)).max(axis=0)
    sag = sag_bound(tracer, span, site, start, end)
    touched = np.all(np.isfinite(centres), axis=(0, 2))
    curved = (spans.kind[span] == 1) != (site >= boundary.segment_count)
    assert touched[curved].sum() > 5 and touched[~curved].sum() > 5
    assert np.all(deviation[touched] <= sag[touched] + 1e-9)
    assert np.all(deviation[touched & curved] >= 0.1 * sag[touched & curved])


def test_a_junction_probed_for_another_pair_of_sites_is_a_vertex_of_the_line():
    # Fuzz seed 20261205, input 1584 (coordinates rounded): both split points lie on the bottom edge, so one
    # chain is a straight segment in line with the other chain's end segments. Where the axis's disks stop
    # touching the right side and start touching the upper left side it has a corner (a junction with the
    # branch between those two sides). The closed form placed a probe exactly there for another pair of sites,
    # the bottom edge's extension beyond a split point and the upper left side: no event of that pair, so its
    # tie went unemitted and the line cut the corner by 3.4 (tolerance 0.19), alone and in a batch.
    polygon = Polygon(
        [
            (59.642, 52.202),
            (35.129, 44.099),
            (15.313, 47.171),
            (18.706, 80.754),
            (-45.117, 9.886),
            (-58.933, -16.613),
            (-62.479, -19.439),
            (-45.172, -28.765),
            (23.042, -56.158),
        ]
    )
    low, high = np.array([-45.172, -28.765]), np.array([23.042, -56.158])
    ends = [low + 0.48 * (high - low), low + 0.21 * (high - low)]
    result = polygon_centerline(polygon, ends)
    chain_a, chain_b = split_polygon(polygon, ends)
    check_centerline(result, chain_a, chain_b, polygon, ends)
    assert_within_tolerance(result, chain_a, chain_b, polygon, default_tolerance(chain_a, chain_b))


def test_a_split_point_inside_an_edge_far_from_the_origin_is_straight():
    # tests/data/star_far_from_origin.wkt: the automatic ends fall inside edges of a 0.065-wide star at x = -1.07e5,
    # placed to that point's rounding (1.5e-11), so the edge's two pieces turn by about 1.6e-8 rad there. The
    # shifted frame's own rounding is a million times finer: the split point read as a corner, and the line cut the
    # axis's corner near it by 1.0e-3 (tolerance 1.6e-4). The input's rounding over the shorter piece counts.
    polygon = shapely.from_wkt((geometry_cases.DATA_FOLDER / "star_far_from_origin.wkt").read_text())
    result = polygon_centerline(polygon)
    ends = shapely.get_coordinates(result.line)[[0, -1]]
    chain_a, chain_b = split_polygon(polygon, ends)
    check_centerline(result, chain_a, chain_b, polygon, ends)
    assert_within_tolerance(result, chain_a, chain_b, polygon, default_tolerance(chain_a, chain_b))


@pytest.mark.parametrize("vertex, other_end", [(167, (1, 2)), (91, (2, 2))])
def test_a_split_point_a_hair_from_a_vertex_keeps_every_foot_on_its_disk(vertex, other_end):
    # Fuzz seed 20261209 input 98318: a square densified every 209 units, its automatic end 7.3e-8 after a vertex
    # inside an edge. The piece between the end and that vertex turns by about 1e-4 rad through rounding, and it
    # gave its direction to the whole straight side it starts (the side's line): a foot 5,000 units along it was
    # 0.03 off its disk alone and 0.2 off in a batch. A straight run's line is now its chord. ``other_end``: the
    # other split point, midway between two corners of the square (the same corner twice: that corner).
    angle = 0.82
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    corners = np.array([[0.0, 0.0], [9000.0, 0.0], [9000.0, 9000.0], [0.0, 9000.0]]) @ rotation.T + (-6557.0, -132.0)
    square = Polygon(corners).segmentize(214.0)
    ring = shapely.get_coordinates(square.exterior)
    toward = (ring[vertex + 1] - ring[vertex]) / np.hypot(*(ring[vertex + 1] - ring[vertex]))
    split_points = [ring[vertex] + 7.3e-8 * toward, 0.5 * (corners[other_end[0]] + corners[other_end[1]])]
    alone = polygon_centerline(square, split_points)
    slab = box(30_000.0, 0.0, 30_040.0, 3.0)
    steps = [_polygon_centerline_steps(slab, [(30_000.0, 1.5), (30_040.0, 1.5)])]
    batch = run_many_steps([*steps, _polygon_centerline_steps(square, split_points)])[1]
    chain_a, chain_b = split_polygon(square, split_points)
    for result in (alone, batch):
        check_centerline(result, chain_a, chain_b, square, [chain_a[0], chain_a[-1]])


def test_a_probe_a_hair_from_an_acute_tip_is_skipped_not_grown_through_it():
    # Fuzz seed 20261210 input 5755: a star whose automatic end lies 6e-9 past a tip of 27 degrees, on the tip's
    # other edge. A probe 3e-10 from that tip touched the tip's other side at a radius below the smallest contact
    # the solver sees (1e-12 of the extent): its disk grew through the tip to a contact 20.5 away, its centre 18
    # outside the star, and the line was refused (``CenterlineError``) alone, though not in a batch.
    star = shapely.from_wkt(
        "POLYGON ((-995.1877662056351 -567.9216961814047, -974.7931273049137 -544.8442390012672, "
        "-953.0407547133572 -566.6466382369018, -962.8290994357433 -537.4456342577979, "
        "-933.0714815384549 -529.508726618743, -963.2544651615624 -523.3851798197768, "
        "-955.2492198558306 -493.6458729450872, -975.6438587565519 -516.7233301252247, "
        "-997.3962313481085 -494.9209308895901, -987.6078866257224 -524.1219348686939, "
        "-1017.3655045230107 -532.0588425077489, -987.1825208999032 -538.1823893067151, "
        "-995.1877662056351 -567.9216961814047))"
    )
    split_points = [(-995.1877662056351, -567.9216961814047), (-955.2492198599119, -493.64587294970545)]
    chain_a, chain_b = split_polygon(star, split_points)
    check_centerline(polygon_centerline(star, split_points), chain_a, chain_b, star, [chain_a[0], chain_a[-1]])
