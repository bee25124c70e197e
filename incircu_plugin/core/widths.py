"""Width outputs of a centerline: its width statistics, its incircles as polygons, and cross-section transects.

Each reads a :class:`~.engine.CenterlineResult`: the centerline's vertices, the incircle radius of each
vertex (the local half-width) and where each incircle touches the two sides (``foot_a``, ``foot_b``).
*Chainage* is the distance along the centerline from its first vertex, CRS units.
"""

from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from .errors import IncirCuError, Message
from .polyline import (
    as_coordinates,
    chord_directions,
    cumulative_lengths,
    nearest_on_polyline,
    piece_between,
    points_at,
)

#: Share of the radius within which the mirror image of a stretch end's bank foot, across the line, counts as
#: the end's foot: the incircle touches the bank and the end, not the other bank (see :func:`measured_stretch`).
GENUINE_END_CONTACT = 0.1

#: Halvings of a segment when finding where an end cap ends on it (2**-60 of its length: float64 precision).
BISECTION_STEPS = 60

#: How :func:`transects` draws a cross-section: ``"straight"``, one straight line square to the centerline's
#: direction (smoothed over the local width), from bank to bank; ``"nearest"``, from the centerline point to the
#: nearest point of each bank (two pieces, which meet at an angle where the banks are not parallel).
TRANSECT_STYLES = ("straight", "nearest")

#: A straight transect's ray first looks this many local radii far for a bank, then across the whole channel.
FIRST_REACH = 4.0


@dataclass(frozen=True)
class Incircle:
    """One incircle of a centerline vertex.

    Attributes
    ----------
    polygon : Polygon
        The circle as a polygon (``4 * quad_segs`` sides, vertices on the circle), CRS units.
    radius : float
        Its radius, the local half-width, CRS units.
    chainage : float
        Distance of its centre along the centerline from the start, CRS units.
    """

    polygon: Polygon
    radius: float
    chainage: float


@dataclass(frozen=True)
class Transect:
    """A cross-section of the channel at one station of the centerline.

    Attributes
    ----------
    line : LineString
        From the foot on side a, through the centerline point, to the foot on side b, CRS units.
    width : float
        Length of ``line``, CRS units: the diameter of the incircle there for a ``"nearest"`` transect, the
        straight cross-section's length from bank to bank for a ``"straight"`` one.
    chainage : float
        Distance of the station along the centerline from the start, CRS units.
    """

    line: LineString
    width: float
    chainage: float


@dataclass
class MeasuredStretch:
    """A centerline's vertices with the measured stretch's first and last ones moved (see :func:`measured_stretch`).

    Attributes
    ----------
    vertices, radii, chainages, foot_a, foot_b : ndarray
        Copies of the arguments of :func:`measured_stretch` (vertices, incircle radii, chainages and the feet on
        the two sides, CRS units), the stretch's first and last vertices moved as it says.
    low, high : float
        Chainages bounding the measured stretch (both included), CRS units; ``low > high`` when it is empty.
    """

    vertices: np.ndarray
    radii: np.ndarray
    chainages: np.ndarray
    foot_a: np.ndarray
    foot_b: np.ndarray
    low: float = 1.0
    high: float = 0.0

    @property
    def feet(self):
        """``(foot_a, foot_b)``: the arrays themselves, written in place while the stretch is measured."""
        return self.foot_a, self.foot_b

    @property
    def empty(self):
        """Whether no chainage lies on the stretch."""
        return self.low > self.high


def vertex_chainages(result):
    """Return the distance of each centerline vertex from the start along the line.

    Parameters
    ----------
    result : CenterlineResult

    Returns
    -------
    ndarray of shape (n,)
        Chainage of every vertex, CRS units; 0 at the first, the line's length at the last.
    """
    vertices = shapely.get_coordinates(result.line)
    return cumulative_lengths(vertices)


