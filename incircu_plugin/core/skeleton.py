"""Skeleton of a polygon for the automatic ends: the dual graph of a conforming Delaunay triangulation.

The boundary (exterior and holes) is simplified by ``SIMPLIFY_FRACTION`` (Douglas-Peucker, whose result GEOS
repairs where it crosses itself; the slower topology-preserving variant only when that leaves other than one
polygon) and densified to
``1 / SAMPLES_PER_WIDTH`` of the typical width ``2 * area / perimeter`` (a coarser step when that would add
more than ``MAX_SAMPLES`` samples), then triangulated (Delaunay, made conforming by splitting the boundary
segments that are not edges of it; a polygon whose first triangulation has only slivers, thinner than its
samples can resolve, is not refined and gets no skeleton), so no triangle crosses the boundary. The triangles
clearly outside the rings (about half of a river's: its hull's pockets, its islands) are dropped as soon as they
are read (see :func:`_kept_triangles`). The triangles inside the polygon are kept, except slivers of nearly
collinear samples along a straight bank. Their dual graph, each triangle placed at its circumcentre (a Voronoi
vertex of the samples, on the approximate medial axis), is the skeleton: every path in it stays in the region
and goes around the islands.

The samples are moved by ``JITTER`` of the step in a fixed pseudo-random pattern before the triangulation:
evenly spaced samples on straight parallel banks are exactly cocircular, which makes the GEOS triangulator
quadratic (minutes on a 1 x 1e-5 box) and, rarely, fail. The pattern is a function of the sample index, so
the result stays deterministic. GEOS inserts the points sorted by x, so the samples are also turned to put
the shape's principal axis along x. Limit: a thin channel whose long reaches run across its principal axis
(a tight meander) still makes GEOS's sweep slower (costs: docs/core-notes.md).
"""

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import shapely

from ._arrays import put_rows, ranges, rows, stable_order
from .errors import InvalidGeometryError, Message
from .polyline import counterclockwise, typical_width

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

#: Rounds of spreading from the triangles along the boundary before the inside triangles are found by
#: labelling the connected components instead (see :func:`reached_from`).
SPREAD_ROUNDS = 16

#: Size of the deterministic displacement of each sample before the triangulation, as a fraction of the
#: step (far below ``SLIVER``, so straight banks stay slivers); a failing triangulation is retried with
#: the larger values.
JITTER = (1e-9, 1e-7, 1e-5)


@dataclass
class Skeletons:
    """The skeletons of a batch of polygons, as flat arrays (see :func:`joint_skeletons`).

    Attributes
    ----------
    nodes : ndarray of shape (k, 2)
        Skeleton vertices, polygon after polygon, each in its polygon's frame, CRS units.
    radii : ndarray of shape (k,)
        Clearance of each node: its triangle's circumradius (the radius of an empty disk touching the
        samples, within ``step**2 / (8 * r)`` of the distance to the boundary), or the exact distance to the
        boundary for a node placed at a centroid; CRS units.
    spans : ndarray of shape (k,)
        Width of the channel across each node's triangle: its height over its longest boundary side (the
        distance between the banks, also where the sampling is coarser than the channel), at most its
        circumdiameter; CRS units.
    edges : ndarray of shape (e, 2) of int
        Node indices of each skeleton edge (into all the nodes).
    owner : ndarray of shape (k,) of int
        Polygon of each node (non-decreasing).
    steps : ndarray of shape (p,)
        Densification step of each polygon's boundary, CRS units.
    errors : list
        Per polygon, None, or the :class:`InvalidGeometryError` raised when no triangulation of its samples
        can be built (it has no node).
    """

    nodes: np.ndarray
    radii: np.ndarray
    spans: np.ndarray
    edges: np.ndarray
    owner: np.ndarray
    steps: np.ndarray
    errors: list


