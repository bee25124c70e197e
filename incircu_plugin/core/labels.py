"""Label lines: the line a curved name of a lake or a wide river follows, or a label point for a round one.

A label line starts from the polygon's main stem (:func:`.api.polygon_centerline`, with its automatic ends,
guide lines or split points) and is

- **trimmed** to the stretch around the widest incircle where the polygon is at least ``trim`` times its
  widest width: walking outwards from the widest point, the line stops at the first narrowing, so it never
  runs through a neck into a bay nor into the thin tips of the outline;
- **smoothed** for lettering with a Gaussian whose length scale is ``smoothing`` times the local width, so a
  label bends gently where the lake is wide;
- **checked**, not hoped: every segment keeps a distance of at least ``clearance`` times the local width from
  the outline, and the radius of curvature at every vertex is at least ``bend`` times the local width. Where
  the smoothed line breaks the clearance it is smoothed less there, where it bends too tightly more, for a
  few rounds; then the longest stretch holding both bounds is kept. The main stem itself is the fallback that
  is inside by construction (its clearance is the incircle radius, half the width);
- **oriented** to read from left to right: west to east, or south to north for a line within
  :data:`VERTICAL_ANGLE` of the north-south direction;
- replaced by a **label point** at the centre of the widest incircle (the pole of inaccessibility of the
  main stem) when the part is not elongated: its centerline's length over its mean width is below
  ``min_elongation``, or no stretch as long as the widest width holds both bounds.

The *local width* of a label vertex is the main stem's width (incircle diameter) at the same arc length of
the trimmed stretch: the label vertex is the smoothed image of that main-stem point.

Example
-------
>>> from shapely.geometry import Point, box
>>> [outcome] = label_lines(box(0, 0, 100, 10))
>>> label = outcome.result
>>> label.kind, label.geometry.coords[0][0] < label.geometry.coords[-1][0], label.elongation > 5
('line', True, True)
>>> [round_lake] = label_lines(Point(0, 0).buffer(100))
>>> round_lake.result.kind, round(round_lake.result.geometry.distance(Point(0, 0)), 6)
('point', 0.0)
"""

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely
from shapely.geometry import LineString, Point

from ._many import one_or_many
from .api import PartOutcome, _multipolygon_centerline_steps
from .errors import IncirCuError, Message, OptionError
from .polyline import cumulative_lengths, points_at

#: Default ``trim``: the label stretch keeps the main stem where the polygon is at least half its widest width.
#: Lettering sized to the stretch's narrowest width is then at least half as tall as the widest point allows,
#: and on an elliptic lake the stretch keeps about the middle 85 % of the axis, leaving out the tips where
#: the main stem bends into the ends (the first and last few percent cartographers leave unlabelled); a
#: bay or an arm behind a neck narrower than half the lake's width is never entered.
TRIM = 0.5

#: Default ``clearance``: every point of the label line is at least a quarter of the local width from the
#: outline, i.e. it keeps to the middle half of the lake, so a label half as tall as the width stays off
#: the shore. The main stem has clearance 0.5 (it is the centre of the incircles).
CLEARANCE = 0.25

#: Default ``bend``: the radius of curvature is at least half the local width (the incircle's radius).
#: Letters a quarter of the width tall (half the band the clearance leaves) then turn by under 20 degrees
#: from one to the next (a character's advance is about 0.6 of its height: 0.6 * w/4 / (w/2) = 0.3 rad),
#: within QGIS's default largest angle between curved characters (20 degrees outside, 25 inside).
BEND = 0.5

#: Default ``smoothing``: the Gaussian's standard deviation along the line, in (smoothed) local widths.
#: Shore wiggles shorter than a width vanish; bends longer than a few widths stay. The rounds raise it where
#: the line still bends too tightly and lower it where it comes too near the shore.
SMOOTHING = 0.5

