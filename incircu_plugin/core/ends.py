"""Automatic ends: the two boundary points a person would call the ends of an elongated polygon.

The ends are the extremities of the polygon's longest internal path, measured along its skeleton (an
approximation of the medial axis), not the farthest pair of points in a straight line: a U-shaped or
meandering river gets its two tips, a Y-shaped one the tips of its two longest arms.

Rule, step by step (deterministic, about O(n log n) in the number ``n`` of boundary samples):

1. **Skeleton.** The boundary (exterior and holes) is densified to a step of one eighth of the typical
   width ``2 * area / perimeter`` (never more than ``MAX_SAMPLES`` samples). The Voronoi edges of these
   samples that lie strictly inside the polygon form a graph close to the medial axis; edges that touch
   the boundary or an island are dropped, so every path in the graph stays in the region and goes around
   the islands.
2. **Longest path.** A double sweep of Dijkstra (from the widest node to the farthest node ``a``, then from
   ``a`` to the farthest node ``b``) gives the longest skeleton path ``a -> b``; it is exact when the
   skeleton is a tree (a polygon without holes) and a close approximation around islands.
3. **Cap centring.** Near each end the path runs into a corner or a rounded cap, not to the middle of the
   end. Walking inward from the tip, ``d`` is the distance travelled (plus the tip's own clearance) and
   ``r`` the radius of the largest inscribed disk there. While ``d <= CAP_REACH * r`` the disk still
   reaches back to the tip: the path is inside the end cap (a corner of 80 degrees or blunter, or a rounded
   cap). The *last trunk point* ``T`` is where ``d`` first exceeds ``CAP_REACH * r``. The end is where the
   trunk's continuation leaves the polygon's exterior ring: the ray from ``T`` in the direction of the trunk (from the
   trunk point one radius further in, through ``T``) meets the boundary there. For a rectangle this is the
   midpoint of the short side, for a flat-capped channel the middle of the cap, for a rounded cap its apex
   and for a pointed end the point itself.

The *start* is the end with the smaller ``x`` (then smaller ``y``) coordinate, so the answer does not depend
on where the ring starts or which way it turns.
"""

import heapq
from dataclasses import dataclass
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Point

from .chains import extent_of, validate_polygon
from .errors import InvalidGeometryError

#: Densification step of the boundary, as a fraction of the typical width ``2 * area / perimeter``.
SAMPLES_PER_WIDTH = 8

#: Upper bound on the number of boundary samples (the step grows when the boundary is longer).
MAX_SAMPLES = 200_000

#: ``d / r`` below which a skeleton point still belongs to the end cap: ``1 / sin(40 deg)``, so corners of
#: 80 degrees or blunter (a flat cap meets its banks at about 90 degrees) and rounded caps are centred.
CAP_REACH = 1.0 / np.sin(np.radians(40.0))

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
    local = shapely.transform(polygon, lambda xy: xy - origin)
    extent = extent_of(bounds.reshape(2, 2))
    samples, segments = _boundary_samples(local)
    nodes, edges = _skeleton_graph(local, samples)
    if len(edges) == 0:
        raise InvalidGeometryError("The polygon is too thin or too small to find its ends automatically.")
    radii = shapely.STRtree(segments).query_nearest(
        shapely.points(nodes), return_distance=True, all_matches=False
    )[1]
    path = _longest_path(nodes, edges, radii)
    trunk = nodes[path]
    trunk_radii = radii[path]
    along = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(trunk, axis=0).T))])
    step = _step(local)
    first = _centred_end(local, trunk, trunk_radii, along, extent, step)
    second = _centred_end(local, trunk[::-1], trunk_radii[::-1], along[-1] - along[::-1], extent, step)
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


def _step(polygon):
    """Return the densification step, CRS units, for a polygon centred on the origin."""
    perimeter = polygon.length
    width = 2.0 * polygon.area / perimeter
    return max(width / SAMPLES_PER_WIDTH, perimeter / MAX_SAMPLES)


def _boundary_samples(polygon):
    """Return the densified boundary: unique sample points and the boundary's segments.

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units (shifted near the origin).

    Returns
    -------
    samples : ndarray of shape (m, 2)
        Vertices of every ring after densification, without the closing duplicates.
    segments : ndarray of LineString
        The segments of every ring (their union is the boundary).
    """
    dense = shapely.segmentize(polygon, _step(polygon))
    rings = [dense.exterior, *dense.interiors]
    samples = []
    segments = []
    for ring in rings:
        coordinates = shapely.get_coordinates(ring)
        samples.append(coordinates[:-1])
        segments.append(shapely.linestrings(np.stack([coordinates[:-1], coordinates[1:]], axis=1)))
    return np.unique(np.concatenate(samples), axis=0), np.concatenate(segments)


def _skeleton_graph(polygon, samples):
    """Return the Voronoi skeleton of the boundary samples that lies strictly inside the polygon.

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units.
    samples : ndarray of shape (m, 2)
        Boundary samples.

    Returns
    -------
    nodes : ndarray of shape (k, 2)
        Skeleton vertices, sorted lexicographically.
    edges : ndarray of shape (e, 2) of int
        Node indices of each skeleton edge.
    """
    voronoi = shapely.voronoi_polygons(shapely.multipoints(samples), only_edges=True)
    ends = shapely.get_coordinates(shapely.get_parts(voronoi)).reshape(-1, 2, 2)
    shapely.prepare(polygon)
    inside = shapely.contains_xy(polygon, ends[:, 0, 0], ends[:, 0, 1]) & shapely.contains_xy(
        polygon, ends[:, 1, 0], ends[:, 1, 1]
    )
    ends = ends[inside]
    boundary = polygon.boundary
    shapely.prepare(boundary)
    ends = ends[~shapely.intersects(boundary, shapely.linestrings(ends))]
    nodes, inverse = np.unique(ends.reshape(-1, 2), axis=0, return_inverse=True)
    edges = inverse.reshape(-1, 2)
    edges = edges[edges[:, 0] != edges[:, 1]]
    return nodes, edges


