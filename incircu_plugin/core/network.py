"""Networks: the medial axis between three or more boundary chains of one polygon (a confluence, a junction).

``k >= 2`` split points on the exterior ring cut it into ``k`` chains ``C_0 .. C_{k-1}`` (counter-clockwise,
``C_m`` from split point ``p_m`` to ``p_{m+1}``). The *network* is the part of the medial axis whose
incircles touch two different chains: a tree whose ``k`` leaves are the split points, whose *junctions* are
the centres of incircles touching three chains, and whose *branches* each separate two chains.

Without split points (or with one) the ends are those of the polygon's arms (:mod:`.arms`); gates shared
with touching polygons (:mod:`.touching`) are ends too.

Method (only the engine's public :func:`centerline_from_chains` and step generators):

1. Because the ring is cyclic, the complement of ``C_i`` is one chain ``D_i`` (``C_{i-1}, C_{i-2}, ...,
   C_{i+1}`` run backwards). The centerline between ``C_i`` and ``D_i`` (run ``i``) runs from ``p_i`` to
   ``p_{i+1}`` through every branch touching ``C_i``; each vertex is labelled with the chain its foot on
   ``D_i`` lies on (its arc length on the ring, one index query per run). Labels follow ``D_i``'s order
   along the line. The runs are traced together in one adaptive tracing (:func:`._steps.run_together`), so
   the cost grows with the outline far less than ``k - 1`` separate runs would (``benchmarks/bench_network.py``).
2. Where the label changes from ``C_j`` to ``C_j'`` the incircle touches ``C_i``, ``C_j`` and ``C_j'``: a
   junction. It is located exactly by Newton's method on the exact distances to the three chains (equal
   distances), starting between the two vertices whose labels differ, and checked to be an empty circle; a
   fourth chain inside it means a branch shorter than the sampling lies between, and the junction splits in
   two. Each junction is computed once (keyed by its three chains) and shared by every branch ending there;
   junctions closer than ``JUNCTION_TOLERANCE`` of the extent (a symmetric crossing) are one junction.
3. Branch ``(i, j)``, ``i < j``, appears in runs ``i`` and ``j``; it is taken from run ``i`` only. Both
   runs sample both chains ``C_i`` and ``C_j`` at the same spacing, so either has the same density, and a
   single run keeps the vertices in the engine's order (no interleaving of two sample sets); for ``k = 2``
   the network is therefore exactly :func:`polygon_centerline`'s line (traced alone, as it is). Run
   ``k - 1`` is not needed (without channel islands).
4. Islands are joined once, for all runs, to the chains of one split of the ring (``C_0`` and ``D_0``)
   with :func:`bridge_islands`: each island becomes part of the chain its slit starts from, so every run
   sees the same chains and the network passes each island on the side of the wider channel. With
   ``islands="channels"`` each large island is instead a chain of its own (index ``k + j``), joined to every
   run's ``D_i``: run ``i`` then traces the channel between ``C_i`` and the island, the labels change to the
   island where the channel starts, and every run is traced (``k`` of them). The island's chains meet twice
   (up- and downstream), so their junctions are also numbered by place.

The result is checked to be a tree (a connected graph with one cycle per channel island) with exactly ``k``
leaves at the split points and junctions of degree three or more; otherwise :class:`IncirCuError` says so.
"""

from dataclasses import dataclass, replace
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Point, Polygon

from ._steps import run_together
from .api import PartOutcome, check_island_mode, part_progress, polygon_parts
from .arms import MIN_ARM_RATIO, find_arm_ends
from .caps import check_end_cap, run_out_ends
from .chains import (
    COINCIDENCE_TOLERANCE,
    counter_clockwise_exterior,
    extent_of,
    polygon_without_folds,
    positions_on_ring,
    split_polygon,
    validate_polygon,
)
from .engine import CenterlineResult, centerline_from_chains, centerline_steps
from .errors import IncirCuError, Message, SplitPointError, format_point
from .islands import bridge_islands
from .polyline import IndexedPolyline, cumulative_lengths

#: Island modes of a network: those of a centerline, and ``"channels"`` (channels on both sides of the large
#: islands, see :func:`polygon_network`).
NETWORK_ISLAND_MODES = ("main_channel", "ignore", "channels")

#: An island is a channel island (``islands="channels"``) when its bounding-box diagonal is at least this
#: many times the local width: its own typical width plus twice its distance to the nearest other ring.
CHANNEL_ISLAND_RATIO = 1.0

#: Junctions closer than this fraction of the extent are one junction (degree four or more).
JUNCTION_TOLERANCE = 1e-9

#: Relative slack with which a fourth chain still counts as outside a junction's circle.
EMPTY_CIRCLE_TOLERANCE = 1e-9

#: Most Newton steps locating one junction.
NEWTON_STEPS = 60

#: Chains with at most this many segments are measured without a spatial index (see ``_Boundary.nearest``).
BRUTE_FORCE_SEGMENTS = 4096


@dataclass(frozen=True)
class NetworkBranch:
    """One branch of a network: the axis between two chains, from a leaf or junction to another.

    Attributes
    ----------
    result : CenterlineResult
        The branch as a centerline: ``foot_a`` on the right chain, ``foot_b`` on the left chain (walking
        along the line); radius 0 at a leaf.
    start_point, end_point : int or None
        Index (in the input order) of the split point at the branch's start and end; None at a junction.
    right_chain, left_chain : int
        Indices into :attr:`NetworkResult.chains` of the chains on either side.
    start_node, end_node : int or None
        Rows of :attr:`NetworkResult.nodes` at the branch's start and end (shared by the branches that meet).
    kind : {"arm", "inner", "loop"} or None
        ``"arm"``: one end is an end of the network; ``"inner"``: between two junctions; ``"loop"``: from a
        junction back to itself.
    """

    result: CenterlineResult
    start_point: Optional[int]
    end_point: Optional[int]
    right_chain: int
    left_chain: int
    start_node: Optional[int] = None
    end_node: Optional[int] = None
    kind: Optional[str] = None


