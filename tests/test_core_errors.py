"""Bad input gets a typed error (an ``IncirCuError`` subclass) with a message a user can act on.

One test per case of the issue: empty or null geometry, fewer than two distinct points, NaN/inf
coordinates, zero-length segments (dropped silently), a self-intersecting polygon (the message says where),
split points too far / identical / not two, open-mode lines that cross or touch, a chain that folds back.
"""

import gc
import math
import re
import weakref

import numpy as np
import pytest
import shapely
import shapely.affinity
from shapely.geometry import LineString, MultiPoint, MultiPolygon, Point, Polygon, box

from incircu_plugin.core import (
    CenterlineError,
    ChainError,
    CrossingLinesError,
    IncirCuError,
    InvalidGeometryError,
    OptionError,
    SplitPointError,
    centerline_from_chains,
    chains,
    find_ends,
    lines_centerline,
    multipolygon_centerlines,
    multipolygon_networks,
    polygon_centerline,
    split_polygon,
)
from incircu_plugin.core.api import BANK_LENGTH_RATIO
from incircu_plugin.core.chains import validate_polygon
from incircu_plugin.core.validation import check_coordinates

RECTANGLE = box(0.0, 0.0, 100.0, 10.0)
ENDS = [(0.0, 5.0), (100.0, 5.0)]
BANK_A = [(0.0, 0.0), (50.0, 0.0), (100.0, 0.0)]
BANK_B = [(0.0, 10.0), (50.0, 10.0), (100.0, 10.0)]


def numbers_in(message):
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?", message)]


def test_every_error_class_is_an_incircu_error_and_a_value_error():
    for error in (InvalidGeometryError, SplitPointError, ChainError, CrossingLinesError):
        assert issubclass(error, IncirCuError)
    assert issubclass(IncirCuError, ValueError)


# Empty or null geometry -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("polygon", "message"),
    [
        (None, "The polygon is null (no geometry)."),
        (Polygon(), "The polygon is empty."),
        (shapely.from_wkt("POLYGON EMPTY"), "The polygon is empty."),
    ],
    ids=["null", "empty", "wkt-empty"],
)
def test_null_or_empty_polygon(polygon, message):
    with pytest.raises(InvalidGeometryError, match=f"^{re.escape(message)}$"):
        polygon_centerline(polygon, ENDS)


@pytest.mark.parametrize(
    "geometry", [LineString([(0, 0), (1, 1)]), Point(0, 0), MultiPolygon([RECTANGLE, box(200, 0, 300, 10)])]
)
def test_not_a_single_polygon(geometry):
    with pytest.raises(InvalidGeometryError, match=geometry.geom_type):
        polygon_centerline(geometry, ENDS)


@pytest.mark.parametrize(
    "line", [None, LineString(), [], np.empty((0, 2))], ids=["null", "empty", "empty-list", "empty-array"]
)
def test_null_or_empty_line(line):
    with pytest.raises(InvalidGeometryError):
        lines_centerline(line, BANK_B)
    with pytest.raises(InvalidGeometryError):
        lines_centerline(BANK_A, line)


# Fewer than two distinct points -----------------------------------------------------------------------


@pytest.mark.parametrize(
    "line",
    [[(3.0, 3.0)], [(3.0, 3.0), (3.0, 3.0)], [(3.0, 3.0), (3.0, 3.0), (3.0, 3.0)]],
    ids=["one", "two-same", "three-same"],
)
def test_line_with_fewer_than_two_distinct_points(line):
    with pytest.raises(ChainError, match=r"^The first line has fewer than 2 distinct points\.$"):
        lines_centerline(line, BANK_B)


def test_line_of_two_points_closer_than_the_coincidence_tolerance():
    with pytest.raises(ChainError, match="fewer than 2 distinct points"):
        lines_centerline([(5.0, 3.0), (5.0 + 1e-13, 3.0)], BANK_B)


# NaN / inf --------------------------------------------------------------------------------------------


