"""Skeleton of a polygon for the automatic ends: the dual graph of a conforming Delaunay triangulation.

The boundary (exterior and holes) is simplified by ``SIMPLIFY_FRACTION`` (Douglas-Peucker; the slower
topology-preserving variant only when that gives an invalid polygon) and densified to
``1 / SAMPLES_PER_WIDTH`` of the typical width ``2 * area / perimeter`` (a coarser step when that would add
more than ``MAX_SAMPLES`` samples), then triangulated (Delaunay, made conforming by splitting the boundary
segments that are not edges of it), so no triangle crosses the boundary. The triangles inside the polygon
are kept, except slivers of nearly collinear samples along a straight bank. Their dual graph, each triangle
placed at its circumcentre (a Voronoi vertex of the samples, on the approximate medial axis), is the
skeleton: every path in it stays in the region and goes around the islands.

The samples are moved by ``JITTER`` of the step in a fixed pseudo-random pattern before the triangulation:
evenly spaced samples on straight parallel banks are exactly cocircular, which makes the GEOS triangulator
quadratic (minutes on a 1 x 1e-5 box) and, rarely, fail. The pattern is a function of the sample index, so
the result stays deterministic. GEOS inserts the points sorted by x, so the samples are also turned to put
the shape's principal axis along x. Speed: about 5 us of CPU per sample (a third of it the triangulation),
at most ``MAX_SAMPLES`` samples. Limit: a thin channel whose long reaches run across its principal axis (a
tight meander) still makes the sweep slower, about 0.3 s for 20,000 samples.
"""

import numpy as np
import shapely
from shapely.geometry import Polygon

from .errors import InvalidGeometryError
from .polyline import typical_width

#: Densification step of the boundary, as a fraction of the typical width ``2 * area / perimeter``.
SAMPLES_PER_WIDTH = 3

#: Tolerance of the simplification before sampling, as a fraction of the typical width (it bounds the
#: error this adds to the ends, and keeps densely digitised outlines fast).
SIMPLIFY_FRACTION = 2e-2

#: Rounds of splitting boundary segments that are not Delaunay edges (each round halves them).
MAX_REFINEMENTS = 12

#: Twice the area, relative to the longest side squared, under which a triangle is a sliver of nearly
#: collinear boundary samples (rounding on a straight bank) and is not part of the skeleton.
SLIVER = 1e-6

#: Densification adds at most about this many samples (the step grows when the boundary is longer; on a
#: channel thinner than ``1 / MAX_SAMPLES`` of its perimeter the step exceeds the width, and the skeleton
#: nodes of the long thin triangles sit at their centroids, still on the axis of a straight reach).
MAX_SAMPLES = 20_000

#: Angle between the samples' principal axis and the x axis during the triangulation, radians (see
#: :func:`_insertion_rotation`; off the axis so that straight banks are not exactly sorted).
SWEEP_ANGLE = 0.1

#: Size of the deterministic displacement of each sample before the triangulation, as a fraction of the
#: step (far below ``SLIVER``, so straight banks stay slivers); a failing triangulation is retried with
#: the larger values.
JITTER = (1e-9, 1e-7, 1e-5)


def skeleton_graph(polygon):
    """Return a skeleton of the polygon: the dual graph of a conforming Delaunay triangulation.

    Each inside triangle is a node placed at its circumcentre, or at its centroid when the circumcentre
    falls beyond its boundary side (outside the polygon); two nodes are linked when their triangles share
    a side.

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units, scaled to a size about 1 near the origin (for accuracy).

    Returns
    -------
    nodes : ndarray of shape (k, 2)
        Skeleton vertices, CRS units.
    radii : ndarray of shape (k,)
        Clearance of each node: its triangle's circumradius (the radius of an empty disk touching the
        samples, within ``step**2 / (8 * r)`` of the distance to the boundary), or the exact distance to the
        boundary for a node placed at a centroid; CRS units.
    spans : ndarray of shape (k,)
        Width of the channel across each node's triangle: its height over its longest boundary side (the
        distance between the banks, also where the sampling is coarser than the channel), at most its
        circumdiameter; CRS units.
    edges : ndarray of shape (e, 2) of int
        Node indices of each skeleton edge.
    step : float
        Densification step, CRS units.

    Raises
    ------
    InvalidGeometryError
        If no triangulation of the samples can be built.
    """
    triangles = triangulation(polygon)
    return joint_dual_graph([triangles])[:4] + (triangles[3],)


