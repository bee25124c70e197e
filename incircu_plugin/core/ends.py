"""Automatic ends: the two boundary points a person would call the ends of an elongated polygon.

The ends are the extremities of the polygon's longest internal path, measured along its skeleton (an
approximation of the medial axis), not the farthest pair of points in a straight line: a U-shaped or
meandering river gets its two tips, a Y-shaped one the tips of its two longest arms.

Rule, step by step (deterministic, about O(n log n) in the number ``n`` of boundary samples):

1. **Skeleton.** The boundary (exterior and holes) is simplified by ``SIMPLIFY_FRACTION`` and densified to
   ``1 / SAMPLES_PER_WIDTH`` of the typical width ``2 * area / perimeter`` (a coarser step when that would
   add more than ``MAX_SAMPLES`` samples), then triangulated (Delaunay, made conforming by splitting the
   boundary segments that are not edges of it), so no triangle crosses the boundary. The triangles inside
   the polygon are kept, except slivers of nearly collinear samples along a straight bank. Their dual
   graph, each triangle placed at its circumcentre (a Voronoi vertex of the samples, on the approximate
   medial axis), is the skeleton: every path in it stays in the region and goes around the islands.
2. **Longest path.** A double sweep (from the first node to the farthest node ``a``, then from ``a`` to the
   farthest node ``b``) gives the longest skeleton path ``a -> b``. Without holes the skeleton is a tree
   (the dual graph of a triangulated simple polygon): each sweep is a plain traversal and the result is
   exact. Around islands each sweep is a Dijkstra search and the result a close approximation.
3. **Cap centring.** Near each end the path runs into a corner or a rounded cap, not to the middle of the
   end. Walking inward from the tip, ``d`` is the distance travelled (plus the tip's own clearance) and
   ``r`` the radius of the largest inscribed disk there. The *last trunk point* ``T`` is the widest
   skeleton junction (a triangle with no side on the boundary: where the branches from the two corners of a
   flat cap, or the fan of a rounded cap, meet the trunk) with ``d <= CAP_WINDOW * r``. Without such a
   junction (a pointed end), ``T`` is where ``d`` first exceeds ``CAP_REACH * r``: up to there the disk
   still reaches back to the tip, so the path is in the end cap. Its disk touches the two banks at ``L``
   and ``R`` (the boundary points nearest to ``T +- r * n``, ``n`` normal to the trunk),
   and the trunk's continuation (the ray from ``T`` perpendicular to ``L - R``, the medial-axis tangent)
   leaves the exterior ring at ``X``. The *end cap* is the arc of the exterior ring from ``R`` to ``L``
   through ``X`` (``X`` itself is the end if that arc were over half the ring). Its *corners* are the
   vertices where the boundary turns by ``CORNER_TURN`` or more towards the inside. The end is the
   arc-length midpoint between the first and last corner (a flat or oblique cut: the middle of the cut,
   the midpoint of a rectangle's short side), the corner itself when there is one (a pointed end), or the
   arc-length midpoint of the whole cap when there is none (a rounded cap: its apex).

Limits: an oblique cut sharper than ``CORNER_TURN`` at its obtuse corner ends at its acute corner; the
skeleton is only as fine as the sampling, so features narrower than a quarter of the typical width may be
missed (they do not change the ends of an elongated shape).

The *start* is the end with the smaller ``x`` (then smaller ``y``) coordinate, so the answer does not depend
on where the ring starts or which way it turns.
"""

import heapq
from dataclasses import dataclass
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Point

from .chains import arc_lengths, extent_of, validate_polygon
from .errors import InvalidGeometryError

#: Densification step of the boundary, as a fraction of the typical width ``2 * area / perimeter``.
SAMPLES_PER_WIDTH = 4

#: Tolerance of the simplification before sampling, as a fraction of the typical width (it bounds the
#: error this adds to the ends, and keeps densely digitised outlines fast).
SIMPLIFY_FRACTION = 1e-3

#: Rounds of splitting boundary segments that are not Delaunay edges (each round halves them).
MAX_REFINEMENTS = 12

#: Twice the area, relative to the longest side squared, under which a triangle is a sliver of nearly
#: collinear boundary samples (rounding on a straight bank) and is not part of the skeleton.
SLIVER = 1e-6

#: Densification adds at most about this many samples (the step grows when the boundary is longer).
MAX_SAMPLES = 200_000

