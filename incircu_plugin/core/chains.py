"""Boundary chains: validation, polygon splitting and orientation of bank lines.

A *chain* is an ``(n, 2)`` float array of vertices with no zero-length segment. The engine takes two chains
``c1`` and ``c2`` running in the same direction, from one end of the centerline to the other.
"""

import weakref
from typing import ClassVar

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from .errors import (
    ChainError,
    CrossingLinesError,
    InvalidGeometryError,
    Message,
    SplitPointError,
    format_point,
    noun,
)
from .polyline import as_coordinates, coordinate_rounding, cumulative_lengths, nearest_entries, points_at
from .validation import check_coordinates, split_point_coordinates, tolerance_length

#: Relative tolerance (of the data's extent) under which two vertices are the same point.
COINCIDENCE_TOLERANCE = 1e-12

#: The smallest positive float64: the least extent, so an extent can divide.
_TINY = float(np.finfo(float).tiny)

#: ``|sin|`` of the turn under which two consecutive segments pointing in opposite directions fold back.
FOLD_SINE_TOLERANCE = 1e-9


def extent_of(*arrays):
    """Return the diagonal of the bounding box of all given coordinate arrays.

    Parameters
    ----------
    *arrays : ndarray of shape (n, 2)
        Coordinates, CRS units.

    Returns
    -------
    float
        Bounding-box diagonal, CRS units; at least the smallest positive float, so it can divide.
    """
    if len(arrays) == 1:
        points = np.asarray(arrays[0], dtype=float).reshape(-1, 2)
    else:
        points = np.concatenate([np.asarray(a, dtype=float).reshape(-1, 2) for a in arrays])
    # Column by column: numpy reduces a column many times faster than an (n, 2) array along its axis 0.
    x, y = points[:, 0], points[:, 1]
    diagonal = float(np.hypot(x.max() - x.min(), y.max() - y.min()))
    return max(diagonal, _TINY)


def signed_area(ring):
    """Return the signed area of a ring, positive when it runs counter-clockwise.

    Parameters
    ----------
    ring : ndarray of shape (n, 2)
        Vertices, closed or not, CRS units.

    Returns
    -------
    float
        Square CRS units.
    """
    x, y = ring[:, 0], ring[:, 1]
    # np.roll(v, -1) by one concatenation: the same products summed in the same order.
    return 0.5 * float(np.dot(x, np.concatenate([y[1:], y[:1]])) - np.dot(y, np.concatenate([x[1:], x[:1]])))


def clean_chain(coordinates, name="chain", tolerance=None):
    """Drop zero-length segments and check that a chain neither degenerates nor folds back.

    Parameters
    ----------
    coordinates : ndarray of shape (n, 2)
        Vertices, CRS units.
    name : str
        How messages call this chain.
    tolerance : float, optional
        Distance, CRS units, under which consecutive vertices are merged; default
        ``COINCIDENCE_TOLERANCE`` times the chain's extent.

    Returns
    -------
    ndarray of shape (m, 2)
        The vertices with consecutive duplicates removed.

    Raises
    ------
    ChainError
        If fewer than two distinct points remain, or the chain folds back over itself.
    """
    if tolerance is None:
        tolerance = COINCIDENCE_TOLERANCE * extent_of(coordinates)
    # The segments' components as separate contiguous arrays: this runs once per feature on a few hundred
    # vertices, where fewer and simpler numpy calls are what saves time.
    dx, dy = _steps(coordinates)
    step = np.hypot(dx, dy)
    long_enough = step > tolerance
    if long_enough.all():
        chain = coordinates.copy()
    else:
        chain = coordinates[np.concatenate([[True], long_enough])]
        dx, dy = _steps(chain)
        step = np.hypot(dx, dy)
    if len(chain) < 2:
        raise ChainError(Message("chain_too_few_points", name=noun(name)))
    # Each turn from the incoming segment (d[:-1]) to the outgoing one (d[1:]).
    # The dot products, summed into the first term's array (at 10^6 vertices each term is 8 MB).
    dot = np.multiply(dx[:-1], dx[1:])
    dot += dy[:-1] * dy[1:]
    backward = dot < 0
    del dot
    if not backward.any():
        return chain
    cross = dx[:-1] * dy[1:] - dy[:-1] * dx[1:]
    folds = np.flatnonzero(backward & (np.abs(cross) <= FOLD_SINE_TOLERANCE * (step[:-1] * step[1:])))
    if len(folds):
        raise ChainError(Message("chain_folds", name=noun(name), point=format_point(chain[folds[0] + 1])))
    return chain


