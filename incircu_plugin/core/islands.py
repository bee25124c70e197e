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
from dataclasses import dataclass, field
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import LinearRing, LineString, Polygon

from .chains import COINCIDENCE_TOLERANCE, extent_of, signed_area
from .errors import IncirCuError, InvalidGeometryError, Message, format_point
from .polyline import IndexedPolyline, as_coordinates, cumulative_lengths, local_origin, points_at

#: Relative tolerance (of the extent) under which an island is as near to ``c1`` as to ``c2``.
BANK_TIE_TOLERANCE = 1e-9

#: Width of a slit, relative to the extent: its two sides are this far apart, so the joined chain never
#: touches itself and every point of a side belongs to one copy only (the engine then knows from which side
#: an incircle touches the slit). Far below any real feature, far above rounding.
SLIT_WIDTH = 1e-11

#: Smallest slit width in units of the last place of the largest coordinate, so rounding cannot close it.
SLIT_ULPS = 64

#: Number of candidate slit starts spread along each island's ring (its vertices are always candidates).
SLIT_CANDIDATES = 256


def bridge_islands(c1, c2, holes, to_second=None):
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
    to_second : sequence of bool, optional
        Per island, True to join it to ``c2`` (directly or through other islands joined to ``c2``) whichever
        chain is nearer (the networks' channel islands, see :func:`.network.polygon_network`).

    Returns
    -------
    c1_bridged, c2_bridged : ndarray of shape (k, 2)
        The chains with their islands spliced in, CRS units; same start and end points as the input.

    Raises
    ------
    InvalidGeometryError
        If a chain is empty or not finite, or an island has fewer than 3 distinct points or non-finite
        coordinates.
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
    chains = [as_coordinates(c1, "first chain"), as_coordinates(c2, "second chain")]
    rings = [_island_ring(hole, index) for index, hole in enumerate(holes)]
    if not rings:
        return chains[0].copy(), chains[1].copy()
    # Work near the origin, where the tolerances below are many units in the last place.
    origin = local_origin(*chains, *rings)
    islands = _Islands.near_origin(chains, rings, origin)
    local = [chain - origin for chain in chains]
    joining = _join_all(local, islands, [False] * len(rings) if to_second is None else list(to_second))
    detours = _detours(joining, islands)
    bridged = []
    for side, original in enumerate(chains):
        chain = _splice(local[side], joining.joins[side], detours, islands.half_width, islands.coincidence) + origin
        chain[0], chain[-1] = original[0], original[-1]
        bridged.append(chain)
    return bridged[0], bridged[1]


@dataclass(frozen=True)
class _Islands:
    """The islands of one region, shifted near the origin, and the distances every slit is built with.

    Attributes
    ----------
    rings : list of ndarray of shape (m + 1, 2)
        Closed ring of each island, CRS units.
    polygons : ndarray of Polygon
        Each island as a polygon.
    tree : STRtree
        Index of ``polygons``.
    tie : float
        Distance, CRS units, under which two candidate pairs are equally near.
    coincidence : float
        Distance, CRS units, under which two points are the same.
    half_width : float
        Half the width of a slit, CRS units.
    """

    rings: list
    polygons: np.ndarray
    tree: shapely.STRtree
    tie: float
    coincidence: float
    half_width: float

    @classmethod
    def near_origin(cls, chains, rings, origin):
        """Shift the island rings by ``-origin`` and size the tolerances from the chains and the rings."""
        extent = extent_of(*chains, *rings)
        largest = float(max(max(np.abs(part).max() for part in (*chains, *rings)), 1.0))
        half_width = max(SLIT_WIDTH * extent, SLIT_ULPS * float(np.spacing(largest))) / 2.0
        rings = [ring - origin for ring in rings]
        polygons = np.array([Polygon(ring) for ring in rings], dtype=object)
        return cls(
            rings=rings,
            polygons=polygons,
            tree=shapely.STRtree(polygons),
            tie=BANK_TIE_TOLERANCE * extent,
            coincidence=COINCIDENCE_TOLERANCE * extent,
            half_width=half_width,
        )


class _Target(IndexedPolyline):
    """A polyline a slit may end on (a chain, or the walk around a joined island): indexed, with its line."""

    def __init__(self, coordinates):
        """Index the segments of ``coordinates`` (an (n, 2) array, CRS units) and make the line."""
        super().__init__(coordinates)
        self.line = LineString(self.xy)


@dataclass(frozen=True)
class _Slit:
    """A slit: its point ``Q`` on the island, its foot ``F`` on the host and ``F``'s arc length (CRS units)."""

    island_point: np.ndarray
    foot: np.ndarray
    position: float


@dataclass
class _Joining:
    """The state of joining the islands one by one.

    Hosts are numbered 0 and 1 for the chains and ``2 + j`` for island ``j`` once it has joined.

    Attributes
    ----------
    pairs : list of (float, int, int, int)
        Heap of candidate pairs: distance (CRS units), chain of the host (0 or 1), host, island. Pairs whose
        every slit is blocked are dropped from it.
    component : ndarray of shape (k + 2,)
        Chain (0 or 1) each host belongs to, -1 for islands not yet joined.
    targets : list of _Target or None
        Per host, the polyline a slit to it may end on; for an island, None until :meth:`target` first needs it
        (most islands host no other).
    slits : list of LineString
        Slits made so far, but the last island's (no island is left for it to block).
    walks : list of ndarray or None
        Per island, its closed walk from ``Q`` around back to ``Q``.
    joins : list of list of (float, int, ndarray)
        Per host, the islands joined to it: foot's arc length along the host, island index, foot.
    """

    pairs: list
    component: np.ndarray
    targets: list
    slits: list = field(default_factory=list)
    walks: list = field(default_factory=list)
    joins: list = field(default_factory=list)

    def target(self, host):
        """The polyline a slit to ``host`` may end on (:class:`_Target`), an island's built on first use."""
        if self.targets[host] is None:
            self.targets[host] = _Target(self.walks[host - 2])
        return self.targets[host]


@dataclass(frozen=True)
class _SlitSearch:
    """One island to join to one host: where its slit may end and what it must not touch.

    Attributes
    ----------
    island : int
        Index of the island.
    gap : float
        Distance between the island and its host, CRS units.
    target : _Target
        Where the slit may end: the host chain, or the walk around the host island.
    inside : Polygon or None
        The host island, whose inside the slit must not enter; None for a chain.
    excluded : frozenset of int
        Islands the slit may touch: the island itself and the host island.
    walls : list of LineString
        Chains the slit must not touch (the other chain; both for an island host).
    slit_tree : STRtree or None
        Earlier slits, which the slit must not touch.
    """

    island: int
    gap: float
    target: _Target
    inside: Optional[Polygon]
    excluded: frozenset
    walls: list
    slit_tree: Optional[shapely.STRtree]


def _join_all(chains, islands, to_second):
    """Join every island to a host, nearest free pair first (see the module docstring).

    Parameters
    ----------
    chains : list of two ndarray of shape (n, 2)
        The chains, shifted like the islands, CRS units.
    islands : _Islands
    to_second : list of bool
        Per island, whether it must end up joined to the second chain.

    Returns
    -------
    _Joining
        With every island's walk and every host's joins filled in.
    """
    count = len(islands.rings)
    region_on_left = signed_area(np.concatenate([chains[0], chains[1][::-1]])) >= 0.0
    targets = [_Target(chains[0]), _Target(chains[1])] + [None] * count
    bank_distance = np.stack([target.distance_to(islands.polygons) for target in targets[:2]], axis=1)
    reach = float(bank_distance.min(axis=1).max()) + islands.tie
    pairs = [
        (float(bank_distance[i, side]), side, side, i)
        for i in range(count)
        for side in (0, 1)
        if side == 1 or not to_second[i]
    ]
    heapq.heapify(pairs)
    component = np.full(count + 2, -1)
    component[:2] = (0, 1)
    joining = _Joining(pairs, component, targets, walks=[None] * count, joins=[[] for _ in range(count + 2)])
    for joined in range(count):
        island, host, slit = _next_join(joining, islands)
        component[2 + island] = component[host]
        clockwise = region_on_left if component[host] == 0 else not region_on_left
        joining.walks[island] = _around(islands.rings[island], slit.island_point, clockwise, islands.coincidence)
        joining.joins[host].append((slit.position, island, slit.foot))
        if joined == count - 1:
            break  # No island is left for this slit to block or this island to host.
        joining.slits.append(LineString([slit.island_point, slit.foot]))
        polygon = islands.polygons[island]
        near = islands.tree.query(polygon, predicate="dwithin", distance=reach)
        near = near[component[2 + near] < 0]
        for other, gap in zip(near.tolist(), shapely.distance(islands.polygons[near], polygon).tolist()):
            if component[host] == 1 or not to_second[other]:
                heapq.heappush(joining.pairs, (gap, int(component[host]), 2 + island, other))
    return joining


def _detours(joining, islands):
    """Return each island's walk, trimmed by the slit's half width, with its own islands spliced in.

    Parameters
    ----------
    joining : _Joining
        After :func:`_join_all`.
    islands : _Islands

    Returns
    -------
    dict of int to ndarray
        Per island, its detour from beside ``Q`` around back to beside ``Q``, CRS units.
    """
    detours = {}
    half_width = islands.half_width
    for island in _reverse_join_order(joining.joins, len(islands.rings)):
        trimmed = _trimmed(joining.walks[island], half_width)
        length = float(cumulative_lengths(trimmed)[-1])
        children = [
            (min(max(position - half_width, 0.0), length), child, foot)
            for position, child, foot in joining.joins[2 + island]
        ]
        detours[island] = _splice(trimmed, children, detours, half_width, islands.coincidence)
    return detours


def _next_join(joining, islands):
    """Pick the next island to join, its host and its slit (the nearest free pair, ties to ``c1``).

    Parameters
    ----------
    joining : _Joining
        The state so far; blocked pairs are dropped from ``joining.pairs``.
    islands : _Islands

    Returns
    -------
    island : int
    host : int
        0 or 1 for a chain, ``2 + j`` for island ``j``.
    slit : _Slit

    Raises
    ------
    IncirCuError
        If no island left can be joined without crossing something.
    """
    pairs, component = joining.pairs, joining.component
    slit_tree = shapely.STRtree(joining.slits) if joining.slits else None
    while True:
        while pairs and component[2 + pairs[0][3]] >= 0:
            heapq.heappop(pairs)
        if not pairs:
            left = np.flatnonzero(component[2:] < 0)
            where = islands.polygons[left[0]].representative_point().coords[0]
            raise IncirCuError(Message("island_blocked", point=format_point(where)))
        gap, _, host, island = _pop_nearest_pair(pairs, component, islands.tie)
        search = _SlitSearch(
            island=island,
            gap=gap,
            target=joining.target(host),
            inside=islands.polygons[host - 2] if host >= 2 else None,
            excluded=frozenset({island, host - 2}),
            walls=[joining.targets[side].line for side in (0, 1) if side != host],
            slit_tree=slit_tree,
        )
        slit = _free_slit(search, islands)
        if slit is not None:
            return island, host, slit


def _pop_nearest_pair(pairs, component, tie):
    """Pop the nearest pair of an island not joined yet; among pairs within ``tie`` of it, ``c1``'s first."""
    nearest = pairs[0][0]
    tied = []
    while pairs and pairs[0][0] <= nearest + tie:
        tied.append(heapq.heappop(pairs))
    tied.sort(key=lambda pair: (pair[1], pair[2], pair[3]))
    chosen = next(pair for pair in tied if component[2 + pair[3]] < 0)
    for pair in tied:
        if pair is not chosen:
            heapq.heappush(pairs, pair)
    return chosen


def _reverse_join_order(joins, count):
    """Return island indices so that every island comes after the islands joined to it."""
    order = []
    stack = [entry[1] for host in (0, 1) for entry in joins[host]]
    while stack:
        island_index = stack.pop()
        order.append(island_index)
        stack.extend(entry[1] for entry in joins[2 + island_index])
    return order[::-1]


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
        raise InvalidGeometryError(Message("island_not_finite", index=index))
    if np.array_equal(coordinates[0], coordinates[-1]):
        coordinates = coordinates[:-1]
    step = np.hypot(*np.diff(np.concatenate([coordinates, coordinates[:1]]), axis=0).T)
    coordinates = coordinates[step > 0.0]
    if len(coordinates) < 3:
        raise InvalidGeometryError(Message("island_too_few_points", index=index))
    return np.concatenate([coordinates, coordinates[:1]])


def _free_slit(search, islands):
    """Return the shortest free slit from an island to its host, or None.

    Candidates start at the vertices of the island's ring densified to ``1 / SLIT_CANDIDATES`` of its
    perimeter and end at their nearest points on the host; they are tried shortest first.

    Parameters
    ----------
    search : _SlitSearch
        The island, its host and what the slit must not touch.
    islands : _Islands

    Returns
    -------
    _Slit or None
    """
    outline = LinearRing(islands.rings[search.island])
    spacing = outline.length / SLIT_CANDIDATES
    starts = shapely.get_coordinates(shapely.segmentize(outline, spacing))[:-1]
    # The shortest slit is usually free: find and test it alone first, then all the others at once. The island's
    # nearest point to the host is at most half a spacing from a start, so the shortest is within this hint.
    shortest, length, position, foot = search.target.closest(starts, within=search.gap + 0.5 * spacing)
    if len(_free_candidates(search, islands, starts[shortest : shortest + 1], foot[None], np.array([length]))):
        return _Slit(island_point=starts[shortest], foot=foot, position=position)
    lengths, positions, feet = search.target.nearest(starts)
    # The others, shortest first (a stable sort: the same order as ties were broken in).
    order = np.argsort(lengths, kind="stable")
    order = order[order != shortest]
    free = _free_candidates(search, islands, starts[order], feet[order], lengths[order])
    if len(free):
        chosen = order[int(free[0])]
        return _Slit(island_point=starts[chosen], foot=feet[chosen], position=float(positions[chosen]))
    return None


def _free_candidates(search, islands, starts, feet, lengths):
    """Return the indices of the candidate slits that touch nothing they must not.

    Parameters
    ----------
    search : _SlitSearch
    islands : _Islands
    starts, feet : ndarray of shape (m, 2)
        Each candidate's point on the island and its foot on the host, CRS units.
    lengths : ndarray of shape (m,)
        Each candidate's length, CRS units.

    Returns
    -------
    ndarray of int
        Increasing indices into the candidates.
    """
    coincidence = islands.coincidence
    long_enough = lengths > 2.0 * coincidence
    direction = np.zeros_like(starts)
    direction[long_enough] = (feet - starts)[long_enough] / lengths[long_enough, None]
    inner = shapely.linestrings(np.stack([starts + coincidence * direction, feet - coincidence * direction], axis=1))
    blocked = shapely.intersects(inner, islands.polygons[search.island]) | shapely.intersects(inner, search.target.line)
    if search.inside is not None:
        blocked |= shapely.intersects(inner, search.inside)
    blocked &= long_enough
    whole = shapely.linestrings(np.stack([starts, feet], axis=1))
    whole[~long_enough] = shapely.points(feet[~long_enough])
    candidate, hit = islands.tree.query(whole, predicate="intersects")
    other = np.ones(len(hit), dtype=bool)
    for excluded in search.excluded:
        other &= hit != excluded
    blocked[candidate[other]] = True
    for wall in search.walls:
        blocked |= shapely.intersects(whole, wall)
    if search.slit_tree is not None:
        blocked[search.slit_tree.query(whole, predicate="intersects")[0]] = True
    return np.flatnonzero(~blocked)


def _splice(path, joins, detours, half_width, coincidence):
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
    coincidence : float
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
        leave_point, back_point = points_at(path, positions, np.array([leave, back]))
        pieces.append(np.concatenate([leave_point[None], detours[island_index], back_point[None]]))
        done = max(int(np.searchsorted(positions, back, side="right")), done)
    pieces.append(path[done:])
    joined = np.concatenate(pieces)
    step = np.hypot(*np.diff(joined, axis=0).T)
    return joined[np.concatenate([[True], step > coincidence])]


def _trimmed(walk, half_width):
    """Return a closed walk without its first and last ``half_width`` of arc length (the slit's two sides)."""
    positions = cumulative_lengths(walk)
    total = positions[-1]
    if total <= 2.0 * half_width:
        return walk.copy()
    keep = (positions > half_width) & (positions < total - half_width)
    start, end = points_at(walk, positions, np.array([half_width, total - half_width]))
    return np.concatenate([start[None], walk[keep], end[None]])


def _around(ring, start, clockwise, coincidence):
    """Return an island's ring as a closed walk from ``start`` back to ``start`` in the asked direction.

    Parameters
    ----------
    ring : ndarray of shape (m + 1, 2)
        Closed ring of the island, CRS units.
    start : ndarray of shape (2,)
        A point on the ring (the slit's end ``Q``).
    clockwise : bool
        Direction of the walk.
    coincidence : float
        Distance, CRS units, under which ``start`` is an existing vertex.

    Returns
    -------
    ndarray of shape (p, 2)
        First and last rows equal ``start``.
    """
    if (signed_area(ring) < 0.0) != clockwise:
        ring = ring[::-1]
    loop = ring[:-1]
    nearest = int(np.argmin(np.hypot(*(loop - start).T)))
    if np.hypot(*(loop[nearest] - start)) <= coincidence:
        rolled = np.roll(loop, -nearest, axis=0)
        return np.concatenate([rolled, rolled[:1]])
    position = LinearRing(ring).project(shapely.points(start))
    cumulative = cumulative_lengths(ring)
    edge = int(np.clip(np.searchsorted(cumulative, position, side="right") - 1, 0, len(loop) - 1))
    rolled = np.roll(loop, -(edge + 1), axis=0)
    return np.concatenate([start[None], rolled, start[None]])