@dataclass(frozen=True)
class NetworkResult:
    """The network of a polygon between its split points.

    Attributes
    ----------
    branches : tuple of NetworkBranch
    split_points : ndarray of shape (k, 2)
        The split points snapped onto the ring, in the input order, CRS units.
    chains : tuple of (int, int)
        For each chain, the input indices of the split points at its start and end (counter-clockwise).
    junctions : ndarray of shape (m, 2)
        The junctions, CRS units.
    point_indices : tuple of int or None
        Set by :func:`multipolygon_networks`: the index of each row of ``split_points`` among all the
        candidate split points (the numbers used by ``chains`` and the branches; None for an end found
        automatically).
    junction_radii : ndarray of shape (m,)
        Radius of each junction's circle, CRS units.
    end_sources : tuple of str
        Per row of ``split_points``: ``"split_point"`` (given), ``"gate"`` (see ``gates`` of
        :func:`polygon_network`) or ``"automatic"`` (see :mod:`.arms`).
    ends_from : {"split_points", "automatic", "split_points_and_automatic"}
        Where the ends came from (gates count as split points).
    chain_nodes : tuple of (int, int)
        For each chain, the rows of ``split_points`` (node ids) at its start and end: ``chains`` before
        :func:`multipolygon_networks` renumbers it.
    notes : tuple of str
        Things the user should know (zero-width spikes removed from the polygon's rings before the chains
        were built: :func:`.chains.polygon_without_folds`).
    """

    branches: tuple
    split_points: np.ndarray
    chains: tuple
    junctions: np.ndarray
    point_indices: Optional[tuple] = None
    junction_radii: Optional[np.ndarray] = None
    end_sources: tuple = ()
    ends_from: str = "split_points"
    chain_nodes: tuple = ()
    notes: tuple = ()

    @property
    def nodes(self):
        """ndarray of shape (k + m, 2): the ends (the rows of ``split_points``) then the junctions, CRS units;
        the rows :attr:`NetworkBranch.start_node` and ``end_node`` refer to."""
        return np.concatenate([self.split_points, self.junctions.reshape(-1, 2)])

    @property
    def node_radii(self):
        """ndarray of shape (k + m,): 0 at an end, the circle's radius at a junction, CRS units."""
        radii = np.zeros(len(self.junctions)) if self.junction_radii is None else self.junction_radii
        return np.concatenate([np.zeros(len(self.split_points)), radii])

    @property
    def node_degrees(self):
        """ndarray of shape (k + m,) of int: the number of branch ends at each node (a loop counts twice)."""
        ends = [node for branch in self.branches for node in (branch.start_node, branch.end_node)]
        return np.bincount(np.asarray(ends, dtype=np.int64), minlength=len(self.split_points) + len(self.junctions))


