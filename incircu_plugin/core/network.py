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
   ``islands="channels"`` each large island is instead a chain of its own (index ``k + j``) in every run's
   ``D_i``: run ``i`` then traces the channel between ``C_i`` and the island, the labels change to the
   island where the channel starts, and every run is traced (``k`` of them). ``D_i`` is the boundary of the
   polygon clipped near ``C_i`` (:func:`_channel_complement`): the islands reaching into that region are
   notches of its outline, not joined by slits (a slit across a channel would be a wall for its circles).
   An island with another channel island near it also gets a *loop run* (:func:`_loop_chains`): the closed
   axis between its ring and the rest of the boundary near it (both closed chains from their seam, as
   :mod:`.rings` traces a ring), which gives the branches between two islands (a road grid's streets between
   two blocks, no outline chain beside them). The island's chains meet twice (up- and downstream), so their
   junctions are also numbered by place. The automatic ends are those of the polygon with its channel
   islands (every one of them kept in the skeleton).

The result is checked to be a tree (a connected graph with one cycle per channel island) with exactly ``k``
leaves at the split points and junctions of degree three or more; otherwise :class:`IncirCuError` says so.
"""

from dataclasses import dataclass, replace
from typing import Optional

import numpy as np
import shapely
from shapely.errors import GEOSException
from shapely.geometry import LineString, Point, Polygon

from ._many import one_or_many
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
from .engine import CenterlineResult, centerline_from_chains, centerline_steps, clean_chains_steps
from .errors import IncirCuError, Message, SplitPointError, format_point
from .islands import bridge_islands
from .polyline import IndexedPolyline, cumulative_lengths
from .rings import seam_chains

#: Most networks in one batch of an array (:func:`multipolygon_networks`): a network traces its own runs, so a
#: batch shares no tracing, and progress and cancel come between batches.
NETWORK_BATCH_FEATURES = 8

#: Island modes of a network: those of a centerline, and ``"channels"`` (channels on both sides of the large
#: islands, see :func:`polygon_network`).
NETWORK_ISLAND_MODES = ("main_channel", "ignore", "channels")

#: An island is a channel island (``islands="channels"``) when its bounding-box diagonal is at least this
#: many times the local width: its own typical width plus twice its distance to the nearest other ring.
CHANNEL_ISLAND_RATIO = 1.0

#: A channel island's loop run sees the polygon within this many times the island's widest channel of it (a
#: circle at a right-angled crossing of two such channels reaches 1.42 times as far).
LOOP_REACH = 2.0

#: Samples along a chain or island measuring its widest channel (the distance to the rest of the boundary).
LOOP_SAMPLES = 256

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
    ends_from : str
        Where the ends came from: ``"split_points"``, ``"gates"``, ``"automatic"`` or those present joined
        by ``"_and_"`` (``"gates_and_automatic"`` for a reach with one gate; see :func:`ends_from`).
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
        Points within ``snap_tolerance`` of the exterior ring. Two or more: the ends (the first starts chain 0,
        the others follow counter-clockwise; two give :func:`polygon_centerline`'s line). None or one: arm ends
        found automatically (:func:`.arms.find_arm_ends`), one given point replacing the nearest within its
        arm's width (else added), first.
    min_arm_ratio, min_arm_length : float, optional
        Automatic ends only: shortest reach of an arm beyond its junction's incircle, in widths of that
        junction and in CRS units (see :mod:`.arms`).
    gates : sequence of Point or (x, y), optional
        Ends shared with a touching polygon (:func:`.touching.touching_gates`), on the exterior ring: ends
        besides the split points, or replacing the nearest automatic end within its arm's width.
    spacing, snap_tolerance : float, optional
        As for :func:`polygon_centerline` (one spacing for every run), CRS units.
    islands : {"main_channel", "ignore", "channels"}
        As in :func:`polygon_centerline`, or ``"channels"``: an island at least ``CHANNEL_ISLAND_RATIO`` times
        the local width across is a chain of its own, so the network loops round it (branches of kind
        ``"loop"``; smaller ones are passed on the wider side): a road area whose blocks are holes gives its
        street network, one branch per street segment between two crossings (see :func:`_channel_islands`).
    end_cap, progress
        As in :func:`polygon_centerline` (``end_cap`` leaves the ends at junctions as they are).
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
    split_points, sources = _network_ends(
        polygon, split_points, gates, islands, channel_islands, min_arm_ratio, min_arm_length
    )
    order = _ring_order(polygon, split_points, snap_tolerance)
    points = [_as_xy(split_points[index]) for index in order]
    chains = _bridged_chains(polygon, points, snap_tolerance, islands)
    junctions = _Junctions(_Boundary(chains, extent_of(*chains, *channel_islands), channel_islands))
    pieces = _traced_pieces(chains, junctions, _runs(chains, spacing, progress, engine_options, channel_islands))
    branches, centres, radii = _assemble(pieces, junctions, order, loops=len(channel_islands))
    if end_cap == "runout":
        region = polygon if islands == "main_channel" else Polygon(polygon.exterior)
        branches = [replace(branch, result=run_out_ends(branch.result, region)) for branch in branches]
    return _network_result(branches, centres, radii, chains, order, sources, (spikes,) if spikes else ())


def _network_result(branches, centres, radii, chains, order, sources, notes):
    """The :class:`NetworkResult` of a network's branches, junctions (``centres``, ``radii``) and chains
    (in ring order; ``order[m]`` is the end chain ``m`` starts at)."""
    k = len(chains)
    snapped = np.empty((k, 2))
    snapped[order] = np.array([chain[0] for chain in chains])
    return NetworkResult(
        branches=tuple(branches),
        split_points=snapped,
        chains=tuple((order[m], order[(m + 1) % k]) for m in range(k)),
        junctions=centres,
        junction_radii=radii,
        chain_nodes=tuple((order[m], order[(m + 1) % k]) for m in range(k)),
        end_sources=tuple(sources),
        ends_from=ends_from(sources),
        notes=notes,
    )


def _network_ends(polygon, split_points, gates, islands, channel_islands, min_arm_ratio, min_arm_length):
    """The ends of a network (the given split points, the gates, then the automatic arm ends when fewer than two
    points are given) and the source of each (``"split_point"``, ``"gate"``, ``"automatic"``)."""
    split_points = [] if split_points is None else list(split_points)
    given = len(split_points)
    gates = [] if gates is None else list(gates)
    sources = ["split_point"] * given + ["gate"] * len(gates)
    split_points = split_points + gates
    if given < 2:
        region = polygon if islands == "main_channel" else Polygon(polygon.exterior)
        every_island = bool(channel_islands)
        if every_island:
            # The arms of a polygon with channel islands go round them too (a road grid's streets).
            region = Polygon(polygon.exterior, channel_islands)
        split_points = with_automatic_ends(region, split_points, min_arm_ratio, min_arm_length, every_island)
    return split_points, sources + ["automatic"] * (len(split_points) - len(sources))


def _traced_pieces(chains, junctions, runs):
    """The pieces of the network's branches from its traced ``runs`` (one per chain, then the loop runs; None
    for a run not traced), cut where their feet change chain (at the junctions, located together)."""
    k = len(chains)
    boundary = junctions.boundary
    traced = [(i, run) for i, run in enumerate(runs) if run is not None]
    feet = [np.asarray(result.foot_b, dtype=float) for _, (result, _) in traced]
    on_ring = np.split(boundary.chain_at(np.concatenate(feet)), np.cumsum([len(f) for f in feet])[:-1])
    labelled = [
        (i, result, _vertex_labels(result, i, boundary, bridged, ring_labels, loop=i >= k))
        for (i, (result, bridged)), ring_labels in zip(traced, on_ring)
    ]
    junctions.locate_ahead([request for run in labelled for request in _label_changes(*run)])
    pieces = []
    for i, result, labels in labelled:
        pieces.extend(
            _run_pieces(result, i, labels, junctions) if i < k else _loop_pieces(result, i, labels, junctions)
        )
    return pieces


def ends_from(sources):
    """Return :attr:`NetworkResult.ends_from` for the sources of the ends.

    Parameters
    ----------
    sources : sequence of {"split_point", "gate", "automatic"}
        Per end, where it came from.

    Returns
    -------
    str
        The sources present, in the order split points, gates, automatic ends, joined by ``"_and_"``:
        ``"split_points"``, ``"gates"``, ``"automatic"``, ``"split_points_and_automatic"``,
        ``"gates_and_automatic"``, ``"split_points_and_gates"`` or ``"split_points_and_gates_and_automatic"``.

    Examples
    --------
    >>> ends_from(["gate", "gate", "gate"]), ends_from(["gate", "automatic"])
    ('gates', 'gates_and_automatic')
    """
    names = {"split_point": "split_points", "gate": "gates", "automatic": "automatic"}
    return "_and_".join(names[source] for source in names if source in sources)


def with_automatic_ends(polygon, split_points, min_arm_ratio=MIN_ARM_RATIO, min_arm_length=None, every_island=False):
    """Return the given points followed by the automatic arm ends they do not replace.

    A given point replaces the automatic end nearest to it when it lies within that arm's width of it (a
    split point placed anywhere across the arm's end).

    Parameters
    ----------
    polygon : Polygon
        CRS units; its holes as the network sees them.
    split_points : sequence of Point or (x, y)
        CRS units (one split point and any gates).
    min_arm_ratio, min_arm_length, every_island : float, float, bool
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
    arms = find_arm_ends(polygon, min_arm_ratio=min_arm_ratio, min_arm_length=min_arm_length, every_island=every_island)
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


