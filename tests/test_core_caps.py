"""End caps (core/caps.py): the straight run-out along the channel's axis at slanted cuts.

A straight channel of width ``W`` along direction ``PHI`` is cut at both ends by a line slanted ``slant``
from the square cut; its axis is the middle line between its banks. The run-out must leave each end along
that axis (within ``ANGLE`` degrees), end exactly at a given split point, stay inside the polygon; the exact
axis (``end_cap="axis"``) leaves a slanted end square to the cut, which the tests check too (so they can fail).
"""

import math

import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon

from incircu_plugin.core import lines_centerline, polygon_centerline, polygon_network
from incircu_plugin.core.caps import END_CAPS, run_out_ends
from incircu_plugin.core.errors import IncirCuError

W, LENGTH, PHI = 10.0, 120.0, math.radians(23.0)
#: Largest angle, degrees, between the run-out and the channel's axis: the axis is exact to the adaptive
#: tolerance (W / 200), so a run-out of about a width may turn by about 1/100 rad, 0.6 degrees.
ANGLE = 2.0
SLANTS = (10.0, 20.0, 30.0, 45.0, 60.0)


def rotate(points, origin=(0.0, 0.0)):
    """Rotate ``(n, 2)`` points by ``PHI`` about the origin and shift them by ``origin``."""
    c, s = math.cos(PHI), math.sin(PHI)
    points = np.asarray(points, dtype=float)
    return points @ np.array([[c, s], [-s, c]]) + np.asarray(origin)


def slanted_channel(slant_degrees, start=0.0, length=LENGTH, slant_end=None):
    """A straight channel from ``start`` to ``start + length`` along the axis (rotated by ``PHI``), width
    ``W``, both ends cut at ``slant_degrees`` (the end at ``slant_end`` when given), and the middle points of
    its cuts (its split points)."""
    t0 = math.tan(math.radians(slant_degrees))
    t1 = math.tan(math.radians(slant_degrees if slant_end is None else slant_end))
    # Local frame: the axis is y = 0, the banks y = -W/2 and y = W/2; a cut at x0 slanted by t: x = x0 + t y.
    x0, x1 = start, start + length
    ring = [(x0 - t0 * W / 2, -W / 2), (x1 - t1 * W / 2, -W / 2), (x1 + t1 * W / 2, W / 2), (x0 + t0 * W / 2, W / 2)]
    return Polygon(rotate(ring)), rotate([(x0, 0.0), (x1, 0.0)])


def axis_direction():
    return rotate([(1.0, 0.0)])[0]


def segment_angle(line, first=True):
    """Angle, degrees, between the line's first (or last) segment and the channel's axis (either way)."""
    coordinates = shapely.get_coordinates(line)
    step = coordinates[1] - coordinates[0] if first else coordinates[-1] - coordinates[-2]
    cosine = abs(float(step @ axis_direction())) / float(np.hypot(*step))
    return math.degrees(math.acos(min(1.0, cosine)))


def inside(polygon, line):
    slack = 1e-9 * LENGTH
    return polygon.buffer(slack).covers(line)


@pytest.mark.parametrize("slant", SLANTS)
def test_run_out_at_given_split_points_follows_the_axis_and_ends_exactly(slant):
    polygon, points = slanted_channel(slant)
    result = polygon_centerline(polygon, points, end_cap="runout")
    coordinates = shapely.get_coordinates(result.line)
    assert segment_angle(result.line) <= ANGLE
    assert segment_angle(result.line, first=False) <= ANGLE
    # The ends are the split points as the exact axis has them (snapped onto the outline, within rounding).
    exact = shapely.get_coordinates(polygon_centerline(polygon, points, end_cap="axis").line)
    assert np.array_equal(coordinates[[0, -1]], exact[[0, -1]])
    assert np.allclose(coordinates[[0, -1]], points, rtol=0.0, atol=1e-12 * LENGTH)
    assert inside(polygon, result.line) and result.line.is_simple
    # The end keeps radius 0 and its feet; the run-out's other vertex spans the channel.
    assert result.radii[0] == 0.0 and result.radii[-1] == 0.0
    assert np.allclose(result.radii[1], W / 2, rtol=1e-3) and np.allclose(result.radii[-2], W / 2, rtol=1e-3)
    assert len(result.radii) == len(coordinates) == len(result.foot_a) == len(result.foot_b)


@pytest.mark.parametrize("slant", SLANTS[1:])
def test_the_exact_axis_leaves_a_slanted_end_square_to_the_cut(slant):
    polygon, points = slanted_channel(slant)
    result = polygon_centerline(polygon, points, end_cap="axis")
    assert segment_angle(result.line) > slant / 2
    assert polygon_centerline(polygon, points).line.equals_exact(result.line, 0.0)


