"""Gates between touching polygons: where two features share a stretch of boundary, the middle of it.

A river cut into reaches, OSM water polygons or road-area pieces touch along short stretches (the cuts). The
middle of each shared stretch becomes a split point (a *gate*) of both features, so their networks end there
exactly and meet. The gate is added as a vertex to both features' rings (exactly the same coordinates), so
each network's end is that very vertex, not a projection of it rounded differently in each feature.

Method: candidate pairs from a spatial index of the features' boxes; a pair's shared boundary is the line part
of the intersection of their boundaries (touching at single points makes no gate), merged into stretches;
each stretch's gate is the point halfway along it.
"""

import numpy as np
import shapely

#: Two rings share a stretch when their boundaries' intersection has line parts at least this long, as a
#: fraction of the smaller feature's bounding-box diagonal (a crossing at a point, or rounding, makes none).
SHARED_FRACTION = 1e-9


def touching_gates(geometries):
    """Return the gates of every pair of touching features, and the features with the gates as vertices.

    Parameters
    ----------
    geometries : sequence of Polygon or MultiPolygon or None
        CRS units; None and empty geometries share nothing.

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
    shapes = np.array([None if g is None or g.is_empty else g for g in geometries], dtype=object)
    gates = [[] for _ in geometries]
    valid = np.flatnonzero([shape is not None for shape in shapes])
    if len(valid) < 2:
        return geometries, [np.empty((0, 2)) for _ in geometries]
    tree = shapely.STRtree(shapes[valid])
    first, second = tree.query(shapes[valid], predicate="intersects")
    pairs = [(int(valid[a]), int(valid[b])) for a, b in zip(first, second) if a < b]
    boundaries = {index: shapely.boundary(shapes[index]) for index in {i for pair in pairs for i in pair}}
    for a, b in pairs:
        shared = shapely.intersection(boundaries[a], boundaries[b])
        lines = [part for part in shapely.get_parts(shared) if part.geom_type in ("LineString", "MultiLineString")]
        if not lines:
            continue
        merged = shapely.line_merge(shapely.union_all(lines))
        scale = min(bounding_diagonal(shapes[a]), bounding_diagonal(shapes[b]))
        for stretch in shapely.get_parts(merged):
            if stretch.length <= SHARED_FRACTION * scale:
                continue
            gate = np.asarray(stretch.interpolate(0.5, normalized=True).coords[0], dtype=float)
            gates[a].append(gate)
            gates[b].append(gate)
    with_gates = [
        geometry if not points else _with_vertices(geometry, points) for geometry, points in zip(geometries, gates)
    ]
    return with_gates, [np.array(points, dtype=float).reshape(-1, 2) for points in gates]


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
