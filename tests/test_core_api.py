"""The public entry points around the engine: spacing rules, sample counts, progress, multipart input.

Expected values come from the shapes' construction (a rectangle's width, the number of parts, which part
was given bad split points), never from a previous run.
"""

import warnings

import numpy as np
import pytest
import shapely
from shapely.geometry import MultiPolygon, Polygon, box

from incircu_plugin.core import (
    Cancelled,
    IncirCuError,
    OptionError,
    SplitPointError,
    centerline_from_chains,
    default_spacing,
    default_tolerance,
    multipolygon_centerlines,
    polygon_centerline,
    split_polygon,
)
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core.api import _polygon_centerline_steps
from incircu_plugin.core.chains import split_checked_polygon
from tests.support import geometry_cases
from tests.support.oracle import check_centerline


def test_default_spacing_is_a_twentieth_of_the_typical_width():
    # The documented rule: typical width = area between the chains / their mean length, spacing = 1/20 of
    # it. For two parallel banks of a rectangle that is exactly its width; closed, the chains also run along
    # the half caps, so it is W * L / (L + W).
    case = geometry_cases.rectangle(length=200.0, width=8.0, n=5)
    assert default_spacing(case.bank_a, case.bank_b) == pytest.approx(8.0 / 20.0, rel=1e-12)
    assert default_spacing(case.chain_a, case.chain_b) == pytest.approx(8.0 * 200.0 / 208.0 / 20.0, rel=1e-12)


@pytest.mark.parametrize("spacing", [None, 0, 0.0])
def test_no_spacing_and_zero_spacing_mean_the_adaptive_default(spacing):
    case = geometry_cases.wavy_channel(seed=21)
    tolerance = default_tolerance(case.chain_a, case.chain_b)
    expected = polygon_centerline(case.polygon, case.split_points, tolerance=tolerance)
    result = polygon_centerline(case.polygon, case.split_points, spacing=spacing)
    assert result.line.equals_exact(expected.line, 0.0)


def test_default_tolerance_is_a_two_hundredth_of_the_typical_width():
    case = geometry_cases.rectangle(length=200.0, width=8.0, n=5)
    assert default_tolerance(case.bank_a, case.bank_b) == pytest.approx(8.0 / 200.0, rel=1e-12)


def test_finer_spacing_gives_more_vertices_on_a_straight_channel():
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=2)
    counts = [len(polygon_centerline(case.polygon, case.split_points, spacing=s).line.coords) for s in (4.0, 2.0, 1.0)]
    assert counts[0] < counts[1] < counts[2]
    # Stations fall on whole x (the half caps are 5 long): a sample at (x, 0) or (x, 10) has the incircle of
    # centre (x, 5) and radius 5, which is empty for 5 <= x <= 95 and crosses a cap otherwise. Both sides give
    # the same 91 centres, plus the two split points.
    assert counts[2] == 91 + 2


def test_samples_per_chain_sets_the_number_of_samples():
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=2)
    few = polygon_centerline(case.polygon, case.split_points, samples_per_chain=9)
    many = polygon_centerline(case.polygon, case.split_points, samples_per_chain=99)
    assert len(few.line.coords) < len(many.line.coords)
    check_centerline(many, case.chain_a, case.chain_b, case.polygon, case.split_points)
    with pytest.raises(IncirCuError):
        polygon_centerline(case.polygon, case.split_points, samples_per_chain=0)


def test_too_many_samples_is_refused_before_any_work():
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=2)
    with pytest.raises(IncirCuError, match="spacing"):
        polygon_centerline(case.polygon, case.split_points, spacing=1e-9)


def test_progress_reports_increasing_fractions_up_to_one():
    case = geometry_cases.synthetic_river(40_000, seed=3)
    seen = []
    polygon_centerline(case.polygon, case.split_points, spacing=case.width / 4.0, progress=seen.append)
    assert len(seen) >= 2
    assert all(0.0 <= f <= 1.0 for f in seen)
    assert all(b >= a for a, b in zip(seen, seen[1:]))
    assert seen[-1] == pytest.approx(1.0)