def multipolygon_networks(geometry, split_points=None, *, snap_tolerance=None, gates=None, **options):
    """Network of each part of a polygon or multipolygon between the split points on its exterior ring; of each
    geometry of an array.

    A part takes the split points within ``snap_tolerance`` of its exterior ring; with fewer than two, the
    ends of its arms are found automatically (see :func:`polygon_network`). A part that fails does not stop
    the others. An array-like of geometries gives a list, per geometry its list of outcomes or the exception
    it raised, as :func:`.api.polygon_centerline` computes an array (``split_points`` and ``gates``: None, or
    one sequence, or None, per geometry; each network traces its own runs together, one geometry after the
    other).

    Parameters
    ----------
    geometry : Polygon or MultiPolygon, or array_like of them
        CRS units.
    split_points : sequence of Point or (x, y), optional
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
    progress = options.pop("progress", None)
    options.update(snap_tolerance=snap_tolerance, gates=gates)
    return one_or_many(
        _multipolygon_network_steps, geometry, split_points, options, progress, ("gates",), NETWORK_BATCH_FEATURES
    )


def _multipolygon_network_steps(geometry, split_points=None, *, snap_tolerance=None, gates=None, **options):
    """:func:`multipolygon_networks` of one geometry as a step generator (:mod:`._steps`) that needs no shared
    tracing: it computes its networks when first advanced and returns their outcomes."""
    return _networks_of_parts(geometry, split_points, snap_tolerance, gates, options)
    yield  # a generator function: computed in an array's batch like the centerlines


def _networks_of_parts(geometry, split_points, snap_tolerance, gates, options):
    """The outcomes of :func:`multipolygon_networks` for one geometry."""
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
        complements = [_channel_complement(chains, i, channel_islands) for i in range(len(complements))]
    steps = [
        centerline_steps(chains[i], complement, spacing, **engine_options) for i, complement in enumerate(complements)
    ]
    loops = [_loop_chains(chains, channel_islands, j) for j in range(len(channel_islands))]
    steps += [clean_chains_steps(*loop, spacing, **engine_options) for loop in loops if loop is not None]
    results = run_together(steps, progress=progress)
    for result in results:
        if isinstance(result, Exception):
            raise result
    bridged = [complement if channel_islands else None for complement in complements]
    traced = iter(results[len(complements) :])
    return list(zip(results, bridged)) + [None if loop is None else (next(traced), loop[1]) for loop in loops]


def _channel_complement(chains, i, islands):
    """Return ``D_i`` with the channel islands for run ``i``: the boundary near ``C_i``, islands included.

    The region within ``LOOP_REACH`` times ``C_i``'s widest channel of it (the polygon clipped there, beyond
    every circle touching ``C_i``) has the islands reaching into it as notches of its outline, so ``D_i`` runs
    round them without a slit (a slit across a channel would be a wall there); only the islands wholly
    inside it are joined by slits (:func:`bridge_islands`). Where that region is not one polygon holding
    ``C_i`` as it is, every island is joined by a slit.
    """
    complement = _complement(chains, i)
    chain = chains[i]
    rings = [Polygon(island) for island in islands]
    rest = shapely.MultiLineString([complement, *islands])
    samples = shapely.points(shapely.get_coordinates(shapely.segmentize(LineString(chain), _sampling(chain))))
    reach = LOOP_REACH * float(np.max(shapely.distance(samples, rest)))
    near = LineString(chain).buffer(reach, join_style="mitre")
    whole = Polygon(np.concatenate([chain, complement[::-1][1:]]), list(islands))
    try:
        parts = [
            part for part in shapely.get_parts(shapely.intersection(whole, near)) if part.intersects(LineString(chain))
        ]
    except GEOSException:  # the outline's chains carry the slits of its small islands: GEOS may refuse them
        parts = []
    if len(parts) == 1:
        ring = shapely.get_coordinates(shapely.geometry.polygon.orient(parts[0], 1.0).exterior)[:-1]
        first = np.flatnonzero(np.all(ring == chain[0], axis=1))
        if len(first) == 1:
            ring = np.roll(ring, -int(first[0]), axis=0)
            if len(ring) > len(chain) and np.array_equal(ring[: len(chain)], chain):
                local = np.concatenate([ring[len(chain) - 1 :], ring[:1]])[::-1]
                outline = Polygon(parts[0].exterior)
                inside = [island for island, polygon in zip(islands, rings) if outline.contains(polygon)]
                if not inside:
                    return local
                return bridge_islands(chain, local, inside, to_second=[True] * len(inside))[1]
    return bridge_islands(chain, complement, islands, to_second=[True] * len(islands))[1]


def _loop_chains(chains, islands, j):
    """Return the two closed chains of channel island ``j``'s loop run, or None when it needs none.

    The run traces the axis around the island between its ring and the rest of the boundary *near* it: the
    region within ``LOOP_REACH`` times the island's widest channel of it (the polygon clipped there; the clip
    lies beyond every circle touching the island and its neighbours across those channels). That region has
    the island as its one hole (other islands reaching into it become notches of its outline): both rings
    counter-clockwise from the seam, the closest pair of points between them, as :func:`.rings.seam_chains`.
    A loop is traced only for an island with another channel island within that reach (the branches between
    two islands come from it; the others from the runs along the outline).
    """
    ring = np.concatenate([chains[0], *[chain[1:] for chain in chains[1:]]])
    island = np.asarray(islands[j], dtype=float)
    others = [other for m, other in enumerate(islands) if m != j]
    if not others:
        return None
    rest = shapely.MultiLineString([ring, *others])
    samples = shapely.points(shapely.get_coordinates(shapely.segmentize(LineString(island), _sampling(island))))
    reach = LOOP_REACH * float(np.max(shapely.distance(samples, rest)))
    near = Polygon(island).buffer(reach, join_style="mitre")
    if not any(near.intersects(Polygon(other)) for other in others):
        return None
    inside = Polygon(island).representative_point()
    try:
        region = shapely.intersection(Polygon(ring, [island, *others]), near)
    except GEOSException:  # the outline's chains carry the slits of its small islands: GEOS may refuse them
        return None
    for part in shapely.get_parts(region):
        holes = [hole for hole in part.interiors if Polygon(hole).contains(inside)]
        if len(holes) == 1 and Polygon(part.exterior).contains(inside):
            outer, inner = seam_chains(shapely.geometry.polygon.orient(Polygon(part.exterior, holes), 1.0))
            # Islands wholly within the reach (blocks narrower than their streets) are joined by slits.
            others = [shapely.get_coordinates(hole) for hole in part.interiors if hole is not holes[0]]
            others = [hole for hole in others if not np.array_equal(hole, shapely.get_coordinates(holes[0]))]
            if others:
                outer = bridge_islands(inner, outer, others, to_second=[True] * len(others))[1]
            return inner, outer
    return None


def _sampling(line):
    """Return the distance between the ``LOOP_SAMPLES`` samples of a chain or ring that measure its widest
    channel (their largest distance to the rest of the boundary), CRS units."""
    return float(cumulative_lengths(np.asarray(line, dtype=float))[-1]) / LOOP_SAMPLES


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


def _insert_vertices(chain, points, coincidence):
    """Return ``chain`` with each point projected onto it as a vertex, and each point's vertex index.

    A point equal to exactly one vertex is that vertex; a point projecting within ``coincidence`` (CRS units,
    along the chain) of a vertex is that vertex; the others are inserted where they project, all at once
    (several on one segment in their order along it).
    """
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    cumulative = cumulative_lengths(chain)
    positions = shapely.line_locate_point(LineString(chain), shapely.points(points))
    vertex = np.full(len(points), -1, dtype=np.int64)
    for row, point in enumerate(points):
        exact = np.flatnonzero(np.all(chain == point, axis=1))
        if len(exact) == 1:
            vertex[row] = exact[0]
            continue
        nearest = int(np.argmin(np.abs(cumulative - positions[row])))
        if abs(cumulative[nearest] - positions[row]) <= coincidence:
            vertex[row] = nearest
    new = np.flatnonzero(vertex < 0)
    if not len(new):
        return chain, vertex
    new = new[np.argsort(positions[new], kind="stable")]
    at = np.searchsorted(cumulative, positions[new], side="right")
    xy = shapely.get_coordinates(shapely.line_interpolate_point(LineString(chain), positions[new]))
    shift = np.searchsorted(at, vertex, side="right")  # inserted before (or at) each old vertex
    index = np.where(vertex >= 0, vertex + shift, 0)
    index[new] = at + np.arange(len(new))
    return np.insert(chain, at, xy, axis=0), index


def _bridged_chains(polygon, points, tolerance, islands):
    """Return the chains ``C_0 .. C_{k-1}`` (counter-clockwise, islands joined) between ring-ordered points.

    ``C_0`` and ``D_0`` come from :func:`split_polygon` exactly as in :func:`polygon_centerline`; the other
    split points are inserted into ``D_0``, the islands are joined to ``C_0`` or ``D_0`` once, and ``D_0`` is
    cut at the other split points.
    """
    c1, c2 = split_polygon(polygon, points[:2], tolerance)
    coincidence = COINCIDENCE_TOLERANCE * extent_of(c1, c2)
    if len(points) > 2:
        c2, _ = _insert_vertices(c2, points[2:], coincidence)
    if islands == "main_channel" and polygon.interiors:
        c1, c2 = bridge_islands(c1, c2, [shapely.get_coordinates(ring) for ring in polygon.interiors])
    cuts = []
    if len(points) > 2:
        c2, index = _insert_vertices(c2, points[:1:-1], coincidence)
        cuts = index.tolist()
    if cuts != sorted(cuts) or len(set(cuts)) != len(cuts) or (cuts and (cuts[0] == 0 or cuts[-1] == len(c2) - 1)):
        raise IncirCuError(Message("network_order"))
    bounds = [0, *cuts, len(c2) - 1]
    backwards = [c2[start : end + 1][::-1].copy() for start, end in zip(bounds[:-1], bounds[1:])]
    return [np.asarray(c1, dtype=float)] + backwards[::-1]


def _complement(chains, i):
    """Return ``D_i``: the other chains from ``p_i`` backwards to ``p_{i+1}``, as one chain."""
    k = len(chains)
    return np.concatenate([chains[(i - step) % k][::-1][(step > 1) :] for step in range(1, k)])


def _vertex_labels(result, i, boundary, bridged=None, on_ring=None, loop=False):
    """Label each vertex of run ``i`` with the chain its foot on ``D_i`` lies on, in ``D_i``'s order.

    Each foot lies on the ring (the chains end to end, counter-clockwise): its arc length there names its
    chain (one index query for all the feet of the run). A foot at ``p_i`` or ``p_{i+1}`` itself, which the
    ring may place on ``C_i``, takes the neighbouring chain. Labels that go back against ``D_i``'s order (a
    foot at the very junction) take the label before them. ``on_ring``: the feet's chains on the ring, when
    already found (:meth:`_Boundary.chain_at` of all runs' feet at once), changed in place.
    """
    k = boundary.exterior_count
    feet = np.asarray(result.foot_b, dtype=float)
    labels = boundary.chain_at(feet) if on_ring is None else on_ring
    if loop:
        return _island_labels(feet, labels, boundary)
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


def _island_labels(feet, labels, boundary):
    """Labels of channel island ``j``'s loop run (``i = k + j``): the chain each foot lies on, ``k + m`` on
    island ``m``."""
    k = boundary.exterior_count
    for m, ring in enumerate(boundary.chains[k:]):
        on = IndexedPolyline(ring).nearest(feet)[0] <= JUNCTION_TOLERANCE * boundary.extent
        labels[on] = k + m
    return labels


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
        #: :meth:`nearest`'s answers by (x, y, chain): a junction's feet are asked for again by its branches.
        self.known = {}
        self.segments = self.segment_counts = None
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
        memo = (float(point[0]), float(point[1]), int(chain))
        if memo in self.known:
            return self.known[memo]
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
            self.known[memo] = float(distance[0]), foot[0]
            return self.known[memo]
        start, direction, squared = indexed
        offset = point - start
        along = np.clip(np.einsum("ij,ij->i", offset, direction) / np.where(squared > 0.0, squared, 1.0), 0.0, 1.0)
        gap = offset - along[:, None] * direction
        distances = np.hypot(gap[:, 0], gap[:, 1])
        nearest = int(np.argmin(distances))
        self.known[memo] = float(distances[nearest]), start[nearest] + along[nearest] * direction[nearest]
        return self.known[memo]

    def nearest_many(self, points, chains):
        """Return the distance from each point to its chain and the foot there, as :meth:`nearest` for each.

        Parameters
        ----------
        points : ndarray of shape (n, 2)
            CRS units.
        chains : ndarray of shape (n,) of int

        Returns
        -------
        distances : ndarray of shape (n,)
        feet : ndarray of shape (n, 2)
        """
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        chains = np.asarray(chains, dtype=np.int64)
        distances, feet = np.empty(len(points)), np.empty((len(points), 2))
        for chain in np.unique(chains):
            if self.indexed[int(chain)] is None:
                self.nearest(points[0], int(chain))  # builds the chain's arrays or index
                self.segments = None
        small = np.array([not isinstance(self.indexed[int(chain)], IndexedPolyline) for chain in chains], dtype=bool)
        for chain in np.unique(chains[~small]):
            rows = np.flatnonzero(chains == chain)
            distance, _, foot = self.indexed[int(chain)].nearest(points[rows])
            distances[rows], feet[rows] = distance, foot
        rows = np.flatnonzero(small)
        if len(rows):
            distances[rows], feet[rows] = self._brute_force(points[rows], chains[rows])
        return distances, feet

    def _brute_force(self, points, chains):
        """:meth:`nearest_many` for chains measured segment by segment: every (point, segment of its chain)
        pair in one numpy pass, the first nearest segment of each point kept (as :meth:`nearest`)."""
        if self.segments is None:
            # Every chain's segments end to end (an indexed chain has none here), and where each chain's start.
            arrays = [
                item if isinstance(item, tuple) else (np.empty((0, 2)),) * 2 + (np.empty(0),) for item in self.indexed
            ]
            self.segments = tuple(np.concatenate([item[n] for item in arrays]) for n in range(3))
            self.segment_counts = np.array([len(item[2]) for item in arrays], dtype=np.int64)
        counts = self.segment_counts[chains]
        owner = np.repeat(np.arange(len(points)), counts)
        firsts = np.cumsum(counts) - counts
        rows = np.arange(len(owner)) - np.repeat(firsts, counts)
        rows += np.repeat((np.cumsum(self.segment_counts) - self.segment_counts)[chains], counts)
        start, direction, squared = (values[rows] for values in self.segments)
        offset = points[owner] - start
        dot = offset[:, 0] * direction[:, 0] + offset[:, 1] * direction[:, 1]
        along = np.clip(dot / np.where(squared > 0.0, squared, 1.0), 0.0, 1.0)
        gap = offset - along[:, None] * direction
        distances = np.hypot(gap[:, 0], gap[:, 1])
        smallest = np.minimum.reduceat(distances, firsts)
        at_min = np.flatnonzero(distances == smallest[owner])
        _, first = np.unique(owner[at_min], return_index=True)
        nearest = at_min[first]
        return distances[nearest], start[nearest] + along[nearest, None] * direction[nearest]

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
        #: Centres located ahead by :meth:`locate_ahead`, by their three chains, taken by :meth:`between`.
        self.located = {}

    def locate_ahead(self, requests):
        """Locate at once (:func:`_newton_many`) the junctions :meth:`between` will be asked for.

        Parameters
        ----------
        requests : list of (int, int, int, ndarray, ndarray)
            ``(i, a, b, start, end)`` of each label change, in the order :meth:`between` will see them: the
            first request of each junction of three outline chains decides its start, as it would alone.
        """
        k = self.boundary.exterior_count
        first = {}
        for i, a, b, start, end in requests:
            key = tuple(sorted((i, a, b)))
            if max(key) < k and len(set(key)) == 3 and key not in self.by_chains and key not in first:
                first[key] = 0.5 * (start + end)
        if not first:
            return
        keys = list(first)
        centres = _newton_many(self.boundary, np.array(keys), np.array([first[key] for key in keys]))
        settled = np.flatnonzero(np.all(np.isfinite(centres), axis=1))
        distances, feet = self.boundary.nearest_many(
            np.repeat(centres[settled], 3, axis=0), np.array(keys)[settled].ravel()
        )
        for row, index in enumerate(settled):
            self.located[keys[index]] = centres[index]
            x, y = (float(value) for value in centres[index])
            for column, chain in enumerate(keys[index]):
                self.boundary.known[(x, y, int(chain))] = float(distances[3 * row + column]), feet[3 * row + column]

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
            centre = self.located.pop(key) if key in self.located else None
            if centre is None:
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


def _newton_many(boundary, keys, starts):
    """:func:`_newton_from` for many junctions at once: the same iteration, vectorised over the junctions.

    Parameters
    ----------
    boundary : _Boundary
    keys : ndarray of shape (m, 3) of int
        Each junction's three chains.
    starts : ndarray of shape (m, 2)
        Where each iteration starts, CRS units.

    Returns
    -------
    ndarray of shape (m, 2)
        The junctions, NaN where the iteration did not settle (the caller tries :func:`_newton_junction`).
    """
    count = len(keys)
    x = np.array(starts, dtype=float)
    floor = 4.0 * np.spacing(np.max(np.abs(x), axis=1) + boundary.extent)
    chains = keys.ravel()

    def residual(points, rows):
        distances, feet = boundary.nearest_many(np.repeat(points, 3, axis=0), chains.reshape(-1, 3)[rows].ravel())
        distances, feet = distances.reshape(-1, 3), feet.reshape(-1, 3, 2)
        return distances[:, :1] - distances[:, 1:], distances, feet

    value, distances, feet = residual(x, np.arange(count))
    found = np.full((count, 2), np.nan)
    active = np.arange(count)
    for _ in range(NEWTON_STEPS):
        if not len(active):
            break
        here = x[active]
        bad = np.any(distances <= 0.0, axis=1)
        gradients = (here[:, None, :] - feet) / np.where(bad[:, None], 1.0, distances)[:, :, None]
        rows = gradients[:, :1] - gradients[:, 1:]
        a, b, c, d = rows[:, 0, 0], rows[:, 0, 1], rows[:, 1, 0], rows[:, 1, 1]
        determinant = a * d - b * c
        bad |= (determinant == 0.0) | ~np.isfinite(determinant)
        safe = np.where(bad, 1.0, determinant)
        step = np.stack([d * -value[:, 0] - b * -value[:, 1], a * -value[:, 1] - c * -value[:, 0]], axis=1)
        step = step / safe[:, None]
        step[bad] = 0.0
        size = np.max(np.abs(value), axis=1)
        trial = [value.copy(), distances.copy(), feet.copy()]
        searching = np.flatnonzero(~bad)
        for _ in range(40):
            if not len(searching):
                break
            got = residual(here[searching] + step[searching], active[searching])
            for store, new in zip(trial, got):
                store[searching] = new
            done = (np.max(np.abs(got[0]), axis=1) < size[searching]) | (
                np.hypot(*step[searching].T) <= floor[active[searching]]
            )
            searching = searching[~done]
            step[searching] = 0.5 * step[searching]
        x[active] = here + step
        value, distances, feet = trial
        settled = ~bad & (np.hypot(*step.T) <= floor[active])
        found[active[settled]] = x[active[settled]]
        keep = ~bad & ~settled
        active, value, distances, feet = active[keep], value[keep], distances[keep], feet[keep]
    close = np.max(np.abs(value), axis=1) <= JUNCTION_TOLERANCE * boundary.extent if len(active) else []
    found[active[close]] = x[active[close]]
    return found


def _label_changes(i, result, labels):
    """Return ``(i, a, b, start, end)`` for each change of label ``a`` to ``b`` along run ``i``, between the
    vertices ``start`` and ``end`` (what :func:`_run_pieces` asks :meth:`_Junctions.between`)."""
    vertices = shapely.get_coordinates(result.line)
    return [
        (i, int(labels[c]), int(labels[c + 1]), vertices[c], vertices[c + 1])
        for c in np.flatnonzero(labels[1:] != labels[:-1])
    ]


def _run_pieces(result, i, labels, junctions, start_node=None, end_node=None):
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
    node = ("leaf", i) if start_node is None else start_node
    pieces = []
    for first, stop in zip(starts, stops):
        label = int(labels[first])
        found = []
        if stop < len(labels):
            vertices = arrays["vertices"]
            found = junctions.between(i, label, int(labels[stop]), vertices[stop - 1], vertices[stop])
        end = ("junction", found[0][0]) if found else (("leaf", (i + 1) % k) if end_node is None else end_node)
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


def _loop_pieces(result, i, labels, junctions):
    """:func:`_run_pieces` of a channel island's loop run (closed: from its seam round to it): the loop is
    turned to start at its first label change, so every piece runs from a junction to a junction."""
    changes = np.flatnonzero(labels[1:] != labels[:-1])
    if not len(changes):
        return []
    start = int(changes[0]) + 1
    order = np.concatenate([np.arange(start, len(labels) - 1), np.arange(0, start)])
    turned = CenterlineResult(
        line=LineString(shapely.get_coordinates(result.line)[order]),
        radii=np.asarray(result.radii, dtype=float)[order],
        foot_a=np.asarray(result.foot_a, dtype=float)[order],
        foot_b=np.asarray(result.foot_b, dtype=float)[order],
    )
    vertices = shapely.get_coordinates(result.line)
    found = junctions.between(i, int(labels[start - 1]), int(labels[start]), vertices[start - 1], vertices[start])
    node = ("junction", found[-1][0])
    return _run_pieces(turned, i, labels[order], junctions, start_node=node, end_node=("junction", found[0][0]))


def _empty():
    """Arrays of a piece with no run vertex (a branch shorter than the sampling)."""
    return {"vertices": np.empty((0, 2)), "radii": np.empty(0), "foot_a": np.empty((0, 2)), "foot_b": np.empty((0, 2))}


def _junction_clusters(junctions):
    """Map each junction key to the key of its cluster (junctions within ``JUNCTION_TOLERANCE``): that of the
    first junction, in the keys' order, within the tolerance of it (itself when none is before it)."""
    keys = sorted(junctions.by_chains)
    if not keys:
        return {}
    tolerance = JUNCTION_TOLERANCE * junctions.boundary.extent
    centres = np.array([junctions.by_chains[key][0] for key in keys])
    near, other = shapely.STRtree(shapely.points(centres)).query(
        shapely.points(centres), predicate="dwithin", distance=tolerance
    )
    first = np.arange(len(keys))
    np.minimum.at(first, near, other)
    cluster = {}
    for index, key in enumerate(keys):
        cluster[key] = cluster[keys[first[index]]] if first[index] < index else key
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
