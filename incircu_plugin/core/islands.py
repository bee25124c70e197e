"""Islands without loops: join every hole of a polygon to one of the two boundary chains.

IncirCu needs exactly two chains. A polygon with islands (holes) has more boundary than that, so each island
is joined to one chain through a *slit*: a cut of negligible width from a point ``F`` of the chain (the
slit's foot) to a point ``Q`` of the island. The joined chain runs along its bank to ``F``, out along the
slit to ``Q``, once around the island back to ``Q``, back along the slit to ``F`` and on along its bank.
For the engine the island is then part of that chain, so:

* the narrow channel between the island and the chain it joined lies between two parts of the *same*
  chain; no incircle there touches the other chain without crossing its own, so the centerline does not
  enter it;
* the centerline passes through the channel between the island and the *other* chain, stays one line from
  end to end, never crosses the island, and every vertex's incircle is empty of the island too.

Rule (documented, deterministic):

1. Each island joins the chain it is nearer to (smallest distance between the island and the chain), so
   the centerline goes around it on the side of the wider channel. When both distances are equal within
   ``TIE_TOLERANCE`` of the extent, the island joins ``c1``.
2. The slit is the shortest of the candidate segments (from points along the island to the nearest point of
   the chain) which crosses no other island, neither
   chain (it only touches its own chain at ``F``) and no earlier slit. Candidates are the nearest chain
   points of every vertex of the island (its ring densified to ``1 / SLIT_CANDIDATES`` of its perimeter),
   tried shortest first; if none is free, the other chain is tried.
3. Islands are inserted in the order of their feet along the chain, so the chain stays ordered from its
   start to its end. The island is traversed so that the region stays on the same side as along the
   chain's bank (clockwise when the region is on the chain's left).

Each slit is a corridor ``SLIT_WIDTH`` of the extent wide (at least ``SLIT_ULPS`` units in the last place of
the coordinates): the chain leaves its bank just before ``F``, runs to the island just beside ``Q``, goes
around and comes back along the other side of the corridor. The chains therefore never touch themselves,
and each side of a slit belongs to one copy only, so the engine knows from which side an incircle touches
it. The returned chains have no zero-length segments.
"""

import heapq

import numpy as np
import shapely
from shapely.geometry import LinearRing, LineString, Polygon

from .chains import COINCIDENCE_TOLERANCE, extent_of, signed_area
from .errors import IncirCuError, InvalidGeometryError, format_point
from .polyline import cumulative_lengths

#: Relative tolerance (of the extent) under which an island is as near to ``c1`` as to ``c2``.
TIE_TOLERANCE = 1e-9

#: Width of a slit, relative to the extent: its two sides are this far apart, so the joined chain never
#: touches itself and every point of a side belongs to one copy only (the engine then knows from which side
#: an incircle touches the slit). Far below any real feature, far above rounding.
SLIT_WIDTH = 1e-11

#: Smallest slit width in units of the last place of the largest coordinate, so rounding cannot close it.
SLIT_ULPS = 64

#: Number of candidate slit starts spread along each island's ring (its vertices are always candidates).
SLIT_CANDIDATES = 256