def width_statistics(results):
    """Summarise one or several centerline results for the attribute table.

    The ends of a centerline lie on the outline, where the width is zero; statistics are taken over the
    vertices with a positive width. The mean is over the length of the line between the first and the last
    such vertex (vertices are denser near the ends and at branch points, so a plain vertex mean would be
    biased).

    Parameters
    ----------
    results : sequence of CenterlineResult
        Results of the parts of one output feature.

    Returns
    -------
    dict
        ``length`` (sum), ``width_min``, ``width_mean``, ``width_max``, ``n_vertices`` (sum), ``ends_found``
        (True when every part had automatic ends), ``ends_from`` (the parts' ``split_points``, ``guide`` or
        ``automatic``, comma-separated; None for lines); lengths in the results' CRS units.
    """
    widths, integral, span, vertices = [], 0.0, 0.0, 0
    for result in results:
        chainages = vertex_chainages(result)
        vertices += len(chainages)
        positive = result.widths > 0
        width, chainage = result.widths[positive], chainages[positive]
        widths.append(width)
        if len(width) > 1:
            integral += float(np.sum(0.5 * (width[1:] + width[:-1]) * (chainage[1:] - chainage[:-1])))
            span += float(chainage[-1] - chainage[0])
    widths = np.concatenate(widths).tolist() if widths else []
    if widths and span <= 0:
        integral, span = sum(widths), len(widths)
    return {
        "length": float(sum(result.length for result in results)),
        "width_min": min(widths) if widths else None,
        "width_mean": integral / span if widths else None,
        "width_max": max(widths) if widths else None,
        "n_vertices": vertices,
        "ends_found": all(bool(result.ends_found) for result in results),
        "ends_from": ",".join(sorted({result.ends_from for result in results if hasattr(result, "ends_from")})) or None,
    }


def incircle_polygons(result, quad_segs=16):
    """Return the incircle of every centerline vertex as a polygon, with its radius and chainage.

    Vertices with a zero radius (the split-point ends of a polygon's centerline) have no circle and are
    left out.

    Parameters
    ----------
    result : CenterlineResult
        A centerline.
    quad_segs : int
        Segments per quarter circle of each polygon (at least 1).

    Returns
    -------
    list of Incircle
        In the order of the vertices along the line.

    Raises
    ------
    IncirCuError
        If ``quad_segs`` is smaller than 1.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> from incircu_plugin.core import polygon_centerline
    >>> result = polygon_centerline(box(0, 0, 100, 10), [(0, 5), (100, 5)], spacing=10.0)
    >>> circles = incircle_polygons(result)
    >>> all(abs(circle.radius - 5.0) < 1e-9 for circle in circles[1:-1])
    True
    """
    if int(quad_segs) < 1:
        raise IncirCuError(Message("circle_segments", value=quad_segs))
    vertices = shapely.get_coordinates(result.line)
    radii = np.asarray(result.radii, dtype=float)
    chainages = vertex_chainages(result)
    keep = np.flatnonzero(radii > 0.0)
    circles = shapely.buffer(shapely.points(vertices[keep]), radii[keep], quad_segs=int(quad_segs))
    return [
        Incircle(polygon=circle, radius=float(radius), chainage=float(chainage))
        for circle, radius, chainage in zip(circles, radii[keep], chainages[keep])
    ]