def _fold_tips(points, closed, tolerance):
    """Indices of the vertices where ``points`` (no repeated closing vertex when ``closed``) folds back: the
    segments before and after point in opposite directions within ``FOLD_SINE_TOLERANCE``, or the shorter one
    ends within ``tolerance`` (CRS units) of the longer one's line (a spike of zero width: no wider at its base
    than float64 places vertices); or one of them is shorter than ``tolerance`` and the vertex repeats its
    neighbour."""
    before = points - np.roll(points, 1, axis=0)
    after = np.roll(points, -1, axis=0) - points
    length_before, length_after = np.hypot(*before.T), np.hypot(*after.T)
    dot = np.einsum("ij,ij->i", before, after)
    cross = before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0]
    longer = np.maximum(length_before, length_after)
    tip = (dot < 0) & (
        (np.abs(cross) <= FOLD_SINE_TOLERANCE * length_before * length_after) | (np.abs(cross) <= tolerance * longer)
    )
    tip |= length_before <= tolerance
    if not closed:
        tip[[0, -1]] = False
    return np.flatnonzero(tip)


def without_folds(coordinates, closed, tolerance):
    """Remove the zero-width parts of a ring or a line: spikes that go out and come back along themselves,
    repeated stretches, repeated vertices.

    A spike's tip (a vertex whose two segments point in opposite directions, within ``FOLD_SINE_TOLERANCE``
    or within ``tolerance`` at the spike's base) is removed, then the tips this uncovers (the spike's earlier vertices, when it
    came back through other vertices), until none is left. No other vertex moves: the boundary loses only the
    sliver of the spike, which has no width to hold a centerline. Valid GEOS polygons have such spikes
    (digitising, snapping); ``make_valid``, ``buffer(0)`` and ``simplify`` keep them.

    Parameters
    ----------
    coordinates : ndarray of shape (n, 2)
        A ring (closed: the last vertex repeats the first) or a line, CRS units.
    closed : bool
        Whether ``coordinates`` is a ring.
    tolerance : float
        A spike no wider than this at its base is of zero width; segments this short or shorter count as a
        repeated vertex (one of their vertices goes; it is not reported). CRS units.

    Returns
    -------
    coordinates : ndarray of shape (m, 2)
        The same array when nothing was removed.
    removed : list of (ndarray of shape (2,), float)
        Each removed spike tip and the longer of its two segments, CRS units, in the order found. A line whose
        end segment doubles back loses its end vertex instead (the tip is as far as the line reaches): that
        vertex and the segment's length.

    Examples
    --------
    >>> ring = np.array([(0, 0), (9, 0), (9, 5), (12, 5 + 1e-12), (9, 5 + 2e-12), (9, 9), (0, 9), (0, 0)], float)
    >>> clean, removed = without_folds(ring, True, 1e-9)
    >>> len(clean), removed[0][0].tolist(), round(removed[0][1], 9)
    (6, [12.0, 5.000000000001], 3.0)
    """
    points = coordinates[:-1] if closed else coordinates
    tips = _fold_tips(points, closed, tolerance)
    if not len(tips):
        return coordinates, []
    removed = []
    while len(tips) and len(points) > (3 if closed else 2):
        # The first tip of each run of neighbours (a ring's last vertex neighbours its first): removing two
        # neighbours at once would skip a fold between them.
        chosen = tips[np.concatenate([[True], np.diff(tips) > 1])]
        if closed and len(chosen) > 1 and chosen[0] == 0 and chosen[-1] == len(points) - 1:
            chosen = chosen[:-1]
        gone = []
        for tip in chosen.tolist():
            before = np.hypot(*(points[tip] - points[tip - 1]))
            after = np.hypot(*(points[(tip + 1) % len(points)] - points[tip]))
            # A line's end segment doubling back within the one before it: the end goes, the line keeps its
            # reach (the tip).
            end = None
            if not closed and min(before, after) > tolerance:
                if tip == len(points) - 2 and after <= before:
                    end, length = len(points) - 1, after
                elif tip == 1 and before <= after:
                    end, length = 0, before
            if end is not None:
                removed.append((points[end].copy(), float(length)))
                gone.append(end)
                continue
            if min(before, after) > tolerance:
                removed.append((points[tip].copy(), float(max(before, after))))
            gone.append(tip)
        points = np.delete(points, np.unique(gone), axis=0)
        tips = _fold_tips(points, closed, tolerance)
    return (np.concatenate([points, points[:1]]) if closed else points), removed