#: Default ``min_elongation``: below this ratio of the main stem's length to the part's mean width (its area
#: over that length) a part gets a label point. A disc has ratio 4/pi = 1.27, an ellipse with axes 2:1 2.5,
#: 3:1 3.8, a rectangle its length over its width: up to about 2.4:1 a horizontal name is the better label.
MIN_ELONGATION = 3.0

#: Lines whose chord is within this angle (degrees) of north-south are read from south to north (bottom to
#: top). A small angle: a renderer that keeps labels upright (QGIS, MapLibre) turns a steep line whose end
#: lies west of its start round, and may then fail to place the name along it.
VERTICAL_ANGLE = 5.0

#: Spacing of the label line's vertices, as a share of the narrowest width on the label stretch.
SPACING_SHARE = 0.25

#: Widths of fixed smoothing between one sample and the largest, of which :func:`_gaussian` interpolates.
LADDER_STEPS = 24

#: Most vertices of one label line (a long river's stretch is sampled more coarsely).
MAX_VERTICES = 600

#: Rounds of local adjustment of the smoothing before the longest valid stretch is taken.
ROUNDS = 8

#: Largest factor by which the rounds may raise or lower the Gaussian's length scale.
MAX_SMOOTHING = 8.0

#: Share of the required clearance and of the curvature bound kept in reserve by the smoothing rounds, so the
#: final check (exact segment distances) rarely has to cut the line.
MARGIN = 0.05


@dataclass(frozen=True)
class LabelResult:
    """The label of one polygon part.

    Attributes
    ----------
    geometry : LineString or Point
        The label line (reading left to right) or the label point, CRS units.
    kind : str
        ``"line"`` or ``"point"``.
    length : float
        Length of the label line, CRS units; 0 for a point.
    width_min : float
        Narrowest width (incircle diameter) along the label stretch, CRS units: the tallest lettering that
        fits; for a point, the widest incircle's diameter.
    elongation : float
        The main stem's length over the part's mean width (its area over that length).
    widths : ndarray of shape (n,)
        Local width of each vertex of ``geometry`` (one value for a point), CRS units.
    centerline : CenterlineResult
        The main stem the label was made from.
    """

    geometry: Any
    kind: str
    length: float
    width_min: float
    elongation: float
    widths: np.ndarray
    centerline: Any

    @property
    def ends_found(self):
        """bool: the main stem's ends were found automatically (no split points)."""
        return self.centerline.ends_found

    @property
    def notes(self):
        """tuple of str: the main stem's messages for the user."""
        return tuple(getattr(self.centerline, "notes", ()))


def check_label_options(trim, clearance, bend, smoothing, min_elongation):
    """Raise :class:`OptionError` unless the label options are numbers in their ranges."""
    ranges = (
        ("trim", trim, 0.0, 1.0, "label_range_share_of_widest"),
        ("clearance", clearance, 0.0, 0.5, "label_range_clearance"),
        ("bend", bend, 0.0, math.inf, "label_range_share_of_width"),
        ("smoothing", smoothing, 0.0, math.inf, "label_range_share_of_width"),
        ("min_elongation", min_elongation, 0.0, math.inf, "label_range_ratio"),
    )
    for name, value, low, high, what in ranges:
        if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
            raise OptionError(Message("label_option_not_number", name=name, what=Message(what), value=value))
        if not (math.isfinite(value) or value == math.inf == high) or not low <= value < high:
            raise OptionError(Message("label_option_out_of_range", name=name, what=Message(what), value=value))