def transects(result, interval, chains=None, style="nearest"):
    """Return cross-sections at every multiple of ``interval`` along the centerline.

    Stations are at chainages ``0, interval, 2 * interval, ...`` on the *measured stretch*: near a split
    point the line first crosses the end cap (about half a width long), where the channel has no
    cross-section, so the stretch starts where the cap ends, however far the next vertex is (see
    :func:`measured_stretch`); at an open end it starts at the end. At a station between vertices ``i`` and
    ``i + 1`` the centerline point ``C`` and the radius ``r`` are interpolated linearly.

    A ``"nearest"`` transect is the incircle's diameter in two pieces meeting at ``C``: the feet are the nearest
    points to ``C`` of each chain (``chains``, else ``result.chains``) on its bank between the stretch's end
    incircles, exact wherever the line is on the axis; they bend at ``C`` and fan out where the banks are
    irregular. A ``"straight"`` transect is one straight line through ``C``, square to the centerline's
    direction there smoothed over the local width (the chord between the line's points at ``r`` before and
    after ``C``, closer alike near the measured stretch's ends), each half up to where it first meets the
    chains (a bank, an island or, near an end, the cut): what a hydrologist surveys; its width is at least the
    incircle's diameter. A result without chains (a network's branch) gets each foot at distance ``r`` from
    ``C``: towards the linearly interpolated foot of that side (``"nearest"``), or square to the line.

    Parameters
    ----------
    result : CenterlineResult
        A centerline.
    interval : float
        Distance between stations, CRS units; positive.
    chains : (LineString or ndarray, LineString or ndarray), optional
        The two sides (``c1`` touched by ``foot_a``, ``c2`` by ``foot_b``), CRS units; default
        ``result.chains``.
    style : {"nearest", "straight"}
        See above and :data:`TRANSECT_STYLES`.

    Returns
    -------
    list of Transect
        In the order of the stations.

    Raises
    ------
    IncirCuError
        If ``interval`` is not a positive finite number, or ``style`` unknown.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> from incircu_plugin.core import polygon_centerline
    >>> result = polygon_centerline(box(0, 0, 100, 10), [(0, 5), (100, 5)], spacing=1.0)
    >>> cuts = transects(result, 25.0)
    >>> [(cut.chainage, cut.width) for cut in cuts]
    [(25.0, 10.0), (50.0, 10.0), (75.0, 10.0)]
    >>> list(cuts[0].line.coords)
    [(25.0, 0.0), (25.0, 5.0), (25.0, 10.0)]
    >>> [list(cut.line.coords) for cut in transects(result, 50.0, style="straight")]
    [[(50.0, 0.0), (50.0, 5.0), (50.0, 10.0)]]
    """
    interval = _checked_interval(interval, style)
    vertices = shapely.get_coordinates(result.line)
    chainages = vertex_chainages(result)
    length = float(chainages[-1])
    radii = np.asarray(result.radii, dtype=float)
    stretch = measured_stretch(vertices, radii, chainages, result.foot_a, result.foot_b)
    stations = interval * np.arange(int(np.floor(length / interval * (1.0 + 1e-12))) + 1)
    stations = stations[(stations >= stretch.low) & (stations <= stretch.high)]
    if len(stations) == 0:
        return []
    feet, centres = _transect_feet(stretch, stations, result.chains if chains is None else chains, style)
    lines = np.stack([feet[0], centres, feet[1]], axis=1)
    widths = np.hypot(*(feet[0] - centres).T) + np.hypot(*(feet[1] - centres).T)
    scale = max(length, float(np.max(stretch.radii, initial=0.0)), np.finfo(float).tiny)
    valid = np.isfinite(widths) & (widths > 1e-12 * scale)
    return [
        Transect(line=LineString(line), width=float(width), chainage=float(station))
        for line, width, station in zip(lines[valid], widths[valid], stations[valid])
    ]


def _checked_interval(interval, style):
    """``interval`` as a positive finite float, CRS units, after checking ``style``; raise as :func:`transects`."""
    if style not in TRANSECT_STYLES:
        raise IncirCuError(Message("unknown_transect_style", style=style, choices=", ".join(TRANSECT_STYLES)))
    try:
        interval = float(interval)
    except (TypeError, ValueError):
        raise IncirCuError(Message("transect_interval_kind", value=interval)) from None
    if not (interval > 0.0 and np.isfinite(interval)):
        raise IncirCuError(Message("transect_interval_positive", value=interval))
    return interval


def _transect_feet(stretch, stations, chains, style):
    """The two feet (each ``(m, 2)``) and the centres of the transects at ``stations`` on a
    :class:`MeasuredStretch`, CRS units; ``chains`` may be None (a network's branch). See :func:`transects`."""
    along = points_at(
        np.column_stack([stretch.vertices, stretch.radii, stretch.foot_a, stretch.foot_b]), stretch.chainages, stations
    )
    centres, radius = along[:, :2], along[:, 2]
    if style == "straight":
        window = _window(stations, radius, stretch.low, stretch.high)
        feet = _straight_feet(stretch.vertices, stretch.chainages, window, centres, radius, along[:, 3:5], chains)
    elif chains is not None:
        first_and_last = np.searchsorted(stretch.chainages, [stretch.low, stretch.high])
        sides = zip(chains, ("first chain", "second chain"), stretch.feet)
        feet = [
            _feet_on_banks(as_coordinates(chain, name), foot[first_and_last], centres) for chain, name, foot in sides
        ]
    else:
        feet = [_foot_towards(centres, radius, along[:, 3:5]), _foot_towards(centres, radius, along[:, 5:7])]
    return feet, centres


def _feet_on_banks(chain, ends, centres):
    """Return the point of a chain nearest to each centre, on its bank between the feet ``ends`` of the
    measured stretch's first and last incircles (CRS units): the end caps, where the bank meets the split
    points, carry no foot (a centre a rounding off the axis beside a cap is otherwise nearer to the cap). A
    closed chain (a ring's, around its hole: see :mod:`.rings`) has no cap: the whole of it is its bank."""
    if len(chain) > 2 and np.array_equal(chain[0], chain[-1]):
        return nearest_on_polyline(chain, centres)[2]
    cumulative = cumulative_lengths(chain)
    along = np.sort(nearest_on_polyline(chain, ends)[1])
    return nearest_on_polyline(piece_between(chain, cumulative, *along), centres)[2]