def polygon_without_folds(polygon):
    """A valid polygon without the zero-width parts of its rings (:func:`without_folds`), and a note naming
    where they were.

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, CRS units.

    Returns
    -------
    polygon : Polygon
        ``polygon`` itself when it has none (or when removing them would leave an invalid polygon, which the
        later checks then report).
    note : str or None
        Where the spikes were and how long, for the result's ``notes``.

    Examples
    --------
    >>> parcel = Polygon([(0, 0), (90, 0), (90, 5), (90.027, 5 + 1e-12), (90, 5 + 2e-12), (90, 10), (0, 10)])
    >>> clean, note = polygon_without_folds(parcel)
    >>> len(clean.exterior.coords), note
    (6, 'A zero-width spike was removed from the exterior ring at (90.027, 5) (0.027 CRS units long) before the centerline was computed.')
    """
    rings = [shapely.get_coordinates(polygon.exterior)] + [shapely.get_coordinates(r) for r in polygon.interiors]
    tolerance = FOLD_SINE_TOLERANCE * extent_of(rings[0])
    cleaned, places = [], []
    for number, ring in enumerate(rings):
        ring, removed = without_folds(ring, True, tolerance)
        cleaned.append(ring)
        kind = "spike_exterior" if number == 0 else "spike_island"
        places += [Message(kind, point=format_point(tip), length=length, number=number) for tip, length in removed]
    if not places:
        return polygon, None
    result = Polygon(cleaned[0], cleaned[1:])
    if not result.is_valid:
        return polygon, None
    _Validated.remember(result)
    return result, _spikes_note(places)


def _spikes_note(places):
    """The note naming the zero-width spikes removed at ``places`` (``spike_*`` :class:`.errors.Message` objects,
    see :func:`without_folds`): the first three, and how many more."""
    count = len(places)
    if count == 1:
        return Message("note_spike_one", places=places[0])
    parts = dict(zip(("first", "second", "third"), places))
    if count == 2:
        shown = Message("places_two", **parts)
    elif count == 3:
        shown = Message("places_three", **parts)
    else:
        shown = Message("places_more", **parts, more=count - 3)
    return Message("note_spikes", count=count, places=shown)


def ensure_bounding_chains(chain_a, chain_b):
    """Raise unless two chains bound a region: each is simple, and they meet only at shared end points.

    Parameters
    ----------
    chain_a, chain_b : ndarray of shape (n, 2)
        Clean chains (:func:`clean_chain`), CRS units.

    Raises
    ------
    ChainError
        If a chain crosses or touches itself.
    CrossingLinesError
        If the chains cross, touch or overlap anywhere but at an end point both share (identical chains, a
        random walk crossing the other).
    """
    ensure_simple(chain_a, "first chain")
    ensure_simple(chain_b, "second chain")
    lines = LineString(chain_a), LineString(chain_b)
    if not shapely.intersects(*lines):
        return
    coincidence = COINCIDENCE_TOLERANCE * extent_of(chain_a, chain_b)
    shared = [end for end in (chain_a[0], chain_a[-1]) if min(np.hypot(*(chain_b[[0, -1]] - end).T)) <= coincidence]
    contact = shapely.get_coordinates(shapely.intersection(*lines))
    if not len(contact):
        # Not seen, but the predicate and the overlay are separate computations: where they meet, nearly.
        contact = shapely.get_coordinates(shapely.shortest_line(*lines))[:1]
    elsewhere = [point for point in contact if all(np.hypot(*(point - end)) > coincidence for end in shared)]
    if elsewhere:
        raise CrossingLinesError(Message("chains_cross", point=format_point(elsewhere[0])))