def test_progress_returning_false_cancels():
    case = geometry_cases.synthetic_river(40_000, seed=3)
    calls = []

    def stop_at_first(fraction):
        calls.append(fraction)
        return False

    with pytest.raises(Cancelled):
        polygon_centerline(case.polygon, case.split_points, spacing=case.width / 4.0, progress=stop_at_first)
    assert len(calls) == 1


def test_engine_takes_the_chains_of_split_polygon():
    case = geometry_cases.annulus_sector()
    c1, c2 = split_polygon(case.polygon, case.split_points)
    assert np.array_equal(c1[0], c2[0]) and np.array_equal(c1[-1], c2[-1])
    assert tuple(c1[0]) == case.split_points[0] and tuple(c1[-1]) == case.split_points[1]
    # The two chains cover the ring exactly once.
    assert shapely.LineString(c1).length + shapely.LineString(c2).length == pytest.approx(
        case.polygon.exterior.length, rel=1e-12
    )
    direct = centerline_from_chains(c1, c2, spacing=1.0)
    through_api = polygon_centerline(case.polygon, case.split_points, spacing=1.0)
    assert direct.line.equals_exact(through_api.line, 0.0)


def test_split_polygon_inserts_a_split_point_inside_an_edge_as_a_vertex():
    polygon = box(0.0, 0.0, 100.0, 10.0)
    c1, c2 = split_polygon(polygon, [(0.0, 3.0), (100.0, 7.5)])
    for chain in (c1, c2):
        assert tuple(chain[0]) == (0.0, 3.0) and tuple(chain[-1]) == (100.0, 7.5)
    assert len(c1) + len(c2) - 2 == 4 + 2


@pytest.mark.parametrize("ulps", [1, 2, 3])
def test_a_split_point_that_rounds_onto_a_vertex_is_that_vertex(ulps):
    # A 0.02 x 0.006 box turned by 0.4 rad, 1.5e5 from the origin (a fuzz input, seed 20261204 case 56841, was
    # such a small star): there a coordinate's last place (2.9e-11 in x) is far above the coincidence distance
    # (1e-12 of the extent). A split point ``ulps`` places below a corner in y projects onto the next edge a few
    # 1e-14 from the corner, and that point rounds onto the corner: inserted, it made a zero-length segment (NaN
    # directions, then an IndexError in the solver).
    turn = np.array([[np.cos(0.4), -np.sin(0.4)], [np.sin(0.4), np.cos(0.4)]])
    corners = np.array([[0.0, 0.0], [0.02, 0.0], [0.02, 0.006], [0.0, 0.006]]) @ turn.T + (148426.98, -723.87)
    near_corner = corners[1] - (0.0, ulps * np.spacing(723.87))
    far_end = (corners[3] + corners[0]) / 2.0
    c1, c2 = split_polygon(shapely.Polygon(corners), [tuple(far_end), tuple(near_corner)])
    for chain in (c1, c2):
        assert np.min(np.hypot(*np.diff(chain, axis=0).T)) > 0.0
        assert np.array_equal(chain[-1], corners[1])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = polygon_centerline(shapely.Polygon(corners), [tuple(far_end), tuple(near_corner)])
    assert np.array_equal(result.line.coords[-1], corners[1])


def test_split_checked_polygon_is_split_polygon_without_the_input_checks():
    polygon = box(0.0, 0.0, 100.0, 10.0)
    points = [(0.0, 3.0), (100.0, 7.5)]
    for checked, plain in zip(split_checked_polygon(polygon, np.array(points)), split_polygon(polygon, points)):
        assert np.array_equal(checked, plain)
    with pytest.raises(SplitPointError, match="exactly 2 split points"):
        split_checked_polygon(polygon, np.array(points[:1]))
    with pytest.raises(OptionError):
        split_checked_polygon(polygon, np.array(points), -1.0)