def bridge_islands(c1, c2, holes):
    """Join each island to the chain it is nearer to through a slit of negligible width.

    See the module docstring for the rule.

    Parameters
    ----------
    c1, c2 : ndarray of shape (n, 2) or LineString
        The two boundary chains, running in the same direction (as :func:`~.chains.split_polygon` or
        :func:`~.chains.orient_bank_lines` return them), CRS units.
    holes : sequence of (ndarray of shape (m, 2), LinearRing or Polygon)
        The islands: rings (closed or not) or polygons (their exterior is used), CRS units. They must lie
        between the chains and not touch each other.

    Returns
    -------
    c1_bridged, c2_bridged : ndarray of shape (k, 2)
        The chains with their islands spliced in, CRS units; same start and end points as the input.

    Raises
    ------
    InvalidGeometryError
        If an island has fewer than 3 distinct points or non-finite coordinates.
    IncirCuError
        If an island cannot be reached from either chain without crossing another island or slit.

    Examples
    --------
    >>> import numpy as np
    >>> c1 = np.array([[0.0, 5.0], [0.0, 0.0], [100.0, 0.0], [100.0, 5.0]])
    >>> c2 = np.array([[0.0, 5.0], [0.0, 10.0], [100.0, 10.0], [100.0, 5.0]])
    >>> island = [(40.0, 2.0), (60.0, 2.0), (60.0, 4.0), (40.0, 4.0)]
    >>> bridged_a, bridged_b = bridge_islands(c1, c2, [island])
    >>> np.round(bridged_a[:6], 6).tolist()
    [[0.0, 5.0], [0.0, 0.0], [40.0, 0.0], [40.0, 2.0], [40.0, 4.0], [60.0, 4.0]]
    >>> len(bridged_b) == len(c2)
    True
    """
    chains = [_as_array(c1), _as_array(c2)]
    rings = [_island_ring(hole, index) for index, hole in enumerate(holes)]
    if not rings:
        return chains[0].copy(), chains[1].copy()
    extent = extent_of(*chains, *rings)
    everything = np.concatenate([*chains, *rings])
    largest = float(max(np.abs(everything).max(), 1.0))
    half_width = max(SLIT_WIDTH * extent, SLIT_ULPS * float(np.spacing(largest))) / 2.0
    # Work near the origin, where the tolerances below are many units in the last place.
    origin = 0.5 * (everything.min(axis=0) + everything.max(axis=0))
    chains = [chain - origin for chain in chains]
    rings = [ring - origin for ring in rings]
    merge = COINCIDENCE_TOLERANCE * extent
    tie = TIE_TOLERANCE * extent
    region_on_left = signed_area(np.concatenate([chains[0], chains[1][::-1]])) >= 0.0
    islands = np.array([Polygon(ring) for ring in rings], dtype=object)
    island_tree = shapely.STRtree(islands)
    count = len(rings)
    # Hosts: 0 and 1 are the chains, 2 + j is island j once it has joined.
    targets = [_Target(chains[0]), _Target(chains[1])] + [None] * count
    bank_distance = np.stack([target.distance_to(islands) for target in targets[:2]], axis=1)
    reach = float(bank_distance.min(axis=1).max()) + tie
    component = np.full(count + 2, -1)
    component[:2] = (0, 1)
    pairs = [(float(bank_distance[i, side]), side, side, i) for i in range(count) for side in (0, 1)]
    heapq.heapify(pairs)
    walks = [None] * count
    joins = [[] for _ in range(count + 2)]
    slits = []
    for _ in range(count):
        island_index, host, slit = _next_join(pairs, component, islands, island_tree, targets, slits, rings, tie, merge)
        island_point, foot, position = slit
        slits.append(LineString([island_point, foot]))
        component[2 + island_index] = component[host]
        clockwise = region_on_left if component[host] == 0 else not region_on_left
        walks[island_index] = _around(rings[island_index], island_point, clockwise, merge)
        targets[2 + island_index] = _Target(walks[island_index])
        joins[host].append((position, island_index, foot))
        near = island_tree.query(islands[island_index], predicate="dwithin", distance=reach)
        near = near[component[2 + near] < 0]
        for other, gap in zip(near.tolist(), shapely.distance(islands[near], islands[island_index]).tolist()):
            heapq.heappush(pairs, (gap, int(component[host]), 2 + island_index, other))
    detours = {}
    for island_index in _reverse_join_order(joins, count):
        trimmed = _trimmed(walks[island_index], half_width)
        length = float(cumulative_lengths(trimmed)[-1])
        children = [
            (min(max(position - half_width, 0.0), length), child, foot)
            for position, child, foot in joins[2 + island_index]
        ]
        detours[island_index] = _splice(trimmed, children, detours, half_width, merge)
    bridged = []
    for side, original in enumerate((c1, c2)):
        chain = _splice(chains[side], joins[side], detours, half_width, merge) + origin
        ends = _as_array(original)[[0, -1]]
        chain[0], chain[-1] = ends[0], ends[1]
        bridged.append(chain)
    return bridged[0], bridged[1]