# Building a shapely geometry with NaN warns; the warning is about the test data, not the core.
@pytest.mark.filterwarnings("ignore:invalid value encountered:RuntimeWarning")
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf], ids=["nan", "inf", "-inf"])
def test_non_finite_polygon_coordinate(bad):
    polygon = Polygon([(0.0, 0.0), (100.0, 0.0), (100.0, bad), (0.0, 10.0)])
    with pytest.raises(InvalidGeometryError, match="NaN or infinite"):
        polygon_centerline(polygon, ENDS)


# Building a shapely geometry with NaN warns; the warning is about the test data, not the core.
@pytest.mark.filterwarnings("ignore:invalid value encountered:RuntimeWarning")
@pytest.mark.parametrize("bad", [math.nan, math.inf], ids=["nan", "inf"])
def test_non_finite_line_coordinate(bad):
    with pytest.raises(InvalidGeometryError, match="NaN or infinite"):
        lines_centerline([(0.0, 0.0), (50.0, bad), (100.0, 0.0)], BANK_B)
    with pytest.raises(InvalidGeometryError, match="NaN or infinite"):
        lines_centerline(BANK_A, LineString([(0.0, 10.0), (bad, 10.0), (100.0, 10.0)]))


@pytest.mark.parametrize("bad", [math.nan, math.inf], ids=["nan", "inf"])
def test_non_finite_split_point(bad):
    with pytest.raises(IncirCuError):
        polygon_centerline(RECTANGLE, [(0.0, bad), (100.0, 5.0)])


@pytest.mark.parametrize("spacing", [-1.0, math.nan, math.inf], ids=["negative", "nan", "inf"])
def test_bad_spacing(spacing):
    with pytest.raises(IncirCuError, match="spacing"):
        polygon_centerline(RECTANGLE, ENDS, spacing=spacing)


# Zero-length segments are dropped silently ------------------------------------------------------------


def test_repeated_vertices_in_a_polygon_are_dropped_silently():
    clean = Polygon([(0.0, 0.0), (50.0, 0.0), (100.0, 0.0), (100.0, 10.0), (50.0, 10.0), (0.0, 10.0)])
    doubled = Polygon(
        [
            (0.0, 0.0),
            (50.0, 0.0),
            (50.0, 0.0),
            (100.0, 0.0),
            (100.0, 10.0),
            (100.0, 10.0),
            (50.0, 10.0),
            (0.0, 10.0),
            (0.0, 10.0),
        ]
    )
    assert doubled.is_valid
    expected = polygon_centerline(clean, ENDS, spacing=1.0)
    result = polygon_centerline(doubled, ENDS, spacing=1.0)
    assert np.array_equal(np.asarray(result.line.coords), np.asarray(expected.line.coords))
    assert np.array_equal(result.radii, expected.radii)


def test_repeated_vertices_in_lines_are_dropped_silently():
    doubled_a = [(0.0, 0.0), (0.0, 0.0), (50.0, 0.0), (50.0, 0.0), (100.0, 0.0)]
    doubled_b = [(0.0, 10.0), (50.0, 10.0), (100.0, 10.0), (100.0, 10.0)]
    expected = lines_centerline(BANK_A, BANK_B, spacing=1.0)
    result = lines_centerline(doubled_a, doubled_b, spacing=1.0)
    assert np.array_equal(np.asarray(result.line.coords), np.asarray(expected.line.coords))
    assert np.array_equal(result.radii, expected.radii)


# Self-intersecting polygon ----------------------------------------------------------------------------


def test_self_intersecting_polygon_says_where():
    bow_tie = Polygon([(0.0, 0.0), (100.0, 10.0), (100.0, 0.0), (0.0, 10.0)])
    with pytest.raises(InvalidGeometryError) as caught:
        polygon_centerline(bow_tie, [(0.0, 5.0), (100.0, 5.0)])
    message = str(caught.value)
    assert "self" in message.lower() and "intersect" in message.lower()
    # The crossing is at (50, 5): the message must carry those coordinates.
    numbers = numbers_in(message)
    assert any(
        math.isclose(x, 50.0, abs_tol=1e-9) and math.isclose(y, 5.0, abs_tol=1e-9) for x, y in zip(numbers, numbers[1:])
    ), message