def test_multipolygon_gives_one_outcome_per_part_and_isolates_failures():
    good = box(0.0, 0.0, 50.0, 4.0)
    bad = box(0.0, 10.0, 50.0, 14.0)
    third = box(0.0, 20.0, 80.0, 26.0)
    points = [(0.0, 2.0), (50.0, 2.0), (0.0, 12.0), (50.0, 12.0), (25.0, 14.0), (0.0, 23.0), (80.0, 23.0)]
    outcomes = multipolygon_centerlines(MultiPolygon([good, bad, third]), points, spacing=0.5)
    assert [o.part_index for o in outcomes] == [0, 1, 2]
    assert outcomes[0].error is None and outcomes[0].result.line.length == pytest.approx(50.0)
    assert outcomes[1].result is None and isinstance(outcomes[1].error, SplitPointError)
    assert "3" in str(outcomes[1].error)
    assert outcomes[2].error is None and outcomes[2].result.line.length == pytest.approx(80.0)
    assert outcomes[2].result.widths[1:-1] == pytest.approx(6.0)


def test_multipolygon_accepts_a_single_polygon():
    outcomes = multipolygon_centerlines(box(0.0, 0.0, 50.0, 4.0), [(0.0, 2.0), (50.0, 2.0)], spacing=0.5)
    assert len(outcomes) == 1 and outcomes[0].result.line.length == pytest.approx(50.0)


def test_widths_and_length_properties():
    case = geometry_cases.rectangle(length=100.0, width=10.0, n=3)
    result = polygon_centerline(case.polygon, case.split_points, spacing=1.0)
    assert np.array_equal(result.widths, 2.0 * result.radii)
    assert result.widths[1:-1] == pytest.approx(10.0, rel=1e-12)
    assert result.length == pytest.approx(100.0, rel=1e-12)


def test_inputs_are_not_modified():
    case = geometry_cases.wavy_channel(seed=22)
    chain_a, chain_b = case.chain_a.copy(), case.chain_b.copy()
    polygon_wkb = case.polygon.wkb
    centerline_from_chains(chain_a, chain_b, spacing=0.5)
    polygon_centerline(case.polygon, case.split_points, spacing=0.5)
    assert np.array_equal(chain_a, case.chain_a) and np.array_equal(chain_b, case.chain_b)
    assert case.polygon.wkb == polygon_wkb


def test_progress_of_a_multipart_geometry_never_goes_back():
    parts = MultiPolygon([box(0.0, 0.0, 100.0, 10.0), box(0.0, 20.0, 100.0, 30.0), box(0.0, 40.0, 100.0, 50.0)])
    seen = []
    outcomes = multipolygon_centerlines(parts, spacing=1.0, progress=seen.append)
    assert all(outcome.error is None for outcome in outcomes)
    assert seen == sorted(seen) and seen[-1] == pytest.approx(1.0)
    assert sum(fraction <= 1.0 / 3.0 for fraction in seen) >= 1


@pytest.mark.parametrize("turn", range(12))
def test_a_split_point_a_hair_from_an_acute_tip_gives_the_line_of_the_tip(turn):
    # Found by the batch fuzz (seed 20261205, input 11694, an automatic end 4e-9 from a star's tip). The 4e-9
    # segment from the split point to the tip has a direction known to about the coordinates' rounding over
    # its length (1e-4 rad here), far above the 1e-9 under which the split point counted as straight: rounding
    # made it a convex corner now and then, the segment was sampled in its middle, its disk missed the tip's
    # other side (closer than the smallest contact) and grew out of the polygon. Half of these kites, alone or
    # traced together with a larger feature, raised "the computed centerline leaves the polygon".
    angle = 0.37 * turn
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    corners = np.array([[-500.0, -60.0], [500.0, 0.0], [-500.0, 60.0], [-520.0, 0.0]]) @ rotation.T
    corners += np.array([137.0, -41.0]) * (turn % 5)
    tip, far = corners[1], 0.5 * (corners[2] + corners[3])
    hair = tip - 4e-9 * (tip - corners[0]) / np.hypot(*(tip - corners[0]))
    kite = Polygon(corners)
    at_tip = polygon_centerline(kite, [tip, far])
    tolerance = default_tolerance(*split_polygon(kite, [tip, far]))
    offset = corners[1] + 3000.0
    slab = Polygon(np.array([[0.0, 0.0], [4000.0, 0.0], [4000.0, 300.0], [0.0, 300.0]]) + offset)
    slab_ends = [offset + (0.0, 150.0), offset + (4000.0, 150.0)]
    together = run_many_steps(
        [_polygon_centerline_steps(slab, slab_ends), _polygon_centerline_steps(kite, [hair, far])]
    )[1]
    for result in (polygon_centerline(kite, [hair, far]), together):
        assert not isinstance(result, Exception), result
        assert result.line.hausdorff_distance(at_tip.line) <= tolerance + 1e-8