def joint_skeletons(polygons):
    """Return the skeletons of several polygons at once: the dual graphs of their triangulations.

    Each polygon's boundary samples are triangulated (conforming Delaunay, one GEOS call per refinement
    round for all polygons). Each inside triangle is a node placed at its circumcentre, or at its centroid
    when the circumcentre falls beyond its boundary side (outside the polygon); two nodes are linked when
    their triangles share a side. Each polygon's samples, jitter, rotation and refinement are its own, so
    each gets exactly the skeleton it gets alone; one pass of numpy calls serves them all.

    Parameters
    ----------
    polygons : sequence of Polygon
        Valid polygons, each scaled to a size about 1 near the origin (for accuracy).

    Returns
    -------
    Skeletons
    """
    if len(polygons) == 0:
        nothing = np.empty(0)
        return Skeletons(
            np.empty((0, 2)), nothing, nothing, np.empty((0, 2), np.int64), np.empty(0, np.int64), nothing, []
        )
    points, corner_ids, following, triangle_owner, steps, made = _triangulations(polygons)
    corners = np.take(points, corner_ids, axis=0)
    nodes, radii, spans, edges, inside = _dual_graph(corners, corner_ids, following, _triangle_shapes(corners))
    errors = [
        None if triangulated else InvalidGeometryError(Message("outline_not_triangulated"))
        for triangulated in made.tolist()
    ]
    return Skeletons(nodes, radii, spans, edges, triangle_owner[inside], steps, errors)


def _triangulations(polygons):
    """Return the conforming Delaunay triangulations of the polygons' boundary samples, as flat arrays.

    Only the triangles that may be inside are returned (see :func:`_kept_triangles`).

    Returns
    -------
    points : ndarray of shape (n, 2)
        The triangulated (displaced) samples, polygon after polygon, CRS units.
    corner_ids : ndarray of shape (t, 3) of int
        Sample index of each corner (samples numbered polygon after polygon, over the triangulated ones),
        triangles polygon after polygon.
    following : ndarray of shape (n,) of int
        Index of the next sample on the same ring.
    triangle_owner : ndarray of shape (t,) of int
        Polygon of each triangle (non-decreasing).
    steps : ndarray of shape (p,)
        Densification step of each polygon, CRS units.
    made : ndarray of shape (p,) of bool
        Whether each polygon was triangulated.
    """
    count = len(polygons)
    samples, ring, owner, steps = _boundary_sample_arrays(polygons)
    made = np.zeros(count, dtype=bool)
    stored = []
    for refinement in range(MAX_REFINEMENTS):
        following = _following(ring)
        local = ranges(np.bincount(owner, minlength=count))[1]
        moved, corner_ids, triangle_owner, failed = _delaunay_all(samples, owner, local, steps, count)
        side_start, side_end = _sides(corner_ids)
        present = np.zeros(len(samples), dtype=bool)
        present[side_start[following[side_start] == side_end]] = True
        present[side_end[following[side_end] == side_start]] = True
        missing = np.bincount(owner[~present], minlength=count) > 0
        if refinement == 0:
            # Only slivers: the polygon is thinner than its samples can resolve (a needle whose sides meet at
            # an angle of 1e-11). Splitting would not converge and only ends in "too thin"; it is not tried.
            unsplit = np.flatnonzero(missing[triangle_owner])
            solid = _triangle_shapes(np.take(moved, corner_ids[unsplit], axis=0))[2]
            flat = np.bincount(triangle_owner[unsplit[solid]], minlength=count) == 0
        refine = missing & ~failed & ~flat & (refinement < MAX_REFINEMENTS - 1)
        done = (np.bincount(owner, minlength=count) > 0) & ~refine & ~failed
        made |= done
        kept = _kept_triangles(moved, corner_ids, following, triangle_owner, done, ~missing)
        stored.append(_Round(moved, corner_ids[kept], following, owner, triangle_owner[kept], done))
        if not np.any(refine):
            break
        split = ~present & refine[owner]
        keep = refine[owner]
        samples, ring, owner = _split_samples(samples, ring, owner, following, split, keep)
    return (*_merged_by_polygon(stored, count), steps, made)


def _kept_triangles(points, corner_ids, following, triangle_owner, done, conforming):
    """Return the triangles that may be inside their polygon: of the polygons ``done``, those not
    :func:`_clearly_outside` where the polygon's triangulation is ``conforming``.

    In a conforming triangulation every boundary segment is an edge, so the rings cross nowhere and the
    spreading from the inside (see :func:`_dual_graph`, never across a boundary side) reaches no triangle
    outside them. Dropping those changes no skeleton: the inside triangles, their order and the order of their
    shared sides stay the same. A triangulation that does not conform (its last round, or only slivers) keeps
    all its triangles.

    Parameters
    ----------
    points : ndarray of shape (n, 2)
        The triangulated samples, CRS units.
    corner_ids : ndarray of shape (t, 3) of int
        Sample index of each corner.
    following : ndarray of shape (n,) of int
        Index of the next sample on the same ring.
    triangle_owner : ndarray of shape (t,) of int
    done, conforming : ndarray of shape (p,) of bool

    Returns
    -------
    ndarray of int
        Indices of the kept triangles, increasing.
    """
    walled = done & conforming
    if not np.any(walled):
        return np.flatnonzero(done[triangle_owner])
    outside = _clearly_outside(points, corner_ids, following) & walled[triangle_owner]
    return np.flatnonzero(done[triangle_owner] & ~outside)