def end_cap_vertices(vertices, radii, chainages, foot_a, foot_b):
    """Return the indices of the end-cap vertices at the start and at the end of a centerline.

    An *end-cap vertex* is an inner vertex, in the half of the line on that side, whose incircle reaches the
    end point or touches the boundary nearer to it than its radius: the incircle touches the end's cut rather
    than both banks. A pointed end (a tip, where the banks meet) has none.

    Parameters
    ----------
    vertices : ndarray of shape (n, 2)
        Centerline vertices, CRS units.
    radii, chainages : ndarray of shape (n,)
        Incircle radius and chainage of each vertex, CRS units.
    foot_a, foot_b : ndarray of shape (n, 2)
        Where each incircle touches the two sides, CRS units.

    Returns
    -------
    start, end : ndarray of int
        Ascending indices.
    """
    slack = 1e-9 * max(float(chainages[-1]), float(np.max(radii, initial=0.0)), np.finfo(float).tiny)
    inner = np.zeros(len(vertices), dtype=bool)
    inner[1:-1] = True
    half = chainages[-1] / 2.0
    found = []
    for end, side in ((vertices[0], chainages <= half), (vertices[-1], chainages >= half)):
        nearest_foot = np.minimum(np.hypot(*(foot_a - end).T), np.hypot(*(foot_b - end).T))
        reaches = np.hypot(*(vertices - end).T) <= radii + slack
        found.append(np.flatnonzero(inner & side & (reaches | (nearest_foot < radii))))
    return found[0], found[1]


def measured_stretch(vertices, radii, chainages, foot_a, foot_b):
    """Return the chainages between which a centerline crosses its channel rather than an end cap, with the
    vertices to interpolate there.

    Near a split point (an end with zero radius) the line first crosses the end cap, about half a width long,
    where the channel has no cross-section. Its end-cap vertices are those of :func:`end_cap_vertices`. The
    innermost one is where the line from the split point meets the axis (both samplings keep it: the adaptive
    line keeps the neighbours of its ends), so the stretch is found whatever the distance to the next vertex;
    at an open end (positive radius) it starts at the end. What that vertex's incircle touches decides where
    the stretch starts (:func:`_end_contacts`): both banks, that vertex; the end only, where the cap ends on
    the segment to the next vertex (:func:`_move_to_cap_end`); a bank and the end, the next vertex. The last
    vertex is found the same way from the other end. ``docs/core-notes.md`` gives the geometry of each case.

    Parameters
    ----------
    vertices : ndarray of shape (n, 2)
        Centerline vertices, CRS units.
    radii : ndarray of shape (n,)
        Incircle radii, CRS units.
    chainages : ndarray of shape (n,)
        Chainage of each vertex, CRS units.
    foot_a, foot_b : ndarray of shape (n, 2)
        Where each incircle touches the two sides, CRS units.

    Returns
    -------
    MeasuredStretch
        Copies of the arguments with the stretch's first and last vertices as described, and the stretch's
        chainages ``low`` and ``high``.
    """
    count = len(vertices)
    slack = 1e-9 * max(float(chainages[-1]), float(np.max(radii, initial=0.0)), np.finfo(float).tiny)
    stretch = MeasuredStretch(
        np.array(vertices, dtype=float),
        np.array(radii, dtype=float),
        np.array(chainages),
        np.array(foot_a, dtype=float),
        np.array(foot_b, dtype=float),
    )
    caps = end_cap_vertices(stretch.vertices, stretch.radii, stretch.chainages, *stretch.feet)
    ends = [stretch.vertices[0].copy(), stretch.vertices[-1].copy()]
    first, last = 0, count - 1
    if stretch.radii[0] <= slack:
        first = max(int(np.max(caps[0], initial=0)), 1)
    if stretch.radii[-1] <= slack:
        last = min(int(np.min(caps[1], initial=count - 1)), count - 2)
    bounds = [first, last]
    for side, (index, step) in enumerate(((first, 1), (last, -1))):
        towards = index + step
        if stretch.radii[0 if step == 1 else -1] > slack or not 0 < towards < count - 1:
            continue
        touches = _end_contacts(stretch, index, ends[side], towards)
        if touches == "bank and end":
            bounds[side] = towards
        elif touches == "end" and first < towards < last:
            _move_to_cap_end(stretch, index, ends[side], towards)
        elif touches == "end":
            # No vertex between the two ends' caps: a straight channel whose line carries no bank.
            _feet_on_the_normal(stretch, index, towards)
    first, last = bounds
    if first <= last and stretch.chainages[first] <= stretch.chainages[last]:
        stretch.low, stretch.high = float(stretch.chainages[first]), float(stretch.chainages[last])
    return stretch


