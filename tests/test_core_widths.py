"""Width outputs (``incircu_plugin.core.widths``): incircle polygons and cross-section transects.

The shapes have a known width everywhere (rectangle, annulus sector, constant-width meander), so every
transect must measure it and every incircle must be the result's own circle. Tolerances: the engine places
vertices and radii to 1e-9 of the extent (its proven invariant), and between two vertices the centerline is
a chord of the true axis, off by at most its sagitta, which ``axis_tolerance`` of each case bounds.
"""

import dataclasses
import math

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Point

from incircu_plugin.core import IncirCuError, lines_centerline, polygon_centerline
from incircu_plugin.core.widths import (
    Incircle,
    Transect,
    incircle_polygons,
    measured_stretch,
    transects,
    vertex_chainages,
    width_statistics,
)
from tests.support import geometry_cases

#: Relative accuracy (of the extent) of the engine's vertices and radii.
ENGINE_ACCURACY = 1e-9


def centerline(case, divisions=10):
    """The centerline of a case at a spacing of ``width / divisions``."""
    return polygon_centerline(case.polygon, case.split_points, spacing=case.width / divisions)


def chord_sagitta(result, curvature_radius):
    """Largest distance, CRS units, between a chord of the centerline and an arc of the given radius."""
    longest = float(np.max(np.hypot(*np.diff(shapely.get_coordinates(result.line), axis=0).T)))
    return curvature_radius - math.sqrt(max(curvature_radius**2 - (longest / 2.0) ** 2, 0.0))


@pytest.mark.parametrize("placement", sorted(geometry_cases.PLACEMENTS))
def test_rectangle_transects_measure_its_width_straight_across(placement):
    case = geometry_cases.rectangle(length=100.0, width=10.0, placement=geometry_cases.PLACEMENTS[placement])
    result = centerline(case)
    interval = case.width / 3.0
    cuts = transects(result, interval)
    tolerance = ENGINE_ACCURACY * case.extent + 8.0 * case.coordinate_ulp * 10.0
    # Transects cover the stretch between the first and the last incircle: half a width from each end.
    half_width = case.width / 2.0
    length = result.line.length
    stations = interval * np.arange(int(np.floor(length / interval)) + 1)
    inner = stations[(stations >= half_width - tolerance) & (stations <= length - half_width + tolerance)]
    assert [cut.chainage for cut in cuts] == pytest.approx(list(inner), abs=tolerance)
    bank_a, bank_b = LineString(case.bank_a), LineString(case.bank_b)
    for cut in cuts:
        assert isinstance(cut, Transect)
        assert cut.width == pytest.approx(case.width, abs=tolerance)
        assert cut.line.length == pytest.approx(cut.width, abs=tolerance)
        start, middle, end = (Point(xy) for xy in cut.line.coords)
        assert bank_a.distance(start) <= tolerance
        assert bank_b.distance(end) <= tolerance
        assert result.line.interpolate(cut.chainage).distance(middle) <= tolerance
        assert case.axis_distance(np.array([middle.coords[0]]))[0] <= tolerance + case.axis_tolerance


def test_annulus_sector_transects_are_radial_and_as_wide_as_the_ring():
    vertices_per_arc = 61
    case = geometry_cases.annulus_sector(r_inner=40.0, r_outer=60.0, n=vertices_per_arc)
    result = centerline(case, divisions=20)
    sagitta = chord_sagitta(result, 50.0)
    tolerance = ENGINE_ACCURACY * case.extent + case.axis_tolerance + sagitta
    # The arcs are polygons: on a chord the nearest point lies off the radial line by up to the half-width
    # times the sine of half the angle a chord spans.
    chord_turn = math.pi / (vertices_per_arc - 1)
    sideways = tolerance + 10.0 * math.sin(chord_turn / 2.0)
    cuts = transects(result, 7.0)
    # No transects in the end caps, about half a width (10) long at each end.
    assert len(cuts) >= int((result.line.length - 20.0) / 7.0) - 1
    centre = np.zeros(2)
    for cut in cuts:
        foot_a, middle, foot_b = np.asarray(cut.line.coords)
        assert cut.width == pytest.approx(20.0, abs=2.0 * tolerance)
        radial = (middle - centre) / np.hypot(*middle)
        for foot in (foot_a, foot_b):
            offset = foot - middle
            assert abs(offset[0] * radial[1] - offset[1] * radial[0]) <= sideways
        assert sorted([np.hypot(*foot_a), np.hypot(*foot_b)]) == pytest.approx([40.0, 60.0], abs=2.0 * tolerance)