def _clearly_outside(points, corner_ids, following):
    """Return whether each triangle lies clearly outside the rings' interior at its first corner.

    Every corner is a boundary sample ``v``; the interior lies on the left of the rings (counter-clockwise
    exterior, clockwise holes), so near ``v`` it is the angle turning counter-clockwise from the next sample
    ``u`` to the previous one ``w``. A triangle of a conforming triangulation lies wholly on one side of the
    boundary; it is outside when the direction from ``v`` through its middle (the sum of its two sides from
    ``v``) lies in the outer angle, from ``w`` to ``u``, by more than the rounding of the cross products
    (``1e-9`` of the sides' lengths, plus ``1e-13`` of their sum for the coordinates' rounding: the samples are
    within about 1 of the origin). A doubtful triangle is not outside.

    Parameters
    ----------
    points : ndarray of shape (n, 2)
        Samples, CRS units, within about 1 of the origin.
    corner_ids : ndarray of shape (t, 3) of int
    following : ndarray of shape (n,) of int
        Index of the next sample on the same ring.

    Returns
    -------
    ndarray of shape (t,) of bool
    """
    preceding = np.empty_like(following)
    preceding[following] = np.arange(len(following))
    vertex = corner_ids[:, 0]
    origin = np.take(points, vertex, axis=0)
    middle = np.take(points, corner_ids[:, 1], axis=0) + np.take(points, corner_ids[:, 2], axis=0) - 2.0 * origin
    after = np.take(points, following[vertex], axis=0) - origin
    before = np.take(points, preceding[vertex], axis=0) - origin
    # An outer angle under a half turn holds the directions past ``w`` and short of ``u``; a wider one, either.
    past_before = _clearly_counterclockwise(before, middle)
    short_of_after = _clearly_counterclockwise(middle, after)
    narrow = (before[:, 0] * after[:, 1] - before[:, 1] * after[:, 0]) > 0.0
    return np.where(narrow, past_before & short_of_after, past_before | short_of_after)


def _clearly_counterclockwise(first, second):
    """Return whether each vector ``second`` turns counter-clockwise from ``first`` by more than the rounding
    of their cross product (see :func:`_clearly_outside`); both of shape (t, 2), CRS units."""
    cross = first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0]
    size_first = np.abs(first[:, 0]) + np.abs(first[:, 1])
    size_second = np.abs(second[:, 0]) + np.abs(second[:, 1])
    return cross > 1e-9 * size_first * size_second + 1e-13 * (size_first + size_second)


class _Round(NamedTuple):
    """The triangulations of one refinement round (samples numbered from 0) and the polygons it finished."""

    points: np.ndarray
    corner_ids: np.ndarray
    following: np.ndarray
    sample_owner: np.ndarray
    triangle_owner: np.ndarray
    done: np.ndarray