@pytest.mark.parametrize("slant", SLANTS[:-1])
def test_run_out_at_automatic_ends_meets_the_cut_on_the_axis(slant):
    # Up to 45 degrees the automatic ends lie in the middle of the cuts (their end caps); at 60 degrees they
    # lie in the cuts' acute corners, tips the exact axis runs into (see the next test).
    polygon, _ = slanted_channel(slant)
    result = polygon_centerline(polygon, end_cap="runout")
    coordinates = shapely.get_coordinates(result.line)
    assert segment_angle(result.line) <= ANGLE and segment_angle(result.line, first=False) <= ANGLE
    assert inside(polygon, result.line) and result.line.is_simple
    # Both ends on the outline, on the axis (y = 0 in the channel's frame), so the line is as long as the axis.
    assert np.all(shapely.distance(polygon.exterior, shapely.points(coordinates[[0, -1]])) <= 1e-9 * LENGTH)
    across = (coordinates[[0, -1]] - rotate([(0.0, 0.0)])) @ rotate([(0.0, 1.0)])[0]
    assert np.all(np.abs(across) <= W / 200)
    assert result.length == pytest.approx(LENGTH, abs=W / 100)


def half_plane(point, direction):
    """The half-plane above the line through ``point`` along ``direction`` (as a large polygon)."""
    point, direction = np.asarray(point, dtype=float), np.asarray(direction, dtype=float)
    normal = np.array([-direction[1], direction[0]])
    normal = normal if normal[1] > 0 else -normal
    return Polygon(
        [
            point - 1e3 * direction,
            point + 1e3 * direction,
            point + 1e3 * direction + 1e3 * normal,
            point - 1e3 * direction + 1e3 * normal,
        ]
    )


def test_automatic_ends_in_tips_keep_the_exact_axis():
    # A channel whose ends taper to points, and one cut 60 degrees off square, whose automatic ends lie in the
    # acute corners: the line runs into each tip along its middle, with or without the run-out.
    tapered = Polygon(
        rotate([(-30.0, 0.0), (0.0, -W / 2), (LENGTH, -W / 2), (LENGTH + 30.0, 0.0), (LENGTH, W / 2), (0.0, W / 2)])
    )
    for polygon in (tapered, slanted_channel(60.0)[0]):
        exact = polygon_centerline(polygon, end_cap="axis")
        runout = polygon_centerline(polygon, end_cap="runout")
        ends = shapely.get_coordinates(exact.line)[[0, -1]]
        assert np.array_equal(shapely.get_coordinates(runout.line)[[0, -1]], ends)
        assert np.all(
            shapely.distance(
                shapely.points(ends), shapely.points(shapely.get_coordinates(polygon.exterior))[:, None]
            ).min(axis=0)
            <= 1e-9 * LENGTH
        )


def test_curved_channel_runs_out_along_its_tangent():
    # A half ring of radii 40 and 60 (axis radius 50, tangent (0, 1) at both ends), each end cut 30 degrees
    # off the radial line through the axis point.
    slant = math.radians(30.0)
    angles = np.linspace(-math.pi / 3, 4 * math.pi / 3, 241)
    ring = np.concatenate([np.column_stack([np.cos(angles), np.sin(angles)]) * radius for radius in (60.0, 40.0)])
    sector = Polygon(np.concatenate([ring[:241], ring[241:][::-1]]))
    points = [(50.0, 0.0), (-50.0, 0.0)]
    cuts = [
        half_plane(points[0], (math.cos(slant), math.sin(slant))),
        half_plane(points[1], (math.cos(slant), -math.sin(slant))),
    ]
    polygon = sector.intersection(cuts[0]).intersection(cuts[1])
    assert polygon.is_valid and polygon.geom_type == "Polygon"
    for end_cap in END_CAPS:
        result = polygon_centerline(polygon, points, end_cap=end_cap)
        coordinates = shapely.get_coordinates(result.line)
        assert inside(polygon, result.line)
        assert np.allclose(coordinates[[0, -1]], points, rtol=0.0, atol=1e-12 * LENGTH)
        for start, end in ((coordinates[0], coordinates[1]), (coordinates[-1], coordinates[-2])):
            # The run-out is a chord of the axis (the circle of radius 50): it joins the end to a point of the
            # axis (within the adaptive tolerance, W / 200) and runs square to the radius through its middle.
            # The exact axis leaves the end square to the cut, 30 degrees off.
            middle, step = 0.5 * (start + end), end - start
            angle = math.degrees(
                math.asin(min(1.0, abs(float(middle @ step)) / float(np.hypot(*middle) * np.hypot(*step))))
            )
            if end_cap == "runout":
                assert abs(float(np.hypot(*end)) - 50.0) <= W / 200 and angle <= 1.0
            else:
                assert angle > 10.0