def _end_contacts(stretch, index, end, towards):
    """What the incircle of end-cap vertex ``index`` touches: ``"banks"``, ``"end"`` (both feet on the end) or
    ``"bank and end"``.

    A foot nearer to ``end`` than the radius may be the incircle's contact with the end rather than with a
    bank: it is replaced (in ``stretch``) by the mirror image of the other foot across the line towards vertex
    ``towards``, the bank's foot where the axis runs straight (``"banks"``), unless that image falls on the
    foot itself (within ``GENUINE_END_CONTACT`` of the radius): the incircle touches a bank and the end.
    """
    vertices, radii, feet = stretch.vertices, stretch.radii, stretch.feet
    distances = [float(np.hypot(*(foot[index] - end))) for foot in feet]
    on_end = int(np.argmin(distances))
    along = vertices[towards] - vertices[index]
    norm = float(np.hypot(*along))
    if distances[on_end] >= radii[index] or norm <= 0.0:
        return "banks"
    if max(distances) < radii[index]:
        return "end"
    along /= norm
    other = feet[1 - on_end][index] - vertices[index]
    mirrored = vertices[index] + 2.0 * float(other @ along) * along - other
    if np.hypot(*(mirrored - feet[on_end][index])) < GENUINE_END_CONTACT * radii[index]:
        return "bank and end"
    feet[on_end][index] = mirrored
    return "banks"


def _move_to_cap_end(stretch, index, end, towards):
    """Move vertex ``index`` (in ``stretch``) to where the end cap ends on the segment to vertex ``towards``.

    That is where ``end`` stops being nearer than both banks, the banks there being the tangents at the feet
    of ``towards``; the moved vertex's radius is its mean distance to the two tangents, its feet lie at that
    distance in the directions of the feet of ``towards``.
    """
    vertices, radii, feet = stretch.vertices, stretch.radii, stretch.feet
    start, target = vertices[index].copy(), vertices[towards]
    normals = [(foot[towards] - target) / radii[towards] for foot in feet]

    def bank_distances(t):
        point = start + t * (target - start)
        return point, [radii[towards] - float((point - target) @ normal) for normal in normals]

    # The end is nearer than a bank before the crossing and not after it (at ``towards``, outside the cap).
    low, high = 0.0, 1.0
    for _ in range(BISECTION_STEPS):
        middle = 0.5 * (low + high)
        point, distances = bank_distances(middle)
        low, high = (middle, high) if np.hypot(*(point - end)) < max(distances) else (low, middle)
    point, distances = bank_distances(high)
    radius = 0.5 * sum(distances)
    vertices[index] = point
    radii[index] = radius
    for foot, normal in zip(feet, normals):
        foot[index] = point + radius * normal
    stretch.chainages[index] = stretch.chainages[towards] - np.sign(towards - index) * float(
        np.hypot(*(target - point))
    )


def _feet_on_the_normal(stretch, index, towards):
    """Give vertex ``index`` (in ``stretch``) feet at its radius square to the segment to vertex ``towards``, on
    the sides of the feet of ``towards``."""
    vertices, radius, (foot_a, foot_b) = stretch.vertices, stretch.radii[index], stretch.feet
    along = vertices[towards] - vertices[index]
    normal = np.array([-along[1], along[0]]) / max(float(np.hypot(*along)), np.finfo(float).tiny)
    side = np.sign(float((foot_a[towards] - vertices[towards]) @ normal)) or 1.0
    foot_a[index] = vertices[index] + side * radius * normal
    foot_b[index] = vertices[index] - side * radius * normal