class _Target:
    """A polyline a slit may end on (a chain, or the walk around a joined island), with a spatial index."""

    def __init__(self, coordinates):
        """Index the segments of ``coordinates`` (an (n, 2) array, CRS units)."""
        self.coordinates = coordinates
        self.starts = coordinates[:-1]
        self.directions = coordinates[1:] - coordinates[:-1]
        self.positions = np.concatenate([[0.0], np.cumsum(np.hypot(*self.directions.T))])
        self.segments = shapely.linestrings(np.stack([coordinates[:-1], coordinates[1:]], axis=1))
        self.tree = shapely.STRtree(self.segments)
        self.line = LineString(coordinates)
        shapely.prepare(self.line)

    def distance_to(self, geometries):
        """Return the distance, CRS units, from each geometry to the polyline."""
        return self.tree.query_nearest(geometries, return_distance=True, all_matches=False)[1]

    def nearest(self, points):
        """Return the nearest point of the polyline to each point and its arc length along the polyline.

        Parameters
        ----------
        points : ndarray of shape (m, 2)
            CRS units.

        Returns
        -------
        feet : ndarray of shape (m, 2)
        positions : ndarray of shape (m,)
            CRS units from the polyline's start.
        """
        segment = self.tree.query_nearest(shapely.points(points), all_matches=False)[1]
        direction = self.directions[segment]
        squared = np.einsum("ij,ij->i", direction, direction)
        along = np.einsum("ij,ij->i", points - self.starts[segment], direction) / np.where(squared > 0, squared, 1.0)
        along = np.clip(along, 0.0, 1.0)
        feet = self.starts[segment] + along[:, None] * direction
        return feet, self.positions[segment] + along * np.sqrt(squared)


def _next_join(pairs, component, islands, island_tree, targets, slits, rings, tie, merge):
    """Pick the next island to join, its host and its slit (the nearest free pair, ties to ``c1``).

    Parameters
    ----------
    pairs : list of (float, int, int, int)
        Heap of candidate pairs: distance (CRS units), chain of the host (0 or 1), host, island. Pairs whose
        every slit is blocked are dropped from it.
    component : ndarray of shape (k + 2,)
        Chain (0 or 1) each host belongs to, -1 for islands not yet joined.
    islands : ndarray of Polygon
        All islands.
    island_tree : STRtree
        Index of ``islands``.
    targets : list of _Target or None
        The chains, then the walk around each joined island.
    slits : list of LineString
        Slits made so far.
    rings : list of ndarray
        Closed rings of the islands, CRS units.
    tie : float
        Distance, CRS units, under which two pairs are equally near.
    merge : float
        Distance, CRS units, under which two points are the same.

    Returns
    -------
    island_index : int
    host : int
        0 or 1 for a chain, ``2 + j`` for island ``j``.
    slit : (ndarray of shape (2,), ndarray of shape (2,), float)
        The slit's point on the island, its foot on the host and the foot's arc length along the host.

    Raises
    ------
    IncirCuError
        If no island left can be joined without crossing something.
    """
    slit_tree = shapely.STRtree(slits) if slits else None
    while True:
        while pairs and component[2 + pairs[0][3]] >= 0:
            heapq.heappop(pairs)
        if not pairs:
            left = np.flatnonzero(component[2:] < 0)
            where = islands[left[0]].representative_point().coords[0]
            raise IncirCuError(
                f"The island at {format_point(where)} cannot be joined to a bank without crossing another island;"
                " use the option to ignore islands."
            )
        nearest = pairs[0][0]
        tied = []
        while pairs and pairs[0][0] <= nearest + tie:
            tied.append(heapq.heappop(pairs))
        tied.sort(key=lambda pair: (pair[1], pair[2], pair[3]))
        chosen = next(pair for pair in tied if component[2 + pair[3]] < 0)
        for pair in tied:
            if pair is not chosen:
                heapq.heappush(pairs, pair)
        _, _, host, island_index = chosen
        excluded = {island_index, host - 2}
        walls = [targets[side].line for side in (0, 1) if side != host]
        inside = islands[host - 2] if host >= 2 else None
        slit = _free_slit(
            rings[island_index],
            islands[island_index],
            targets[host],
            inside,
            island_tree,
            excluded,
            walls,
            slit_tree,
            merge,
        )
        if slit is not None:
            return island_index, host, slit


def _reverse_join_order(joins, count):
    """Return island indices so that every island comes after the islands joined to it."""
    order = []
    stack = [entry[1] for host in (0, 1) for entry in joins[host]]
    while stack:
        island_index = stack.pop()
        order.append(island_index)
        stack.extend(entry[1] for entry in joins[2 + island_index])
    return order[::-1]


def _as_array(chain):
    """Return a chain's vertices as a float array of shape (n, 2)."""
    if isinstance(chain, shapely.Geometry):
        return shapely.get_coordinates(chain).astype(float)
    return np.asarray(chain, dtype=float)[:, :2].copy()