#: ``d / r`` below which a skeleton point still belongs to the end cap: ``1 / sin(40 deg)``, so corners of
#: 80 degrees or blunter (a flat cap meets its banks at about 90 degrees) and rounded caps are centred.
CAP_REACH = 1.0 / np.sin(np.radians(40.0))

#: Left turn of a counter-clockwise exterior ring at which a vertex of an end cap counts as a corner
#: (an interior angle of 140 degrees or sharper), radians.
CORNER_TURN = np.radians(40.0)

#: Reach, in radii of the inscribed disk, of the window next to a tip in which the skeleton junction where
#: the corner branches of an end cap meet is looked for (a right-angled corner's branch meets at 1.41).
CAP_WINDOW = 3.0

#: Ratio of the longest skeleton path to the largest inscribed diameter under which a shape is not
#: elongated (a circle scores 1, a square about 1.4, a 2:1 rectangle about 2.4).
ELONGATION_THRESHOLD = 2.0


@dataclass(frozen=True)
class EndsResult:
    """The two ends found on a polygon's boundary.

    Attributes
    ----------
    start : Point
        First end, on the exterior ring (the one with the smaller x, then y), CRS units.
    end : Point
        Second end, on the exterior ring, CRS units.
    elongated : bool
        False when the shape is not elongated (its longest skeleton path is shorter than
        ``ELONGATION_THRESHOLD`` times its largest inscribed diameter); the ends are then arbitrary
        though deterministic, and the caller should warn.
    trunk : LineString or None
        The longest skeleton path the ends were derived from (diagnostics), CRS units.
    """

    start: Point
    end: Point
    elongated: bool
    trunk: Optional[LineString] = None


def find_ends(polygon):
    """Find the two boundary points a person would call the ends of a polygon.

    See the module docstring for the rule (longest skeleton path, then cap centring).

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, possibly with holes (islands), CRS units.

    Returns
    -------
    EndsResult
        ``start`` and ``end`` on the boundary of the polygon, and whether the shape is elongated.

    Raises
    ------
    InvalidGeometryError
        If the polygon is null, empty, not a single polygon, not finite or not valid, or so degenerate
        that no skeleton can be built.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> ends = find_ends(box(0, 0, 10, 2))
    >>> [round(c, 6) for c in ends.start.coords[0] + ends.end.coords[0]]
    [0.0, 1.0, 10.0, 1.0]
    """
    validate_polygon(polygon)
    bounds = np.asarray(polygon.bounds, dtype=float)
    origin = (bounds[:2] + bounds[2:]) / 2.0
    local = shapely.geometry.polygon.orient(shapely.transform(polygon, lambda xy: xy - origin), 1.0)
    extent = extent_of(bounds.reshape(2, 2))
    nodes, radii, edges, step = _skeleton_graph(local)
    if len(edges) == 0:
        raise InvalidGeometryError("The polygon is too thin or too small to find its ends automatically.")
    path = _longest_path(nodes, edges, acyclic=len(local.interiors) == 0)
    trunk = nodes[path]
    trunk_radii = radii[path]
    junction = np.bincount(edges.ravel(), minlength=len(nodes))[path] >= 3
    along = arc_lengths(trunk)
    first = _centred_end(local, trunk, trunk_radii, junction, along, extent, step)
    second = _centred_end(local, trunk[::-1], trunk_radii[::-1], junction[::-1], along[-1] - along[::-1], extent, step)
    diameter = 2.0 * float(trunk_radii.max())
    path_length = float(along[-1] + trunk_radii[0] + trunk_radii[-1])
    elongated = bool(diameter > 0.0 and path_length >= ELONGATION_THRESHOLD * diameter)
    first, second = sorted([first + origin, second + origin], key=lambda xy: (xy[0], xy[1]))
    return EndsResult(
        start=Point(first),
        end=Point(second),
        elongated=elongated,
        trunk=LineString(trunk + origin) if len(trunk) > 1 else None,
    )


def _typical_width(polygon):
    """Return ``2 * area / perimeter``, CRS units: about the width of an elongated polygon."""
    return 2.0 * polygon.area / polygon.length