def triangulation(polygon):
    """Return the conforming Delaunay triangulation of a polygon's boundary samples, and their step.

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units, scaled to a size about 1 near the origin (for accuracy).

    Returns
    -------
    corners : ndarray of shape (t, 3, 2)
        Triangle corners, CRS units.
    corner_ids : ndarray of shape (t, 3) of int
        Sample index of each corner.
    following : ndarray of shape (n,) of int
        Index of the next sample on the same ring, for each sample.
    step : float
        Densification step, CRS units.

    Raises
    ------
    InvalidGeometryError
        If no triangulation of the samples can be built.
    """
    rings, step = boundary_samples(polygon)
    return _conforming_triangulation(rings, step) + (step,)


def joint_dual_graph(triangulations):
    """Return the skeletons of several polygons at once: the dual graph of all their triangles.

    The polygons' triangles are only concatenated (each in its own frame), so each polygon's skeleton is
    exactly the one it gets alone; one pass of numpy calls serves them all.

    Parameters
    ----------
    triangulations : list of tuple
        Per polygon, what :func:`triangulation` returns.

    Returns
    -------
    nodes, radii, spans : ndarray
        As :func:`skeleton_graph` returns them, the polygons' nodes one polygon after the other; CRS units
        of each polygon's frame.
    edges : ndarray of shape (e, 2) of int
        Node indices of each skeleton edge (into all the nodes).
    owner : ndarray of shape (k,) of int
        Index in ``triangulations`` of each node's polygon (non-decreasing).
    """
    sample_counts = [len(triangles[2]) for triangles in triangulations]
    offsets = np.concatenate([[0], np.cumsum(sample_counts)[:-1]]).astype(np.int64)
    corners = np.concatenate([np.empty((0, 3, 2))] + [triangles[0] for triangles in triangulations])
    corner_ids = np.concatenate(
        [np.empty((0, 3), np.int64)] + [triangles[1] + offset for triangles, offset in zip(triangulations, offsets)]
    )
    following = np.concatenate(
        [np.empty(0, np.int64)] + [triangles[2] + offset for triangles, offset in zip(triangulations, offsets)]
    )
    triangle_owner = np.repeat(np.arange(len(triangulations)), [len(triangles[0]) for triangles in triangulations])
    nodes, radii, spans, edges, inside = _dual_graph(corners, corner_ids, following)
    return nodes, radii, spans, edges, triangle_owner[inside]


def boundary_samples(polygon):
    """Return the simplified and densified rings the skeleton is built on, and the step.

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units.

    Returns
    -------
    rings : list of ndarray of shape (m, 2)
        Exterior (counter-clockwise) then holes (clockwise), without their closing point, CRS units.
    step : float
        Densification step, CRS units.
    """
    width = typical_width(polygon.area, polygon.length / 2.0)
    simplified = polygon.simplify(SIMPLIFY_FRACTION * width, preserve_topology=False)
    if not (isinstance(simplified, Polygon) and simplified.is_valid):
        simplified = polygon.simplify(SIMPLIFY_FRACTION * width, preserve_topology=True)
    simplified = shapely.geometry.polygon.orient(simplified, 1.0)
    step = max(width / SAMPLES_PER_WIDTH, simplified.length / MAX_SAMPLES)
    dense = shapely.segmentize(simplified, step)
    return [shapely.get_coordinates(ring)[:-1] for ring in (dense.exterior, *dense.interiors)], step


def _conforming_triangulation(rings, step):
    """Return the Delaunay triangles of the ring samples once every ring segment is one of their sides.

    Parameters
    ----------
    rings : list of ndarray of shape (m, 2)
        Exterior (counter-clockwise) and holes without their closing point, CRS units.
    step : float
        Sampling step, CRS units.

    Returns
    -------
    corners : ndarray of shape (t, 3, 2)
    corner_ids : ndarray of shape (t, 3) of int
        Sample index of each corner, in the rings' concatenated order (after the splits).
    following : ndarray of shape (n,) of int
        Index of the next sample on the same ring, for each sample.
    """
    for _ in range(MAX_REFINEMENTS):
        samples = np.concatenate(rings)
        count = len(samples)
        following = np.concatenate(
            [offset + np.roll(np.arange(len(ring)), -1) for offset, ring in zip(_offsets(rings), rings)]
        )
        corners, corner_ids = _delaunay(samples, step)
        side_start, side_end = corner_ids.ravel(), np.roll(corner_ids, -1, axis=1).ravel()
        present = np.zeros(count, dtype=bool)
        present[side_start[following[side_start] == side_end]] = True
        present[side_end[following[side_end] == side_start]] = True
        missing = ~present
        if not np.any(missing):
            break
        rings = _split_segments(rings, missing)
    return corners, corner_ids, following