def _merged_by_polygon(rounds, count):
    """Return the triangulations of the polygons each round finished as one set, polygon after polygon:
    ``points, corner_ids, following, triangle_owner``.

    Within a polygon the order of its samples and triangles is kept (a polygon is finished in one round); each
    item is copied once, from its round to its place.
    """
    if len(rounds) == 1 and np.all(rounds[0].done[rounds[0].sample_owner]):
        (part,) = rounds
        return part.points, part.corner_ids, part.following, part.triangle_owner
    kept = [
        (np.flatnonzero(part.done[part.sample_owner]), np.flatnonzero(part.done[part.triangle_owner]))
        for part in rounds
    ]
    sample_slots = _slots([part.sample_owner[samples] for part, (samples, _) in zip(rounds, kept)], count)
    triangle_slots = _slots([part.triangle_owner[triangles] for part, (_, triangles) in zip(rounds, kept)], count)
    sample_firsts = np.cumsum([0] + [len(part.following) for part in rounds])
    triangle_firsts = np.cumsum([0] + [len(part.triangle_owner) for part in rounds])
    # Each merged item's source among the rounds' items put end to end, and each sample's place when merged.
    renumbered = np.full(sample_firsts[-1], -1, dtype=np.int64)
    sample_source = np.empty(sum(len(samples) for samples, _ in kept), dtype=np.int64)
    triangle_source = np.empty(sum(len(triangles) for _, triangles in kept), dtype=np.int64)
    for number, ((samples, triangles), sample_slot, triangle_slot) in enumerate(
        zip(kept, sample_slots, triangle_slots)
    ):
        renumbered[sample_firsts[number] + samples] = sample_slot
        sample_source[sample_slot] = sample_firsts[number] + samples
        triangle_source[triangle_slot] = triangle_firsts[number] + triangles

    def merged(parts, source):
        return np.take(np.concatenate(parts), source, axis=0)

    corner_ids = [part.corner_ids + first for part, first in zip(rounds, sample_firsts)]
    following = [part.following + first for part, first in zip(rounds, sample_firsts)]
    return (
        merged([part.points for part in rounds], sample_source),
        renumbered[merged(corner_ids, triangle_source)],
        renumbered[merged(following, sample_source)],
        merged([part.triangle_owner for part in rounds], triangle_source),
    )


def _slots(owners, count):
    """Return the place of each item when the items of all parts are put polygon after polygon.

    ``owners`` holds each part's (non-decreasing) polygon of each item; a polygon's items are all in one part
    and keep their order.
    """
    sizes = sum(np.bincount(owner, minlength=count) for owner in owners)
    firsts = np.cumsum(sizes) - sizes
    return [firsts[owner] + ranges(np.bincount(owner, minlength=count))[1] for owner in owners]


def _boundary_sample_arrays(polygons):
    """Return the samples of :func:`boundary_samples` of many polygons as flat arrays.

    Returns
    -------
    samples : ndarray of shape (n, 2)
        Every ring's samples without its closing point, polygon after polygon, exterior (counter-clockwise)
        then holes (clockwise), CRS units.
    ring, owner : ndarray of shape (n,) of int
        Ring (numbered over all polygons) and polygon of each sample.
    steps : ndarray of shape (p,)
        Densification step of each polygon, CRS units.
    """
    polygons = np.asarray(polygons, dtype=object)
    widths = typical_width(shapely.area(polygons), shapely.length(polygons) / 2.0)
    tolerance = SIMPLIFY_FRACTION * widths
    simplified = shapely.simplify(polygons, tolerance, preserve_topology=False)
    # GEOS repairs a self-crossing result (its buffer by 0), which may leave several polygons or none.
    bad = shapely.get_type_id(simplified) != 3
    if np.any(bad):
        simplified[bad] = shapely.simplify(polygons[bad], tolerance[bad], preserve_topology=True)
    simplified = counterclockwise(simplified)
    steps = np.maximum(widths / SAMPLES_PER_WIDTH, shapely.length(simplified) / MAX_SAMPLES)
    rings, ring_owner = shapely.get_rings(simplified, return_index=True)
    samples, ring = _densified(*shapely.get_coordinates(rings, return_index=True), steps[ring_owner])
    return samples, ring, ring_owner[ring], steps


def _densified(coordinates, ring, steps):
    """Return closed rings' vertices with every segment split into ``ceil(length / step)`` equal pieces, each
    ring without its closing vertex, and the ring of each (the points GEOS 3.14's ``segmentize`` gives, computed
    as it computes them; a segment of no length adds nothing).

    Parameters
    ----------
    coordinates : ndarray of shape (n, 2)
        The rings' vertices, ring after ring, each ring closed, CRS units.
    ring : ndarray of shape (n,) of int
        Ring of each vertex (non-decreasing).
    steps : ndarray
        Largest piece of each ring, CRS units.

    Returns
    -------
    samples : ndarray of shape (m, 2)
        CRS units.
    ring : ndarray of shape (m,) of int
        Ring of each sample.
    """
    delta = coordinates[1:] - coordinates[:-1]
    length = np.sqrt(delta[:, 0] * delta[:, 0] + delta[:, 1] * delta[:, 1])
    within = (ring[1:] == ring[:-1]) & (length > 0.0)
    pieces = np.where(within, np.maximum(np.ceil(length / steps[ring[:-1]]), 1.0), 0.0).astype(np.int64)
    segment, rank = ranges(pieces)
    piece = length / np.maximum(pieces, 1)
    fraction = rank * piece[segment] / np.where(within, length, 1.0)[segment]
    return coordinates[segment] + fraction[:, None] * delta[segment], ring[segment]


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
    samples, ring, _, steps = _boundary_sample_arrays([polygon])
    return np.split(samples, np.flatnonzero(ring[1:] != ring[:-1]) + 1), float(steps[0])