def _skeleton_graph(polygon):
    """Return a skeleton of the polygon: the dual graph of a conforming Delaunay triangulation.

    The boundary is simplified by ``SIMPLIFY_FRACTION`` of the typical width (topology preserved) and
    densified to ``1 / SAMPLES_PER_WIDTH`` of it. The Delaunay triangulation of these samples is made
    conforming (every boundary segment is an edge of it) by splitting the segments that are not, so every
    triangle lies either inside the polygon or outside it (in a hole or beyond the exterior); the inside
    ones are kept. Each is a node placed at its circumcentre (a Voronoi vertex of the samples, on the
    approximate medial axis), or at its centroid when the circumcentre falls outside the polygon; two nodes
    are linked when their triangles share a side.

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units (shifted near the origin).

    Returns
    -------
    nodes : ndarray of shape (k, 2)
        Skeleton vertices, CRS units.
    radii : ndarray of shape (k,)
        Clearance of each node: its triangle's circumradius (the radius of an empty disk touching the
        samples, within ``step**2 / (8 * r)`` of the distance to the boundary), or the exact distance to the
        boundary for a node placed at a centroid; CRS units.
    edges : ndarray of shape (e, 2) of int
        Node indices of each skeleton edge.
    step : float
        Densification step, CRS units.
    """
    width = _typical_width(polygon)
    simplified = shapely.geometry.polygon.orient(
        polygon.simplify(SIMPLIFY_FRACTION * width, preserve_topology=True), 1.0
    )
    step = max(width / SAMPLES_PER_WIDTH, simplified.length / MAX_SAMPLES)
    dense = shapely.segmentize(simplified, step)
    rings = [shapely.get_coordinates(ring)[:-1] for ring in (dense.exterior, *dense.interiors)]
    for _ in range(MAX_REFINEMENTS):
        samples = np.concatenate(rings)
        count = len(samples)
        following = np.concatenate(
            [offset + np.roll(np.arange(len(ring)), -1) for offset, ring in zip(_offsets(rings), rings)]
        )
        corners, corner_ids = _delaunay(samples)
        side_start, side_end = corner_ids.ravel(), np.roll(corner_ids, -1, axis=1).ravel()
        boundary_keys = _edge_keys(np.arange(count), following, count)
        missing = ~np.isin(boundary_keys, _edge_keys(side_start, side_end, count))
        if not np.any(missing):
            break
        rings = _split_segments(rings, missing)
    # Inside triangles: those whose counter-clockwise sides run along the boundary the way the (oriented)
    # rings do, and every triangle reachable from them without crossing the boundary. Slivers (flat
    # triangles of nearly collinear samples, whose orientation means nothing) take no part.
    first_side, second_side = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    signed = first_side[:, 0] * second_side[:, 1] - first_side[:, 1] * second_side[:, 0]
    clockwise = signed < 0.0
    corners[clockwise] = corners[clockwise][:, ::-1]
    corner_ids[clockwise] = corner_ids[clockwise][:, ::-1]
    double_area = np.abs(signed)
    side_start, side_end = corner_ids.ravel(), np.roll(corner_ids, -1, axis=1).ravel()
    side_keys = _edge_keys(side_start, side_end, count)
    on_boundary = np.isin(side_keys, boundary_keys).reshape(-1, 3)
    forward = np.isin(side_start.astype(np.int64) * count + side_end, np.arange(count) * count + following)
    side_lengths = np.hypot(*(np.roll(corners, -1, axis=1) - corners).transpose(2, 0, 1))
    solid = double_area > SLIVER * np.max(side_lengths, axis=1) ** 2
    region = _components(len(corners), side_keys, ~on_boundary.ravel() & np.repeat(solid, 3))
    seeds = solid & np.any(forward.reshape(-1, 3), axis=1)
    inside = solid & np.isin(region, np.unique(region[seeds]))
    corners, on_boundary, side_lengths = corners[inside], on_boundary[inside], side_lengths[inside]
    side_keys = side_keys.reshape(-1, 3)[inside]
    nodes = _circumcentres(corners)
    radii = np.hypot(*(nodes - corners[:, 0]).T)
    # An obtuse triangle whose longest side is on the boundary has its circumcentre beyond that side, outside
    # the polygon: place its node at its centroid instead, with the centroid's distance to that side.
    longest = np.argmax(side_lengths, axis=1)
    rows = np.arange(len(corners))
    squared = side_lengths**2
    obtuse = 2.0 * squared[rows, longest] > squared.sum(axis=1)
    beyond = obtuse & on_boundary[rows, longest]
    nodes[beyond] = corners[beyond].mean(axis=1)
    radii[beyond] = double_area[inside][beyond] / (3.0 * side_lengths[beyond, longest[beyond]])
    keys = side_keys.ravel()
    owner = np.repeat(rows, 3)
    order = np.argsort(keys, kind="stable")
    keys, owner = keys[order], owner[order]
    shared = np.flatnonzero(keys[1:] == keys[:-1])
    edges = np.stack([owner[shared], owner[shared + 1]], axis=1)
    return nodes, radii, edges, step