def test_polygon_with_a_spike_folding_back_is_rejected():
    spike = Polygon([(0.0, 0.0), (100.0, 0.0), (100.0, 10.0), (60.0, 10.0), (60.0, 20.0), (60.0, 10.0), (0.0, 10.0)])
    with pytest.raises(InvalidGeometryError):
        polygon_centerline(spike, ENDS)


# Split points -----------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "points", [[], [(0.0, 5.0)], [(0.0, 5.0), (100.0, 5.0), (50.0, 0.0)]], ids=["zero", "one", "three"]
)
def test_split_points_not_two(points):
    # An empty list means "find the ends" to polygon_centerline, one point "find the other end"; split_polygon
    # needs exactly two.
    with pytest.raises(SplitPointError, match="exactly 2") as caught:
        split_polygon(RECTANGLE, points)
    assert str(len(points)) in str(caught.value)
    if len(points) > 1:
        with pytest.raises(SplitPointError, match="exactly 2"):
            polygon_centerline(RECTANGLE, points)


def test_split_point_too_far_from_the_ring_names_point_distance_and_tolerance():
    with pytest.raises(SplitPointError) as caught:
        polygon_centerline(RECTANGLE, [(-1.0, 5.0), (100.0, 5.0)], snap_tolerance=0.5)
    numbers = numbers_in(str(caught.value))
    assert 1.0 in numbers and 0.5 in numbers, str(caught.value)


def test_split_point_inside_the_polygon_beyond_the_default_tolerance():
    # The default tolerance is 1e-6 of the extent (1e-4 here): a point 1e-3 inside is refused.
    with pytest.raises(SplitPointError):
        polygon_centerline(RECTANGLE, [(1e-3, 5.0), (100.0, 5.0)])


def test_split_point_within_the_tolerance_is_snapped_onto_the_ring():
    result = polygon_centerline(RECTANGLE, [(0.2, 5.0), (100.0, 5.3)], snap_tolerance=0.5, spacing=1.0)
    coords = np.asarray(result.line.coords)
    # Snapped to the nearest ring point, to the rounding of a projection onto an edge (1e-12 of the extent).
    assert coords[0] == pytest.approx((0.0, 5.0), abs=1e-12 * 100.0)
    assert coords[-1] == pytest.approx((100.0, 5.3), abs=1e-12 * 100.0)


@pytest.mark.parametrize(
    "points",
    [[(0.0, 5.0), (0.0, 5.0)], [Point(100.0, 5.0), (100.0, 5.0)], [(0.0, 0.0), (0.0, 1e-9)]],
    ids=["same", "point-and-tuple", "snap-to-same-place"],
)
def test_identical_split_points(points):
    with pytest.raises(SplitPointError, match="same place"):
        polygon_centerline(RECTANGLE, points)


# Open mode: crossing or touching lines ----------------------------------------------------------------


def test_crossing_lines_say_where():
    with pytest.raises(CrossingLinesError) as caught:
        lines_centerline([(0.0, 0.0), (100.0, 10.0)], [(0.0, 10.0), (100.0, 0.0)])
    numbers = numbers_in(str(caught.value))
    assert 50.0 in numbers and 5.0 in numbers, str(caught.value)


def test_lines_found_to_meet_say_where_even_when_their_intersection_comes_back_empty(monkeypatch):
    # The predicate and the overlay are separate GEOS computations; should they disagree, the message still
    # names the place (where the lines come nearest).
    monkeypatch.setattr(chains.shapely, "intersection", lambda *lines: LineString())
    with pytest.raises(CrossingLinesError) as caught:
        lines_centerline([(0.0, 0.0), (100.0, 10.0)], [(0.0, 10.0), (100.0, 0.0)])
    numbers = numbers_in(str(caught.value))
    assert 50.0 in numbers and 5.0 in numbers, str(caught.value)