def _dijkstra(adjacency, weights, source):
    """Return the shortest distance from ``source`` to every node and each node's predecessor.

    Parameters
    ----------
    adjacency : list of list of int
        Neighbours of each node.
    weights : list of list of float
        Edge lengths matching ``adjacency``, CRS units.
    source : int

    Returns
    -------
    distance : ndarray of float
        ``inf`` for unreachable nodes.
    predecessor : ndarray of int
        ``-1`` for the source and unreachable nodes.
    """
    count = len(adjacency)
    distance = [float("inf")] * count
    predecessor = [-1] * count
    distance[source] = 0.0
    queue = [(0.0, source)]
    while queue:
        reached, node = heapq.heappop(queue)
        if reached > distance[node]:
            continue
        for neighbour, weight in zip(adjacency[node], weights[node]):
            candidate = reached + weight
            if candidate < distance[neighbour]:
                distance[neighbour] = candidate
                predecessor[neighbour] = node
                heapq.heappush(queue, (candidate, neighbour))
    return np.asarray(distance), np.asarray(predecessor)


def _longest_path(nodes, edges, radii):
    """Return the node indices of the longest skeleton path found by a double Dijkstra sweep.

    Parameters
    ----------
    nodes : ndarray of shape (k, 2)
        Skeleton vertices, CRS units.
    edges : ndarray of shape (e, 2) of int
        Skeleton edges.
    radii : ndarray of shape (k,)
        Distance of each node to the boundary, CRS units; the sweep starts at the widest node (first one on
        ties), so it runs in the main component of the skeleton.

    Returns
    -------
    ndarray of int
        Node indices from one end of the path to the other.
    """
    lengths = np.hypot(*(nodes[edges[:, 0]] - nodes[edges[:, 1]]).T)
    adjacency = [[] for _ in range(len(nodes))]
    weights = [[] for _ in range(len(nodes))]
    for (u, v), length in zip(edges.tolist(), lengths.tolist()):
        adjacency[u].append(v)
        weights[u].append(length)
        adjacency[v].append(u)
        weights[v].append(length)
    source = int(np.argmax(radii))
    distance, _ = _dijkstra(adjacency, weights, source)
    first = int(np.argmax(np.where(np.isfinite(distance), distance, -1.0)))
    distance, predecessor = _dijkstra(adjacency, weights, first)
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


def _centred_end(polygon, trunk, radii, along, extent, step):
    """Return the end at the start of ``trunk``, centred in its end cap (see the module docstring).

    Parameters
    ----------
    polygon : Polygon
        Valid polygon, CRS units.
    trunk : ndarray of shape (k, 2)
        Longest skeleton path, starting at the end to centre.
    radii : ndarray of shape (k,)
        Clearance of each trunk vertex, CRS units.
    along : ndarray of shape (k,)
        Arc length of each trunk vertex from the start, CRS units.
    extent : float
        Bounding-box diagonal of the polygon, CRS units (length of the ray).
    step : float
        Densification step, CRS units (smallest look-back for the trunk direction).

    Returns
    -------
    ndarray of shape (2,)
        The end, on the polygon's boundary, CRS units.
    """
    if len(trunk) < 2:
        return _nearest_boundary_point(polygon, trunk[0])
    travelled = radii[0] + along
    excess = travelled - CAP_REACH * radii
    half = along[-1] / 2.0
    outside = np.flatnonzero((excess > 0.0) & (along <= half))
    if len(outside) == 0:
        position = half
    else:
        index = int(outside[0])
        if index == 0:
            position = 0.0
        else:
            before, after = excess[index - 1], excess[index]
            position = along[index - 1] + (along[index] - along[index - 1]) * (-before) / (after - before)
    last_trunk_point = _interpolate(trunk, along, position)
    look_back = max(float(np.interp(position, along, radii)), 2.0 * step)
    inward = _interpolate(trunk, along, position + look_back)
    direction = last_trunk_point - inward
    norm = float(np.hypot(*direction))
    if norm <= 0.0:
        direction = trunk[0] - inward
        norm = float(np.hypot(*direction))
    if norm <= 0.0:
        return _nearest_boundary_point(polygon, last_trunk_point)
    ray = LineString([last_trunk_point, last_trunk_point + direction / norm * 2.0 * extent])
    hits = shapely.get_coordinates(shapely.intersection(ray, polygon.exterior))
    if len(hits) == 0:
        return _nearest_boundary_point(polygon, last_trunk_point)
    return hits[int(np.argmin(np.hypot(*(hits - last_trunk_point).T)))]


def _nearest_boundary_point(polygon, xy):
    """Return the point of the polygon's exterior ring nearest to ``xy``, CRS units."""
    return np.asarray(shapely.shortest_line(Point(xy), polygon.exterior).coords[1])