def polygon_network(
    polygon,
    split_points=None,
    *,
    spacing=None,
    snap_tolerance=None,
    islands="main_channel",
    end_cap="axis",
    min_arm_ratio=MIN_ARM_RATIO,
    min_arm_length=None,
    gates=None,
    progress=None,
    **engine_options,
):
    """Medial-axis network of a polygon between ``k >= 2`` ends on its exterior ring.

    Parameters
    ----------
    polygon : Polygon
        A valid polygon, CRS units; holes are islands.
    split_points : sequence of Point or (x, y), optional
        Points within ``snap_tolerance`` of the exterior ring. Two or more: the ends of the network. The
        first one starts chain 0, the others follow counter-clockwise whatever their order; with two points
        the branch runs from the first to the second, as :func:`polygon_centerline`'s line. None, none or
        one: the ends of the arms are found automatically (:func:`.arms.find_arm_ends`); one given point
        replaces the automatic end nearest to it when within that arm's width, and is added otherwise; it
        comes first.
    min_arm_ratio : float
        Automatic ends only: shortest reach of an arm beyond the incircle of the junction it leaves, in
        widths of that junction (see :mod:`.arms`).
    min_arm_length : float, optional
        Automatic ends only: shortest reach of an arm beyond its junction's incircle, CRS units.
    gates : sequence of Point or (x, y), optional
        Ends shared with a touching polygon (see :func:`.touching.touching_gates`), on the exterior ring: each
        replaces the automatic end nearest to it when within that arm's width and is an end otherwise;
        with two or more split points they are ends besides those.
    spacing : float, optional
        Distance between boundary samples, CRS units; None: the engine's default (the same for every run).
    snap_tolerance : float, optional
        Largest distance, CRS units, between a split point and the ring; default ``1e-6`` of the extent.
    islands : {"main_channel", "ignore", "channels"}
        As in :func:`polygon_centerline`, or ``"channels"``: every island whose bounding-box diagonal is at
        least ``CHANNEL_ISLAND_RATIO`` times the local width (its own typical width plus twice its distance
        to the nearest other ring) is a chain of its own, so the network has a loop around it (a junction upstream and
        one downstream, exact; branches of kind ``"loop"`` along it); smaller islands are passed on the side
        of the wider channel. Every run is traced (``k`` instead of ``k - 1``); a branch between two channel
        islands (no outline chain) is not traced.
    end_cap : {"axis", "runout"}
        How a branch crosses the end cap at an end on the outline, as in :func:`polygon_centerline` (the
        branches' junction ends are left as they are).
    progress : callable, optional
        Called with the fraction done; returning False raises :class:`Cancelled`.
    **engine_options
        Passed to :func:`centerline_from_chains` (e.g. ``samples_per_chain``).

    Returns
    -------
    NetworkResult
        For two split points, one branch equal to :func:`polygon_centerline`'s line.

    Raises
    ------
    InvalidGeometryError, SplitPointError, ChainError, IncirCuError

    Examples
    --------
    >>> from shapely.geometry import box
    >>> network = polygon_network(box(0, 0, 100, 10), [(0, 5), (100, 5)], spacing=1.0)
    >>> [round(branch.result.length, 9) for branch in network.branches]
    [100.0]
    """
    validate_polygon(polygon)
    if islands not in NETWORK_ISLAND_MODES:
        check_island_mode(islands)
    check_end_cap(end_cap)
    polygon, spikes = polygon_without_folds(polygon)
    channel_islands, polygon = _channel_islands(polygon) if islands == "channels" else ([], polygon)
    if islands == "channels":
        islands = "main_channel"
    split_points = [] if split_points is None else list(split_points)
    given = len(split_points)
    gates = [] if gates is None else list(gates)
    sources = ["split_point"] * given + ["gate"] * len(gates)
    split_points = split_points + gates
    if given < 2:
        region = polygon if islands == "main_channel" else Polygon(polygon.exterior)
        split_points = with_automatic_ends(region, split_points, min_arm_ratio, min_arm_length)
    sources += ["automatic"] * (len(split_points) - len(sources))
    order = _ring_order(polygon, split_points, snap_tolerance)
    points = [_as_xy(split_points[index]) for index in order]
    chains = _bridged_chains(polygon, points, snap_tolerance, islands)
    k = len(chains)
    extent = extent_of(*chains, *channel_islands)
    boundary = _Boundary(chains, extent, channel_islands)
    junctions = _Junctions(boundary)
    pieces = []
    runs = _runs(chains, spacing, progress, engine_options, channel_islands)
    for i, (result, bridged) in enumerate(runs):
        labels = _vertex_labels(result, i, boundary, bridged)
        pieces.extend(_run_pieces(result, i, labels, junctions))
    branches, centres, radii = _assemble(pieces, junctions, order, loops=len(channel_islands))
    if end_cap == "runout":
        region = polygon if islands == "main_channel" else Polygon(polygon.exterior)
        branches = [replace(branch, result=run_out_ends(branch.result, region)) for branch in branches]
    snapped = np.empty((k, 2))
    snapped[order] = np.array([chain[0] for chain in chains])
    automatic = "automatic" in sources
    return NetworkResult(
        branches=tuple(branches),
        split_points=snapped,
        chains=tuple((order[m], order[(m + 1) % k]) for m in range(k)),
        junctions=centres,
        junction_radii=radii,
        chain_nodes=tuple((order[m], order[(m + 1) % k]) for m in range(k)),
        end_sources=tuple(sources),
        ends_from=("split_points_and_automatic" if len(sources) > sources.count("automatic") else "automatic")
        if automatic
        else "split_points",
        notes=(spikes,) if spikes else (),
    )


def with_automatic_ends(polygon, split_points, min_arm_ratio=MIN_ARM_RATIO, min_arm_length=None):
    """Return the given points followed by the automatic arm ends they do not replace.

    A given point replaces the automatic end nearest to it when it lies within that arm's width of it (a
    split point placed anywhere across the arm's end).

    Parameters
    ----------
    polygon : Polygon
        CRS units; its holes as the network sees them.
    split_points : sequence of Point or (x, y)
        CRS units (one split point and any gates).
    min_arm_ratio, min_arm_length : float
        See :func:`.arms.find_arm_ends`.

    Returns
    -------
    list of ndarray of shape (2,)
        CRS units, the given point first.

    Raises
    ------
    SplitPointError
        When fewer than two ends are found (a shape without arms, such as a ring around an island).
    """
    given = [_as_xy(point) for point in split_points]
    arms = find_arm_ends(polygon, min_arm_ratio=min_arm_ratio, min_arm_length=min_arm_length)
    automatic = list(zip(arms.points, arms.widths))
    for point in given:
        if automatic:
            distances = [float(np.hypot(*(point - end))) for end, _ in automatic]
            nearest = int(np.argmin(distances))
            if distances[nearest] <= automatic[nearest][1]:
                automatic.pop(nearest)
    points = given + [end for end, _ in automatic]
    if len(points) < 2:
        raise SplitPointError(Message("arm_ends_too_few", count=len(points)))
    return points


def multipolygon_networks(geometry, split_points, *, snap_tolerance=None, gates=None, **options):
    """Network of each part of a polygon or multipolygon between the split points on its exterior ring.

    A part takes the split points within ``snap_tolerance`` of its exterior ring; with fewer than two, the
    ends of its arms are found automatically (see :func:`polygon_network`). A part that fails does not stop
    the others.

    Parameters
    ----------
    geometry : Polygon or MultiPolygon
        CRS units.
    split_points : sequence of Point or (x, y)
        Candidate split points for all parts.
    snap_tolerance : float, optional
        CRS units; default ``1e-6`` of the geometry's extent.
    gates : sequence of Point or (x, y), optional
        Gates for all parts (see :func:`polygon_network`); a part takes those within ``snap_tolerance`` of
        its exterior ring.
    **options
        Passed to :func:`polygon_network` (``spacing``, ``islands``, ``progress``, ...).

    Returns
    -------
    list of PartOutcome
        One per part, in input order; a result's split point indices refer to ``split_points`` (None for a
        gate or an end found automatically).

    Raises
    ------
    InvalidGeometryError
        As :func:`.api.polygon_parts` (a null, empty or non-polygonal geometry); a part's own errors are
        reported in its outcome.

    Examples
    --------
    Two parallel channels, their four split points given in no particular order:

    >>> from shapely.geometry import MultiPolygon, box
    >>> channels = MultiPolygon([box(0, 0, 50, 4), box(0, 10, 50, 14)])
    >>> outcomes = multipolygon_networks(channels, [(0, 12), (50, 2), (50, 12), (0, 2)], spacing=1.0)
    >>> [[(b.start_point, b.end_point) for b in o.result.branches] for o in outcomes]
    [[(1, 3)], [(0, 2)]]
    """
    parts, points, snap_tolerance = polygon_parts(geometry, split_points, snap_tolerance)
    gate_points = list(shapely.points(np.asarray(gates, dtype=float).reshape(-1, 2))) if gates is not None else []
    progress = options.pop("progress", None)
    outcomes = []
    for index, (part, near) in enumerate(parts):
        try:
            # What is wrong with the polygon itself comes first (as for a centerline), then its split points.
            validate_polygon(part)
            part_gates = [gate for gate in gate_points if part.exterior.distance(gate) <= snap_tolerance]
            network = polygon_network(
                part,
                [points[i] for i in near],
                snap_tolerance=snap_tolerance,
                gates=part_gates,
                progress=part_progress(progress, index, len(parts)),
                **options,
            )
            indices = list(near) + [None] * (len(network.split_points) - len(near))
            outcomes.append(PartOutcome(index, _renumbered(network, indices), None))
        except IncirCuError as error:
            outcomes.append(PartOutcome(index, None, error))
    return outcomes