@pytest.mark.parametrize(
    "line_b",
    [
        [(0.0, 10.0), (50.0, 0.0), (100.0, 10.0)],
        [(0.0, 10.0), (100.0, 10.0), (100.0, 0.0)],
        [(0.0, 0.0), (0.0, 10.0), (100.0, 10.0)],
    ],
    ids=["vertex-on-edge", "end-on-end", "start-on-start"],
)
def test_touching_lines(line_b):
    with pytest.raises(CrossingLinesError):
        lines_centerline(BANK_A, line_b)


def test_overlapping_lines():
    with pytest.raises(CrossingLinesError):
        lines_centerline(BANK_A, [(20.0, 0.0), (80.0, 0.0)])


# A chain folding back over itself ---------------------------------------------------------------------


@pytest.mark.parametrize(
    "line",
    [[(0.0, 0.0), (100.0, 0.0), (60.0, 0.0)], [(0.0, 0.0), (60.0, 0.0), (60.0, 0.0), (30.0, 0.0), (100.0, 0.0)]],
    ids=["end-folds-back", "fold-behind-a-duplicate"],
)
def test_line_folding_back_over_itself_loses_the_fold_and_says_where(line):
    """A fold of zero width is removed before the chains are built (``chains.without_folds``); the note names
    the vertex that went (the end coming back, or the spike's tip)."""
    result = lines_centerline(line, BANK_B)
    (note,) = result.notes
    assert note.startswith("A zero-width spike was removed from the first line at ")
    gone = line[-1] if line[-1][0] < line[-2][0] else (60.0, 0.0)
    assert gone[0] in numbers_in(note), note
    assert result.line.coords[0] == (0.0, 5.0) and result.line.coords[-1] == (100.0, 5.0)


def test_line_crossing_itself_says_where():
    loop = [(0.0, 0.0), (60.0, 0.0), (60.0, 5.0), (40.0, 5.0), (40.0, -5.0), (100.0, -5.0)]
    with pytest.raises(ChainError, match="crosses itself") as caught:
        lines_centerline(loop, BANK_B)
    numbers = numbers_in(str(caught.value))
    assert 40.0 in numbers and 0.0 in numbers, str(caught.value)


def test_errors_leave_later_calls_working():
    # A failed call leaves no state behind: the next good call gives the same result as a fresh one.
    expected = polygon_centerline(RECTANGLE, ENDS, spacing=1.0)
    for bad in (None, Polygon([(0.0, 0.0), (100.0, 10.0), (100.0, 0.0), (0.0, 10.0)])):
        with pytest.raises(IncirCuError):
            polygon_centerline(bad, ENDS, spacing=1.0)
    result = polygon_centerline(RECTANGLE, ENDS, spacing=1.0)
    assert result.line.equals_exact(expected.line, 0.0)


def test_lines_on_one_line_enclose_nothing():
    with pytest.raises(ChainError, match="no area"):
        lines_centerline([(0.0, 0.0), (10.0, 0.0)], [(20.0, 0.0), (30.0, 0.0)])


@pytest.mark.parametrize(
    "chain, error",
    [
        ([(0.0, 0.0)], ChainError),
        ([(0.0, 0.0), (math.nan, 0.0)], InvalidGeometryError),
        ([(0.0, 0.0), (0.0, 0.0)], ChainError),
    ],
)
def test_the_engine_checks_its_chains_too(chain, error):
    with pytest.raises(error):
        centerline_from_chains(np.array(chain), np.array(BANK_B), spacing=1.0)


def test_a_failed_part_keeps_no_traceback_and_frees_its_caller():
    import gc
    import weakref

    class Caller:
        def report(self, fraction):
            return True

    caller = Caller()
    alive = weakref.ref(caller)
    bow_tie = Polygon([(0, 20), (100, 30), (100, 20), (0, 30)])
    gc.disable()
    try:
        outcomes = multipolygon_centerlines(MultiPolygon([RECTANGLE, bow_tie]), ENDS, progress=caller.report)
        del caller
        assert alive() is None, "a stored error keeps the progress callback's owner alive"
    finally:
        gc.enable()
    assert outcomes[0].error is None
    assert isinstance(outcomes[1].error, InvalidGeometryError)
    assert outcomes[1].error.__traceback__ is None


