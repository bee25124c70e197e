"""Automatic ends of many polygons at once (``find_ends_together``): the same answers as ``find_ends`` alone.

The batched path shares the skeleton, the chain contraction and the cap centring of all polygons, so any
leak between polygons (a node, an edge or a ring vertex of one polygon used for another) moves an end by
a sizeable fraction of the polygon: the tolerance is a tiny fraction of each polygon's own extent.
"""

import random

import numpy as np
import pytest
import shapely
import shapely.affinity
from shapely.geometry import LineString, Polygon, box

from benchmarks.rivers import river_layer
from incircu_plugin.core import Cancelled, find_ends, polygon_centerline
from incircu_plugin.core import ends as ends_module
from incircu_plugin.core._many import run_many_steps
from incircu_plugin.core.api import _polygon_centerline_steps
from incircu_plugin.core.ends import find_ends_together
from incircu_plugin.core.errors import IncirCuError, InvalidGeometryError
from incircu_plugin.core.polyline import typical_width
from incircu_plugin.core.skeleton import connected_labels, joint_skeletons
from tests.support import geometry_cases

#: Largest distance between a batched end and the lone one, as a fraction of the polygon's bounding-box
#: diagonal (rounding only: both run the same operations on the same numbers).
SAME_END = 1e-9


@pytest.fixture(autouse=True)
def joint_path_only(monkeypatch):
    """Fail a test whose batch fell back to one polygon at a time.

    ``_ends_together`` answers a batch whose joint computation raised by computing each polygon alone, which
    would hide any fault of the joint path from every comparison with ``find_ends`` below.
    """
    computing = []
    fallbacks = []
    joint = ends_module._ends_together

    def watched(polygons, *arguments):
        if computing:
            fallbacks.append(len(polygons))
        computing.append(True)
        try:
            return joint(polygons, *arguments)
        finally:
            computing.pop()

    monkeypatch.setattr(ends_module, "_ends_together", watched)
    yield
    assert not fallbacks, "a batch fell back to one polygon at a time"


def extent(polygon):
    """Bounding-box diagonal of a polygon, CRS units."""
    west, south, east, north = polygon.bounds
    return float(np.hypot(east - west, north - south))


def assert_same_ends(polygon, together, alone):
    """Assert that a batched outcome equals the lone one (same ends, same elongation, same error type)."""
    if isinstance(alone, Exception):
        assert type(together) is type(alone)
        assert str(together) == str(alone)
        return
    assert not isinstance(together, Exception), together
    tolerance = SAME_END * extent(polygon)
    assert together.start.distance(alone.start) <= tolerance
    assert together.end.distance(alone.end) <= tolerance
    assert together.elongated == alone.elongated
    assert together.guided == alone.guided


def alone_outcome(polygon, **options):
    """``find_ends`` of one polygon, or the exception it raises."""
    try:
        return find_ends(polygon, **options)
    except InvalidGeometryError as error:
        return error


def analytic_polygons():
    """The analytic cases' polygons (every placement), two reversed rings, and a polygon with an island."""
    polygons = [case.polygon for case in geometry_cases.analytic_cases()]
    polygons.append(shapely.reverse(polygons[0]))
    polygons.append(box(0.0, 0.0, 200.0, 30.0).difference(box(80.0, 10.0, 120.0, 20.0)))
    polygons.append(LineString([(0.0, 0.0), (100.0, 0.0), (100.0, 80.0)]).buffer(6.0))
    return polygons


@pytest.mark.parametrize("rule", ["main_stem", "longest_path"])
def test_batch_of_analytic_shapes_equals_each_alone(rule):
    polygons = analytic_polygons()
    together = find_ends_together(polygons, rule=rule)
    assert len(together) == len(polygons)
    for polygon, outcome in zip(polygons, together):
        assert_same_ends(polygon, outcome, alone_outcome(polygon, rule=rule))


def test_batch_of_rivers_with_islands_equals_each_alone():
    polygons = [river.polygon for river in river_layer(count=40)]
    assert any(len(polygon.interiors) for polygon in polygons)
    together = find_ends_together(polygons)
    for polygon, outcome in zip(polygons, together):
        assert_same_ends(polygon, outcome, find_ends(polygon))


def mixed_batch():
    """Good polygons around an invalid one (a bow tie), a too thin one, a None and a non-polygon."""
    return [
        box(0.0, 0.0, 100.0, 10.0),
        Polygon([(0, 0), (10, 10), (10, 0), (0, 10)]),
        geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0).polygon,
        Polygon([(0.0, 0.0), (1.0, 0.0), (1.0, 1e-12)]),
        None,
        LineString([(0.0, 0.0), (1.0, 1.0)]),
        box(5.0, 5.0, 7.0, 45.0),
    ]


def test_one_bad_polygon_fails_alone():
    polygons = mixed_batch()
    together = find_ends_together(polygons)
    alone = [alone_outcome(polygon) for polygon in polygons]
    assert [isinstance(outcome, Exception) for outcome in alone] == [False, True, False, True, True, True, False]
    for polygon, outcome, expected in zip(polygons, together, alone):
        assert_same_ends(polygon or box(0, 0, 1, 1), outcome, expected)
    assert all(isinstance(outcome, InvalidGeometryError) for outcome in together[1::2][:3])


def test_order_does_not_change_the_answers():
    polygons = analytic_polygons()[:10] + [river.polygon for river in river_layer(count=6)]
    in_order = find_ends_together(polygons)
    shuffled = list(range(len(polygons)))
    random.Random(7).shuffle(shuffled)
    assert shuffled != sorted(shuffled)
    reordered = find_ends_together([polygons[index] for index in shuffled])
    for position, index in enumerate(shuffled):
        assert_same_ends(polygons[index], reordered[position], in_order[index])


