"""Label lines (``core/labels.py``): inside with the clearance, curvature bounded, trimmed, oriented; label points.

Every bound is checked here with computations of the test's own: the exact distance of every segment to the
outline (GEOS), the circumradius of every three consecutive vertices from the side lengths, and the widest
point of the exact medial axis from the oracle (``tests/support/oracle.py``, Boost's segment Voronoi
diagram). label_centerlines' own fixtures (its Alps polygon) are not in its PyPI sdist, so they are not used.
"""

import json
import math

import numpy as np
import pytest
import shapely
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import unary_union

from incircu_plugin.core import (
    LabelResult,
    LocalProjection,
    OptionError,
    feature_label,
    label_lines,
    polygon_centerline,
    split_polygon,
)
from incircu_plugin.core.labels import BEND, CLEARANCE, TRIM
from tests.support.oracle import MedialOracle
from tests.support.real_rivers import DATA, real_rivers


def circumradii(coordinates):
    """Radius of the circle through each three consecutive vertices (R = abc / 4K), inf on a straight line."""
    a, b, c = coordinates[:-2], coordinates[1:-1], coordinates[2:]
    ab, bc, ca = (np.hypot(*(q - p).T) for p, q in ((a, b), (b, c), (c, a)))
    area = 0.5 * np.abs((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    with np.errstate(divide="ignore"):
        return np.where(area > 0, ab * bc * ca / (4.0 * area), np.inf)


def assert_good_line(label, polygon, clearance=CLEARANCE, bend=BEND):
    """One simple part inside ``polygon``, every segment ``clearance`` local widths off the outline, every
    vertex's radius of curvature at least ``bend`` local widths."""
    assert isinstance(label, LabelResult) and label.kind == "line"
    line = label.geometry
    assert line.geom_type == "LineString" and line.is_simple and len(line.coords) >= 2
    assert polygon.contains(line)
    xy = shapely.get_coordinates(line)
    widths = label.widths
    assert len(widths) == len(xy) and np.all(widths > 0)
    # The local widths are the main stem's: at most its widest, at least its narrowest positive width.
    stem = label.centerline.widths
    assert widths.max() <= stem.max() * (1 + 1e-9)
    segments = shapely.linestrings(np.stack([xy[:-1], xy[1:]], axis=1))
    distances = shapely.distance(segments, polygon.boundary)
    assert np.all(distances >= clearance * np.minimum(widths[:-1], widths[1:]) * (1 - 1e-9))
    assert np.all(circumradii(xy) >= bend * widths[1:-1] * (1 - 1e-9))
    assert label.length == pytest.approx(line.length)
    assert label.width_min == pytest.approx(widths.min())


def assert_reads_left_to_right(line):
    dx, dy = np.subtract(line.coords[-1], line.coords[0])
    if abs(dx) > math.sin(math.radians(5.0)) * math.hypot(dx, dy):
        assert dx > 0
    else:
        assert dy > 0


@pytest.fixture(scope="module")
def reservoir_labels():
    rivers = real_rivers()
    return [(river, label_lines(river.polygon)) for river in rivers]


def test_real_reservoirs_give_good_lines(reservoir_labels):
    for river, outcomes in reservoir_labels:
        assert len(outcomes) == 1 and outcomes[0].error is None, river.name
        label = outcomes[0].result
        assert_good_line(label, river.polygon)
        assert_reads_left_to_right(label.geometry)
        # Reservoirs are elongated: a line, and a real share of the main stem, not a stub.
        assert label.elongation > 10
        assert label.length > 0.2 * label.centerline.length, river.name


def test_real_reservoirs_in_lon_lat_round_trip():
    """A label computed in the local projection and brought back to degrees stays inside the lon/lat lake."""
    features = json.loads(DATA.read_text(encoding="utf-8"))["features"]
    lake = shapely.geometry.shape(next(f["geometry"] for f in features if f["properties"]["role"] == "polygon"))
    projection = LocalProjection.around(lake)
    [outcome] = label_lines(projection.to_local(lake))
    back = projection.to_geographic(outcome.result.geometry)
    assert lake.contains(back)


def test_array_input_gives_the_same_labels(reservoir_labels):
    rivers = [river for river, _ in reservoir_labels[:4]]
    together = label_lines([river.polygon for river in rivers])
    for (_, alone), outcomes in zip(reservoir_labels[:4], together):
        a, b = alone[0].result.geometry, outcomes[0].result.geometry
        assert a.hausdorff_distance(b) <= 1e-6 * a.length


def test_ends_are_trimmed_out_of_a_bay():
    """A 1000 x 200 lake with a 600 x 30 bay continuing its axis: the main stem runs into the bay, the label
    stops before its mouth (the bay is narrower than half the lake)."""
    lake = unary_union([box(0, -100, 1000, 100), box(990, -15, 1600, 15)])
    [outcome] = label_lines(lake)
    label = outcome.result
    assert label.centerline.line.bounds[2] > 1300  # the main stem goes into the bay
    assert_good_line(label, lake)
    assert label.geometry.bounds[2] < 1000
    assert label.width_min >= TRIM * label.centerline.widths.max() * (1 - 1e-9)


@pytest.mark.parametrize("angle", [0.0, 30.0, 150.0, 180.0, 200.0, 330.0])
def test_lines_read_west_to_east(angle):
    lake = affinity.rotate(box(0, 0, 1000, 100), angle, origin=(0, 0))
    [outcome] = label_lines(lake)
    assert outcome.result.kind == "line"
    assert_reads_left_to_right(outcome.result.geometry)
    dx = np.subtract(outcome.result.geometry.coords[-1], outcome.result.geometry.coords[0])[0]
    assert dx > 0


@pytest.mark.parametrize("angle", [90.0, 270.0, 88.0, 92.0])
def test_vertical_lines_read_south_to_north(angle):
    lake = affinity.rotate(box(0, 0, 1000, 100), angle, origin=(0, 0))
    [outcome] = label_lines(lake)
    line = outcome.result.geometry
    assert line.coords[-1][1] > line.coords[0][1]


def test_meandering_river_stays_inside_with_bounded_bends():
    xs = np.linspace(0, 3000, 600)
    axis = LineString(np.column_stack([xs, 150 * np.sin(xs / 250.0)]))
    river = axis.buffer(40.0, cap_style="flat")
    [outcome] = label_lines(river)
    label = outcome.result
    assert_good_line(label, river)
    # The bends (radius 250**2/150 = 417 at the crests, over five widths) are followed, not cut.
    assert label.length > 0.5 * axis.length


@pytest.mark.parametrize("clearance,bend", [(0.1, 0.25), (0.4, 2.0)])
def test_other_bounds_hold(clearance, bend):
    xs = np.linspace(0, 3000, 600)
    river = LineString(np.column_stack([xs, 150 * np.sin(xs / 250.0)])).buffer(40.0, cap_style="flat")
    [outcome] = label_lines(river, clearance=clearance, bend=bend)
    if outcome.result.kind == "line":
        assert_good_line(outcome.result, river, clearance, bend)


def test_round_lake_gives_the_centre():
    lake = Point(500, 300).buffer(100, quad_segs=64)
    [outcome] = label_lines(lake)
    label = outcome.result
    assert label.kind == "point" and label.length == 0.0
    assert label.geometry.distance(Point(500, 300)) < 1e-6 * 100
    assert label.width_min == pytest.approx(2 * lake.exterior.distance(Point(500, 300)), rel=1e-6)
    assert label.elongation < 3


def test_compact_lake_point_is_the_exact_axis_widest_point():
    """An irregular pentagon: the label point is the widest point of the exact medial axis (a Voronoi vertex
    where three sides touch its incircle), within the engine's tolerance."""
    lake = Polygon([(0, 0), (420, -30), (560, 260), (250, 480), (-60, 300)])
    [outcome] = label_lines(lake)
    label = outcome.result
    assert label.kind == "point"
    centerline = polygon_centerline(lake)
    ends = [centerline.line.coords[0], centerline.line.coords[-1]]
    oracle = MedialOracle(*split_polygon(lake, ends), region=lake)
    starts, ends_ = oracle.segments[:, 0], oracle.segments[:, 1]
    samples = np.concatenate([starts + t * (ends_ - starts) for t in np.linspace(0, 1, 201)[:, None, None]])
    radii = shapely.distance(shapely.points(samples), lake.boundary)
    pole, radius = samples[np.argmax(radii)], float(radii.max())
    tolerance = radius / 100  # the adaptive tracing's default tolerance is width / 200
    assert label.geometry.distance(Point(pole)) <= tolerance
    assert label.width_min / 2 == pytest.approx(radius, abs=tolerance)


def test_short_elongation_threshold_gives_a_line_for_an_ellipse():
    ellipse = affinity.scale(Point(0, 0).buffer(100, quad_segs=64), 3.0, 1.0)
    [point] = label_lines(ellipse, min_elongation=6.0)
    [line] = label_lines(ellipse, min_elongation=2.0)
    assert point.result.kind == "point" and line.result.kind == "line"
    assert_good_line(line.result, ellipse)


def test_multipart_labels_each_part_and_feature_label_takes_the_largest():
    parts = shapely.MultiPolygon([box(0, 0, 1000, 100), box(0, 500, 500, 560)])
    outcomes = label_lines(parts)
    assert [outcome.part_index for outcome in outcomes] == [0, 1]
    assert all(outcome.result.kind == "line" for outcome in outcomes)
    assert feature_label(outcomes, parts) is outcomes[0].result


@pytest.mark.parametrize(
    "options",
    [{"trim": 1.0}, {"clearance": 0.5}, {"clearance": -0.1}, {"bend": float("nan")}, {"smoothing": "1"}],
)
def test_bad_options_are_named(options):
    with pytest.raises(OptionError, match=next(iter(options))):
        label_lines(box(0, 0, 100, 10), **options)