def _label_line_steps(
    geometry,
    split_points=None,
    *,
    trim=TRIM,
    clearance=CLEARANCE,
    bend=BEND,
    smoothing=SMOOTHING,
    min_elongation=MIN_ELONGATION,
    **options,
):
    """:func:`label_lines` of one geometry as steps (see :mod:`._steps`).

    Returns
    -------
    list of PartOutcome
        One per part, ``result`` a :class:`LabelResult`.
    """
    check_label_options(trim, clearance, bend, smoothing, min_elongation)
    outcomes = yield from _multipolygon_centerline_steps(geometry, split_points, **options)
    parts = shapely.get_parts(geometry)
    labelled = []
    for outcome in outcomes:
        if outcome.error is not None:
            labelled.append(outcome)
            continue
        try:
            label = label_from_centerline(
                parts[outcome.part_index], outcome.result, trim, clearance, bend, smoothing, min_elongation
            )
            labelled.append(PartOutcome(outcome.part_index, label, None))
        except IncirCuError as error:
            labelled.append(PartOutcome(outcome.part_index, None, error))
    return labelled


def label_lines(geometry, split_points=None, **options):
    """Label line (or point) of every part of a polygon, or of every polygon of an array.

    Parameters
    ----------
    geometry : Polygon, MultiPolygon or array_like of them
        CRS units (project a layer in degrees with :class:`.geodesy.LocalProjection`: lengths are then
        metres).
    split_points : sequence of Point or (x, y), optional
        As for :func:`.api.multipolygon_centerlines` (for an array: None, or one sequence per geometry).
    trim : float
        Share of the widest width where the label stretch ends (default :data:`TRIM`).
    clearance : float
        Least distance from the outline, as a share of the local width, under 0.5 (default :data:`CLEARANCE`).
    bend : float
        Least radius of curvature, as a share of the local width (default :data:`BEND`).
    smoothing : float
        Gaussian length scale along the line, in local widths (default :data:`SMOOTHING`).
    min_elongation : float
        Below this main-stem length over mean width (area over that length), a label point (default :data:`MIN_ELONGATION`).
    **options
        The centerline's: ``end_rule``, ``guide``, ``islands``, ``tolerance``, ``snap_tolerance``, ...

    Returns
    -------
    list of PartOutcome, or a list of them per geometry
        For one geometry, one :class:`.api.PartOutcome` per part whose ``result`` is a :class:`LabelResult`;
        for an array, per geometry that list, or the exception the geometry raised (computed in batches, as
        :func:`.api.polygon_centerline` computes an array).

    Raises
    ------
    InvalidGeometryError, OptionError
        For a single geometry that is not a (multi)polygon, or a bad option.
    """
    progress = options.pop("progress", None)
    return one_or_many(_label_line_steps, geometry, split_points, options, progress)


def feature_label(outcomes, geometry):
    """The one label of a feature: that of its largest part with a label (what QGIS labels by default).

    Parameters
    ----------
    outcomes : list of PartOutcome
        From :func:`label_lines` of ``geometry``.
    geometry : Polygon or MultiPolygon

    Returns
    -------
    LabelResult or None
        None when no part has a label.
    """
    areas = shapely.area(shapely.get_parts(geometry))
    labelled = [outcome for outcome in outcomes if outcome.result is not None]
    if not labelled:
        return None
    return max(labelled, key=lambda outcome: areas[outcome.part_index]).result


def label_from_centerline(
    polygon,
    centerline,
    trim=TRIM,
    clearance=CLEARANCE,
    bend=BEND,
    smoothing=SMOOTHING,
    min_elongation=MIN_ELONGATION,
):
    """The label of one polygon part from its main stem.

    Parameters
    ----------
    polygon : Polygon
        The part, CRS units.
    centerline : CenterlineResult
        Its main stem.
    trim, clearance, bend, smoothing, min_elongation : float
        See :func:`label_lines`.

    Returns
    -------
    LabelResult
    """
    xy = shapely.get_coordinates(centerline.line)
    widths = np.asarray(centerline.widths, dtype=float)
    # The mean width of the part: its area over its main stem's length (a rectangle's width, pi/4 of an
    # ellipse's minor axis). The incircles' mean would undercount compact shapes, whose main stem runs through
    # the thin stubs where the incircles touch one point of the outline.
    elongation = centerline.length**2 / polygon.area if polygon.area > 0 else math.inf
    widest = int(np.argmax(widths))

    def point_label():
        return LabelResult(
            Point(xy[widest]), "point", 0.0, float(widths[widest]), elongation, widths[[widest]], centerline
        )

    if widths[widest] <= 0 or elongation < min_elongation:
        return point_label()
    stations, stretch_widths = _trimmed_stretch(xy, widths, trim)
    chosen = _smoothed_within(polygon, stations, stretch_widths, clearance, bend, smoothing)
    if chosen is None:
        return point_label()
    line, line_widths = chosen
    if cumulative_lengths(line)[-1] < widths[widest]:
        return point_label()
    if _reads_backwards(line):
        line, line_widths = line[::-1], line_widths[::-1]
    geometry = LineString(line)
    return LabelResult(
        geometry, "line", float(geometry.length), float(line_widths.min()), elongation, line_widths, centerline
    )