def _dual_graph(corners, corner_ids, following):
    """Return the nodes, radii, spans and edges of the dual graph of the triangles inside the rings.

    Also returns the mask of the triangles kept (one node each, in order).

    Inside triangles are those whose counter-clockwise sides run along the boundary the way the (oriented)
    rings do, and every triangle reachable from them without crossing the boundary. Slivers (flat triangles
    of nearly collinear samples, whose orientation means nothing) take no part.
    """
    first_side, second_side = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    signed = first_side[:, 0] * second_side[:, 1] - first_side[:, 1] * second_side[:, 0]
    clockwise = signed < 0.0
    corners[clockwise] = corners[clockwise][:, ::-1]
    corner_ids[clockwise] = corner_ids[clockwise][:, ::-1]
    double_area = np.abs(signed)
    side_start, side_end = corner_ids.ravel(), np.roll(corner_ids, -1, axis=1).ravel()
    forward = following[side_start] == side_end
    on_boundary = (forward | (following[side_end] == side_start)).reshape(-1, 3)
    side_lengths = np.hypot(*(np.roll(corners, -1, axis=1) - corners).transpose(2, 0, 1))
    solid = double_area > SLIVER * np.max(side_lengths, axis=1) ** 2
    shared_side, first, second = _shared_sides(side_start, side_end, len(following))
    linking = ~on_boundary.ravel()[shared_side] & solid[first] & solid[second]
    region = connected_labels(len(corners), first[linking], second[linking])
    seeds = solid & np.any(forward.reshape(-1, 3), axis=1)
    inside = solid & np.isin(region, np.unique(region[seeds]))
    renumbered = np.cumsum(inside) - 1
    both = linking & inside[first] & inside[second]
    edges = np.stack([renumbered[first[both]], renumbered[second[both]]], axis=1)
    corners, on_boundary, side_lengths = corners[inside], on_boundary[inside], side_lengths[inside]
    double_area = double_area[inside]
    circumcentres = _circumcentres(corners)
    nodes = circumcentres.copy()
    radii = np.hypot(*(nodes - corners[:, 0]).T)
    spans = 2.0 * radii
    # An obtuse triangle whose longest side is on the boundary has its circumcentre beyond that side, outside
    # the polygon: place its node at its centroid instead, with the centroid's distance to that side.
    longest = np.argmax(side_lengths, axis=1)
    rows = np.arange(len(corners))
    squared = side_lengths**2
    obtuse = 2.0 * squared[rows, longest] > squared.sum(axis=1)
    beyond = obtuse & on_boundary[rows, longest]
    nodes[beyond] = corners[beyond].mean(axis=1)
    radii[beyond] = double_area[beyond] / (3.0 * side_lengths[beyond, longest[beyond]])
    # Across a channel sampled coarser than its width, the circumcircle overestimates the width: the height
    # of the triangle over its longest boundary side is the distance to the other bank.
    boundary_side = np.max(np.where(on_boundary, side_lengths, 0.0), axis=1, initial=0.0)
    across = boundary_side > 0.0
    spans[across] = np.minimum(spans[across], double_area[across] / boundary_side[across])
    return nodes, radii, spans, edges, inside


def _shared_sides(side_start, side_end, count):
    """Return the pairs of triangles sharing a side.

    Parameters
    ----------
    side_start, side_end : ndarray of int
        Sample indices of the sides, three per triangle in order.
    count : int
        Number of samples.

    Returns
    -------
    side : ndarray of int
        Index of the shared side in the first triangle's sides (``3 * triangle + k``).
    first, second : ndarray of int
        The two triangles.
    """
    keys = _edge_keys(side_start, side_end, count)
    order = np.argsort(keys, kind="stable")
    shared = np.flatnonzero(keys[order][1:] == keys[order][:-1])
    return order[shared], order[shared] // 3, order[shared + 1] // 3


def connected_labels(count, first, second):
    """Label the connected components of a graph by their smallest node index.

    Parameters
    ----------
    count : int
        Number of nodes.
    first, second : ndarray of int
        End nodes of each edge.

    Returns
    -------
    ndarray of shape (count,) of int
    """
    label = np.arange(count)
    while True:
        low = np.minimum(label[first], label[second])
        high = np.maximum(label[first], label[second])
        if np.all(low == high):
            return label
        np.minimum.at(label, high, low)
        while True:
            jumped = label[label]
            if np.array_equal(jumped, label):
                break
            label = jumped


def _offsets(rings):
    """Return the index of the first sample of each ring in their concatenation."""
    return np.concatenate([[0], np.cumsum([len(ring) for ring in rings])[:-1]]).astype(np.int64)


def _edge_keys(first, second, count):
    """Return one integer per undirected edge between sample indices ``first`` and ``second``."""
    low = np.minimum(first, second).astype(np.int64)
    high = np.maximum(first, second).astype(np.int64)
    return low * count + high


def _jitter_pattern(count):
    """Return a fixed pseudo-random pattern of ``count`` offsets in ``[-0.5, 0.5)**2`` (a Weyl sequence)."""
    index = np.arange(count, dtype=float)[:, None]
    return np.modf(index * np.array([0.7548776662466927, 0.5698402909980532]) + 0.5)[0] - 0.5