def _window(stations, radius, low, high):
    """The chainages, CRS units, between which the line's direction at each station is taken: ``radius``
    before and after it, shortened alike to stay on the measured stretch ``[low, high]`` (the caps' lines do
    not follow the channel); one-sided, ``radius`` long, at the stretch's ends."""
    half = np.minimum(radius, np.minimum(stations - low, high - stations))
    start, end = stations - half, stations + half
    short = half <= 1e-9 * np.maximum(radius, np.finfo(float).tiny)
    at_low = short & (stations - low <= high - stations)
    start[short], end[short] = stations[short], stations[short]
    end[at_low] += radius[at_low]
    start[short & ~at_low] -= radius[short & ~at_low]
    return start, end


def _straight_feet(vertices, chainages, window, centres, radius, towards_a, chains):
    """The two ends of straight transects through ``centres``, square to the line's chord over ``window``
    (its chainages before and after each centre): each where its half first meets the chains (without chains,
    at ``radius``); side a is the side of ``towards_a`` (the interpolated foot on chain a). CRS units; NaN where
    no bank is met."""
    directions = chord_directions(vertices, chainages, *window)
    normals = np.column_stack([-directions[:, 1], directions[:, 0]])
    side = np.sign(np.einsum("ij,ij->i", towards_a - centres, normals))
    normals *= np.where(np.isfinite(side) & (side != 0.0), side, 1.0)[:, None]
    if chains is None:
        return [centres + radius[:, None] * normals, centres - radius[:, None] * normals]
    segments = _boundary_segments(
        [as_coordinates(chain, name) for chain, name in zip(chains, ("first chain", "second chain"))]
    )
    return [
        centres + _first_hits(centres, sign * normals, radius, segments)[:, None] * sign * normals
        for sign in (1.0, -1.0)
    ]


def _boundary_segments(chains):
    """The segments of the chains, ``(k, 2, 2)``, without the slits joining islands to them (segments run once
    each way) nor zero-length ones; with the segments closing the region between the chains' ends."""
    first, second = chains
    ring = np.concatenate([first, second[::-1], first[:1]])
    segments = np.stack([ring[:-1], ring[1:]], axis=1)
    segments = segments[np.any(segments[:, 0] != segments[:, 1], axis=1)]
    forward = {tuple(segment.ravel()) for segment in segments}
    backward = np.array([tuple(segment[::-1].ravel()) in forward for segment in segments], dtype=bool)
    return segments[~backward]


def _first_hits(origins, directions, radius, segments):
    """Distance from each origin along its (unit) direction to the first segment it meets, CRS units; NaN
    when none (or without a direction). The rays first reach :data:`FIRST_REACH` radii, those that meet nothing then the whole extent."""
    tree = shapely.STRtree(shapely.linestrings(segments))
    distances = np.full(len(origins), np.nan)
    extent = float(np.ptp(segments.reshape(-1, 2), axis=0).max()) * 2.0
    todo = np.flatnonzero(np.isfinite(origins).all(axis=1) & np.isfinite(directions).all(axis=1))
    for reach in (FIRST_REACH * radius, np.full(len(origins), extent)):
        if len(todo) == 0:
            break
        ends = origins[todo] + reach[todo, None] * directions[todo]
        rays, hits = tree.query(shapely.linestrings(np.stack([origins[todo], ends], axis=1)), predicate="intersects")
        start, edge = segments[hits, 0], segments[hits, 1] - segments[hits, 0]
        ray = directions[todo[rays]]
        offset = start - origins[todo[rays]]
        denominator = ray[:, 0] * edge[:, 1] - ray[:, 1] * edge[:, 0]
        with np.errstate(invalid="ignore", divide="ignore"):
            along = (offset[:, 0] * edge[:, 1] - offset[:, 1] * edge[:, 0]) / denominator
        along[~np.isfinite(along) | (along < 0.0)] = np.inf
        nearest = np.full(len(todo), np.inf)
        np.minimum.at(nearest, rays, along)
        found = np.isfinite(nearest)
        distances[todo[found]] = nearest[found]
        todo = todo[~found]
    return distances


def _foot_towards(centres, radius, towards):
    """Return the points at distance ``radius`` from each centre in the direction of ``towards``.

    Parameters
    ----------
    centres, towards : ndarray of shape (m, 2)
        CRS units.
    radius : ndarray of shape (m,)
        CRS units.

    Returns
    -------
    ndarray of shape (m, 2)
        NaN where ``towards`` coincides with the centre (no direction).
    """
    offset = towards - centres
    norm = np.hypot(*offset.T)
    with np.errstate(invalid="ignore", divide="ignore"):
        unit = offset / norm[:, None]
    unit[norm <= 0.0] = np.nan
    return centres + radius[:, None] * unit