def _trimmed_stretch(xy, widths, trim):
    """The main stem between the first and the last point where its width reaches ``trim`` times the widest,
    resampled evenly; returns the points ``(n, 2)`` and their widths ``(n,)``."""
    chainage = cumulative_lengths(xy)
    limit = trim * widths.max()
    wide = np.flatnonzero(widths >= limit)
    first, last = wide[0], wide[-1]
    start = chainage[0] if first == 0 else _chainage_at_width(chainage, widths, first - 1, first, limit)
    end = chainage[-1] if last == len(widths) - 1 else _chainage_at_width(chainage, widths, last, last + 1, limit)
    values = np.column_stack([xy, widths])
    inner = widths[(chainage > start) & (chainage < end)]
    narrowest = min(limit, float(inner.min(initial=np.inf)))
    spacing = max(SPACING_SHARE * narrowest, (end - start) / (MAX_VERTICES - 1))
    count = max(math.ceil((end - start) / spacing) + 1, 3) if end > start else 1
    stations = points_at(values, chainage, np.linspace(start, end, count))
    return stations[:, :2], stations[:, 2]


def _chainage_at_width(chainage, widths, i, j, limit):
    """Arc length between vertices ``i`` and ``j`` where the width (linear between them) equals ``limit``."""
    span = widths[j] - widths[i]
    fraction = 0.0 if span == 0 else min(max((limit - widths[i]) / span, 0.0), 1.0)
    return chainage[i] + fraction * (chainage[j] - chainage[i])


def _smoothed_within(polygon, points, widths, clearance, bend, smoothing):
    """Smooth the stretch ``points`` and keep its longest piece within the bounds.

    The Gaussian's length scale at each vertex is ``smoothing`` times the width profile (itself smoothed, so
    the scale varies gently), times a factor adjusted over :data:`ROUNDS` rounds: halved where the line comes
    too near the outline, raised by half where it bends too tightly, each change spread over the kernel's
    reach. Then the exact check: segment distances to the outline and the curvature at every vertex.

    Returns
    -------
    tuple of (ndarray of shape (m, 2), ndarray of shape (m,)) or None
        The label line's vertices and their local widths; None when no piece of two vertices holds the bounds.
    """
    if len(points) < 2:
        return None
    boundary = _BoundaryIndex(polygon)
    spacing = float(np.hypot(*(points[1] - points[0])))
    positions = np.arange(len(points), dtype=float)
    profile = _gaussian(np.column_stack([positions * spacing, widths]), spacing, widths)[:, 1]
    log_factor = np.zeros(len(points))
    reserve = 1.0 + MARGIN
    for _ in range(ROUNDS):
        sigma = smoothing * profile * np.exp(log_factor)
        line = _gaussian(points, spacing, sigma)
        tight = boundary.distance_points(line) < reserve * clearance * widths
        sharp = np.zeros(len(line), dtype=bool)
        sharp[1:-1] = _curvature(line) * reserve * bend * widths[1:-1] > 1.0
        if not (tight.any() or sharp.any()):
            break
        change = np.where(tight, math.log(0.5), np.where(sharp, math.log(1.5), 0.0))
        reach = np.maximum(sigma / spacing, 1.0) if spacing > 0 else np.ones(len(points))
        spread = 2.0 * _gaussian(np.column_stack([positions, change]), 1.0, reach)[:, 1]
        log_factor += np.where(np.abs(change) > np.abs(spread), change, spread)
        log_factor = np.clip(log_factor, math.log(1.0 / MAX_SMOOTHING), math.log(MAX_SMOOTHING))
    segment_ok = boundary.distance_segments(line) >= clearance * np.minimum(widths[1:], widths[:-1])
    segment_ok &= boundary.inside(line[1:]) & boundary.inside(line[:-1])
    vertex_ok = np.ones(len(line), dtype=bool)
    vertex_ok[1:-1] = _curvature(line) * bend * widths[1:-1] <= 1.0
    first, last = _longest_run(segment_ok, vertex_ok, cumulative_lengths(line))
    if last <= first:
        return None
    piece = slice(first, last + 1)
    return line[piece], widths[piece]


