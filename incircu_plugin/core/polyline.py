"""Polyline helpers shared by the core: the one home of each small piece of polyline geometry.

A *polyline* here is an ``(n, 2)`` float array of vertices in CRS units (a chain, a centerline, an island's
ring). Its *arc length* at a point is the distance from its first vertex along it, CRS units; the
*cumulative lengths* are the arc lengths of its vertices. Every helper is vectorised over its points.
"""

import numpy as np
import shapely

from .errors import InvalidGeometryError, Message, noun
from .validation import check_coordinates

#: Whether Shapely has ``orient_polygons`` (2.1 and later); else :func:`counterclockwise` orients one by one.
HAS_ORIENT_POLYGONS = hasattr(shapely, "orient_polygons")


def counterclockwise(polygons):
    """Return the polygons with counterclockwise exteriors and clockwise interiors.

    ``shapely.orient_polygons`` where Shapely has it (2.1 and later), else ``shapely.geometry.polygon.orient``
    polygon by polygon (Shapely 2.0, e.g. Ubuntu 24.04's).

    Parameters
    ----------
    polygons : ndarray of Polygon, shape (n,)

    Returns
    -------
    ndarray of Polygon, shape (n,)

    Examples
    --------
    >>> from shapely.geometry import Polygon
    >>> counterclockwise(np.array([Polygon([(0, 0), (0, 1), (1, 0)])]))[0].exterior.is_ccw
    True
    """
    if HAS_ORIENT_POLYGONS:
        return shapely.orient_polygons(polygons, exterior_cw=False)
    oriented = np.empty(len(polygons), dtype=object)
    oriented[:] = [shapely.geometry.polygon.orient(polygon, 1.0) for polygon in polygons]
    return oriented


def as_coordinates(geometry, name="line"):
    """Return the vertices of a line as a new float array, rejecting empty or non-finite input.

    Parameters
    ----------
    geometry : LineString, LinearRing or array_like of shape (n, 2)
        The line, CRS units; extra dimensions (z, m) are dropped.
    name : str
        How messages call this line.

    Returns
    -------
    ndarray of shape (n, 2)
        CRS units; never a view of the input.

    Raises
    ------
    InvalidGeometryError
        If the geometry is null, empty, not a line, or has NaN, infinite or unusably large coordinates
        (see :func:`.validation.check_coordinates`).
    TypeError
        If the geometry is text (WKT) rather than a geometry or coordinates.

    Examples
    --------
    >>> from shapely.geometry import LineString
    >>> as_coordinates(LineString([(0, 0, 5), (3, 4, 5)])).tolist()
    [[0.0, 0.0], [3.0, 4.0]]
    >>> try:
    ...     as_coordinates([(0, 0), (float("nan"), 1)], "first line")
    ... except InvalidGeometryError as error:
    ...     print(error)
    The first line has a NaN or infinite coordinate: (nan, 1.0).
    """
    if geometry is None:
        raise InvalidGeometryError(Message("named_null", name=noun(name)))
    if isinstance(geometry, shapely.Geometry):
        if geometry.is_empty:
            raise InvalidGeometryError(Message("named_empty", name=noun(name)))
        if geometry.geom_type not in ("LineString", "LinearRing"):
            raise InvalidGeometryError(Message("not_single_line", name=noun(name), kind=geometry.geom_type))
        coordinates = shapely.get_coordinates(geometry)
    else:
        if isinstance(geometry, (str, bytes)):
            raise TypeError(f"The {name} must be a LineString or coordinates, not text (parse WKT with shapely first).")
        try:
            coordinates = np.asarray(geometry, dtype=float)
        except (TypeError, ValueError):
            raise InvalidGeometryError(Message("not_number_array", name=noun(name))) from None
        if coordinates.ndim != 2 or coordinates.shape[1] < 2 or len(coordinates) == 0:
            raise InvalidGeometryError(Message("not_coordinate_array", name=noun(name)))
        coordinates = coordinates[:, :2]
    check_coordinates(coordinates, name, whole=False)
    return np.array(coordinates, dtype=float)