def _island_ring(hole, index):
    """Return an island's ring as a closed (m + 1, 2) array without zero-length segments.

    Parameters
    ----------
    hole : ndarray of shape (m, 2), LinearRing or Polygon
        The island, CRS units.
    index : int
        Its position in the input (for messages).

    Returns
    -------
    ndarray of shape (m + 1, 2)
        First vertex repeated at the end.
    """
    if isinstance(hole, Polygon):
        hole = hole.exterior
    if isinstance(hole, shapely.Geometry):
        coordinates = shapely.get_coordinates(hole)
    else:
        coordinates = np.asarray(hole, dtype=float)[:, :2]
    if len(coordinates) == 0 or not np.all(np.isfinite(coordinates)):
        raise InvalidGeometryError(f"Island {index} is empty or has a NaN or infinite coordinate.")
    if np.array_equal(coordinates[0], coordinates[-1]):
        coordinates = coordinates[:-1]
    step = np.hypot(*np.diff(np.concatenate([coordinates, coordinates[:1]]), axis=0).T)
    coordinates = coordinates[step > 0.0]
    if len(coordinates) < 3:
        raise InvalidGeometryError(f"Island {index} has fewer than 3 distinct points.")
    return np.concatenate([coordinates, coordinates[:1]])


def _free_slit(ring, island, target, inside, island_tree, excluded, walls, slit_tree, merge):
    """Return the shortest free slit from an island to its host, or None.

    Parameters
    ----------
    ring : ndarray of shape (m + 1, 2)
        The island's closed ring, CRS units.
    island : Polygon
        The island.
    target : _Target
        Where the slit may end: the host chain, or the walk around the host island.
    inside : Polygon or None
        The host island, whose inside the slit must not enter; None for a chain.
    island_tree : STRtree
        Index of all islands; the slit must touch none but those in ``excluded``.
    excluded : set of int
        The island itself and the host island.
    walls : list of LineString
        Chains the slit must not touch (the other chain; both for an island host).
    slit_tree : STRtree or None
        Earlier slits, which the slit must not touch.
    merge : float
        Distance, CRS units, under which two points are the same.

    Returns
    -------
    (ndarray of shape (2,), ndarray of shape (2,), float) or None
        The slit's point ``Q`` on the island, its foot ``F`` on the host and ``F``'s arc length along the
        host.
    """
    outline = LinearRing(ring)
    starts = shapely.get_coordinates(shapely.segmentize(outline, outline.length / SLIT_CANDIDATES))[:-1]
    feet, positions = target.nearest(starts)
    lengths = np.hypot(*(feet - starts).T)
    order = np.argsort(lengths, kind="stable")
    starts, feet, positions, lengths = starts[order], feet[order], positions[order], lengths[order]
    # The shortest slit is usually free: test it alone first, then all the others at once.
    for batch in (slice(0, 1), slice(1, None)):
        free = _free_candidates(
            starts[batch],
            feet[batch],
            lengths[batch],
            island,
            target,
            inside,
            island_tree,
            excluded,
            walls,
            slit_tree,
            merge,
        )
        if len(free):
            chosen = batch.start + int(free[0])
            return starts[chosen], feet[chosen], float(positions[chosen])
    return None


def _free_candidates(starts, feet, lengths, island, target, inside, island_tree, excluded, walls, slit_tree, merge):
    """Return the indices of the candidate slits that touch nothing they must not (see :func:`_free_slit`)."""
    long_enough = lengths > 2.0 * merge
    direction = np.zeros_like(starts)
    direction[long_enough] = (feet - starts)[long_enough] / lengths[long_enough, None]
    inner = shapely.linestrings(np.stack([starts + merge * direction, feet - merge * direction], axis=1))
    blocked = shapely.intersects(inner, island) | shapely.intersects(inner, target.line)
    if inside is not None:
        blocked |= shapely.intersects(inner, inside)
    blocked &= long_enough
    whole = shapely.linestrings(np.stack([starts, feet], axis=1))
    whole[~long_enough] = shapely.points(feet[~long_enough])
    candidate, hit = island_tree.query(whole, predicate="intersects")
    other = ~np.isin(hit, list(excluded))
    blocked[candidate[other]] = True
    for wall in walls:
        blocked |= shapely.intersects(whole, wall)
    if slit_tree is not None:
        blocked[slit_tree.query(whole, predicate="intersects")[0]] = True
    return np.flatnonzero(~blocked)