def _gaussian(points, spacing, sigma):
    """Smooth evenly spaced ``points`` with a Gaussian of standard deviation ``sigma[i]`` (CRS units) at each.

    Each vertex takes its value from the two nearest of a ladder of fixed-width smoothings, interpolated
    linearly in the standard deviation; each fixed width is three box filters (running sums), whose
    standard deviation is ``sqrt(b (b + 1))`` samples for a half-width of ``b``: linear time, whatever the
    width. The line is extended past its ends by point reflection (odd reflection), which keeps the ends in
    place and a straight line straight.

    Parameters
    ----------
    points : ndarray of shape (n, d)
        Evenly spaced vertices (and any values carried along), CRS units.
    spacing : float
        Distance between neighbouring vertices, CRS units.
    sigma : ndarray of shape (n,)
        CRS units; 0: the vertex is kept.

    Returns
    -------
    ndarray of shape (n, d)
    """
    count = len(points)
    if spacing <= 0 or count < 3 or not np.any(sigma > 0):
        return points.copy()
    samples = sigma / spacing
    largest = min(float(samples.max()), 4.0 * count)
    halves = np.unique(np.round(np.geomspace(1.0, max(largest, 1.0), LADDER_STEPS)).astype(int))
    halves = halves[np.concatenate([[True], np.sqrt(halves[:-1] * (halves[:-1] + 1.0)) < largest])]
    ladder_sigma = np.concatenate([[0.0], np.sqrt(halves * (halves + 1.0))])
    ladder = [points] + [_box3(points, half) for half in halves]
    position = np.interp(np.minimum(samples, ladder_sigma[-1]), ladder_sigma, np.arange(len(ladder_sigma)))
    lower = np.minimum(np.floor(position).astype(int), len(ladder) - 2) if len(ladder) > 1 else np.zeros(count, int)
    fraction = (position - lower)[:, None]
    stacked = np.stack(ladder)
    rows = np.arange(count)
    return (1.0 - fraction) * stacked[lower, rows] + fraction * stacked[np.minimum(lower + 1, len(ladder) - 1), rows]


def _box3(points, half):
    """Three running means of ``2 half + 1`` samples over ``points`` extended by point reflection."""
    count = len(points)
    pad = 3 * half + 1
    index = np.arange(-pad, count + pad)
    low, high = index < 0, index > count - 1
    mirrored = np.clip(np.where(low, -index, np.where(high, 2 * (count - 1) - index, index)), 0, count - 1)
    extended = points[mirrored]
    extended = np.where(low[:, None], 2.0 * points[0] - extended, extended)
    extended = np.where(high[:, None], 2.0 * points[-1] - extended, extended)
    width = 2 * half + 1
    for _ in range(3):
        running = np.concatenate([np.zeros((1, extended.shape[1])), np.cumsum(extended, axis=0)])
        middle = (running[width:] - running[:-width]) / width
        extended = np.concatenate([extended[:half], middle, extended[len(extended) - half :]])
    return extended[pad : pad + count]