def test_transect_feet_lie_on_the_chains_when_the_chains_are_given():
    case = geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0)
    result = centerline(case)
    chains = (LineString(case.chain_a), LineString(case.chain_b))
    cuts = transects(result, 13.0, chains=chains)
    tolerance = ENGINE_ACCURACY * case.extent
    smallest_curvature_radius = (400.0 / (2.0 * math.pi)) ** 2 / 40.0
    axis_error = case.axis_tolerance + chord_sagitta(result, smallest_curvature_radius - case.width / 2.0)
    for cut in cuts:
        foot_a, _, foot_b = (Point(xy) for xy in cut.line.coords)
        assert chains[0].distance(foot_a) <= tolerance
        assert chains[1].distance(foot_b) <= tolerance
        assert cut.width == pytest.approx(case.width, abs=2.0 * axis_error + tolerance)


def test_interpolated_and_chain_feet_agree_on_a_meander():
    case = geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0)
    result = centerline(case)
    chains = (case.chain_a, case.chain_b)
    interpolated = transects(result, 11.0)
    exact = transects(result, 11.0, chains=chains)
    assert [cut.chainage for cut in interpolated] == [cut.chainage for cut in exact]
    spacing = float(np.max(np.hypot(*np.diff(shapely.get_coordinates(result.line), axis=0).T)))
    for a, b in zip(interpolated, exact):
        gap = np.hypot(*(np.asarray(a.line.coords) - np.asarray(b.line.coords)).T).max()
        assert gap <= spacing


@pytest.mark.parametrize("placement", sorted(geometry_cases.PLACEMENTS))
def test_incircles_are_the_results_circles(placement):
    case = geometry_cases.meander(
        length=800.0, width=20.0, amplitude=40.0, wavelength=400.0, placement=geometry_cases.PLACEMENTS[placement]
    )
    result = centerline(case)
    circles = incircle_polygons(result, quad_segs=8)
    vertices = shapely.get_coordinates(result.line)
    nonzero = np.flatnonzero(result.radii > 0.0)
    assert len(circles) == len(nonzero)
    chainages = vertex_chainages(result)
    tolerance = ENGINE_ACCURACY * case.extent
    for circle, index in zip(circles, nonzero):
        assert isinstance(circle, Incircle)
        assert circle.radius == result.radii[index]
        assert circle.chainage == pytest.approx(chainages[index], abs=tolerance)
        corners = shapely.get_coordinates(circle.polygon.exterior)[:-1]
        assert len(corners) == 4 * 8
        assert np.hypot(*(corners - vertices[index]).T) == pytest.approx(circle.radius, abs=tolerance)
    assert np.all(np.diff([circle.chainage for circle in circles]) >= 0.0)


def test_incircles_are_empty_circles_of_the_polygon():
    case = geometry_cases.rectangle(length=100.0, width=10.0)
    result = centerline(case)
    tolerance = ENGINE_ACCURACY * case.extent
    for circle in incircle_polygons(result):
        assert case.polygon.buffer(tolerance).contains(circle.polygon)
        assert circle.radius == pytest.approx(5.0, abs=tolerance)


def test_chainage_of_the_last_vertex_is_the_line_length():
    case = geometry_cases.tapered_channel()
    result = centerline(case)
    chainages = vertex_chainages(result)
    assert chainages[0] == 0.0
    assert chainages[-1] == pytest.approx(result.line.length, rel=1e-12)


def test_tapered_channel_transects_narrow_with_the_channel():
    case = geometry_cases.tapered_channel(length=100.0, width_start=20.0, width_end=5.0)
    result = centerline(case)
    widths = [cut.width for cut in transects(result, 10.0)]
    assert len(widths) >= 8
    assert np.all(np.diff(widths) < 0.0)


@pytest.mark.parametrize("interval", [0.0, -1.0, float("nan"), float("inf"), "ten"])
def test_bad_interval_is_a_typed_error(interval):
    result = centerline(geometry_cases.rectangle())
    with pytest.raises(IncirCuError):
        transects(result, interval)


def test_bad_circle_resolution_is_a_typed_error():
    result = centerline(geometry_cases.rectangle())
    with pytest.raises(IncirCuError):
        incircle_polygons(result, quad_segs=0)