# Hostile input: every public entry point answers with a typed error saying what to change ------------------

BOW_TIE = Polygon([(0, 20), (100, 30), (100, 20), (0, 30)])


def scaled(geometry, factor):
    return shapely.transform(geometry, lambda xy: xy * factor)


@pytest.mark.parametrize("factor", [1e154, 1e299], ids=["1e155", "1e300"])
@pytest.mark.parametrize(
    "call",
    [
        lambda p: polygon_centerline(p),
        lambda p: polygon_centerline(p, [(0, 5), (100, 5)]),
        lambda p: find_ends(p),
        lambda p: split_polygon(p, [(0, 5), (100, 5)]),
        lambda p: multipolygon_centerlines(p),
    ],
    ids=["auto", "split", "find_ends", "split_polygon", "multi"],
)
def test_huge_coordinates_are_refused_as_overflowing(factor, call):
    with pytest.raises(InvalidGeometryError, match="overflow float64") as caught:
        call(scaled(RECTANGLE, factor))
    assert f"{100 * factor:.3g}" in str(caught.value)


@pytest.mark.parametrize("factor", [1e-171, 1e-301], ids=["1e-170", "1e-300"])
def test_tiny_shapes_are_refused_as_underflowing(factor):
    for call in (polygon_centerline, find_ends):
        with pytest.raises(InvalidGeometryError, match="underflow float64.*Scale the data up"):
            call(scaled(RECTANGLE, factor))


def test_bank_lines_of_huge_coordinates_are_refused():
    with pytest.raises(InvalidGeometryError, match="first line .* overflow"):
        lines_centerline([(0, 0), (1e300, 0)], [(0, 1e299), (1e300, 1e299)])


def test_shape_too_small_for_its_distance_from_the_origin_is_refused():
    far = shapely.affinity.translate(RECTANGLE, 1e15, 1e15)
    with pytest.raises(InvalidGeometryError, match="cannot resolve.*Shift the data nearer the origin"):
        polygon_centerline(far)


def test_moderate_scales_and_offsets_still_work():
    for factor in (1e-40, 1e40):
        result = polygon_centerline(scaled(RECTANGLE, factor), [(0, 5 * factor), (100 * factor, 5 * factor)])
        assert abs(result.length - 100 * factor) <= 1e-9 * 100 * factor
    far = shapely.affinity.translate(RECTANGLE, 1e9, 1e9)
    assert abs(polygon_centerline(far, [(1e9, 1e9 + 5), (1e9 + 100, 1e9 + 5)]).length - 100) < 1e-4


@pytest.mark.parametrize("value", [math.nan, math.inf, -1.0, "1"], ids=["nan", "inf", "negative", "text"])
def test_bad_samples_per_chain_is_an_option_error_naming_the_value(value):
    for call in (
        lambda: polygon_centerline(RECTANGLE, ENDS, samples_per_chain=value),
        lambda: lines_centerline(BANK_A, BANK_B, samples_per_chain=value),
    ):
        with pytest.raises(OptionError, match=f"(samples_per_chain|samples per chain) .*{re.escape(repr(value))}"):
            call()


def first_part(outcomes):
    """The result of a multipolygon's first part, or its error raised."""
    if outcomes[0].error is not None:
        raise outcomes[0].error
    return outcomes[0].result


@pytest.mark.parametrize("name", ["spacing", "tolerance"])
@pytest.mark.parametrize("value", [math.nan, -math.inf, -1.0, "1"], ids=["nan", "-inf", "negative", "text"])
def test_bad_spacing_or_tolerance_is_an_option_error_naming_the_value(name, value):
    for call in (
        lambda: polygon_centerline(RECTANGLE, ENDS, **{name: value}),
        lambda: lines_centerline(BANK_A, BANK_B, **{name: value}),
        lambda: first_part(multipolygon_centerlines(RECTANGLE, ENDS, **{name: value})),
    ):
        with pytest.raises(OptionError, match=f"{name} must be .*{re.escape(repr(value))}"):
            outcome = call()
            raise AssertionError(f"accepted {name}={value!r}: {outcome}")