@pytest.mark.parametrize("slant", (15.0, 40.0))
def test_joined_reaches_meet_in_line(slant):
    # Two reaches of one channel share a slanted cut and its middle point.
    first, first_points = slanted_channel(slant, start=0.0, length=60.0)
    second, second_points = slanted_channel(slant, start=60.0, length=60.0)
    assert np.allclose(first_points[1], second_points[0])
    assert first.intersection(second).length == pytest.approx(W / math.cos(math.radians(slant)))
    lines = [
        polygon_centerline(part, points, end_cap="runout").line
        for part, points in ((first, first_points), (second, second_points))
    ]
    joint = shapely.get_coordinates(lines[0])[-1]
    assert np.allclose(joint, shapely.get_coordinates(lines[1])[0], rtol=0.0, atol=1e-12 * LENGTH)
    incoming = shapely.get_coordinates(lines[0])[-1] - shapely.get_coordinates(lines[0])[-2]
    outgoing = shapely.get_coordinates(lines[1])[1] - shapely.get_coordinates(lines[1])[0]
    turn = math.degrees(math.acos(float(incoming @ outgoing) / float(np.hypot(*incoming) * np.hypot(*outgoing))))
    assert turn <= 2 * ANGLE
    # The exact axis zig-zags there: it leaves and reaches the joint square to the cut.
    exact = [
        polygon_centerline(part, points, end_cap="axis").line
        for part, points in ((first, first_points), (second, second_points))
    ]
    assert segment_angle(exact[0], first=False) > slant / 2 and segment_angle(exact[1]) > slant / 2


@pytest.mark.parametrize("slant", (10.0, 30.0, 60.0))
def test_bank_lines_run_out_to_the_middle_of_a_slanted_gap(slant):
    polygon, points = slanted_channel(slant)
    bank_a, bank_b = (np.asarray(polygon.exterior.coords)[[0, 1]], np.asarray(polygon.exterior.coords)[[3, 2]])
    for end_cap in END_CAPS:
        result = lines_centerline(bank_a, bank_b, end_cap=end_cap)
        coordinates = shapely.get_coordinates(result.line)
        if end_cap == "runout":
            assert segment_angle(result.line) <= ANGLE and segment_angle(result.line, first=False) <= ANGLE
        else:
            # The exact axis first follows the parabola between the start of the shorter line and the other.
            assert segment_angle(result.line) > 1.0
        assert np.allclose(coordinates[[0, -1]], points, atol=1e-9 * LENGTH)
        assert inside(polygon, result.line)
        # The ends keep their values: half the gap.
        gap = W / 2 / math.cos(math.radians(slant))
        assert result.radii[0] == pytest.approx(gap) and result.radii[-1] == pytest.approx(gap)


def test_network_branches_run_out_at_their_split_points():
    polygon, points = slanted_channel(30.0)
    network = polygon_network(polygon, points, end_cap="runout")
    (branch,) = network.branches
    assert segment_angle(branch.result.line) <= ANGLE
    assert np.allclose(shapely.get_coordinates(branch.result.line)[[0, -1]], points, atol=1e-9 * LENGTH)


def test_a_run_out_leaving_the_region_keeps_the_exact_axis():
    polygon, points = slanted_channel(45.0)
    exact = polygon_centerline(polygon, points, end_cap="axis")
    coordinates = shapely.get_coordinates(exact.line)
    runout = shapely.get_coordinates(run_out_ends(exact, polygon).line)
    # An island right on the start's run-out: that end keeps the exact axis, the other runs out.
    middle = 0.5 * (runout[0] + runout[1])
    blocked = polygon.difference(shapely.Point(middle).buffer(0.2))
    kept = shapely.get_coordinates(run_out_ends(exact, blocked).line)
    start = np.flatnonzero(np.all(coordinates == kept[1], axis=1))
    assert np.array_equal(kept[0], coordinates[0]) and len(start) == 1
    assert np.array_equal(kept[: start[0] + 1], coordinates[: start[0] + 1])
    assert np.array_equal(kept[-2:], runout[-2:])


def test_unknown_end_cap_is_a_typed_error():
    polygon, points = slanted_channel(30.0)
    with pytest.raises(IncirCuError, match="Unknown end cap 'straight'; use one of runout, axis"):
        polygon_centerline(polygon, points, end_cap="straight")
    assert END_CAPS == ("runout", "axis")