def test_open_mode_transects_reach_both_open_ends():
    gap = 8.0
    result = lines_centerline([(0.0, 0.0), (100.0, 0.0)], [(0.0, gap), (100.0, gap)], spacing=1.0)
    cuts = transects(result, 25.0)
    tolerance = ENGINE_ACCURACY * 100.0
    assert [cut.chainage for cut in cuts] == pytest.approx([0.0, 25.0, 50.0, 75.0, 100.0], abs=tolerance)
    assert [cut.width for cut in cuts] == pytest.approx([gap] * 5, abs=tolerance)


def test_width_statistics_of_a_rectangle_and_of_two_parts():
    # A 100 x 10 rectangle between split points on its short sides: every inner incircle is 10 wide, the two
    # ends on the outline have no width and are left out.
    width, length = 10.0, 100.0
    result = polygon_centerline(shapely.box(0, 0, length, width), [(0, 5), (length, 5)], spacing=1.0)
    statistics = width_statistics([result])
    assert statistics["length"] == pytest.approx(length, rel=1e-12)
    for name in ("width_min", "width_mean", "width_max"):
        assert statistics[name] == pytest.approx(width, rel=1e-9)
    assert statistics["n_vertices"] == len(result.line.coords)
    assert statistics["ends_found"] is False
    # A second part twice as wide and as long: the lengths add up, the mean is weighted by length.
    wide = polygon_centerline(shapely.box(0, 20, 2 * length, 20 + 2 * width))
    both = width_statistics([result, wide])
    assert both["length"] == pytest.approx(result.length + wide.length, rel=1e-12)
    assert both["width_min"] == pytest.approx(width, rel=1e-9)
    assert both["width_max"] == pytest.approx(2 * width, rel=1e-9)
    assert width < both["width_mean"] < 2 * width
    assert both["ends_found"] is False and width_statistics([wide])["ends_found"] is True


def adaptive_centerline(case, tolerance):
    """The default (adaptive) centerline of a case within ``tolerance`` (CRS units) of its axis."""
    return polygon_centerline(case.polygon, case.split_points, tolerance=tolerance)


def stations_between(length, interval, low, high, slack):
    """The multiples of ``interval`` from ``low`` to ``high`` (within ``slack``) on a line of ``length``."""
    stations = interval * np.arange(int(np.floor(length / interval)) + 1)
    return stations[(stations >= low - slack) & (stations <= high + slack)]


@pytest.mark.parametrize("interval", [40.0, 100.0])
def test_transects_cover_a_long_straight_channel_whose_line_has_few_vertices(interval):
    # The adaptive line of a rectangle has four vertices: the ends and where the stubs from the split points
    # meet the axis, half a width in. Transects belong everywhere between those two, not only past the next
    # vertex (the far one).
    case = geometry_cases.rectangle(length=1000.0, width=40.0)
    tolerance = case.width / 200.0
    result = adaptive_centerline(case, tolerance)
    assert len(result.line.coords) < 10
    cuts = transects(result, interval)
    # The line is within ``tolerance`` of the axis and each foot lies at the radius from it, so a width is off
    # by at most twice that.
    half_width, length = case.width / 2.0, result.line.length
    expected = stations_between(length, interval, half_width, length - half_width, tolerance)
    assert len(expected) == {40.0: 24, 100.0: 9}[interval]
    assert [cut.chainage for cut in cuts] == pytest.approx(list(expected), abs=tolerance)
    bank_a, bank_b = LineString(case.bank_a), LineString(case.bank_b)
    for cut in cuts:
        assert cut.width == pytest.approx(case.width, abs=2.0 * tolerance)
        start, middle, end = (Point(xy) for xy in cut.line.coords)
        assert bank_a.distance(start) <= 2.0 * tolerance
        assert bank_b.distance(end) <= 2.0 * tolerance
        assert case.axis_distance(np.array([middle.coords[0]]))[0] <= tolerance + case.axis_tolerance