def cumulative_lengths(xy):
    """Return the arc length of each vertex of a polyline: the distance along it from its first vertex.

    Parameters
    ----------
    xy : ndarray of shape (n, 2)
        Vertices, CRS units.

    Returns
    -------
    ndarray of shape (n,)
        CRS units, starting at 0 and non-decreasing; the last value is the polyline's length.

    Examples
    --------
    >>> import numpy as np
    >>> cumulative_lengths(np.array([[0.0, 0.0], [3.0, 4.0], [3.0, 4.0], [3.0, 6.0]])).tolist()
    [0.0, 5.0, 5.0, 7.0]
    """
    xy = np.asarray(xy, dtype=float)
    if len(xy) == 0:
        return np.zeros(1)
    step = xy[1:, :2] - xy[:-1, :2]
    cumulative = np.empty(len(xy))
    cumulative[0] = 0.0
    np.cumsum(np.hypot(step[:, 0], step[:, 1]), out=cumulative[1:])
    return cumulative


def nearest_entries(ascending, values):
    """Index of the entry of ``ascending`` (strictly increasing, at least two) nearest each of ``values``, the
    first of two equally near: ``np.abs(ascending[:, None] - values).argmin(axis=0)`` without its (n, k) array
    (the nearest entry is one of the two around the value).

    >>> nearest_entries(np.array([0.0, 1.0, 3.0]), np.array([-1.0, 0.5, 2.5, 9.0]))
    array([0, 0, 2, 2])
    """
    after = np.clip(np.searchsorted(ascending, values), 1, len(ascending) - 1)
    before = after - 1
    return np.where(np.abs(ascending[after] - values) < np.abs(ascending[before] - values), after, before)


def points_at(xy, cumulative, s):
    """Return the points of a polyline at arc lengths ``s`` (linear interpolation between vertices).

    ``xy`` may carry more columns than two (for instance a radius or the feet of each vertex): every
    column is interpolated the same way.

    Parameters
    ----------
    xy : ndarray of shape (n, d)
        Vertices (and any values attached to them), CRS units; ``n >= 1``.
    cumulative : ndarray of shape (n,)
        Arc length of each vertex, CRS units (:func:`cumulative_lengths`).
    s : float or ndarray of shape (m,)
        Arc lengths, CRS units; clipped to ``[0, cumulative[-1]]``.

    Returns
    -------
    ndarray of shape (d,) for a scalar ``s``, else (m, d)
        CRS units. Inside a zero-length segment the point is its start.

    Examples
    --------
    >>> import numpy as np
    >>> path = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 5.0]])
    >>> points_at(path, cumulative_lengths(path), [2.5, 12.0, 99.0]).tolist()
    [[2.5, 0.0], [10.0, 2.0], [10.0, 5.0]]
    >>> points_at(path, cumulative_lengths(path), 10.0).tolist()
    [10.0, 0.0]
    """
    xy = np.asarray(xy, dtype=float)
    cumulative = np.asarray(cumulative, dtype=float)
    scalar = np.ndim(s) == 0
    # np.minimum / np.maximum rather than np.clip (the same values): this runs on a few points at a time,
    # where np.clip's Python layers cost more than the arithmetic.
    s = np.minimum(np.maximum(np.atleast_1d(np.asarray(s, dtype=float)), cumulative[0]), cumulative[-1])
    if len(xy) == 1:
        points = np.repeat(xy, len(s), axis=0)
        return points[0] if scalar else points
    # s >= cumulative[0], so the segment before the insertion point is never below 0.
    segment = np.minimum(np.searchsorted(cumulative, s, side="right") - 1, len(xy) - 2)
    before = cumulative[segment]
    span = cumulative[segment + 1] - before
    positive = span > 0.0
    fraction = np.where(positive, (s - before) / np.where(positive, span, 1.0), 0.0)
    fraction = np.minimum(np.maximum(fraction, 0.0), 1.0)[:, None]
    start = xy[segment]
    points = start + fraction * (xy[segment + 1] - start)
    return points[0] if scalar else points


def piece_between(xy, cumulative, start, end):
    """Return the piece of a polyline between arc lengths ``start`` and ``end``: its vertices in between, and
    the points at both arc lengths.

    Parameters
    ----------
    xy : ndarray of shape (n, 2)
        Vertices, CRS units.
    cumulative : ndarray of shape (n,)
        Arc length of each vertex, CRS units (:func:`cumulative_lengths`).
    start, end : float
        Arc lengths, CRS units, ``start <= end``; clipped to the polyline.

    Returns
    -------
    ndarray of shape (k, 2)
        CRS units; two equal points when ``start == end``.

    Examples
    --------
    >>> import numpy as np
    >>> path = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 5.0]])
    >>> piece_between(path, cumulative_lengths(path), 2.5, 12.0).tolist()
    [[2.5, 0.0], [10.0, 0.0], [10.0, 2.0]]
    """
    inside = xy[(cumulative > start) & (cumulative < end)]
    first, last = points_at(xy, cumulative, [start, end])
    return np.concatenate([first[None], inside, last[None]])


