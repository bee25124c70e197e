"""Width outputs of a centerline: its width statistics, its incircles as polygons, and cross-section transects.

Each reads a :class:`~.engine.CenterlineResult`: the centerline's vertices, the incircle radius of each
vertex (the local half-width) and where each incircle touches the two sides (``foot_a``, ``foot_b``).
*Chainage* is the distance along the centerline from its first vertex, CRS units.
"""

from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from .errors import IncirCuError
from .polyline import as_coordinates, cumulative_lengths, nearest_on_polyline, points_at


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
        Length of ``line`` (the diameter of the incircle there), CRS units.
    chainage : float
        Distance of the station along the centerline from the start, CRS units.
    """

    line: LineString
    width: float
    chainage: float


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
        raise IncirCuError(f"A circle needs at least 1 segment per quarter, got {quad_segs!r}.")
    vertices = shapely.get_coordinates(result.line)
    radii = np.asarray(result.radii, dtype=float)
    chainages = vertex_chainages(result)
    keep = np.flatnonzero(radii > 0.0)
    circles = shapely.buffer(shapely.points(vertices[keep]), radii[keep], quad_segs=int(quad_segs))
    return [
        Incircle(polygon=circle, radius=float(radius), chainage=float(chainage))
        for circle, radius, chainage in zip(circles, radii[keep], chainages[keep])
    ]


def transects(result, interval, chains=None):
    """Return cross-sections at every multiple of ``interval`` along the centerline.

    Stations are at chainages ``0, interval, 2 * interval, ...`` on the *measured stretch*: near a split
    point the line first crosses the end cap (about half a width long), where the channel has no
    cross-section, so the stretch starts at the vertex after the innermost one whose incircle reaches the
    split point or touches the boundary nearer to it than its radius (at least one vertex in); at an open
    end it starts at the end. At a station
    between vertices ``i`` and ``i + 1`` the centerline point ``C`` and the radius ``r`` are interpolated
    linearly; each foot is the point at distance ``r`` from ``C`` towards the linearly interpolated foot of
    that side (exact on straight banks, and on the circle of radius ``r`` around ``C`` in any case). When
    ``chains`` are given, the feet are instead the nearest points of each chain to ``C``.

    Parameters
    ----------
    result : CenterlineResult
        A centerline.
    interval : float
        Distance between stations, CRS units; positive.
    chains : (LineString or ndarray, LineString or ndarray), optional
        The two sides (``c1`` touched by ``foot_a``, ``c2`` by ``foot_b``), CRS units.

    Returns
    -------
    list of Transect
        In the order of the stations.

    Raises
    ------
    IncirCuError
        If ``interval`` is not a positive finite number.

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
    """
    try:
        interval = float(interval)
    except (TypeError, ValueError):
        raise IncirCuError(f"The transect interval must be a distance, got {interval!r}.") from None
    if not (interval > 0.0 and np.isfinite(interval)):
        raise IncirCuError(f"The transect interval must be a positive distance, got {interval!r}.")
    vertices = shapely.get_coordinates(result.line)
    chainages = vertex_chainages(result)
    length = float(chainages[-1])
    radii = np.asarray(result.radii, dtype=float)
    foot_a, foot_b = np.asarray(result.foot_a, dtype=float), np.asarray(result.foot_b, dtype=float)
    low, high = _measured_stretch(vertices, radii, chainages, foot_a, foot_b)
    stations = interval * np.arange(int(np.floor(length / interval * (1.0 + 1e-12))) + 1)
    stations = stations[(stations >= low) & (stations <= high)]
    if len(stations) == 0:
        return []
    along = points_at(np.column_stack([vertices, radii, foot_a, foot_b]), chainages, stations)
    centres, radius = along[:, :2], along[:, 2]
    if chains is not None:
        names = ("first chain", "second chain")
        feet = [nearest_on_polyline(as_coordinates(chain, name), centres)[2] for chain, name in zip(chains, names)]
    else:
        feet = [_foot_towards(centres, radius, along[:, 3:5]), _foot_towards(centres, radius, along[:, 5:7])]
    lines = np.stack([feet[0], centres, feet[1]], axis=1)
    widths = np.hypot(*(feet[0] - centres).T) + np.hypot(*(feet[1] - centres).T)
    scale = max(length, float(np.max(radii, initial=0.0)), np.finfo(float).tiny)
    valid = np.isfinite(widths) & (widths > 1e-12 * scale)
    return [
        Transect(line=LineString(line), width=float(width), chainage=float(station))
        for line, width, station in zip(lines[valid], widths[valid], stations[valid])
    ]


def _measured_stretch(vertices, radii, chainages, foot_a, foot_b):
    """Return the chainages between which a centerline crosses its channel rather than an end cap.

    Near a split point (an end with zero radius) the line first crosses the end cap, about half a width
    long, where the channel has no cross-section. An *end-cap vertex* is an inner vertex, in the half of the
    line on that side, whose incircle reaches the end point or touches the boundary nearer to it than its
    radius. The measured stretch starts at the vertex after the innermost end-cap vertex (after the end
    itself when there is none) and ends symmetrically; at an open end (positive radius) it starts at the
    end.

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
    low, high : float
        Chainages bounding the measured stretch (both included), CRS units; ``low > high`` when empty.
    """
    count = len(vertices)
    slack = 1e-9 * max(float(chainages[-1]), float(np.max(radii, initial=0.0)), np.finfo(float).tiny)
    half = chainages[-1] / 2.0
    inner = np.zeros(count, dtype=bool)
    inner[1:-1] = True

    def end_cap(end, side):
        nearest_foot = np.minimum(np.hypot(*(foot_a - end).T), np.hypot(*(foot_b - end).T))
        reaches = np.hypot(*(vertices - end).T) <= radii + slack
        return np.flatnonzero(inner & side & (reaches | (nearest_foot < radii)))

    first, last = 0, count - 1
    if radii[0] <= slack:
        first = int(np.max(end_cap(vertices[0], chainages <= half), initial=0)) + 1
    if radii[-1] <= slack:
        last = int(np.min(end_cap(vertices[-1], chainages >= half), initial=count - 1)) - 1
    if first > last:
        return 1.0, 0.0
    return float(chainages[first]), float(chainages[last])


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