def test_tapered_channel_transects_follow_its_width_along_the_whole_line():
    width_start, width_end, length = 60.0, 20.0, 1000.0
    case = geometry_cases.tapered_channel(length=length, width_start=width_start, width_end=width_end)
    tolerance = case.width / 200.0
    result = adaptive_centerline(case, tolerance)
    interval = 25.0
    cuts = transects(result, interval)
    # The axis is the x-axis; the incircle at x touches both banks, which slope by ``slope``, so its diameter
    # is the vertical width at x times the cosine of the slope.
    slope = 0.5 * (width_start - width_end) / length
    cosine = 1.0 / math.sqrt(1.0 + slope**2)

    def width_at(x):
        return (width_start + (width_end - width_start) * x / length) * cosine

    # End caps: the line reaches the full width within half the width of each end.
    assert len(cuts) >= int((length - 0.5 * (width_start + width_end) * cosine) / interval) - 1
    assert cuts[0].chainage <= width_start / 2.0 + interval
    assert cuts[-1].chainage >= length - width_end / 2.0 - interval
    bank_a, bank_b = LineString(case.bank_a), LineString(case.bank_b)
    for cut in cuts:
        start, middle, end = (Point(xy) for xy in cut.line.coords)
        assert cut.width == pytest.approx(width_at(middle.x), abs=2.0 * tolerance)
        assert bank_a.distance(start) <= 2.0 * tolerance
        assert bank_b.distance(end) <= 2.0 * tolerance
    assert np.all(np.diff([cut.width for cut in cuts]) < 0.0)


@pytest.mark.parametrize(
    "case, bend",
    [
        (geometry_cases.rectangle(length=1000.0, width=40.0), None),
        (geometry_cases.tapered_channel(length=1000.0, width_start=60.0, width_end=20.0), None),
        # The meander's axis bends at radius wavelength**2 / (4 pi**2 amplitude) at the tightest.
        (
            geometry_cases.meander(length=800.0, width=20.0, amplitude=40.0, wavelength=400.0),
            (400.0 / (2.0 * math.pi)) ** 2 / 40.0,
        ),
    ],
    ids=["rectangle", "tapered", "meander"],
)
def test_adaptive_and_fixed_sampling_give_the_same_transects(case, bend):
    tolerance = case.width / 200.0
    adaptive = adaptive_centerline(case, tolerance)
    fixed = centerline(case, divisions=20)
    # Both lines lie near the axis: the adaptive one within ``tolerance``, the fixed one (straight on a straight
    # axis) within its chords' sagitta on the tightest bend.
    sagitta = 0.0 if bend is None else chord_sagitta(fixed, bend)
    offset = tolerance + sagitta + case.axis_tolerance + ENGINE_ACCURACY * case.extent
    # Chainages on the two lines drift apart by at most the difference of their lengths.
    drift = abs(adaptive.line.length - fixed.line.length)
    interval = case.width
    ours, theirs = transects(adaptive, interval), transects(fixed, interval)
    assert len(ours) >= int(adaptive.line.length / interval) - 2
    assert len(ours) == len(theirs)
    for a, b in zip(ours, theirs):
        assert a.chainage == pytest.approx(b.chainage, abs=drift + offset)
        middle_a, middle_b = np.asarray(a.line.coords)[1], np.asarray(b.line.coords)[1]
        assert np.hypot(*(middle_a - middle_b)) <= drift + 2.0 * offset
        assert a.width == pytest.approx(b.width, abs=4.0 * offset)


@pytest.mark.parametrize("offset", [0.01, 2.0, 12.0, 18.0])
def test_split_points_off_the_middle_leave_the_end_caps_out(offset):
    # Off the middle of a flat end, the line first runs along the end's normal (incircles touching the end
    # only), then bisects the end and the nearer bank (touching one bank): no cross-section until the
    # incircle spans the channel, at x = width / 2.
    length, width = 1000.0, 40.0
    ends = [(0.0, width / 2.0 - offset), (length, width / 2.0 + offset)]
    tolerance = width / 200.0
    result = polygon_centerline(shapely.box(0.0, 0.0, length, width), ends, tolerance=tolerance)
    interval = 5.0
    cuts = transects(result, interval)
    assert len(cuts) >= int((length - 2.0 * width) / interval) - 1
    for cut in cuts:
        (x_a, y_a), _, (x_b, y_b) = cut.line.coords
        assert cut.width == pytest.approx(width, abs=2.0 * tolerance)
        assert sorted([y_a, y_b]) == pytest.approx([0.0, width], abs=2.0 * tolerance)
        assert width / 2.0 - 2.0 * tolerance <= min(x_a, x_b) <= max(x_a, x_b) <= length - width / 2.0 + 2.0 * tolerance