def _curvature(line):
    """Curvature (1 / radius of the circle through it and its two neighbours) at each interior vertex, 1/CRS units."""
    a, b, c = line[:-2], line[1:-1], line[2:]
    ab, bc, ca = b - a, c - b, a - c
    cross = np.abs(ab[:, 0] * bc[:, 1] - ab[:, 1] * bc[:, 0])
    product = np.hypot(*ab.T) * np.hypot(*bc.T) * np.hypot(*ca.T)
    with np.errstate(divide="ignore", invalid="ignore"):
        curvature = np.where(product > 0, 2.0 * cross / product, np.inf)
    return curvature


def curvature_radii(line):
    """Radius of curvature at each interior vertex of a polyline (of the circle through it and its two
    neighbours), CRS units; ``inf`` on a straight stretch.

    Examples
    --------
    >>> circle = [(math.cos(t), math.sin(t)) for t in np.linspace(0, 1, 5)]
    >>> np.round(curvature_radii(circle), 9).tolist()
    [1.0, 1.0, 1.0]
    """
    with np.errstate(divide="ignore"):
        return 1.0 / _curvature(np.asarray(line, dtype=float))


def _spread(flags, reach):
    """``flags`` widened by ``reach`` entries on both sides."""
    if not flags.any():
        return flags
    before = np.concatenate([[0], np.cumsum(flags)])
    index = np.arange(len(flags))
    return before[np.minimum(index + reach + 1, len(flags))] > before[np.maximum(index - reach, 0)]


def _longest_run(segment_ok, vertex_ok, chainage):
    """Vertex indices ``(first, last)`` of the longest piece whose segments are all fine and whose interior
    vertices are all fine (its two end vertices need not be: a line does not turn at its ends)."""
    best, best_length = (0, 0), 0.0
    first = 0
    for k in range(len(segment_ok)):
        if not segment_ok[k]:
            first = k + 1
            continue
        # Segment k joins vertices k and k + 1; vertex k is interior unless the piece starts at it.
        if k > first and not vertex_ok[k]:
            first = k
        length = chainage[k + 1] - chainage[first]
        if length > best_length:
            best, best_length = (first, k + 1), length
    return best


def _reads_backwards(line):
    """True when the line runs east to west (or, within :data:`VERTICAL_ANGLE` of north-south, north to south)."""
    dx, dy = line[-1] - line[0]
    if abs(dx) <= math.sin(math.radians(VERTICAL_ANGLE)) * math.hypot(dx, dy):
        return dy < 0
    return dx < 0


class _BoundaryIndex:
    """Exact distances to a polygon's outline (all rings) through a spatial index of its segments."""

    def __init__(self, polygon):
        rings = [polygon.exterior, *polygon.interiors]
        segments = []
        for ring in rings:
            xy = shapely.get_coordinates(ring)
            segments.append(np.stack([xy[:-1], xy[1:]], axis=1))
        segments = np.concatenate(segments)
        self.tree = shapely.STRtree(shapely.linestrings(segments))
        # A private copy is prepared: the caller's polygon is left as given.
        self.polygon = shapely.force_2d(polygon)
        shapely.prepare(self.polygon)

    def _nearest(self, geometries):
        indices, distances = self.tree.query_nearest(geometries, return_distance=True, all_matches=False)
        result = np.full(len(geometries), np.inf)
        result[indices[0]] = distances
        return result

    def distance_points(self, xy):
        """Distance of each point to the outline, CRS units."""
        return self._nearest(shapely.points(xy))

    def distance_segments(self, xy):
        """Distance of each segment of the polyline ``xy`` to the outline, CRS units."""
        return self._nearest(shapely.linestrings(np.stack([xy[:-1], xy[1:]], axis=1)))

    def inside(self, xy):
        """True for the points inside the polygon (or on its outline)."""
        return shapely.intersects_xy(self.polygon, xy[:, 0], xy[:, 1])