#: Fewest points that :meth:`IndexedPolyline.nearest` answers as a cluster (one index query for all), and the
#: most (point, segment) pairs it then tests at once.
CLUSTER_POINTS = 32
CLUSTER_PAIRS = 1 << 16

#: :meth:`IndexedPolyline.closest` measures every this many points of a cluster first.
PROBE_STEP = 8


class IndexedPolyline:
    """A polyline with a spatial index of its segments, for repeated nearest-point queries.

    Parameters
    ----------
    xy : ndarray of shape (n, 2)
        Vertices, CRS units; ``n >= 1``.

    Attributes
    ----------
    xy : ndarray of shape (n, 2)
        The vertices, CRS units.
    cumulative : ndarray of shape (n,)
        Arc length of each vertex, CRS units.
    segments : ndarray of LineString
        One two-point line per segment.
    tree : STRtree
        Index of ``segments``.
    """

    def __init__(self, xy):
        self.xy = np.asarray(xy, dtype=float)[:, :2]
        self.cumulative = cumulative_lengths(self.xy)
        path = self.xy if len(self.xy) > 1 else np.repeat(self.xy, 2, axis=0)
        self.segments = shapely.linestrings(np.stack([path[:-1], path[1:]], axis=1))
        self.tree = shapely.STRtree(self.segments)

    def distance_to(self, geometries):
        """Return the distance, CRS units, from each shapely geometry to the polyline."""
        return self.tree.query_nearest(geometries, return_distance=True, all_matches=False)[1]

    def nearest(self, points):
        """Return the nearest point of the polyline to each point; see :func:`nearest_on_polyline`.

        Many points close together (a cluster, such as the slit candidates around an island) are answered
        from the few segments near them, found with one index query (:meth:`_segments_near`); otherwise
        each point queries the index.
        """
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        return self._measured(points, self._segments_near(points))

    def closest(self, points, within=None):
        """Return the first of the points nearest to the polyline, with what :meth:`nearest` gives for it.

        The result is that of ``nearest(points)`` at its first smallest distance; a cluster of points is
        answered measuring only the points that can be that one (:meth:`_closest_within`, else
        :meth:`_may_be_closest`).

        Parameters
        ----------
        points : ndarray of shape (m, 2)
            CRS units; ``m >= 1``.
        within : float, optional
            A distance, CRS units, that some point is expected to come within of the polyline (a hint, such as
            a known distance between the shape the points lie on and the polyline): only the segments that can
            come that near the points are measured. When no point does, the answer is found without it.

        Returns
        -------
        index : int
            The point's index (the smallest among equally near points).
        distance, arc_length : float
            Its distance to the polyline and its foot's arc length from the polyline's start, CRS units.
        foot : ndarray of shape (2,)
            CRS units.
        """
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        if within is not None and len(points) >= CLUSTER_POINTS and len(self.xy) > 1:
            found = self._closest_within(points, within)
            if found is not None:
                return found
        near = self._segments_near(points)
        candidates = np.arange(len(points)) if near is None else self._may_be_closest(points, near)
        distance, arc_length, foot = self._measured(points[candidates], near)
        first = int(np.argmin(distance))
        return int(candidates[first]), float(distance[first]), float(arc_length[first]), foot[first]

    def _closest_within(self, points, within):
        """:meth:`closest` measuring every point on the segments that can come ``within`` (CRS units) of them;
        None when no point comes that near.

        A point that comes ``within`` of the polyline has its nearest segment among those, so it is measured
        exactly; any other point is farther, whatever those segments give it.
        """
        # With a little slack, so rounding cannot leave out a segment at exactly that distance.
        near = self._segments_within(points, within + 1e-9 * (within + float(np.abs(points).max())))
        if not len(near):
            return None
        distance, arc_length, foot = self._feet(points, self._nearest_of(points, near))
        first = int(np.argmin(distance))
        if distance[first] > within:
            return None
        return first, float(distance[first]), float(arc_length[first]), foot[first]

    def _measured(self, points, near):
        """Distance, foot's arc length and foot (CRS units) of each point on the polyline: from the segments
        ``near`` them (see :meth:`_segments_near`), or from the index when ``near`` is None."""
        if len(self.xy) == 1:
            foot = np.repeat(self.xy, len(points), axis=0)
            return np.hypot(*(points - foot).T), np.zeros(len(points)), foot
        if near is None:
            return self._feet(points, self.tree.query_nearest(shapely.points(points), all_matches=False)[1])
        return self._feet(points, self._nearest_of(points, near))

    def _may_be_closest(self, points, near):
        """Sorted indices of the points that may be the nearest to the polyline (``near``: the segments that
        can be nearest to them, see :meth:`_segments_near`).

        Every ``PROBE_STEP``-th point (in the given order, such as along an island's outline) is measured; a
        point between two probes is at least a probe's distance minus its distance from that probe away, so
        only the points this bound lets come as near as the nearest probe can be the nearest.
        """
        probes = np.arange(0, len(points), PROBE_STEP)
        distance = self._feet(points[probes], self._nearest_of(points[probes], near))[0]
        before = np.arange(len(points)) // PROBE_STEP
        after = np.minimum(before + 1, len(probes) - 1)
        to_before = np.hypot(*(points - points[probes[before]]).T)
        to_after = np.hypot(*(points - points[probes[after]]).T)
        bound = np.maximum(distance[before] - to_before, distance[after] - to_after)
        # With a little slack, so rounding cannot leave out a point as near as the nearest probe.
        nearest_probe = float(distance.min())
        slack = 1e-9 * (nearest_probe + float(to_before.max()) + float(to_after.max()))
        return np.flatnonzero(bound <= nearest_probe + slack)

    def _feet(self, points, segment):
        """Distance, foot's arc length and foot (CRS units) of each point on its ``segment`` (indices)."""
        start = self.xy[segment]
        direction = self.xy[segment + 1] - start
        along = _projected(*(points - start).T, *direction.T)
        foot = start + along[:, None] * direction
        length = np.sqrt(np.einsum("ij,ij->i", direction, direction))
        return np.hypot(*(points - foot).T), self.cumulative[segment] + along * length, foot

    def _segments_near(self, points):
        """Sorted indices of the segments that can be nearest to some of the points; None when the points are
        no cluster (fewer than ``CLUSTER_POINTS``, or more than ``CLUSTER_PAIRS`` (point, segment) pairs) or the
        polyline is one vertex.

        The first point's nearest distance ``d`` bounds every other point's by its distance to the first
        point plus ``d``; a segment farther than that bound ``reach`` from all the points' box is nobody's
        nearest, so the query box is the points' box widened by ``reach``.
        """
        if len(points) < CLUSTER_POINTS or len(self.xy) == 1:
            return None
        first = self.tree.query_nearest(shapely.points(points[0]), return_distance=True, all_matches=False)[1][0]
        # With a little slack, so rounding cannot leave out a segment at exactly that distance.
        near = self._segments_within(points, (float(np.hypot(*(points - points[0]).T).max()) + first) * (1.0 + 1e-9))
        return None if len(near) * len(points) > CLUSTER_PAIRS else near

    def _segments_within(self, points, reach):
        """Sorted indices of the segments whose boxes come within ``reach`` (CRS units) of the points' box."""
        low, high = (points.min(axis=0) - reach).tolist(), (points.max(axis=0) + reach).tolist()
        # Python floats: shapely.box takes far longer to read NumPy scalars.
        return np.sort(self.tree.query(shapely.box(*low, *high)))

    def _nearest_of(self, points, near):
        """The nearest segment of each point among ``near`` (sorted segment indices that include it); equally
        near segments: the first."""
        # Per coordinate as (points, segments) arrays: contiguous, unlike the last axis of (m, k, 2) ones.
        x, y = self.xy[:, 0], self.xy[:, 1]
        start_x, start_y = x[near], y[near]
        offset_x, offset_y = points[:, :1] - start_x, points[:, 1:] - start_y
        direction_x, direction_y = x[near + 1] - start_x, y[near + 1] - start_y
        along = _projected(offset_x, offset_y, direction_x, direction_y)
        away_x = offset_x - along * direction_x
        away_y = offset_y - along * direction_y
        return near[np.argmin(away_x * away_x + away_y * away_y, axis=1)]