def _following(ring):
    """Return the index of the next sample on the same ring, for each sample (rings are consecutive runs)."""
    index = np.arange(len(ring))
    last = np.append(ring[1:] != ring[:-1], True)
    first = np.flatnonzero(np.insert(ring[1:] != ring[:-1], 0, True))
    return np.where(last, first[np.cumsum(np.insert(ring[1:] != ring[:-1], 0, True)) - 1], index + 1)


def _split_samples(samples, ring, owner, following, split, keep):
    """Keep the samples flagged ``keep`` and insert the midpoint of every flagged segment after its start.

    Every segment flagged ``split`` starts at a sample flagged ``keep``.
    """
    where = np.flatnonzero(split)
    middles = 0.5 * (samples[where] + samples[following[where]])
    kept = np.flatnonzero(keep)
    after = np.searchsorted(kept, where) + 1
    return (
        np.insert(rows(samples, kept), after, middles, axis=0),
        np.insert(ring[kept], after, ring[where]),
        np.insert(owner[kept], after, owner[where]),
    )


def _delaunay_all(samples, owner, local, steps, count):
    """Return the Delaunay triangles of each polygon's (slightly displaced) samples, one GEOS call for all.

    Parameters
    ----------
    samples : ndarray of shape (n, 2)
        Points, CRS units, polygon after polygon.
    owner, local : ndarray of shape (n,) of int
        Polygon of each sample, and its index among that polygon's samples (sets its jitter).
    steps : ndarray of shape (count,)
        Sampling step of each polygon, CRS units (scale of the displacement, see ``JITTER``).
    count : int
        Number of polygons.

    Returns
    -------
    moved : ndarray of shape (n, 2)
        The displaced samples that were triangulated (in the samples' frame), CRS units.
    corner_ids : ndarray of shape (t, 3) of int
        Index in ``samples`` of each corner (read from its z; one of them for a repeated point), triangles
        polygon after polygon.
    triangle_owner : ndarray of shape (t,) of int
    failed : ndarray of shape (count,) of bool
        Polygons whose samples GEOS could not triangulate with any displacement.
    """
    pattern = _jitter_pattern(local)
    cosine, sine = _insertion_rotations(samples, owner, count)
    waiting = np.bincount(owner, minlength=count) > 0
    triangles = np.full(count, None, dtype=object)
    moved_all = samples.copy()
    for jitter in JITTER:
        mask = waiting[owner]
        if not np.any(mask):
            break
        moved = samples[mask] + jitter * steps[owner[mask], None] * pattern[mask]
        turned = _turned(moved, cosine[owner[mask]], sine[owner[mask]])
        polygons, sizes = _distinct_runs(owner[mask])
        found = _each_delaunay(_point_runs(turned, np.flatnonzero(mask), sizes))
        success = np.zeros(count, dtype=bool)
        success[polygons] = [item is not None for item in found]
        triangles[polygons[success[polygons]]] = [item for item in found if item is not None]
        took = success[owner[mask]]
        put_rows(moved_all, np.flatnonzero(mask)[took], moved[took])
        waiting &= ~success
    made = np.flatnonzero(~shapely.is_missing(triangles))
    coordinates = shapely.get_coordinates(triangles[made], include_z=True)
    triangle_owner = np.repeat(made, shapely.get_num_geometries(triangles[made]))
    corner_ids = coordinates[:, 2].reshape(-1, 4)[:, :3].astype(np.int64)
    return moved_all, corner_ids, triangle_owner, waiting


def _distinct_runs(values):
    """Return the distinct values of a sorted array and the length of each one's run."""
    starts = np.flatnonzero(np.insert(values[1:] != values[:-1], 0, True)) if len(values) else np.zeros(0, int)
    return values[starts], np.diff(np.append(starts, len(values)))


