"""Gates between touching polygons: where two features share a stretch of boundary, the middle of it.

A river cut into reaches, OSM water polygons or road-area pieces touch along short stretches (the cuts). The
middle of each shared stretch becomes a split point (a *gate*) of both features, so their networks end there
exactly and meet. The gate is added as a vertex to both features' rings (exactly the same coordinates), so
each network's end is that very vertex, not a projection of it rounded differently in each feature.

Method: candidate pairs from a spatial index of the features' boxes; a pair's shared boundary is the line part
of the intersection of their boundaries (touching at single points makes no gate), merged into stretches;
each stretch's gate is the point halfway along it. A feature whose coordinates are not all finite shares
nothing (its own network reports it); where GEOS fails on a pair (an invalid geometry it cannot read), that pair
shares nothing and the feature at fault (the invalid one of the two, else both) gets the error, the others
their gates.
"""

import numpy as np
import shapely
from shapely.errors import GEOSException

from .errors import InvalidGeometryError, Message

#: Two rings share a stretch when their boundaries' intersection has line parts at least this long, as a
#: fraction of the smaller feature's bounding-box diagonal (a crossing at a point, or rounding, makes none).
SHARED_FRACTION = 1e-9


def touching_gates(geometries, *, errors=None):
    """Return the gates of every pair of touching features, and the features with the gates as vertices.

    Parameters
    ----------
    geometries : sequence of Polygon or MultiPolygon or None
        CRS units; None and empty geometries, and those with a coordinate that is not finite, share nothing.
    errors : list, optional
        Where GEOS fails on a feature (see the module docstring), ``(index, InvalidGeometryError)`` is appended
        here and the other features keep their gates; without it the first such error is raised.

    Returns
    -------
    geometries : list
        The input geometries, each gate of a feature inserted as a vertex of the ring it lies on (the others
        unchanged, the same objects).
    gates : list of ndarray of shape (m, 2)
        Per feature, its gates, CRS units.

    Examples
    --------
    Two reaches of a river cut at ``x = 50``: one gate, the middle of the cut.

    >>> from shapely.geometry import box
    >>> shapes, gates = touching_gates([box(0, 0, 50, 10), box(50, 0, 100, 10)])
    >>> [g.tolist() for g in gates]
    [[[50.0, 5.0]], [[50.0, 5.0]]]
    """
    geometries = list(geometries)
    failed = {}
    shapes = np.array([None if g is None or g.is_empty else g for g in geometries], dtype=object)
    gates = [[] for _ in geometries]
    valid = np.flatnonzero([shape is not None and _finite(shape) for shape in shapes])
    if len(valid) < 2:
        return geometries, [np.empty((0, 2)) for _ in geometries]
    tree = shapely.STRtree(shapes[valid])
    boundaries = {}
    for a, b in _touching_pairs(tree, shapes, valid, failed):
        try:
            for index in (a, b):
                if index not in boundaries:
                    boundaries[index] = _boundary(shapes[index], failed, index)
            if boundaries[a] is None or boundaries[b] is None:
                continue
            found = _shared_gates(boundaries[a], boundaries[b], shapes[a], shapes[b])
        except GEOSException as error:
            for index in [index for index in (a, b) if not shapely.is_valid(shapes[index])] or [a, b]:
                failed.setdefault(index, error)
            continue
        for gate in found:
            gates[a].append(gate)
            gates[b].append(gate)
    with_gates = list(geometries)
    for index, points in enumerate(gates):
        if points:
            try:
                with_gates[index] = _with_vertices(geometries[index], points)
            except GEOSException as error:
                failed.setdefault(index, error)
                gates[index] = []
    for index in sorted(failed):
        error = InvalidGeometryError(Message("gates_failed", reason=str(failed[index])))
        if errors is None:
            raise error
        errors.append((index, error))
    return with_gates, [np.array(points, dtype=float).reshape(-1, 2) for points in gates]


def _finite(shape):
    """Whether every coordinate of a geometry is finite."""
    return bool(np.all(np.isfinite(shapely.get_coordinates(shape))))


def _touching_pairs(tree, shapes, valid, failed):
    """Return the pairs ``(a, b)``, ``a < b``, of features whose geometries intersect; a feature GEOS cannot
    query goes into ``failed`` (index to the exception) and into no pair."""
    try:
        first, second = tree.query(shapes[valid], predicate="intersects")
    except GEOSException:
        first, second = [], []
        for position, index in enumerate(valid):
            try:
                found = tree.query(shapes[index], predicate="intersects")
            except GEOSException as error:
                failed[int(index)] = error
                continue
            first.extend([position] * len(found))
            second.extend(found.tolist())
    return [
        (int(valid[a]), int(valid[b]))
        for a, b in zip(first, second)
        if a < b and int(valid[a]) not in failed and int(valid[b]) not in failed
    ]


def _boundary(shape, failed, index):
    """Return a geometry's boundary; None, with the exception in ``failed[index]``, where GEOS fails on it."""
    try:
        return shapely.boundary(shape)
    except GEOSException as error:
        failed[index] = error
        return None


def _shared_gates(boundary, other_boundary, first, second):
    """Return the gates of two touching geometries (and their boundaries): the middle of each stretch of
    boundary they share."""
    shared = shapely.intersection(boundary, other_boundary)
    lines = [part for part in shapely.get_parts(shared) if part.geom_type in ("LineString", "MultiLineString")]
    if not lines:
        return []
    merged = shapely.line_merge(shapely.union_all(lines))
    scale = min(bounding_diagonal(first), bounding_diagonal(second))
    return [
        np.asarray(stretch.interpolate(0.5, normalized=True).coords[0], dtype=float)
        for stretch in shapely.get_parts(merged)
        if stretch.length > SHARED_FRACTION * scale
    ]


def bounding_diagonal(geometry):
    """Bounding-box diagonal of a geometry (0 for none or an empty one), CRS units."""
    if geometry is None or geometry.is_empty:
        return 0.0
    west, south, east, north = geometry.bounds
    return float(np.hypot(east - west, north - south))


def _with_vertices(geometry, points):
    """Return a (multi)polygon with each point inserted as a vertex of the ring segment nearest to it."""
    polygons = list(shapely.get_parts(geometry))
    result = []
    for polygon in polygons:
        rings = [
            _ring_with(np.asarray(ring.coords, dtype=float), points) for ring in (polygon.exterior, *polygon.interiors)
        ]
        result.append(shapely.Polygon(rings[0], rings[1:]))
    return result[0] if geometry.geom_type == "Polygon" else shapely.MultiPolygon(result)


def _ring_with(ring, points):
    """Return a closed ring's coordinates with each point near it inserted into its nearest segment (points
    equal to a vertex, or farther than ``SHARED_FRACTION`` of the ring's extent, change nothing)."""
    extent = float(np.hypot(*np.ptp(ring, axis=0)))
    for point in points:
        if np.any(np.all(ring == point, axis=1)):
            continue
        start, direction = ring[:-1], np.diff(ring, axis=0)
        squared = np.einsum("ij,ij->i", direction, direction)
        along = np.clip(np.einsum("ij,ij->i", point - start, direction) / np.where(squared > 0, squared, 1.0), 0, 1)
        distance = np.hypot(*(point - start - along[:, None] * direction).T)
        segment = int(np.argmin(distance))
        if distance[segment] <= SHARED_FRACTION * extent:
            ring = np.insert(ring, segment + 1, point, axis=0)
    return ring