@pytest.mark.parametrize("value", [math.nan, math.inf, -1.0, "0.1"], ids=["nan", "inf", "negative", "text"])
def test_bad_snap_tolerance(value):
    far_point = [(300.0, 400.0), (100.0, 5.0)]
    for call in (
        lambda: polygon_centerline(RECTANGLE, far_point, snap_tolerance=value),
        lambda: multipolygon_centerlines(RECTANGLE, far_point, snap_tolerance=value),
        lambda: split_polygon(RECTANGLE, far_point, value),
    ):
        with pytest.raises(OptionError, match="snap_tolerance must be a (non-negative, finite distance|number)"):
            call()


def test_multipoint_split_points_are_used_as_points():
    result = polygon_centerline(RECTANGLE, MultiPoint(ENDS))
    assert result.line.coords[0] == ENDS[0] and result.line.coords[-1] == ENDS[1]
    (outcome,) = multipolygon_centerlines(RECTANGLE, MultiPoint(ENDS))
    assert outcome.result.line.coords[-1] == ENDS[1]


@pytest.mark.parametrize(
    "points, message",
    [
        ([Point(), Point()], "Split point 0 is an empty point"),
        (Point(0, 5), "sequence of two points .* got a Point"),
        ((0.0, 5.0), "Split point 0 is the number 0.0"),
        ([LineString([(0, 0), (0, 10)]), Point(100, 5)], "Split point 0 must be a point, not a LineString"),
        ([(0, 5, 1, 2), (100, 5)], r"Split point 0 must be an \(x, y\) pair"),
    ],
    ids=["empty-points", "one-point", "one-pair", "line", "four-numbers"],
)
def test_split_points_of_the_wrong_kind(points, message):
    for call in (polygon_centerline, multipolygon_centerlines, split_polygon):
        with pytest.raises(SplitPointError, match=message):
            call(RECTANGLE, points)


def test_text_where_a_geometry_is_expected_is_a_type_error_or_typed():
    with pytest.raises(TypeError, match="parse WKT"):
        lines_centerline("LINESTRING (0 0, 100 0)", "LINESTRING (0 8, 100 8)")
    with pytest.raises(InvalidGeometryError, match="got a str"):
        polygon_centerline("POLYGON ((0 0, 1 0, 1 1, 0 0))")


def test_ragged_coordinates_are_an_invalid_geometry():
    with pytest.raises(InvalidGeometryError, match=r"\(n, 2\) array of numbers"):
        lines_centerline([(0, 0), (1, 2, 3)], BANK_B)


def test_invalid_part_is_reported_as_invalid_not_as_split_point_count():
    outcomes = multipolygon_centerlines(BOW_TIE, [(0, 25), (100, 25), (50, 25)])
    assert isinstance(outcomes[0].error, InvalidGeometryError)
    assert "Self-intersection" in str(outcomes[0].error)


@pytest.mark.parametrize("geometry", [None, Polygon(), MultiPolygon()], ids=["none", "empty", "empty-multi"])
def test_null_or_empty_multipolygon(geometry):
    with pytest.raises(InvalidGeometryError, match="null|empty"):
        multipolygon_centerlines(geometry)


# The last guard: no self-crossing line, no identical automatic ends ---------------------------------------


def test_a_crossing_line_is_never_returned():
    from dataclasses import replace

    from incircu_plugin.core.api import _checked

    result = polygon_centerline(RECTANGLE, ENDS)
    crossing = replace(result, line=LineString([(0, 0), (10, 10), (10, 0), (0, 10)]))
    with pytest.raises(CenterlineError, match=r"crosses itself at \(5, 5\)"):
        _checked(crossing)
    assert _checked(result) is result


def test_a_line_leaving_its_polygon_is_never_returned():
    from dataclasses import replace

    from incircu_plugin.core.api import _checked

    result = polygon_centerline(RECTANGLE, ENDS)
    outside = replace(result, line=LineString([(0, 5), (50, 12), (100, 5)]))
    with pytest.raises(CenterlineError, match=r"leaves the polygon at \(50, 12\) \(2 outside\)"):
        _checked(outside, RECTANGLE)
    assert _checked(result, RECTANGLE) is result