def _components(count, side_keys, linking):
    """Label the triangles connected through shared sides that are not on the boundary.

    Parameters
    ----------
    count : int
        Number of triangles.
    side_keys : ndarray of shape (3 * count,)
        Key of each triangle side (see :func:`_edge_keys`), three per triangle in order.
    linking : ndarray of shape (3 * count,) of bool
        Sides that may join two triangles.

    Returns
    -------
    ndarray of shape (count,) of int
        The smallest triangle index of each triangle's component.
    """
    owner = np.repeat(np.arange(count), 3)[linking]
    keys = side_keys[linking]
    order = np.argsort(keys, kind="stable")
    keys, owner = keys[order], owner[order]
    shared = np.flatnonzero(keys[1:] == keys[:-1])
    first, second = owner[shared], owner[shared + 1]
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


def _delaunay(samples):
    """Return the Delaunay triangles of the samples, as corners and as sample indices.

    Parameters
    ----------
    samples : ndarray of shape (n, 2)
        Points, CRS units.

    Returns
    -------
    corners : ndarray of shape (t, 3, 2)
    corner_ids : ndarray of shape (t, 3) of int
        Index in ``samples`` of each corner (one of them for a repeated point).
    """
    triangles = shapely.get_parts(shapely.delaunay_triangles(shapely.multipoints(samples)))
    corners = shapely.get_coordinates(triangles).reshape(-1, 4, 2)[:, :3]
    # Delaunay keeps the input coordinates exactly: look each corner up among the samples, as complex keys
    # (numpy orders complex numbers by real, then imaginary part).
    keys = np.ascontiguousarray(samples).view(np.complex128).ravel()
    order = np.argsort(keys, kind="stable")
    position = np.searchsorted(keys[order], np.ascontiguousarray(corners.reshape(-1, 2)).view(np.complex128).ravel())
    corner_ids = order[np.minimum(position, len(order) - 1)].reshape(-1, 3)
    return corners, corner_ids


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


def _dijkstra(graph, source):
    """Return the shortest distance from ``source`` to every node and each node's predecessor.

    Parameters
    ----------
    graph : (list of int, list of int, list of float)
        Compressed adjacency: the neighbours of node ``i`` are ``neighbours[start[i]:start[i + 1]]`` at
        the matching ``lengths`` (CRS units).
    source : int

    Returns
    -------
    distance : ndarray of float
        ``inf`` for unreachable nodes.
    predecessor : ndarray of int
        ``-1`` for the source and unreachable nodes.
    """
    start, neighbours, lengths = graph
    count = len(start) - 1
    distance = [float("inf")] * count
    predecessor = [-1] * count
    distance[source] = 0.0
    queue = [(0.0, source)]
    while queue:
        reached, node = heapq.heappop(queue)
        if reached > distance[node]:
            continue
        for k in range(start[node], start[node + 1]):
            neighbour = neighbours[k]
            candidate = reached + lengths[k]
            if candidate < distance[neighbour]:
                distance[neighbour] = candidate
                predecessor[neighbour] = node
                heapq.heappush(queue, (candidate, neighbour))
    return np.asarray(distance), np.asarray(predecessor)


def _tree_distances(graph, source):
    """Like :func:`_dijkstra` for a forest, where every reachable node has exactly one path from the source."""
    start, neighbours, lengths = graph
    count = len(start) - 1
    distance = [float("inf")] * count
    predecessor = [-1] * count
    distance[source] = 0.0
    stack = [source]
    while stack:
        node = stack.pop()
        reached = distance[node]
        for k in range(start[node], start[node + 1]):
            neighbour = neighbours[k]
            if predecessor[neighbour] == -1 and neighbour != source:
                distance[neighbour] = reached + lengths[k]
                predecessor[neighbour] = node
                stack.append(neighbour)
    return np.asarray(distance), np.asarray(predecessor)