def _splice(path, joins, detours, half_width, merge):
    """Insert island detours into a path (a chain or the walk around an island) at their slit feet.

    Each slit is a corridor ``2 * half_width`` wide: the path leaves itself ``half_width`` before the foot
    ``F`` (arc length), follows the detour, and comes back ``half_width`` after ``F``.

    Parameters
    ----------
    path : ndarray of shape (n, 2)
        The chain or walk, CRS units.
    joins : list of (float, int, ndarray)
        For each island joined to this path: its foot's arc length along the path, the island's index and
        the foot ``F``.
    detours : dict of int to ndarray
        For each island, its walk from ``Q`` around (with its own islands spliced in) back to ``Q``, trimmed
        by ``half_width`` at both ends.
    half_width : float
        Half the width of a slit, CRS units.
    merge : float
        Distance, CRS units, under which two points are the same.

    Returns
    -------
    ndarray of shape (k, 2)
        Without zero-length segments.
    """
    if not joins:
        return path.copy()
    positions = cumulative_lengths(path)
    pieces = []
    done = 0
    for position, island_index, _ in sorted(joins, key=lambda join: (join[0], join[1])):
        leave = min(max(position - half_width, positions[0]), positions[-1])
        back = min(max(position + half_width, leave), positions[-1])
        before = max(int(np.searchsorted(positions, leave, side="left")), done)
        pieces.append(path[done:before])
        pieces.append(
            np.concatenate(
                [_point_at(path, positions, leave)[None], detours[island_index], _point_at(path, positions, back)[None]]
            )
        )
        done = max(int(np.searchsorted(positions, back, side="right")), done)
    pieces.append(path[done:])
    joined = np.concatenate(pieces)
    step = np.hypot(*np.diff(joined, axis=0).T)
    return joined[np.concatenate([[True], step > merge])]


def _trimmed(walk, half_width):
    """Return a closed walk without its first and last ``half_width`` of arc length (the slit's two sides)."""
    positions = cumulative_lengths(walk)
    total = positions[-1]
    if total <= 2.0 * half_width:
        return walk.copy()
    keep = (positions > half_width) & (positions < total - half_width)
    return np.concatenate(
        [
            _point_at(walk, positions, half_width)[None],
            walk[keep],
            _point_at(walk, positions, total - half_width)[None],
        ]
    )


def _point_at(path, positions, at):
    """Return the point at arc length ``at`` of a polyline whose vertices are at ``positions``."""
    index = int(np.clip(np.searchsorted(positions, at, side="right") - 1, 0, len(path) - 2))
    span = positions[index + 1] - positions[index]
    fraction = 0.0 if span <= 0.0 else min(max((at - positions[index]) / span, 0.0), 1.0)
    return path[index] + fraction * (path[index + 1] - path[index])


def _around(ring, start, clockwise, merge):
    """Return an island's ring as a closed walk from ``start`` back to ``start`` in the asked direction.

    Parameters
    ----------
    ring : ndarray of shape (m + 1, 2)
        Closed ring of the island, CRS units.
    start : ndarray of shape (2,)
        A point on the ring (the slit's end ``Q``).
    clockwise : bool
        Direction of the walk.
    merge : float
        Distance, CRS units, under which ``start`` is an existing vertex.

    Returns
    -------
    ndarray of shape (p, 2)
        First and last rows equal ``start``.
    """
    if (signed_area(ring) < 0.0) != clockwise:
        ring = ring[::-1]
    loop = ring[:-1]
    line = LinearRing(ring)
    position = line.project(shapely.points(start))
    edges = np.hypot(*np.diff(ring, axis=0).T)
    cumulative = np.concatenate([[0.0], np.cumsum(edges)])
    nearest = int(np.argmin(np.hypot(*(loop - start).T)))
    if np.hypot(*(loop[nearest] - start)) <= merge:
        rolled = np.roll(loop, -nearest, axis=0)
        return np.concatenate([rolled, rolled[:1]])
    edge = int(np.clip(np.searchsorted(cumulative, position, side="right") - 1, 0, len(loop) - 1))
    rolled = np.roll(loop, -(edge + 1), axis=0)
    return np.concatenate([start[None], rolled, start[None]])