def _renumbered(network, indices):
    """Return a network whose split point indices ``m`` become ``indices[m]``."""

    def renumber(m):
        return None if m is None else indices[m]

    branches = tuple(
        replace(branch, start_point=renumber(branch.start_point), end_point=renumber(branch.end_point))
        for branch in network.branches
    )
    chains = tuple((renumber(start), renumber(end)) for start, end in network.chains)
    return replace(network, branches=branches, chains=chains, point_indices=tuple(indices))


def _as_xy(point):
    """Return a Point or (x, y) as a float array of shape (2,)."""
    return np.asarray(point.coords[0] if isinstance(point, Point) else point, dtype=float)[:2]


def _runs(chains, spacing, progress, engine_options, channel_islands=()):
    """Return ``(centerline, D_i with the channel islands or None)`` of the runs ``i < k - 1`` (all ``k`` with
    channel islands), traced together.

    One run (two chains) is traced alone, exactly as :func:`polygon_centerline` traces it; more runs are
    traced side by side in one adaptive tracing (:func:`._steps.run_together`), the same lines up to float64
    rounding at a fraction of the cost of tracing them one by one.

    Raises
    ------
    Cancelled
        When ``progress`` returned False.
    IncirCuError
        The first run's error, if one failed.
    """
    k = len(chains)
    if k == 2 and not channel_islands:
        return [
            (centerline_from_chains(chains[0], chains[1][::-1], spacing, progress=progress, **engine_options), None)
        ]
    complements = [_complement(chains, i) for i in range(k if channel_islands else k - 1)]
    if channel_islands:
        # Each run sees every channel island as part of the rest of the ring, so it traces its own channel.
        complements = [
            bridge_islands(chains[i], complement, channel_islands, to_second=[True] * len(channel_islands))[1]
            for i, complement in enumerate(complements)
        ]
    steps = [
        centerline_steps(chains[i], complement, spacing, **engine_options) for i, complement in enumerate(complements)
    ]
    results = run_together(steps, progress=progress)
    for result in results:
        if isinstance(result, Exception):
            raise result
    return [(result, complement if channel_islands else None) for result, complement in zip(results, complements)]


def _channel_islands(polygon):
    """Return the rings of the channel islands (see ``islands="channels"``) and the polygon without them.

    The local width of an island is its own typical width (``2 A / P``) plus twice its distance to the
    nearest other ring (the outline or another island).
    """
    rings = [polygon.exterior, *polygon.interiors]
    big, small = [], []
    for index, ring in enumerate(polygon.interiors, start=1):
        island = Polygon(ring)
        west, south, east, north = island.bounds
        gap = min(float(shapely.distance(island, other)) for number, other in enumerate(rings) if number != index)
        local = 2.0 * island.area / island.length + 2.0 * gap
        (big if np.hypot(east - west, north - south) >= CHANNEL_ISLAND_RATIO * local else small).append(ring)
    return [shapely.get_coordinates(ring) for ring in big], Polygon(polygon.exterior, small)


def _ring_order(polygon, split_points, tolerance):
    """Return the input indices of the split points counter-clockwise along the ring from the first one.

    Raises
    ------
    SplitPointError
        Fewer than two points, a point too far from the ring, or two points at the same place.
    """
    if len(split_points) < 2:
        raise SplitPointError(Message("network_too_few_points", count=len(split_points)))
    xy = [_as_xy(point) for point in split_points]
    if not all(np.all(np.isfinite(p)) for p in xy):
        raise SplitPointError(Message("split_point_not_finite"))
    ring = counter_clockwise_exterior(polygon)
    extent = extent_of(ring)
    if tolerance is None or tolerance <= 0:
        tolerance = 1e-6 * extent
    perimeter = float(cumulative_lengths(ring)[-1])
    along = positions_on_ring(ring, xy, tolerance)
    relative = np.mod(np.asarray(along) - along[0], perimeter)
    order = [0] + sorted(range(1, len(xy)), key=lambda index: relative[index])
    gaps = np.diff(np.append(relative[order], perimeter))
    close = int(np.argmin(gaps))
    if gaps[close] <= max(tolerance, COINCIDENCE_TOLERANCE * extent):
        raise SplitPointError(Message("network_same_place", point=format_point(xy[order[close]])))
    return order