def _longest_path(nodes, edges, acyclic):
    """Return the node indices of the longest skeleton path found by a double sweep.

    Parameters
    ----------
    nodes : ndarray of shape (k, 2)
        Skeleton vertices, CRS units.
    edges : ndarray of shape (e, 2) of int
        Skeleton edges.
    acyclic : bool
        The skeleton is a forest (the polygon has no holes): each sweep is a plain traversal, and the double
        sweep is exact. Otherwise each sweep is a Dijkstra search.

    Returns
    -------
    ndarray of int
        Node indices from one end of the path to the other.
    """
    count = len(nodes)
    lengths = np.hypot(*(nodes[edges[:, 0]] - nodes[edges[:, 1]]).T)
    sources = np.concatenate([edges[:, 0], edges[:, 1]])
    order = np.argsort(sources, kind="stable")
    start = np.concatenate([[0], np.cumsum(np.bincount(sources, minlength=count))])
    graph = (
        start.tolist(),
        np.concatenate([edges[:, 1], edges[:, 0]])[order].tolist(),
        np.concatenate([lengths, lengths])[order].tolist(),
    )
    sweep = _tree_distances if acyclic else _dijkstra
    distance, _ = sweep(graph, 0)
    first = int(np.argmax(np.where(np.isfinite(distance), distance, -1.0)))
    distance, predecessor = sweep(graph, first)
    last = int(np.argmax(np.where(np.isfinite(distance), distance, -1.0)))
    path = [last]
    while path[-1] != first:
        path.append(int(predecessor[path[-1]]))
    return np.asarray(path[::-1])


def _interpolate(points, along, position):
    """Return the point at arc length ``position`` of a polyline with cumulative lengths ``along``."""
    position = min(max(position, 0.0), along[-1])
    index = int(np.clip(np.searchsorted(along, position, side="right") - 1, 0, len(points) - 2))
    span = along[index + 1] - along[index]
    fraction = 0.0 if span <= 0.0 else (position - along[index]) / span
    return points[index] + fraction * (points[index + 1] - points[index])


def _centred_end(polygon, trunk, radii, junction, along, extent, step):
    """Return the end at the start of ``trunk``, centred in its end cap (see the module docstring).

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units.
    trunk : ndarray of shape (k, 2)
        Longest skeleton path, starting at the end to centre.
    radii : ndarray of shape (k,)
        Clearance of each trunk vertex, CRS units.
    junction : ndarray of shape (k,) of bool
        Whether each trunk vertex is a junction of the skeleton (three neighbours).
    along : ndarray of shape (k,)
        Arc length of each trunk vertex from the start, CRS units.
    extent : float
        Bounding-box diagonal of the polygon, CRS units (length of the ray).
    step : float
        Densification step, CRS units (smallest look-back and reach).

    Returns
    -------
    ndarray of shape (2,)
        The end, on the polygon's exterior ring, CRS units.
    """
    if len(trunk) < 2:
        return _nearest_boundary_point(polygon, trunk[0])
    position = _last_trunk_position(radii, along, junction)
    last_trunk_point = _interpolate(trunk, along, position)
    radius = max(float(np.interp(position, along, radii)), step)
    chord = last_trunk_point - _interpolate(trunk, along, position + max(radius, 2.0 * step))
    if not np.any(chord):
        chord = trunk[0] - last_trunk_point
    if not np.any(chord):
        return _nearest_boundary_point(polygon, last_trunk_point)
    chord = chord / np.hypot(*chord)
    normal = np.array([-chord[1], chord[0]])
    left = _nearest_boundary_point(polygon, last_trunk_point + radius * normal)
    right = _nearest_boundary_point(polygon, last_trunk_point - radius * normal)
    tangent = np.array([left[1] - right[1], right[0] - left[0]])
    tangent_norm = float(np.hypot(*tangent))
    if tangent_norm <= 1e-9 * extent:
        tangent = chord
    else:
        tangent = tangent / tangent_norm * np.sign(np.dot(tangent, chord) or 1.0)
    ray = LineString([last_trunk_point, last_trunk_point + tangent * 2.0 * extent])
    hits = shapely.get_coordinates(shapely.intersection(ray, polygon.exterior))
    if len(hits) == 0:
        return _nearest_boundary_point(polygon, last_trunk_point)
    exit_point = hits[int(np.argmin(np.hypot(*(hits - last_trunk_point).T)))]
    return _cap_middle(polygon.exterior, left, right, exit_point)