def _delaunay(samples, step):
    """Return the Delaunay triangles of the (slightly displaced) samples, as corners and as sample indices.

    Parameters
    ----------
    samples : ndarray of shape (n, 2)
        Points, CRS units.
    step : float
        Sampling step, CRS units (scale of the displacement, see ``JITTER``).

    Returns
    -------
    corners : ndarray of shape (t, 3, 2)
        Corners of each triangle (the displaced samples, in the samples' frame).
    corner_ids : ndarray of shape (t, 3) of int
        Index in ``samples`` of each corner (one of them for a repeated point).

    Raises
    ------
    InvalidGeometryError
        If GEOS fails on every displacement.
    """
    pattern = _jitter_pattern(len(samples))
    rotation = _insertion_rotation(samples)
    for jitter in JITTER:
        moved = samples + jitter * step * pattern
        turned = moved @ rotation.T
        try:
            triangles = shapely.delaunay_triangles(_multipoint(turned))
        except shapely.errors.GEOSException:
            continue
        found = shapely.get_coordinates(triangles).reshape(-1, 4, 2)[:, :3]
        # Delaunay keeps the input coordinates exactly: look each corner up among the samples, as complex
        # keys (numpy orders complex numbers by real, then imaginary part).
        keys = np.ascontiguousarray(turned).view(np.complex128).ravel()
        order = np.argsort(keys)
        flat = np.ascontiguousarray(found.reshape(-1, 2)).view(np.complex128).ravel()
        position = np.searchsorted(keys[order], flat)
        corner_ids = order[np.minimum(position, len(order) - 1)].reshape(-1, 3)
        return moved[corner_ids], corner_ids
    raise InvalidGeometryError("The polygon's outline could not be triangulated to find its ends automatically.")


def _insertion_rotation(samples):
    """Return the rotation matrix that turns the samples' principal axis to ``SWEEP_ANGLE`` from the x axis.

    GEOS inserts the points sorted by x; sweeping across a long reach (many points of about the same x)
    is slow, up to quadratic on a thin strip across the x axis, while sweeping along the shape's principal
    axis keeps the front short. The triangulation itself does not depend on the rotation.
    """
    centred = samples - samples.mean(axis=0)
    covariance = centred.T @ centred
    eigenvalues, eigenvectors = np.linalg.eigh(covariance)
    axis = eigenvectors[:, int(np.argmax(eigenvalues))]
    angle = SWEEP_ANGLE - np.arctan2(axis[1], axis[0])
    return np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])


def _multipoint(points):
    """Return a MultiPoint of the points, built through WKB (twice as fast as from point objects)."""
    record = np.dtype([("order", "u1"), ("kind", "<u4"), ("xy", "<f8", (2,))])
    header = np.array([(1, 4, len(points))], dtype=[("order", "u1"), ("kind", "<u4"), ("count", "<u4")])
    body = np.zeros(len(points), dtype=record)
    body["order"], body["kind"], body["xy"] = 1, 1, points
    return shapely.from_wkb(header.tobytes() + body.tobytes())


def _split_segments(rings, split):
    """Insert the midpoint of every flagged segment of the rings.

    Parameters
    ----------
    rings : list of ndarray of shape (m, 2)
        Rings without their closing point, CRS units.
    split : ndarray of bool
        One flag per segment (from each sample to the next on its ring), in the rings' concatenated order.

    Returns
    -------
    list of ndarray
    """
    refined = []
    for offset, ring in zip(_offsets(rings), rings):
        flags = split[offset : offset + len(ring)]
        following = np.roll(ring, -1, axis=0)
        where = np.flatnonzero(flags)
        refined.append(np.insert(ring, where + 1, 0.5 * (ring[where] + following[where]), axis=0))
    return refined


def _circumcentres(corners):
    """Return the circumcentres of triangles.

    Parameters
    ----------
    corners : ndarray of shape (t, 3, 2)
        Triangle corners, CRS units (near the origin for accuracy).

    Returns
    -------
    ndarray of shape (t, 2)
        Circumcentres, CRS units; a flat triangle gets its centroid.
    """
    a = corners[:, 0]
    b = corners[:, 1] - a
    c = corners[:, 2] - a
    determinant = 2.0 * (b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0])
    b2 = np.einsum("ij,ij->i", b, b)
    c2 = np.einsum("ij,ij->i", c, c)
    flat = np.abs(determinant) <= 1e-12 * np.maximum(b2, c2)
    safe = np.where(flat, 1.0, determinant)
    offset = np.stack([(c[:, 1] * b2 - b[:, 1] * c2) / safe, (b[:, 0] * c2 - c[:, 0] * b2) / safe], axis=1)
    offset[flat] = ((b + c) / 3.0)[flat]
    return a + offset