def _steps(coordinates):
    """The x and y components of each segment of a polyline (an (n, 2) array, CRS units): two (n - 1,) arrays."""
    x, y = coordinates[:, 0], coordinates[:, 1]
    return x[1:] - x[:-1], y[1:] - y[:-1]


def find_self_crossing(chain):
    """Return a point where a chain touches or crosses itself, or None.

    Parameters
    ----------
    chain : ndarray of shape (n, 2)
        Vertices without zero-length segments, CRS units.

    Returns
    -------
    ndarray of shape (2,) or None
    """
    segments = shapely.linestrings(np.stack([chain[:-1], chain[1:]], axis=1))
    tree = shapely.STRtree(segments)
    first, second = tree.query(segments, predicate="intersects")
    apart = second > first + 1
    if not np.any(apart):
        return None
    i, j = first[apart][0], second[apart][0]
    return shapely.get_coordinates(shapely.intersection(segments[i], segments[j]))[0]


def ensure_simple(chain, name):
    """Raise :class:`ChainError`, calling the chain ``name``, if ``chain`` (vertices, CRS units) touches itself."""
    crossing = find_self_crossing(chain)
    if crossing is not None:
        raise ChainError(Message("chain_crosses", name=noun(name), point=format_point(crossing)))


class _Validated:
    """Weak references to the polygons :func:`validate_polygon` passed, by ``id`` (shapely geometries are
    immutable; an entry goes when its polygon does, so a reused ``id`` is never trusted).

    The public functions check what they are given and call one another (a multipolygon's part is checked by
    ``multipolygon_centerlines``, ``polygon_centerline`` and ``split_polygon``), and a batch checks each
    feature before asking for the ends of all (:func:`.ends.find_ends_together`); GEOS's validity test is most
    of a check's cost (docs/core-notes.md), so each polygon is tested once.
    """

    polygons: ClassVar[weakref.WeakValueDictionary] = weakref.WeakValueDictionary()

    @classmethod
    def holds(cls, polygon):
        """Whether ``polygon`` was found valid."""
        return polygon is not None and cls.polygons.get(id(polygon)) is polygon

    @classmethod
    def remember(cls, polygon):
        """Remember ``polygon`` as found valid (without keeping it alive)."""
        cls.polygons[id(polygon)] = polygon


def validate_polygon(polygon):
    """Check that a polygon is a non-empty, finite, valid single polygon.

    Parameters
    ----------
    polygon : Polygon

    Raises
    ------
    InvalidGeometryError
        With the reason and location GEOS reports for an invalid polygon.
    """
    if _Validated.holds(polygon):
        return
    if polygon is None:
        raise InvalidGeometryError(Message("polygon_null"))
    if not isinstance(polygon, Polygon):
        kind = getattr(polygon, "geom_type", type(polygon).__name__)
        raise InvalidGeometryError(Message("not_polygon", kind=kind))
    if polygon.is_empty:
        raise InvalidGeometryError(Message("polygon_empty"))
    check_coordinates(shapely.get_coordinates(polygon), "polygon")
    if not polygon.is_valid:
        raise InvalidGeometryError(Message("polygon_invalid", reason=shapely.is_valid_reason(polygon)))
    _Validated.remember(polygon)


#: Coordinate roundings (:func:`.polyline.coordinate_rounding`) within which a split point next to a vertex is
#: that vertex: the piece between would be too short for its direction to be known to a thousandth of a radian
#: (at 1e6 from the origin, 1.9e-6 units).
SPLIT_SNAP_ROUNDINGS = 1e3