def _last_trunk_position(radii, along, junction):
    """Return the arc length of the last trunk point ``T`` seen from the tip at ``along == 0``.

    ``T`` is the widest junction of the skeleton (a triangle with no side on the boundary, where a corner
    branch meets the trunk) within ``CAP_WINDOW`` radii of the tip; without one, the point where ``d`` first
    exceeds ``CAP_REACH * r``.

    Parameters
    ----------
    radii : ndarray of shape (k,)
        Clearance of each trunk vertex, CRS units.
    along : ndarray of shape (k,)
        Arc length of each trunk vertex from the tip, CRS units.
    junction : ndarray of shape (k,) of bool
        Whether each trunk vertex is a junction of the skeleton.

    Returns
    -------
    float
        Arc length of ``T``, CRS units; at most half the path.
    """
    travelled = radii[0] + along
    half = along[-1] / 2.0
    candidates = np.flatnonzero(junction & (travelled <= CAP_WINDOW * radii) & (along <= half))
    if len(candidates):
        return float(along[candidates[int(np.argmax(radii[candidates]))]])
    excess = travelled - CAP_REACH * radii
    beyond = np.flatnonzero((excess > 0.0) & (along <= half))
    if len(beyond) == 0:
        return half
    index = int(beyond[0])
    if index == 0:
        return 0.0
    before, after = excess[index - 1], excess[index]
    return float(along[index - 1] + (along[index] - along[index - 1]) * (-before) / (after - before))


def _cap_middle(exterior, left, right, exit_point):
    """Return the middle of the end cap: the ring arc from ``right`` to ``left`` through the exit.

    Corners are the arc's vertices where a counter-clockwise ring turns left by ``CORNER_TURN`` or more.
    With two or more corners (a flat or oblique cut) the end is the arc-length midpoint between the first
    and the last corner; with one (a pointed end) it is that corner; with none (a rounded cap) it is the
    arc-length midpoint of the whole arc.

    Parameters
    ----------
    exterior : LinearRing
        The polygon's exterior ring, counter-clockwise, CRS units.
    left, right : ndarray of shape (2,)
        Where the last trunk point's disk touches the two banks, CRS units.
    exit_point : ndarray of shape (2,)
        Where the trunk's continuation leaves the polygon, CRS units.

    Returns
    -------
    ndarray of shape (2,)
        The end, CRS units; ``exit_point`` itself when the arc is more than half the ring.
    """
    perimeter = exterior.length
    at_left, at_right, at_exit = (exterior.project(Point(xy)) for xy in (left, right, exit_point))
    forward = (at_left - at_right) % perimeter
    if (at_exit - at_right) % perimeter <= forward:
        start, length = at_right, forward
    else:
        start, length = at_left, perimeter - forward
    if length > perimeter / 2.0:
        return exit_point
    ring = shapely.get_coordinates(exterior)
    step = np.diff(ring, axis=0)
    keep = np.hypot(*step.T) > 0.0
    vertices = ring[:-1][keep]
    positions = np.concatenate([[0.0], np.cumsum(np.hypot(*step.T))])[:-1][keep]
    incoming = vertices - np.roll(vertices, 1, axis=0)
    outgoing = np.roll(vertices, -1, axis=0) - vertices
    turn = np.arctan2(
        incoming[:, 0] * outgoing[:, 1] - incoming[:, 1] * outgoing[:, 0],
        np.einsum("ij,ij->i", incoming, outgoing),
    )
    offset = (positions - start) % perimeter
    corners = np.sort(offset[(offset > 0.0) & (offset < length) & (turn >= CORNER_TURN)])
    if len(corners) == 1:
        target = corners[0]
    elif len(corners) > 1:
        target = (corners[0] + corners[-1]) / 2.0
    else:
        target = length / 2.0
    return np.asarray(exterior.interpolate((start + target) % perimeter).coords[0])


def _nearest_boundary_point(polygon, xy):
    """Return the point of the polygon's exterior ring nearest to ``xy``, CRS units."""
    return np.asarray(shapely.shortest_line(Point(xy), polygon.exterior).coords[1])