def test_square_whose_automatic_ends_coincide_is_a_split_point_error():
    square = shapely.segmentize(
        box(499.04325887565847, 203.26611626641056, 500.04325887565847, 204.26611626641056), 1 / 14
    )
    try:
        result = polygon_centerline(square)
    except SplitPointError as error:
        assert "coincide" in str(error) and "Give two split points" in str(error)
    else:
        assert result.line.is_simple and result.line.length > 0


@pytest.mark.parametrize("corners", [5, 6, 7, 8, 13])
def test_regular_polygon_with_automatic_ends_is_simple_or_refused(corners):
    angles = 2 * np.pi * np.arange(corners) / corners
    polygon = Polygon(np.stack([np.cos(angles), np.sin(angles)], axis=1))
    try:
        result = polygon_centerline(polygon)
    except CenterlineError as error:
        assert "crosses itself at" in str(error)
    else:
        assert result.line.is_simple


def test_validation_remembers_only_the_same_valid_polygon():
    import gc

    from incircu_plugin.core.chains import validate_polygon

    valid = box(0.0, 0.0, 10.0, 2.0)
    validate_polygon(valid)
    validate_polygon(valid)
    with pytest.raises(InvalidGeometryError, match="null"):
        validate_polygon(None)
    bowtie = Polygon([(0, 0), (2, 2), (2, 0), (0, 2)])
    for _ in range(2):
        with pytest.raises(InvalidGeometryError, match="not valid"):
            validate_polygon(bowtie)
    validate_polygon(valid)
    del valid
    gc.collect()
    with pytest.raises(InvalidGeometryError, match="null"):
        validate_polygon(None)


@pytest.mark.parametrize("prepared", [False, True])
def test_final_check_leaves_the_region_as_given(prepared):
    from incircu_plugin.core.api import _checked

    region = box(0.0, 0.0, 100.0, 10.0)
    if prepared:
        shapely.prepare(region)
    result = polygon_centerline(region, ENDS)
    assert _checked(result, region) is result
    assert shapely.is_prepared(region) == prepared


def test_a_polygon_found_valid_is_checked_once_while_it_lives(monkeypatch):
    """A batch checks each feature, then finds the ends of all (which check them again): the second check of
    each of two polygons asks nothing of GEOS."""
    checked = []
    monkeypatch.setattr(chains, "check_coordinates", lambda *arguments, **options: checked.append(arguments))
    first, second = box(0.0, 0.0, 2.0, 1.0), box(5.0, 5.0, 9.0, 6.0)
    for polygon in (first, second, first, second):
        validate_polygon(polygon)
    assert len(checked) == 2


def test_a_reused_id_is_never_trusted_and_no_polygon_is_kept_alive(monkeypatch):
    """Every polygon under one ``id`` (what a freed polygon's reused address gives): a valid polygon remembered
    under it does not vouch for another; a remembered polygon is not kept alive."""
    monkeypatch.setattr(chains._Validated, "polygons", type(chains._Validated.polygons)())
    monkeypatch.setattr(chains, "id", lambda polygon: 1, raising=False)
    valid = box(0.0, 0.0, 2.0, 1.0)
    validate_polygon(valid)
    bow_tie = Polygon([(0.0, 0.0), (4.0, 4.0), (4.0, 0.0), (0.0, 4.0)])
    with pytest.raises(InvalidGeometryError, match="not valid"):
        validate_polygon(bow_tie)
    freed = weakref.ref(valid)
    del valid
    gc.collect()
    assert freed() is None


@pytest.mark.parametrize(
    ("coordinates", "words"),
    [
        ([[-1e155, 0.0], [0.0, 1.0]], "scale the data down"),
        ([[-1e6, -1e6], [-1e6 + 1e-5, -1e6], [-1e6, -1e6 + 1e-5]], "Shift the data nearer the origin"),
    ],
    ids=["huge", "tiny-far"],
)
def test_the_magnitude_of_negative_coordinates_counts(coordinates, words):
    # The largest |coordinate| is a negative one: its magnitude decides both checks.
    with pytest.raises(InvalidGeometryError, match=words):
        check_coordinates(np.array(coordinates), "polygon")