def test_transects_beside_an_island_run_straight_across_the_channel():
    """A channel 800 x 120 with an island near one bank: the adaptive line keeps few vertices on the straight
    reaches, and their incircles touch the island where the line bends; the transects measure across to the
    chains themselves (the result keeps them), so on the reaches a width away from the island each runs square
    from bank to bank, 120 wide (interpolating the feet between those vertices slanted them to the island)."""
    island = shapely.affinity.scale(Point(400.0, 80.0).buffer(1.0, 32), 120.0, 15.0)
    channel = shapely.Polygon(shapely.box(0.0, 0.0, 800.0, 120.0).exterior.coords, [island.exterior.coords])
    result = polygon_centerline(channel, [(0.0, 60.0), (800.0, 60.0)])
    tolerance = 120.0 / 200.0
    reaches = []
    for cut in transects(result, 40.0):
        (x_a, y_a), (x, _), (x_b, y_b) = cut.line.coords
        if x < 280.0 - 120.0 or x > 520.0 + 120.0:
            reaches.append(cut)
            assert x_a == pytest.approx(x, abs=2.0 * tolerance) and x_b == pytest.approx(x, abs=2.0 * tolerance)
            assert sorted([y_a, y_b]) == pytest.approx([0.0, 120.0], abs=2.0 * tolerance)
            assert cut.width == pytest.approx(120.0, abs=2.0 * tolerance)
    assert len(reaches) >= 4


def angle_to(vector, direction):
    """Angle, degrees, between a vector and a direction, either way (0 to 90)."""
    cosine = abs(float(np.dot(vector, direction))) / float(np.hypot(*vector) * np.hypot(*direction))
    return math.degrees(math.acos(min(1.0, cosine)))


def assert_straight_and_inside(cut, polygon, tolerance):
    """A straight transect: its three points on one line, inside the polygon, its width its length."""
    start, middle, end = np.asarray(cut.line.coords)
    across = end - start
    aside = middle - start
    off_line = abs(float(across[0] * aside[1] - across[1] * aside[0])) / float(np.hypot(*across))
    assert off_line <= tolerance
    assert cut.width == pytest.approx(float(np.hypot(*across)), abs=tolerance)
    assert polygon.buffer(tolerance).covers(cut.line)


@pytest.mark.parametrize("angle", (0.0, 37.0))
def test_straight_transects_run_square_to_a_straight_channel(angle):
    # A channel 300 x 20 turned by ``angle``, its banks wobbling (+-2) so nearest points fan out.
    x = np.linspace(0.0, 300.0, 151)
    wobble = 2.0 * np.sin(x / 7.0) * np.sin(x / 23.0)
    bank_a, bank_b = np.column_stack([x, wobble]), np.column_stack([x, 20.0 + wobble[::-1] * 0.5])
    polygon = shapely.affinity.rotate(shapely.Polygon(np.concatenate([bank_a, bank_b[::-1]])), angle, origin=(0, 0))
    points = shapely.affinity.rotate(
        shapely.MultiPoint([(0.0, 10.0), (300.0, 10.0 + wobble[-1] * 0.75)]), angle, origin=(0, 0)
    )
    result = polygon_centerline(polygon, list(points.geoms))
    axis = np.array([math.cos(math.radians(angle)), math.sin(math.radians(angle))])
    tolerance = 1e-9 * 300.0
    straight = transects(result, 10.0, style="straight")
    nearest = transects(result, 10.0)
    assert [cut.chainage for cut in straight] == [cut.chainage for cut in nearest]
    for cut in straight:
        start, middle, end = np.asarray(cut.line.coords)
        assert_straight_and_inside(cut, polygon, tolerance)
        # Square to the axis within the line's own turns (the wobbles move the axis by about 1 in 20).
        assert angle_to(end - start, axis) >= 90.0 - 8.0
        # Both ends on the banks, each the first boundary point from the centerline.
        assert (
            polygon.exterior.distance(Point(start)) <= tolerance and polygon.exterior.distance(Point(end)) <= tolerance
        )
        assert cut.width >= 2.0 * polygon.exterior.distance(Point(middle)) - tolerance
    # The nearest-bank transects bend at the centerline somewhere; the straight ones never do.
    bends = [angle_to(np.subtract(*cut.line.coords[:2]), np.subtract(*cut.line.coords[1:])) for cut in nearest]
    assert max(bends) > 5.0