def _projected(offset_x, offset_y, dx, dy):
    """Where the foot of each offset (a point minus its segment's start) lies on its segment (direction ``dx``,
    ``dy``), as a fraction of the segment (0 to 1; 0 on a segment of length zero); coordinates as arrays that
    broadcast together, CRS units."""
    squared = dx * dx + dy * dy
    along = (offset_x * dx + offset_y * dy) / np.where(squared > 0.0, squared, 1.0)
    return np.minimum(np.maximum(along, 0.0), 1.0)


def chord_directions(xy, cumulative, start, end):
    """Return the unit vectors from the points of a polyline at arc lengths ``start`` to those at ``end``: its
    direction at each place, smoothed over the stretch between them.

    Parameters
    ----------
    xy : ndarray of shape (n, 2)
        Vertices, CRS units.
    cumulative : ndarray of shape (n,)
        Arc length of each vertex, CRS units (:func:`cumulative_lengths`).
    start, end : ndarray of shape (m,)
        Arc lengths, CRS units; clipped to the polyline.

    Returns
    -------
    ndarray of shape (m, 2)
        NaN where the two points coincide.

    Examples
    --------
    >>> import numpy as np
    >>> path = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]])
    >>> chord_directions(path, cumulative_lengths(path), np.array([0.0, 5.0]), np.array([5.0, 15.0])).tolist()
    [[1.0, 0.0], [0.7071067811865475, 0.7071067811865475]]
    """
    chord = points_at(xy, cumulative, np.asarray(end, dtype=float)) - points_at(xy, cumulative, np.asarray(start))
    norm = np.hypot(chord[:, 0], chord[:, 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(norm[:, None] > 0.0, chord / norm[:, None], np.nan)


def nearest_on_polyline(xy, points):
    """Return, for each point, its distance to a polyline, the arc length of its foot and the foot.

    The *foot* is the nearest point of the polyline. The nearest segment comes from a spatial index, the
    foot from an exact orthogonal projection on it (clamped to the segment).

    Parameters
    ----------
    xy : ndarray of shape (n, 2) or IndexedPolyline
        Vertices, CRS units; pass an :class:`IndexedPolyline` to query the same polyline many times.
    points : ndarray of shape (m, 2)
        CRS units.

    Returns
    -------
    distance : ndarray of shape (m,)
        CRS units.
    arc_length : ndarray of shape (m,)
        Arc length of each foot from the polyline's start, CRS units.
    foot : ndarray of shape (m, 2)
        CRS units.

    Examples
    --------
    >>> import numpy as np
    >>> path = np.array([[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]])
    >>> distance, arc_length, foot = nearest_on_polyline(path, np.array([[4.0, 3.0], [13.0, 6.0]]))
    >>> distance.tolist(), arc_length.tolist(), foot.tolist()
    ([3.0, 3.0], [4.0, 16.0], [[4.0, 0.0], [10.0, 6.0]])
    """
    polyline = xy if isinstance(xy, IndexedPolyline) else IndexedPolyline(xy)
    return polyline.nearest(points)


def turn_angles(xy, closed=False):
    """Return the signed turn of a polyline at each vertex, radians (positive to the left).

    The turn is the angle from the incoming to the outgoing segment, in ``(-pi, pi]``; 0 on a straight
    continuation, ``pi / 2`` at a left right-angle corner.

    Parameters
    ----------
    xy : ndarray of shape (n, 2)
        Vertices without zero-length segments, CRS units.
    closed : bool
        False: the turns at the ``n - 2`` interior vertices. True: ``xy`` is a ring (a repeated closing
        vertex is ignored) and every vertex has a turn.

    Returns
    -------
    ndarray of shape (n - 2,), or one value per distinct vertex of a ring
        Radians.

    Examples
    --------
    >>> import numpy as np
    >>> square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    >>> np.degrees(turn_angles(square)).tolist()
    [90.0, 90.0]
    >>> np.degrees(turn_angles(square[::-1], closed=True)).tolist()
    [-90.0, -90.0, -90.0, -90.0]
    """
    xy = np.asarray(xy, dtype=float)
    if closed:
        if len(xy) > 1 and np.array_equal(xy[0], xy[-1]):
            xy = xy[:-1]
        incoming = xy - np.roll(xy, 1, axis=0)
        outgoing = np.roll(xy, -1, axis=0) - xy
    else:
        step = np.diff(xy, axis=0)
        incoming, outgoing = step[:-1], step[1:]
    return turns_between(incoming, outgoing)


def turns_between(incoming, outgoing):
    """Return the signed turn, radians (positive to the left, in ``(-pi, pi]``), from each vector of
    ``incoming`` to the vector of ``outgoing`` in the same row (two ``(n, 2)`` arrays of any lengths).

    Examples
    --------
    >>> import numpy as np
    >>> np.degrees(turns_between(np.array([[1.0, 0.0]]), np.array([[0.0, 2.0]]))).tolist()
    [90.0]
    """
    cross = incoming[:, 0] * outgoing[:, 1] - incoming[:, 1] * outgoing[:, 0]
    return np.arctan2(cross, np.einsum("ij,ij->i", incoming, outgoing))


def local_origin(*arrays):
    """Return the centre of the bounding box of all given coordinates: the shift for numerical conditioning.

    Working on ``xy - origin`` keeps coordinates near zero, where a tolerance relative to the extent is many
    units in the last place even for projected coordinates in the millions; add the origin back to results.

    Parameters
    ----------
    *arrays : array_like of shape (n, 2)
        Coordinates, CRS units.

    Returns
    -------
    ndarray of shape (2,)
        CRS units.

    Examples
    --------
    >>> import numpy as np
    >>> local_origin(np.array([[500000.0, 10.0], [500010.0, 20.0]]), np.array([[500004.0, 30.0]])).tolist()
    [500005.0, 20.0]
    """
    if len(arrays) == 1:
        points = np.asarray(arrays[0], dtype=float).reshape(-1, 2)
    else:
        points = np.concatenate([np.asarray(a, dtype=float).reshape(-1, 2) for a in arrays])
    x, y = points[:, 0], points[:, 1]
    return 0.5 * (np.array([x.min(), y.min()]) + np.array([x.max(), y.max()]))


#: Float64 spacings at a shape's largest coordinate under which two of its points, or a point and a line
#: through its vertices, cannot be told apart: the rounding of its coordinates.
ROUNDING_SPACINGS = 16.0


def coordinate_rounding(points):
    """Distance under which points of a shape are the same up to their coordinates' rounding.

    Parameters
    ----------
    points : ndarray of shape (n, 2)
        CRS units.

    Returns
    -------
    float
        ``ROUNDING_SPACINGS`` float64 spacings at the largest absolute coordinate, CRS units (0 without points).

    Examples
    --------
    >>> import numpy as np
    >>> float(coordinate_rounding(np.array([[0.0, 1.0], [-2.0, 0.5]])) / np.spacing(2.0))
    16.0
    """
    return ROUNDING_SPACINGS * float(np.spacing(np.abs(points).max())) if len(points) else 0.0


def typical_width(area, length):
    """Return the typical width of an elongated region: its area divided by its length along the channel.

    One formula for every caller. For two chains ``length`` is their mean length; for a polygon it is half
    its perimeter (its boundary is the two chains, so this is the same number, and ``2 * area / perimeter``
    is the same formula). A rectangle ``L`` by ``w`` split at the middles of its short sides gives
    ``L * w / (L + w)``: ``w`` within ``w / L``. Two straight banks ``L`` long and ``w`` apart give exactly
    ``w``.

    Parameters
    ----------
    area : float or ndarray
        Area of the region, square CRS units.
    length : float or ndarray
        Its length along the channel, CRS units.

    Returns
    -------
    float or ndarray
        CRS units (an array for arrays, one width per region); 0 where ``length`` is not positive.

    Examples
    --------
    >>> typical_width(1000.0, 100.0)
    10.0
    >>> from shapely.geometry import box
    >>> rectangle = box(0, 0, 90, 10)
    >>> typical_width(rectangle.area, rectangle.length / 2.0)
    9.0
    >>> typical_width(np.array([1000.0, 5.0]), np.array([100.0, 0.0]))
    array([10.,  0.])
    """
    if np.ndim(area) or np.ndim(length):
        area, length = np.broadcast_arrays(np.asarray(area, dtype=float), np.asarray(length, dtype=float))
        return np.divide(area, length, out=np.zeros(area.shape), where=length > 0)
    return float(area) / float(length) if length > 0 else 0.0