def test_checked_coordinates_give_their_extent_when_whole():
    # The bounding box's diagonal (what a polygon's default snap tolerance is a millionth of).
    coordinates = np.array([[-3.0, 1.0], [0.0, 5.0], [-1.0, 2.0]])
    assert check_coordinates(coordinates, "polygon") == 5.0
    assert check_coordinates(coordinates[:1], "polygon") == 0.0
    assert check_coordinates(coordinates, "pair of lines", whole=False) is None


def test_a_wrong_split_point_count_names_no_part_of_a_single_polygon():
    # Three split points for a centerline of a plain polygon: there is no "part 0" to speak of, and the
    # tolerance has its unit.
    points = [(0.0, 2.0), (50.0, 2.0), (25.0, 0.0)]
    (outcome,) = multipolygon_centerlines(box(0.0, 0.0, 50.0, 4.0), points, snap_tolerance=0.5)
    message = str(outcome.error)
    assert message.startswith("The polygon has 3 split points within the snap tolerance (0.5 CRS units) of"), message
    assert "Part" not in message


@pytest.mark.parametrize("find", [multipolygon_centerlines, multipolygon_networks], ids=["centerline", "network"])
def test_one_split_point_is_one_end_and_the_other_is_found(find):
    (outcome,) = find(box(0.0, 0.0, 50.0, 4.0), [(0.0, 1.0)], snap_tolerance=0.5)
    assert outcome.error is None
    result = outcome.result if find is multipolygon_centerlines else outcome.result.branches[0].result
    ends = sorted(tuple(np.round(xy, 9)) for xy in shapely.get_coordinates(result.line)[[0, -1]])
    assert ends == [(0.0, 1.0), (50.0, 2.0)]


def test_a_wrong_split_point_count_of_a_part_speaks_of_the_part():
    # Three split points on the second part: its outcome's index says which part; the message says "the part".
    parts = MultiPolygon([box(0.0, 0.0, 50.0, 4.0), box(0.0, 10.0, 50.0, 14.0)])
    points = [(0.0, 2.0), (50.0, 2.0), (0.0, 12.0), (50.0, 12.0), (25.0, 14.0)]
    outcomes = multipolygon_centerlines(parts, points, snap_tolerance=0.5)
    assert outcomes[0].error is None and outcomes[1].part_index == 1
    assert str(outcomes[1].error).startswith("The part has 3 split points within the snap tolerance (0.5 CRS units)")


def test_a_far_split_point_names_the_unit_of_the_distances():
    with pytest.raises(SplitPointError, match=r"is 3 CRS units away .* the snap tolerance is 0\.5 CRS units\."):
        polygon_centerline(box(0.0, 0.0, 50.0, 4.0), [(-3.0, 2.0), (50.0, 2.0)], snap_tolerance=0.5)


@pytest.mark.parametrize("ratio", [0.5 * BANK_LENGTH_RATIO, 5.0 * BANK_LENGTH_RATIO])
def test_banks_of_very_different_lengths_are_noted(ratio):
    # A channel 10 wide: the second bank covers the first's first 100 units, the first runs on to 100 * ratio.
    # Beyond the shorter bank the region is closed by the chord from (100, 10) to the first bank's end.
    result = lines_centerline([(0.0, 0.0), (100.0 * ratio, 0.0)], [(0.0, 10.0), (100.0, 10.0)])
    if ratio <= BANK_LENGTH_RATIO:
        assert result.notes == ()
        return
    (note,) = result.notes
    assert note.startswith(f"The first line is {100.0 * ratio:g} long, {ratio:g} times the second one (100 CRS units)")
    assert "follows that gap" in note
    # What the note warns of: the widest incircle is far wider than the channel.
    assert result.widths.max() > 2.0 * 10.0