def _insert_vertex(chain, point, coincidence):
    """Return ``chain`` with ``point`` projected onto it as a vertex, and that vertex's index."""
    exact = np.flatnonzero(np.all(chain == point, axis=1))
    if len(exact) == 1:
        return chain, int(exact[0])
    line = LineString(chain)
    position = line.project(Point(point))
    cumulative = cumulative_lengths(chain)
    nearest = int(np.argmin(np.abs(cumulative - position)))
    if abs(cumulative[nearest] - position) <= coincidence:
        return chain, nearest
    index = int(np.searchsorted(cumulative, position, side="right"))
    return np.insert(chain, index, np.asarray(line.interpolate(position).coords[0]), axis=0), index


def _bridged_chains(polygon, points, tolerance, islands):
    """Return the chains ``C_0 .. C_{k-1}`` (counter-clockwise, islands joined) between ring-ordered points.

    ``C_0`` and ``D_0`` come from :func:`split_polygon` exactly as in :func:`polygon_centerline`; the other
    split points are inserted into ``D_0``, the islands are joined to ``C_0`` or ``D_0`` once, and ``D_0`` is
    cut at the other split points.
    """
    c1, c2 = split_polygon(polygon, points[:2], tolerance)
    coincidence = COINCIDENCE_TOLERANCE * extent_of(c1, c2)
    for point in points[2:]:
        c2, _ = _insert_vertex(c2, point, coincidence)
    if islands == "main_channel" and polygon.interiors:
        c1, c2 = bridge_islands(c1, c2, [shapely.get_coordinates(ring) for ring in polygon.interiors])
    cuts = []
    for point in points[:1:-1]:
        before = len(c2)
        c2, index = _insert_vertex(c2, point, coincidence)
        cuts = [cut + (len(c2) - before if cut >= index else 0) for cut in cuts] + [index]
    if cuts != sorted(cuts) or len(set(cuts)) != len(cuts) or (cuts and (cuts[0] == 0 or cuts[-1] == len(c2) - 1)):
        raise IncirCuError(Message("network_order"))
    bounds = [0, *cuts, len(c2) - 1]
    backwards = [c2[start : end + 1][::-1].copy() for start, end in zip(bounds[:-1], bounds[1:])]
    return [np.asarray(c1, dtype=float)] + backwards[::-1]


def _complement(chains, i):
    """Return ``D_i``: the other chains from ``p_i`` backwards to ``p_{i+1}``, as one chain."""
    k = len(chains)
    return np.concatenate([chains[(i - step) % k][::-1][(step > 1) :] for step in range(1, k)])


def _vertex_labels(result, i, boundary, bridged=None):
    """Label each vertex of run ``i`` with the chain its foot on ``D_i`` lies on, in ``D_i``'s order.

    Each foot lies on the ring (the chains end to end, counter-clockwise): its arc length there names its
    chain (one index query for all the feet of the run). A foot at ``p_i`` or ``p_{i+1}`` itself, which the
    ring may place on ``C_i``, takes the neighbouring chain. Labels that go back against ``D_i``'s order (a
    foot at the very junction) take the label before them.
    """
    k = boundary.exterior_count
    feet = np.asarray(result.foot_b, dtype=float)
    labels = boundary.chain_at(feet)
    if bridged is not None:
        return _channel_labels(feet, labels, i, boundary, bridged)
    _outline_ends(labels, feet, i, boundary)
    rank = np.maximum.accumulate(np.mod(i - 1 - labels, k))
    return np.mod(i - 1 - rank, k)


def _outline_ends(labels, feet, i, boundary):
    """Relabel, in place, the feet the ring put on run ``i``'s own chain (at ``p_i`` or ``p_{i+1}``: the
    neighbour they are nearer to by distance, as the ring's arc length is ambiguous at its closing point
    ``p_0``) and the run's two ends (the chains before and after ``C_i``)."""
    k = boundary.exterior_count
    own = labels == i
    if np.any(own):
        chain = boundary.chains[i]
        nearer_start = np.hypot(*(feet[own] - chain[0]).T) <= np.hypot(*(feet[own] - chain[-1]).T)
        labels[own] = np.where(nearer_start, (i - 1) % k, (i + 1) % k)
    labels[0], labels[-1] = (i - 1) % k, (i + 1) % k


def _channel_labels(feet, labels, i, boundary, bridged):
    """Labels of run ``i`` with channel islands: a foot on island ``j`` is labelled ``k + j``; a label whose
    foot lies back along the bridged ``D_i`` (a foot at the very junction) takes the one before it."""
    k = boundary.exterior_count
    for j, ring in enumerate(boundary.chains[k:]):
        on = IndexedPolyline(ring).nearest(feet)[0] <= JUNCTION_TOLERANCE * boundary.extent
        labels[on] = k + j
    _outline_ends(labels, feet, i, boundary)
    along = IndexedPolyline(bridged).nearest(feet)[1]
    back = along < np.maximum.accumulate(along) - JUNCTION_TOLERANCE * boundary.extent
    for index in np.flatnonzero(back):
        labels[index] = labels[index - 1]
    return labels


