"""The public functions take one geometry or an array of them, as Shapely's do.

An array gives a list, one outcome per geometry in input order: its result, to the last bit what the
geometry gives alone, or the exception it raises alone (without traceback). Every other argument is one value
for all or one per geometry. Expected outcomes are the single calls', never numbers from a previous run.
"""

import warnings

import geopandas
import numpy as np
import pytest
from shapely.geometry import LineString, MultiPolygon, box

from fuzz.checks import outcome_key
from incircu_plugin import core
from incircu_plugin.core import (
    Cancelled,
    InvalidGeometryError,
    OptionError,
    label_lines,
    lines_centerline,
    multipolygon_centerlines,
    multipolygon_networks,
    polygon_centerline,
)
from tests.support import geometry_cases


def outcome_of(function, *arguments, **options):
    """What ``function`` returns or raises for one geometry."""
    try:
        return function(*arguments, **options)
    except Exception as error:  # noqa: BLE001 - the error is the expected outcome
        return error


def assert_identical(many, singles):
    assert len(many) == len(singles)
    for index, (one, other) in enumerate(zip(many, singles)):
        assert outcome_key(one) == outcome_key(other), index
        if isinstance(one, Exception):
            assert one.__traceback__ is None, index


def channels():
    """Rectangles and a meander with their split points, and a tolerance for each (None: the default)."""
    cases = [geometry_cases.rectangle(length=100.0 + 10 * n, width=5.0 + n, n=5 + n) for n in range(5)]
    cases.append(geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0, n=(101, 97)))
    return cases


def test_an_array_of_polygons_gives_what_each_gives_alone():
    cases = channels()
    polygons = [case.polygon for case in cases] + [None, box(0, 0, 1, 1).buffer(-1), cases[0].polygon]
    points = [case.split_points for case in cases] + [None, None, None]
    tolerances = [None, 0.05, None, 0.2, None, None, None, None, 0.1]
    singles = [
        outcome_of(polygon_centerline, polygon, point, tolerance=tolerance)
        for polygon, point, tolerance in zip(polygons, points, tolerances)
    ]
    assert isinstance(singles[-2], InvalidGeometryError) and isinstance(singles[-1], core.PolygonCenterlineResult)
    for array in (polygons, np.array(polygons, dtype=object), geopandas.GeoSeries(polygons)):
        assert_identical(polygon_centerline(array, points, tolerance=tolerances), singles)


def test_one_option_value_serves_every_polygon_and_split_points_may_be_none():
    cases = channels()
    polygons = [case.polygon for case in cases]
    singles = [polygon_centerline(polygon, end_cap="runout", islands="ignore") for polygon in polygons]
    assert_identical(polygon_centerline(polygons, end_cap="runout", islands="ignore"), singles)
    assert polygon_centerline([]) == []


def test_an_option_with_the_wrong_number_of_values_is_an_option_error():
    polygons = [case.polygon for case in channels()]
    with pytest.raises(OptionError, match=r"tolerance has 2 values for 6 geometries"):
        polygon_centerline(polygons, tolerance=[0.1, 0.2])
    with pytest.raises(OptionError, match=r"split_points has 1 values for 6 geometries"):
        polygon_centerline(polygons, [[(0, 0), (1, 1)]])


def test_arrays_of_bank_lines_pair_them_and_a_single_line_pairs_with_each():
    cases = channels()[:4]
    banks = [geometry_cases.bank_pair(case) for case in cases]
    singles = [outcome_of(lines_centerline, a, b) for a, b in banks]
    assert_identical(lines_centerline([a for a, _ in banks], [b for _, b in banks]), singles)
    base = LineString([(0, 0), (100, 0)])
    tops = [LineString([(0, h), (100, h)]) for h in (4.0, 8.0, -3.0)] + [LineString([(0, 0), (100, 1)])]
    assert_identical(lines_centerline(base, tops), [outcome_of(lines_centerline, base, top) for top in tops])


def test_arrays_of_multipolygons_and_labels_give_what_each_gives_alone():
    two = MultiPolygon([box(0, 0, 50, 4), box(0, 10, 60, 14)])
    geometries = [two, box(0, 0, 100, 10), None]
    for function in (multipolygon_centerlines, label_lines):
        singles = [outcome_of(function, geometry) for geometry in geometries]
        many = function(geometries)
        assert_identical(many, singles)
        assert [len(outcome) for outcome in many[:2]] == [2, 1]


def test_the_progress_of_an_array_rises_to_one_and_can_cancel():
    polygons = [case.polygon for case in channels()] * 60
    fractions = []
    polygon_centerline(polygons, progress=fractions.append)
    assert fractions == sorted(fractions) and fractions[-1] == pytest.approx(1.0)
    with pytest.raises(Cancelled):
        polygon_centerline(polygons, progress=lambda fraction: fraction < 0.5)


def test_the_step_protocol_of_0_2_still_answers_with_a_deprecation_warning():
    case = channels()[0]
    with pytest.warns(DeprecationWarning, match="polygon_centerline\\(array\\)"):
        together = core.centerlines_together
    with pytest.warns(DeprecationWarning, match="deprecated since IncirCu 0.3"):
        steps = core.polygon_centerline_steps
    assert outcome_key(together([steps(case.polygon, case.split_points)])[0]) == outcome_key(
        polygon_centerline(case.polygon, case.split_points)
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert "centerlines_together" not in core.__all__ and not hasattr(core, "no_such_name")


def test_an_array_of_networks_gives_what_each_gives_alone():
    channels = MultiPolygon([box(0, 0, 50, 4), box(0, 10, 50, 14)])
    corners = [(0, 0), (100, 0), (100, 10), (0, 10)]
    geometries = [channels, box(0, 0, 100, 10), None]
    points = [[(0, 12), (50, 2), (50, 12), (0, 2)], corners, None]
    singles = [outcome_of(multipolygon_networks, g, p, spacing=1.0) for g, p in zip(geometries, points)]
    many = multipolygon_networks(geometries, points, spacing=1.0)
    assert [type(outcome) for outcome in many] == [type(outcome) for outcome in singles]
    assert isinstance(many[2], InvalidGeometryError) and str(many[2]) == str(singles[2])
    for mine, alone in zip(many[:2], singles[:2]):
        assert [o.result.branches[0].result.line.wkb for o in mine] == [
            o.result.branches[0].result.line.wkb for o in alone
        ]
        assert [len(o.result.branches) for o in mine] == [len(o.result.branches) for o in alone]
    assert len(many[1][0].result.branches) == 5  # the rectangle's whole medial axis between its four corners