@pytest.mark.parametrize("spacings", [1, 2, 4, 8])
def test_a_split_point_a_few_spacings_from_a_tip_is_that_tip(spacings):
    # A 4-unit kite 9e4 from the origin (the batch fuzz, seed 20261201 input 91 of its small sample, was such a
    # star): a coordinate's float64 spacing there (1.5e-11) exceeds the coincidence distance (1e-12 of the
    # extent). A split point a few spacings from the tip was inserted as a vertex: a segment with no direction,
    # whose normal at the split point pointed anywhere. The tip is the split point.
    angle = 0.3 + 0.2 * spacings
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    corners = np.array([[-2.0, -0.3], [2.0, 0.0], [-2.0, 0.3], [-2.1, 0.0]]) @ rotation.T + (-91_900.0, -23_600.0)
    tip, far = corners[1], 0.5 * (corners[2] + corners[3])
    toward = (corners[0] - tip) / np.hypot(*(corners[0] - tip))
    near_tip = tip + spacings * np.spacing(91_900.0) * toward
    kite = Polygon(corners)
    for chain in split_polygon(kite, [far, near_tip]):
        assert np.array_equal(chain[-1], tip)
    at_tip = polygon_centerline(kite, [far, tip])
    tolerance = default_tolerance(*split_polygon(kite, [far, tip]))
    offset = tip + 30.0
    slab = Polygon(np.array([[0.0, 0.0], [40.0, 0.0], [40.0, 3.0], [0.0, 3.0]]) + offset)
    steps = [_polygon_centerline_steps(slab, [offset + (0.0, 1.5), offset + (40.0, 1.5)])]
    together = run_many_steps([*steps, _polygon_centerline_steps(kite, [far, near_tip])])[1]
    for result in (polygon_centerline(kite, [far, near_tip]), together):
        assert not isinstance(result, Exception), result
        assert result.line.hausdorff_distance(at_tip.line) <= tolerance


@pytest.mark.parametrize("spacings", [1, 3])
def test_a_split_point_a_few_spacings_before_the_rings_first_vertex_is_that_vertex(spacings):
    # Fuzz seed 20261208 input 97634: an automatic end a spacing short of the ring's closing vertex (its arc
    # length a rounding below the perimeter) was taken as that vertex, then matched to the vertex before it:
    # both chains came out one point long (an IndexError in the solver).
    corners = np.array([[0.0, 0.0], [0.0024, 0.0007], [0.003, 0.003], [0.0012, 0.0047], [-0.0012, 0.004]])
    corners += (-774.795, 1189.535)
    kite = Polygon(corners)
    toward = (corners[-1] - corners[0]) / np.hypot(*(corners[-1] - corners[0]))
    near_first = corners[0] + spacings * np.spacing(1189.535) * toward
    far = 0.5 * (corners[2] + corners[3])
    for chain in split_polygon(kite, [near_first, far]):
        assert len(chain) > 2 and np.array_equal(chain[0], corners[0])
    result = polygon_centerline(kite, [near_first, far])
    assert np.array_equal(result.line.coords[0], corners[0])