def test_straight_transects_on_a_bend_are_radial():
    case = geometry_cases.annulus_sector(r_inner=40.0, r_outer=60.0, n=181)
    result = polygon_centerline(case.polygon, case.split_points)
    # Square to the axis (the circle of radius 50) means along the radius; the direction is smoothed over a
    # width, an arc of 20 / 50 rad, whose chord is square to the radius through its middle: exact on a circle.
    tolerance = 0.5 / 100 * 20.0
    cuts = transects(result, 5.0, style="straight")
    assert len(cuts) > 20
    for cut in cuts:
        start, middle, end = np.asarray(cut.line.coords)
        assert_straight_and_inside(cut, case.polygon, 1e-6)
        # The chord's two ends are each within the adaptive tolerance (width / 200 = 0.1) of the axis: the chord,
        # 2 r = 20 long, turns by at most 2 * 0.1 / 20 rad, and the station lies a tolerance off its middle.
        assert angle_to(end - start, middle) <= math.degrees(2.0 * 0.1 / 10.0)
        assert sorted([float(np.hypot(*start)), float(np.hypot(*end))]) == pytest.approx([40.0, 60.0], abs=tolerance)
        assert cut.width == pytest.approx(20.0, abs=2 * tolerance)


def test_straight_transects_stop_at_an_island():
    island = shapely.box(380.0, 70.0, 420.0, 90.0)
    channel = shapely.Polygon(shapely.box(0.0, 0.0, 800.0, 120.0).exterior.coords, [island.exterior.coords[::-1]])
    result = polygon_centerline(channel, [(0.0, 60.0), (800.0, 60.0)])
    cuts = transects(result, 10.0, style="straight")
    tolerance = 1e-9 * 800.0
    beside = [cut for cut in cuts if 385.0 <= cut.line.coords[1][0] <= 415.0]
    assert beside
    for cut in cuts:
        assert_straight_and_inside(cut, channel, tolerance)
    for cut in beside:
        # The line passes the island on the wider side (below it); the transect runs from the bank y = 0 up
        # to the island's bottom, y = 70, not through it to the far bank.
        ys = sorted(y for _, y in cut.line.coords[::2])
        assert ys == pytest.approx([0.0, 70.0], abs=0.5)
        assert cut.width == pytest.approx(70.0, abs=0.5)
        assert not cut.line.crosses(island.exterior)


def test_straight_transects_without_chains_reach_the_incircle():
    result = polygon_centerline(shapely.box(0.0, 0.0, 100.0, 10.0), [(0.0, 5.0), (100.0, 5.0)])
    bare = transects(dataclasses.replace(result, chains=None), 25.0, style="straight")
    assert [list(cut.line.coords) for cut in bare] == [[(x, 0.0), (x, 5.0), (x, 10.0)] for x in (25.0, 50.0, 75.0)]


def test_unknown_transect_style_is_a_typed_error():
    result = polygon_centerline(shapely.box(0.0, 0.0, 100.0, 10.0), [(0.0, 5.0), (100.0, 5.0)])
    with pytest.raises(IncirCuError, match="Unknown transect style 'square'; use one of straight, nearest"):
        transects(result, 10.0, style="square")


@pytest.mark.parametrize("offset", [0.01, 2.0])
def test_the_measured_stretch_starts_where_the_incircle_spans_the_channel_in_copies_of_its_arguments(offset):
    # Split points off the middle of a box's flat ends: near the middle the cap vertex's incircle touches both
    # banks, farther off a bank and the end (the stretch then starts at the next vertex); either way the
    # cross-sections begin half a width (20) from each end, and the arguments are left as they were.
    tolerance = 0.2
    ends = [(0.0, 20.0 - offset), (1000.0, 20.0 + offset)]
    result = polygon_centerline(shapely.box(0.0, 0.0, 1000.0, 40.0), ends, tolerance=tolerance)
    vertices = shapely.get_coordinates(result.line)
    arguments = [vertices, result.radii, vertex_chainages(result), result.foot_a, result.foot_b]
    before = [argument.copy() for argument in arguments]
    stretch = measured_stretch(*arguments)
    assert all(np.array_equal(argument, copy) for argument, copy in zip(arguments, before))
    moved = [stretch.vertices, stretch.radii, stretch.chainages, stretch.foot_a, stretch.foot_b]
    assert not any(np.shares_memory(new, old) for new, old in zip(moved, arguments))
    assert stretch.feet[0] is stretch.foot_a and stretch.feet[1] is stretch.foot_b
    assert not stretch.empty and stretch.low < stretch.high
    first, last = np.searchsorted(stretch.chainages, [stretch.low, stretch.high])
    assert stretch.vertices[first, 0] == pytest.approx(20.0, abs=2.0 * tolerance)
    assert stretch.vertices[last, 0] == pytest.approx(980.0, abs=2.0 * tolerance)
    assert stretch.radii[[first, last]] == pytest.approx([20.0, 20.0], abs=2.0 * tolerance)