def _point_runs(points, ids, sizes):
    """Return one line per run of ``sizes`` consecutive points, each point carrying its id as its z.

    The Delaunay triangulation of a geometry is that of its distinct vertices (GEOS sorts them by x and y and
    drops repeated ones, whatever the geometry), and it keeps each input coordinate, z included, so a
    triangle's corners tell which points they are without a lookup. A line holds its vertices in one
    coordinate sequence where a multipoint holds one point geometry per vertex, which makes them cheaper to
    build (through WKB, ISO type with z), triangulate and free, for the same triangles (measured in
    docs/core-notes.md). Every run has at least two points (a polygon's boundary has three samples or more).
    """
    body = np.empty((len(points), 3))
    body[:, :2], body[:, 2] = points, ids
    header = np.zeros(len(sizes), dtype=[("order", "u1"), ("kind", "<u4"), ("count", "<u4")])
    header["order"], header["kind"], header["count"] = 1, 1002, sizes
    data, heads = body.tobytes(), header.tobytes()
    bounds = (np.append(0, np.cumsum(sizes)) * body.itemsize * 3).tolist()
    size = header.itemsize
    blobs = [heads[size * k : size * (k + 1)] + data[bounds[k] : bounds[k + 1]] for k in range(len(sizes))]
    return shapely.from_wkb(np.array(blobs, dtype=object))


def _each_delaunay(point_runs):
    """Return the Delaunay triangles of each run of points: one GEOS call, or one each (None where GEOS fails)."""
    try:
        return list(shapely.delaunay_triangles(point_runs))
    except shapely.errors.GEOSException:
        found = []
        for points in point_runs:
            try:
                found.append(shapely.delaunay_triangles(points))
            except shapely.errors.GEOSException:
                found.append(None)
        return found


def _insertion_rotations(samples, owner, count):
    """Return ``(cos, sin)`` per polygon of the rotation turning its samples' principal axis to ``SWEEP_ANGLE``.

    GEOS inserts the points sorted by x; sweeping across a long reach (many points of about the same x)
    is slow, up to quadratic on a thin strip across the x axis, while sweeping along the shape's principal
    axis keeps the front short. The triangulation itself does not depend on the rotation.
    """
    sizes = np.maximum(np.bincount(owner, minlength=count), 1)
    centred = samples - np.stack([np.bincount(owner, samples[:, k], count) / sizes for k in (0, 1)], axis=1)[owner]
    x, y = centred.T
    xx, yy, xy = (np.bincount(owner, product, count) for product in (x * x, y * y, x * y))
    angle = SWEEP_ANGLE - 0.5 * np.arctan2(2.0 * xy, xx - yy)
    return np.cos(angle), np.sin(angle)


def _turned(points, cosine, sine):
    """Return the points rotated by the angles of ``cosine`` and ``sine`` (one each)."""
    return np.stack([cosine * points[:, 0] - sine * points[:, 1], sine * points[:, 0] + cosine * points[:, 1]], axis=1)


def _jitter_pattern(index):
    """Return a fixed pseudo-random pattern of offsets in ``[-0.5, 0.5)**2`` for sample numbers ``index``
    (a Weyl sequence)."""
    index = np.asarray(index, dtype=float)[:, None]
    return np.modf(index * np.array([0.7548776662466927, 0.5698402909980532]) + 0.5)[0] - 0.5


def _dual_graph(corners, corner_ids, following, shapes):
    """Return the nodes, radii, spans and edges of the dual graph of the triangles inside the rings.

    ``shapes`` are the triangles' :func:`_triangle_shapes` (changed in place, as the corners are).

    Also returns the mask of the triangles kept (one node each, in order).

    Inside triangles are those whose counter-clockwise sides run along the boundary the way the (oriented)
    rings do, and every triangle reachable from them without crossing the boundary. Slivers (flat triangles
    of nearly collinear samples, whose orientation means nothing) take no part.
    """
    signed, side_lengths, solid = shapes
    clockwise = signed < 0.0
    corners[clockwise] = corners[clockwise][:, ::-1]
    corner_ids[clockwise] = corner_ids[clockwise][:, ::-1]
    # Reversed corners (c2, c1, c0) have the sides c2-c1, c1-c0, c0-c2: the old second, first and third.
    side_lengths[clockwise] = side_lengths[clockwise][:, [1, 0, 2]]
    double_area = np.abs(signed)
    side_start, side_end = _sides(corner_ids)
    forward = following[side_start] == side_end
    on_boundary = (forward | (following[side_end] == side_start)).reshape(-1, 3)
    first, second = _shared_sides(np.flatnonzero(~on_boundary.ravel()), side_start, side_end, len(following))
    linking = solid[first] & solid[second]
    forward_sides = forward.reshape(-1, 3)
    seeds = solid & (forward_sides[:, 0] | forward_sides[:, 1] | forward_sides[:, 2])
    inside = reached_from(seeds, first[linking], second[linking])
    renumbered = np.cumsum(inside) - 1
    both = linking & inside[first] & inside[second]
    edges = np.stack([renumbered[first[both]], renumbered[second[both]]], axis=1)
    corners, on_boundary, side_lengths = (
        np.compress(inside, part, axis=0) for part in (corners, on_boundary, side_lengths)
    )
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
    boundary_side = _row_largest(np.where(on_boundary, side_lengths, 0.0))
    across = boundary_side > 0.0
    spans[across] = np.minimum(spans[across], double_area[across] / boundary_side[across])
    return nodes, radii, spans, edges, inside