class _Boundary:
    """The chains with spatial indices (built when first needed): exact distances and feet to each chain."""

    def __init__(self, chains, extent, islands=()):
        #: Outline chains first, then the channel islands' rings (chains of their own).
        self.exterior_count = len(chains)
        chains = [*chains, *islands]
        self.chains = chains
        self.indexed = [None] * len(chains)
        self.extent = extent
        chains = chains[: self.exterior_count]
        self.ring = IndexedPolyline(np.concatenate([chains[0], *[chain[1:] for chain in chains[1:]]]))
        ends = np.cumsum([0] + [len(chain) - 1 for chain in chains])
        #: Arc length on the ring where each chain starts (and the ring's length last), CRS units.
        self.starts = self.ring.cumulative[ends]

    def chain_at(self, points):
        """Return the chain each point of the ring lies on (the first one at a split point)."""
        along = self.ring.nearest(points)[1]
        return np.clip(np.searchsorted(self.starts, along, side="right") - 1, 0, len(self.chains) - 1)

    def nearest(self, point, chain):
        """Return the distance from ``point`` to chain ``chain`` and the foot there.

        A chain of at most ``BRUTE_FORCE_SEGMENTS`` segments is measured segment by segment in one numpy pass
        (a few microseconds; the junctions ask one point at a time), a longer one through its spatial index.
        """
        point = np.asarray(point, dtype=float)
        if self.indexed[chain] is None:
            xy = np.asarray(self.chains[chain], dtype=float)
            if len(xy) - 1 <= BRUTE_FORCE_SEGMENTS and len(xy) > 1:
                direction = np.diff(xy, axis=0)
                self.indexed[chain] = (xy[:-1], direction, np.einsum("ij,ij->i", direction, direction))
            else:
                self.indexed[chain] = IndexedPolyline(xy)
        indexed = self.indexed[chain]
        if isinstance(indexed, IndexedPolyline):
            distance, _, foot = indexed.nearest(point[None])
            return float(distance[0]), foot[0]
        start, direction, squared = indexed
        offset = point - start
        along = np.clip(np.einsum("ij,ij->i", offset, direction) / np.where(squared > 0.0, squared, 1.0), 0.0, 1.0)
        gap = offset - along[:, None] * direction
        distances = np.hypot(gap[:, 0], gap[:, 1])
        nearest = int(np.argmin(distances))
        return float(distances[nearest]), start[nearest] + along[nearest] * direction[nearest]

    def distances_within(self, point, reach):
        """Return ``{chain: distance}`` for the chains nearer than ``reach`` to ``point`` (CRS units): one
        index query on the ring, then the exact distance to each chain found."""
        segments = self.ring.tree.query(Point(point), predicate="dwithin", distance=reach)
        near = {int(chain) for chain in np.searchsorted(self.starts, self.ring.cumulative[segments], side="right") - 1}
        # A segment starting at a chain's end vertex belongs to the next chain; its predecessor may be near too.
        near |= {(chain - 1) % len(self.chains) for chain in near}
        near |= set(range(self.exterior_count, len(self.chains)))
        found = {chain: self.nearest(point, chain)[0] for chain in sorted(near)}
        return {chain: distance for chain, distance in found.items() if distance < reach}


class _Junctions:
    """Junctions keyed by their three chains, located once and shared by every branch ending there."""

    def __init__(self, boundary):
        self.boundary = boundary
        self.by_chains = {}

    def between(self, i, a, b, start, end, depth=0):
        """Return the junctions on run ``i`` between a vertex labelled ``a`` and the next labelled ``b``.

        Parameters
        ----------
        i, a, b : int
            The run's chain and the labels on either side of the change.
        start, end : ndarray of shape (2,)
            The two vertices, CRS units.

        Returns
        -------
        list of (tuple of int, ndarray of shape (2,), float)
            Each junction's three chains (sorted), centre and radius, from ``a``'s side to ``b``'s.
        """
        key = self._key(tuple(sorted((i, a, b))), start, end)
        if key not in self.by_chains:
            centre = _newton_junction(self.boundary, key[:3], start, end)
            radius = float(np.mean([self.boundary.nearest(centre, chain)[0] for chain in key[:3]]))
            distances = self.boundary.distances_within(centre, radius * (1.0 - EMPTY_CIRCLE_TOLERANCE))
            inside = [m for m in sorted(distances, key=distances.get) if m not in key[:3]]
            if inside:
                k = self.boundary.exterior_count
                between = None if max(a, b, inside[0]) >= k else _between_in_order(i, a, b, int(inside[0]), k)
                if between is None or depth > k:
                    raise IncirCuError(Message("junction_out_of_order", point=format_point(centre)))
                return self.between(i, a, between, start, centre, depth + 1) + self.between(
                    i, between, b, centre, end, depth + 1
                )
            self.by_chains[key] = (centre, radius)
        centre, radius = self.by_chains[key]
        return [(key, centre, radius)]

    def _key(self, chains, start, end):
        """Return the key of the junction of ``chains`` between two run vertices: the chains themselves, or,
        for a channel island's chains (which meet twice: up- and downstream of it), the chains and the number
        of the junction of theirs lying near the segment (a new number when none does)."""
        if max(chains) < self.boundary.exterior_count:
            return chains
        same = [key for key in self.by_chains if key[:3] == chains]
        segment = LineString([start, end]) if np.any(start != end) else Point(start)
        for key in same:
            if segment.distance(Point(self.by_chains[key][0])) <= max(segment.length, JUNCTION_TOLERANCE):
                return key
        return chains if not same else (*chains, len(same))


def _between_in_order(i, a, b, m, k):
    """Return ``m`` if it lies strictly between ``a`` and ``b`` in ``D_i``'s order, else None."""
    rank = [(i - 1 - label) % k for label in (a, m, b)]
    return m if rank[0] < rank[1] < rank[2] else None


def _newton_junction(boundary, key, start, end):
    """Locate the point equidistant from three chains by Newton's method on the exact distances.

    The iteration starts midway between two run vertices on either side of the junction, then (when it
    meets a singular step, e.g. from a point outside the region, or does not settle) at other points
    between them.

    Parameters
    ----------
    boundary : _Boundary
    key : tuple of three int
        The chains.
    start, end : ndarray of shape (2,)
        The two run vertices, CRS units.

    Returns
    -------
    ndarray of shape (2,)

    Raises
    ------
    IncirCuError
        When no start settles.
    """
    for fraction in (0.5, 0.25, 0.75, 0.0, 1.0):
        found = _newton_from(boundary, key, start + fraction * (end - start))
        if found is not None:
            return found
    found = _junction_off_a_split_point(boundary, key)
    if found is not None:
        return found
    raise IncirCuError(Message("junction_several_contacts", point=format_point(0.5 * (start + end))))