def test_guides_are_per_polygon():
    channel = LineString([(0.0, 0.0), (100.0, 0.0), (100.0, 80.0)]).buffer(6.0, cap_style="flat")
    arm = LineString([(100.0, 0.0), (180.0, 0.0)]).buffer(6.0, cap_style="flat")
    polygon = channel.union(arm)
    guide = LineString([(0.0, 0.0), (100.0, 0.0), (100.0, 80.0)])
    moved, moved_guide = (shapely.affinity.translate(item, 500.0, 300.0) for item in (polygon, guide))
    polygons = [polygon, box(0.0, 0.0, 100.0, 10.0), polygon, moved]
    together = find_ends_together(polygons, guides=[guide, None, None, moved_guide])
    assert together[0].guided and not together[2].guided and together[3].guided
    assert_same_ends(polygon, together[0], find_ends(polygon, guide=guide))
    assert_same_ends(polygon, together[2], find_ends(polygon))
    assert_same_ends(moved, together[3], find_ends(moved, guide=moved_guide))
    # The guide up the arm changes the ends: a batch that dropped it would fail the line above.
    assert together[0].end.distance(together[2].end) > 10.0 or together[0].start.distance(together[2].start) > 10.0


def test_empty_batch_and_unknown_rule():
    assert find_ends_together([]) == []
    with pytest.raises(IncirCuError):
        find_ends_together([box(0.0, 0.0, 10.0, 1.0)], rule="shortest")
    with pytest.raises(IncirCuError):
        find_ends_together([box(0.0, 0.0, 10.0, 1.0)], guides=[None, None])


def test_progress_rises_and_cancel_stops_the_batch():
    polygons = [box(0.0, 0.0, 100.0, 10.0 + index) for index in range(40)]
    fractions = []
    find_ends_together(polygons, progress=lambda fraction: fractions.append(fraction) or True)
    assert fractions == sorted(fractions) and fractions[0] == 0.0 and fractions[-1] == 1.0
    calls = []
    with pytest.raises(Cancelled):
        find_ends_together(polygons, progress=lambda fraction: calls.append(fraction) or len(calls) < 3)
    assert len(calls) == 3


def test_a_batch_of_centerlines_finds_its_automatic_ends_together(monkeypatch):
    from incircu_plugin.core import _steps as steps

    polygons = [box(0.0, 0.0, 100.0, 10.0 + index) for index in range(5)] + [box(0.0, 0.0, 10.0, 10.0)]
    expected = [polygon_centerline(polygon) for polygon in polygons]
    batches = []
    joint = steps.find_ends_together
    monkeypatch.setattr(
        steps, "find_ends_together", lambda polygons, **options: batches.append(polygons) or joint(polygons, **options)
    )
    monkeypatch.setattr(steps, "find_ends", None)
    together = run_many_steps([_polygon_centerline_steps(polygon) for polygon in polygons])
    assert [len(batch) for batch in batches] == [len(polygons)]
    for polygon, outcome, alone in zip(polygons, together, expected):
        assert outcome.notes == alone.notes and outcome.ends_from == alone.ends_from == "automatic"
        rounding = 1e-9 * extent(polygon)
        for index in (0, -1):
            assert np.hypot(*np.subtract(outcome.line.coords[index], alone.line.coords[index])) <= rounding
    assert together[-1].notes and "not elongated" in together[-1].notes[0]


def test_a_features_own_progress_can_cancel_the_ends_round(monkeypatch):
    from incircu_plugin.core import _steps as steps

    monkeypatch.setattr(steps, "_traced", None)  # cancelled before any tracing
    generators = [
        _polygon_centerline_steps(box(0.0, 0.0, 100.0, 10.0)),
        _polygon_centerline_steps(box(0.0, 0.0, 100.0, 12.0), progress=lambda fraction: fraction < 0.05),
    ]
    with pytest.raises(Cancelled):
        run_many_steps(generators)


@pytest.mark.parametrize("index", [178, 840])
def test_a_river_whose_skeleton_keeps_a_cycle_gets_the_ends_of_its_caps(index):
    """Two rivers without islands (``river_layer`` seed 7) whose skeletons keep a cycle (triangles across a
    narrow gap between two reaches stay inside): the sweeps traverse such a skeleton as a tree, each node
    reached once, and the ends stay within two typical widths of the river's caps, alone and in a batch,
    where shortest distances would cut across the gap."""
    river = river_layer(1, seed=7, first=index)[0]
    polygon = river.polygon
    origin, scale = ends_module._local_box(polygon, None)
    local = shapely.transform(polygon, lambda xy: (xy - origin) / scale)
    skeleton = joint_skeletons([local])
    components = len(np.unique(connected_labels(len(skeleton.nodes), *skeleton.edges.T)))
    assert len(skeleton.edges) > len(skeleton.nodes) - components
    width = typical_width(polygon.area, polygon.length / 2.0)
    caps = np.array([point.coords[0] for point in river.ends])
    for ends in (find_ends(polygon), find_ends_together([box(0, 0, 10, 1), polygon])[1]):
        found = np.array([ends.start.coords[0], ends.end.coords[0]])
        gaps = np.hypot(*(found[:, None, :] - caps[None, :, :]).transpose(2, 0, 1))
        assert min(gaps[0, 0] + gaps[1, 1], gaps[0, 1] + gaps[1, 0]) <= 2.0 * width