def _insert_at(ring, positions, along, tolerance):
    """Insert the points at arc lengths ``along`` into a closed ring, each unless a vertex is already there.

    ``ring`` holds the ring's vertices (closed), ``positions`` their arc lengths; ``along`` are arc lengths
    farther than ``tolerance`` apart (CRS units), so no inserted vertex stands where another point is
    tested, and they are inserted in one pass. A point within ``SPLIT_SNAP_ROUNDINGS`` times the coordinates'
    rounding of a vertex (:func:`.polyline.coordinate_rounding`) is not inserted either. Returns the ring's vertices and their arc
    lengths.
    """
    along = np.sort(np.asarray(along, dtype=float))
    new = np.abs(positions[None, :-1] - along[:, None]).min(axis=1) > tolerance
    if not new.any():
        return ring, positions
    along = along[new]
    index = np.searchsorted(positions, along, side="right")
    points = points_at(ring, positions, along)
    # A small shape far from the origin: the coordinates' rounding can exceed ``tolerance``, and a point a hair
    # from a vertex rounds onto it, or next to it. That vertex is the split point: a piece a few roundings long
    # would have no direction (its normal, where the line starts, would be anything; see SPLIT_SNAP_ROUNDINGS).
    near = SPLIT_SNAP_ROUNDINGS * coordinate_rounding(ring)
    apart = (np.hypot(*(points - ring[index - 1]).T) > near) & (np.hypot(*(points - ring[index]).T) > near)
    if not apart.all():
        along, index, points = along[apart], index[apart], points[apart]
        if not len(along):
            return ring, positions
    index = index.tolist()
    # np.insert's result, from slices (a handful of points: np.insert's set-up costs more than the copy).
    bounds = [0, *index, len(ring)]
    ring_pieces, position_pieces = [ring[: bounds[1]]], [positions[: bounds[1]]]
    for number in range(len(index)):
        ring_pieces += [points[number : number + 1], ring[bounds[number + 1] : bounds[number + 2]]]
        position_pieces += [along[number : number + 1], positions[bounds[number + 1] : bounds[number + 2]]]
    return np.concatenate(ring_pieces), np.concatenate(position_pieces)


def counter_clockwise_exterior(polygon):
    """The vertices of a polygon's exterior ring (closed: the last repeats the first), counter-clockwise, CRS
    units; the same ring as ``shapely.geometry.polygon.orient(polygon, 1.0).exterior``."""
    ring = shapely.get_coordinates(polygon.exterior)
    return ring if signed_area(ring) >= 0 else ring[::-1]


def positions_on_ring(ring, points, tolerance):
    """Return the arc length along a ring of the nearest point to each split point.

    Parameters
    ----------
    ring : ndarray of shape (n, 2)
        The ring's vertices, closed, CRS units.
    points : sequence of ndarray of shape (2,)
        The split points, CRS units.
    tolerance : float
        Largest distance, CRS units, between a split point and the ring.

    Returns
    -------
    list of float
        CRS units from the ring's first vertex.

    Raises
    ------
    SplitPointError
        If a point is farther than ``tolerance`` from the ring.
    """
    exterior = shapely.linestrings(ring)
    geometries = shapely.points(np.asarray(points, dtype=float).reshape(-1, 2))
    for point, distance in zip(points, shapely.distance(exterior, geometries).tolist()):
        if distance > tolerance:
            raise SplitPointError(
                Message("split_point_far", point=format_point(point), distance=distance, tolerance=tolerance)
            )
    return shapely.line_locate_point(exterior, geometries).tolist()


def split_polygon(polygon, split_points, tolerance=None):
    """Split a polygon's exterior ring into the two chains between two split points.

    Each split point is snapped to the nearest point of the exterior ring and inserted as a vertex when it
    falls inside an edge.

    Parameters
    ----------
    polygon : Polygon
        A valid polygon; its holes are ignored here.
    split_points : sequence of two Point or (x, y)
        The ends of the centerline.
    tolerance : float, optional
        Largest distance, CRS units, between a split point and the ring; default ``1e-6`` of the polygon's
        extent.

    Returns
    -------
    c1, c2 : ndarray of shape (n, 2)
        Both chains run from the first split point to the second; ``c1`` follows the ring counter-clockwise.

    Raises
    ------
    SplitPointError
        If there are not exactly two points, a point is farther than ``tolerance`` from the ring, or both
        snap to the same place.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> c1, c2 = split_polygon(box(0, 0, 10, 2), [(0, 1), (10, 1)])
    >>> c1.tolist()
    [[0.0, 1.0], [0.0, 0.0], [10.0, 0.0], [10.0, 1.0]]
    """
    validate_polygon(polygon)
    return split_checked_polygon(polygon, split_point_coordinates(split_points), tolerance)