def _junction_off_a_split_point(boundary, key):
    """Return the junction whose circle touches a split point shared by two of the chains ``key`` and the
    third chain, or None.

    A split point ``p`` on a smooth stretch of bank (a gate in the middle of a side, where a touching
    polygon's reach joins) makes the two chains meeting there equidistant from every point of the inward
    normal at ``p`` near it: Newton's system is singular there. The junction is the point ``p + t n`` of that
    normal at distance ``t`` from the third chain, found by bisection, and kept when ``p`` is indeed nearest
    to it on both chains (the circle is empty of them).
    """
    k = boundary.exterior_count
    for m in key:
        if m >= k:
            continue
        before = (m - 1) % k
        if before not in key:
            continue
        (third,) = set(key) - {m, before}
        point = boundary.chains[m][0]
        incoming = boundary.chains[before][-1] - boundary.chains[before][-2]
        outgoing = boundary.chains[m][1] - boundary.chains[m][0]
        tangent = incoming / np.hypot(*incoming) + outgoing / np.hypot(*outgoing)
        if not np.any(tangent):
            continue
        tangent = tangent / np.hypot(*tangent)
        normal = np.array([-tangent[1], tangent[0]])  # inward: the ring runs counter-clockwise

        low, high = 0.0, boundary.extent
        if _excess(boundary, point, normal, third, high) > 0.0:
            continue
        for _ in range(200):
            middle = 0.5 * (low + high)
            if high - middle <= 4.0 * float(np.spacing(boundary.extent + np.max(np.abs(point)))):
                break
            if _excess(boundary, point, normal, third, middle) > 0.0:
                low = middle
            else:
                high = middle
        centre = point + high * normal
        distances = [boundary.nearest(centre, chain)[0] for chain in key]
        if max(distances) - min(distances) <= JUNCTION_TOLERANCE * boundary.extent:
            return centre
    return None


def _excess(boundary, point, normal, chain, t):
    """How much farther than ``t`` the point ``point + t normal`` lies from chain ``chain``, CRS units."""
    return boundary.nearest(point + t * normal, chain)[0] - t


def _newton_from(boundary, key, x):
    """Run Newton's method for :func:`_newton_junction` from ``x``; None when it does not settle."""
    step_floor = 4.0 * float(np.spacing(np.max(np.abs(x)) + boundary.extent))

    def residual(point):
        near = [boundary.nearest(point, chain) for chain in key]
        distances = np.array([d for d, _ in near])
        return distances[0] - distances[1:], distances, np.array([foot for _, foot in near])

    value, distances, feet = residual(x)
    for _ in range(NEWTON_STEPS):
        if np.any(distances <= 0.0):
            return None
        gradients = (x - feet) / distances[:, None]
        (a, b), (c, d) = gradients[0] - gradients[1:]
        determinant = a * d - b * c
        if determinant == 0.0 or not np.isfinite(determinant):
            return None
        # The 2 x 2 system by Cramer's rule (numpy's solver costs more than the distances here).
        step = np.array([d * -value[0] - b * -value[1], a * -value[1] - c * -value[0]]) / determinant
        for _ in range(40):
            trial = residual(x + step)
            if np.max(np.abs(trial[0])) < np.max(np.abs(value)) or np.hypot(*step) <= step_floor:
                break
            step = 0.5 * step
        x = x + step
        value, distances, feet = trial
        if np.hypot(*step) <= step_floor:
            return x
    return x if np.max(np.abs(value)) <= JUNCTION_TOLERANCE * boundary.extent else None


def _run_pieces(result, i, labels, junctions):
    """Cut run ``i`` where its labels change and keep the pieces ``(i, j)`` with ``i < j``.

    Returns
    -------
    list of dict
        ``chains`` (i, j); ``ends``, two nodes, ``("leaf", m)`` for split point ``m`` (ring order) or
        ``("junction", key)``; ``vertices``, ``radii``, ``foot_a`` (on ``C_i``), ``foot_b`` (on ``C_j``) of
        the run's vertices on the piece, in run order (a junction is not among them).
    """
    k = junctions.boundary.exterior_count
    arrays = {
        "vertices": shapely.get_coordinates(result.line),
        "radii": np.asarray(result.radii, dtype=float),
        "foot_a": np.asarray(result.foot_a, dtype=float),
        "foot_b": np.asarray(result.foot_b, dtype=float),
    }
    change = np.flatnonzero(labels[1:] != labels[:-1])
    starts, stops = np.concatenate([[0], change + 1]), np.concatenate([change + 1, [len(labels)]])
    node = ("leaf", i)
    pieces = []
    for first, stop in zip(starts, stops):
        label = int(labels[first])
        found = []
        if stop < len(labels):
            vertices = arrays["vertices"]
            found = junctions.between(i, label, int(labels[stop]), vertices[stop - 1], vertices[stop])
        end = ("junction", found[0][0]) if found else ("leaf", (i + 1) % k)
        piece = {name: values[first:stop] for name, values in arrays.items()}
        pieces.append({"chains": (i, label), "ends": (node, end), **piece})
        for before, after in zip(found[:-1], found[1:]):
            (shared,) = set(before[0][:3]) & set(after[0][:3]) - {i}
            pieces.append(
                {"chains": (i, shared), "ends": (("junction", before[0]), ("junction", after[0])), **_empty()}
            )
        if found:
            node = ("junction", found[-1][0])
    return [piece for piece in pieces if piece["chains"][0] < piece["chains"][1]]


def _empty():
    """Arrays of a piece with no run vertex (a branch shorter than the sampling)."""
    return {"vertices": np.empty((0, 2)), "radii": np.empty(0), "foot_a": np.empty((0, 2)), "foot_b": np.empty((0, 2))}