def _sides(corner_ids):
    """Return the first and second sample of each side of the triangles, three sides per triangle in order
    (from corner k to corner k + 1)."""
    return corner_ids.ravel(), corner_ids.take([1, 2, 0], axis=1).ravel()


def _triangle_shapes(corners):
    """Return each triangle's signed double area (positive counter-clockwise, CRS units squared), its side
    lengths (shape (t, 3), from corner k to corner k + 1, CRS units) and whether it is solid: not a sliver of
    nearly collinear samples (twice its area above ``SLIVER`` times its longest side squared)."""
    x, y = corners[:, :, 0], corners[:, :, 1]
    side_x, side_y = x[:, [1, 2, 0]] - x, y[:, [1, 2, 0]] - y
    signed = side_x[:, 0] * (y[:, 2] - y[:, 0]) - side_y[:, 0] * (x[:, 2] - x[:, 0])
    side_lengths = np.hypot(side_x, side_y)
    return signed, side_lengths, np.abs(signed) > SLIVER * _row_largest(side_lengths) ** 2


def _row_largest(values):
    """Return the largest of the three values in each row of ``values`` (shape (t, 3)), as ``np.max`` along the
    rows gives it (an order of magnitude faster on three columns)."""
    return np.maximum(np.maximum(values[:, 0], values[:, 1]), values[:, 2])


def _shared_sides(sides, side_start, side_end, count):
    """Return the pairs of triangles sharing one of the sides ``sides``, in the order of the sides' keys.

    Parameters
    ----------
    sides : ndarray of int
        Increasing indices of the sides to pair (``3 * triangle + k``): all sides with a given pair of
        samples, or none of them.
    side_start, side_end : ndarray of int
        Sample indices of all sides, three per triangle in order.
    count : int
        Number of samples.

    Returns
    -------
    first, second : ndarray of int
        The two triangles (the first one's side comes first).
    """
    keys = _edge_keys(side_start[sides], side_end[sides], count)
    order = stable_order(keys, count * count)
    shared = np.flatnonzero(keys[order][1:] == keys[order][:-1])
    return sides[order[shared]] // 3, sides[order[shared + 1]] // 3


def reached_from(seeds, first, second):
    """Return which nodes of a graph a path joins to a seed: the union of the seeds' connected components.

    The seeds spread one edge per round (two rounds for a river's triangles, each near a bank); a graph that
    needs more than ``SPREAD_ROUNDS`` rounds is labelled by :func:`connected_labels` instead.

    Parameters
    ----------
    seeds : ndarray of shape (count,) of bool
    first, second : ndarray of int
        End nodes of each edge.

    Returns
    -------
    ndarray of shape (count,) of bool
    """
    reached = seeds.copy()
    for _ in range(SPREAD_ROUNDS):
        spreading = reached[first] != reached[second]
        if not np.any(spreading):
            return reached
        reached[first[spreading]] = True
        reached[second[spreading]] = True
    labels = connected_labels(len(seeds), first, second)
    return np.isin(labels, labels[seeds])


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


def _edge_keys(first, second, count):
    """Return one integer per undirected edge between sample indices ``first`` and ``second``."""
    low = np.minimum(first, second).astype(np.int64)
    high = np.maximum(first, second).astype(np.int64)
    return low * count + high


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