def split_checked_polygon(polygon, points, tolerance=None):
    """:func:`split_polygon` of a polygon :func:`validate_polygon` passed and split points
    :func:`.validation.split_point_coordinates` returned (an (n, 2) float array, CRS units), which are not
    checked again; raises as :func:`split_polygon` does."""
    if len(points) != 2:
        raise SplitPointError(Message("split_points_not_two", count=len(points)))
    tolerance = tolerance_length(tolerance, "snap_tolerance")
    ring = counter_clockwise_exterior(polygon)
    extent = extent_of(ring)
    if tolerance is None:
        tolerance = 1e-6 * extent
    coincidence = COINCIDENCE_TOLERANCE * extent
    ring = np.concatenate([clean_chain(ring[:-1], "exterior ring", coincidence), ring[:1]])
    positions = cumulative_lengths(ring)
    along = positions_on_ring(ring, points, tolerance)
    perimeter = positions[-1]
    along = [0.0 if position >= perimeter - coincidence else position for position in along]
    gap = abs(along[0] - along[1])
    if min(gap, perimeter - gap) <= max(tolerance, coincidence):
        raise SplitPointError(Message("split_points_same_place", point=format_point(points[0])))
    ring, positions = _insert_at(ring, positions, along, coincidence)
    loop = ring[:-1]
    n = len(loop)
    # The closing vertex is the first one: a split point a rounding short of the perimeter is the ring's start.
    start, end = (nearest_entries(positions, along) % n).tolist()
    if start == end:
        raise SplitPointError(Message("split_points_same_place", point=format_point(points[0])))
    forward = np.arange(start, start + (end - start) % n + 1) % n
    backward = np.arange(start, start - (start - end) % n - 1, -1) % n
    return loop[forward], loop[backward]


def orient_bank_lines(line_a, line_b, notes=None):
    """Validate two bank lines and orient them so their starts face each other.

    A line that doubles back on itself (a spike, a repeated stretch: :func:`without_folds`) loses that
    zero-width part first; no other vertex moves.

    Parameters
    ----------
    line_a, line_b : LineString or array_like of shape (n, 2)
        The two lines bounding the region, CRS units.
    notes : list of str, optional
        Where a note naming the removed spikes is appended.

    Returns
    -------
    c1, c2 : ndarray of shape (n, 2)
        ``c1`` is ``line_a`` as given; ``c2`` is ``line_b``, reversed when that makes the starts face each
        other (smaller sum of the distances between matching ends).

    Raises
    ------
    InvalidGeometryError, ChainError, CrossingLinesError
    """
    a = as_coordinates(line_a, "first line")
    b = as_coordinates(line_b, "second line")
    check_coordinates(np.concatenate([a, b]), "pair of lines")
    fold = FOLD_SINE_TOLERANCE * extent_of(a, b)
    (a, removed_a), (b, removed_b) = without_folds(a, False, fold), without_folds(b, False, fold)
    places = [
        Message(kind, point=format_point(tip), length=length)
        for kind, removed in (("spike_first_line", removed_a), ("spike_second_line", removed_b))
        for tip, length in removed
    ]
    if places and notes is not None:
        notes.append(_spikes_note(places))
    coincidence = COINCIDENCE_TOLERANCE * extent_of(a, b)
    a = clean_chain(a, "first line", coincidence)
    b = clean_chain(b, "second line", coincidence)
    ensure_simple(a, "first line")
    ensure_simple(b, "second line")
    # A predicate first: GEOS 3.11 builds the empty intersection of two disjoint collinear lines with a NaN z
    # (a RuntimeWarning from shapely), and lines that bound a region never meet.
    lines = LineString(a), LineString(b)
    if shapely.intersects(*lines):
        touching = shapely.intersection(*lines)
        if touching.is_empty:
            # Not seen, but the predicate and the overlay are separate computations: where they meet, nearly.
            touching = shapely.shortest_line(*lines)
        raise CrossingLinesError(Message("lines_cross", point=format_point(shapely.get_coordinates(touching)[0])))
    same = np.hypot(*(a[0] - b[0])) + np.hypot(*(a[-1] - b[-1]))
    swapped = np.hypot(*(a[0] - b[-1])) + np.hypot(*(a[-1] - b[0]))
    if swapped < same:
        b = b[::-1].copy()
    if abs(signed_area(np.concatenate([a, b[::-1]]))) <= COINCIDENCE_TOLERANCE * extent_of(a, b) ** 2:
        raise ChainError(Message("lines_no_area"))
    return a, b