def _junction_clusters(junctions):
    """Map each junction key to the key of its cluster (junctions within ``JUNCTION_TOLERANCE``)."""
    keys = sorted(junctions.by_chains)
    tolerance = JUNCTION_TOLERANCE * junctions.boundary.extent
    cluster = {}
    for key in keys:
        centre = junctions.by_chains[key][0]
        cluster[key] = next(
            (cluster[other] for other in cluster if np.hypot(*(junctions.by_chains[other][0] - centre)) <= tolerance),
            key,
        )
    return cluster


def _end_of(node, junctions, cluster):
    """Return a piece end as (graph node, centre or None for a leaf already among the vertices, radius)."""
    kind, value = node
    if kind == "leaf":
        return ("leaf", value), None, 0.0
    centre, radius = junctions.by_chains[cluster[value]]
    return ("junction", cluster[value]), centre, radius


def _piece_arrays(piece, ends, junctions):
    """Vertices, radii and feet of a piece with its junction ends added (vertices at a junction dropped)."""
    boundary = junctions.boundary
    i, j = piece["chains"]
    tolerance = JUNCTION_TOLERANCE * boundary.extent
    keep = np.ones(len(piece["vertices"]), dtype=bool)
    for _, centre, _ in ends:
        if centre is not None:
            keep &= np.hypot(*(piece["vertices"] - centre).T) > tolerance
    parts = {name: [piece[name][keep]] for name in ("vertices", "radii", "foot_a", "foot_b")}
    for position, (_, centre, radius) in enumerate(ends):
        if centre is None:
            continue
        row = {
            "vertices": centre[None],
            "radii": np.array([radius]),
            "foot_a": boundary.nearest(centre, i)[1][None],
            "foot_b": boundary.nearest(centre, j)[1][None],
        }
        for name, value in row.items():
            parts[name].insert(0 if position == 0 else len(parts[name]), value)
    return {name: np.concatenate(values) for name, values in parts.items()}


def _assemble(pieces, junctions, order, loops=0):
    """Turn the pieces of all runs into oriented branches and check that they form the expected tree.

    Parameters
    ----------
    pieces : list of dict
        See :func:`_run_pieces`.
    junctions : _Junctions
    order : list of int
        Input index of each split point in ring order.
    loops : int
        Number of channel islands: independent cycles the graph must have.

    Returns
    -------
    branches : list of NetworkBranch
        With their nodes (the ends by input index, then the junctions) and kinds.
    centres : ndarray of shape (m, 2)
        The junctions the branches end at, CRS units.
    radii : ndarray of shape (m,)
        Their radii, CRS units.

    Raises
    ------
    IncirCuError
        When the branches are not a tree with one leaf at each split point and junctions of degree >= 3.
    """
    cluster = _junction_clusters(junctions)
    branches, edges = [], []
    for piece in pieces:
        ends = [_end_of(node, junctions, cluster) for node in piece["ends"]]
        if ends[0][0] == ends[1][0]:
            continue
        arrays = _piece_arrays(piece, ends, junctions)
        if len(arrays["vertices"]) < 2:
            raise IncirCuError(Message("branch_too_short"))
        right, left = piece["chains"]
        if ends[0][0][0] == "junction" and ends[1][0][0] == "leaf":
            ends = ends[::-1]
            arrays = {name: values[::-1] for name, values in arrays.items()}
            arrays["foot_a"], arrays["foot_b"] = arrays["foot_b"], arrays["foot_a"]
            right, left = left, right
        result = CenterlineResult(
            line=LineString(arrays["vertices"]), radii=arrays["radii"], foot_a=arrays["foot_a"], foot_b=arrays["foot_b"]
        )
        point_of = [order[node[1]] if node[0] == "leaf" else None for node, _, _ in ends]
        branches.append(NetworkBranch(result, point_of[0], point_of[1], right, left))
        edges.append((ends[0][0], ends[1][0]))
    _check_tree(edges, len(order), loops)
    used = sorted({node[1] for edge in edges for node in edge if node[0] == "junction"})
    number = {key: len(order) + index for index, key in enumerate(used)}

    def node_id(node):
        return order[node[1]] if node[0] == "leaf" else number[node[1]]

    branches = [
        replace(
            branch,
            start_node=node_id(start),
            end_node=node_id(end),
            kind="loop"
            if start == end or max(branch.right_chain, branch.left_chain) >= len(order)
            else ("arm" if "leaf" in (start[0], end[0]) else "inner"),
        )
        for branch, (start, end) in zip(branches, edges)
    ]
    centres = np.array([junctions.by_chains[key][0] for key in used]).reshape(-1, 2)
    return branches, centres, np.array([junctions.by_chains[key][1] for key in used], dtype=float)


def _check_tree(edges, k, loops=0):
    """Raise :class:`IncirCuError` unless the edges form a tree with leaves 0..k-1 and junctions of degree >= 3
    (a connected graph with ``loops`` independent cycles, one around each channel island)."""
    degree = {}
    for edge in edges:
        for node in edge:
            degree[node] = degree.get(node, 0) + 1
    leaves = sorted(node[1] for node, count in degree.items() if node[0] == "leaf" and count == 1)
    weak = [node for node, count in degree.items() if node[0] == "junction" and count < 3]
    parent = {node: node for node in degree}

    def root(node):
        while parent[node] != node:
            node = parent[node]
        return node

    for a, b in edges:
        parent[root(a)] = root(b)
    connected = len({root(node) for node in degree}) == 1
    if leaves != list(range(k)) or weak or not connected or len(edges) != len(degree) - 1 + loops:
        raise IncirCuError(Message("network_not_tree", k=k, branches=len(edges), ends=len(leaves), weak=len(weak)))
