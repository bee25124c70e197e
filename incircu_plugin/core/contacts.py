"""Contact kernels: the first boundary contact of a family of growing disks, in closed form and in bulk.

For every sample ``P`` of a chain with inward direction ``b`` the disk family has centre ``P + t*b`` and
radius ``k*t`` (``k = 1`` on an edge or at a reflex vertex, ``k = sin(alpha/2)`` on the bisector of a convex
vertex of interior angle ``alpha``); it touches the chain at ``P`` only. :func:`solve` finds the first ``t``
at which the disk touches any other part of the boundary, in closed form per segment, and which *site*
(a segment's interior or a vertex) it touches there. When that first contact lies on the *other* chain the
disk is a maximal empty disk touching both chains, so its centre lies on the medial axis between them.

Candidate segments come from a grid over runs of consecutive segments (:class:`BoxGrid`) queried in bulk
with the bounding box of a trial disk; a sample is settled once its first contact lies inside the trial disk,
otherwise the trial parameter at most doubles, up to the best contact found so far.
"""

import math
from dataclasses import dataclass
from functools import partial

import numpy as np

from ._arrays import ArrayRecord, group_minima, put_rows, ranges, rows
from .errors import InvalidGeometryError, Message
from .polyline import ROUNDING_SPACINGS, coordinate_rounding, cumulative_lengths

#: Relative slack (of a segment's length) with which a tangency at a segment's end still counts as inside.
ALONG_TOLERANCE = 1e-9

#: Relative distance (of the vertex from the sample) within which a vertex counts as on a corner's edge line.
GRAZING_TOLERANCE = 1e-10

#: Relative distance (of the contact parameter) from the sample point within which a vertex is not touched.
NEAR_VERTEX = 1e-7

#: Status of a sample: its first contact is on its own chain (or nowhere), on both chains within
#: ``TIE_TOLERANCE``, or on the other chain only.
SKIPPED, TIED, CLEAR = 0, 1, 2

#: Relative slack with which a contact on the other chain still wins over a tie on the sample's own chain.
TIE_TOLERANCE = 1e-10

#: Samples given to one solve (bounds the memory of the per-sample arrays; ``SOLVE_BLOCK`` and ``SOLVE_PAIRS``
#: bound that of the candidate pairs).
CHUNK = 16_384

#: Most samples in one round of :func:`solve` (a block: the samples still pending, then fresh ones), so that a
#: block's (sample, segment) pairs stay in the processor's cache; and most (sample, segment) pairs of a block,
#: judged from the pairs per sample of the round before that took fresh samples (a boundary with many vertices
#: per width has hundreds of pairs per sample). Each sample is solved from its own candidate pairs, so the blocks
#: change no result. The measurements behind both: docs/core-notes.md.
SOLVE_BLOCK = 4096
SOLVE_PAIRS = 1 << 16

#: Ratio between the sample strides of two levels of the coarse-to-fine solution, and the number of levels
#: above the finest one for features with enough samples.
COARSE_STRIDE = 8
COARSE_LEVELS = 2

#: Smallest trial radius of the coarse-to-fine solution, as a fraction of the global one.
SMALLEST_TRIAL = 1.0 / 16.0

#: Most consecutive samples whose candidate boxes share one spatial-index query: consecutive boxes overlap along
#: a chain, so one query serves several (the grouping changes no pair; measured in docs/core-notes.md).
QUERY_GROUP = 8

#: Consecutive segments that share one entry of the spatial index (a smaller index; a run's hits are filtered
#: segment by segment).
INDEX_RUN = 8

#: Most cells of a :class:`BoxGrid`, and most (box, cell) entries, per box indexed (more cells keep them fine
#: where a boundary is sparse in a large extent).
GRID_CELLS = 16

#: Side of a :class:`BoxGrid`'s cells, in mean extents of its boxes.
GRID_CELL_SIDE = 2.0

#: Most segments of a :class:`Boundary`: its sites (segments and vertices) are indexed with int32.
MAX_SEGMENTS = 2**30 - 1

#: Most (box, segment) pairs that :meth:`Boundary.candidates` tests all at once instead of querying the index.
ALL_PAIRS = 1 << 15


@dataclass(frozen=True)
class Samples(ArrayRecord):
    """Samples of the chains, sorted by chain, then by arc-length ``position`` along it.

    The disk family of sample ``i`` has centre ``point + t*direction`` and radius ``scale*t``; segments
    ``first_own..last_own`` (global indices) touch it by construction. At a convex vertex the disk touches
    the incident edges ``slide*t`` away from the vertex (``slide`` is 0 elsewhere). ``chain`` is the
    sample's own chain (0 or 1).
    """

    chain: np.ndarray
    point: np.ndarray
    direction: np.ndarray
    scale: np.ndarray
    position: np.ndarray
    slide: np.ndarray
    first_own: np.ndarray
    last_own: np.ndarray


class Boundary:
    """The segments of both chains, with a spatial index.

    A *site* is what a disk can touch: the interior of segment ``g`` (site ``g``) or a vertex (site
    ``segment_count + v``, with ``v`` the vertex's index in ``vertex``, the chains' vertices one chain after
    the other). Segment ``g`` runs from vertex ``g + chain_id[g]`` (:meth:`start_vertex`) to the next one.
    Per segment it holds one copy of each quantity (the x and y columns of ``start`` and ``unit`` are views;
    the bounding boxes are four contiguous columns, which the candidate search gathers from; end points are
    read from ``vertex``), coordinates and lengths in float64 (CRS units), chain ids and sites in int32.

    ``input_rounding`` (per chain, CRS units; None: none) is the rounding of each chain's coordinates where they
    come from (:func:`.polyline.coordinate_rounding` before the shift into this frame): a split point inserted
    far from the origin is placed to that, not to this frame's rounding.

    ``index_shift`` (per chain, shape (chains, 2), CRS units; None: none) moves each chain's segments in the
    spatial index only: a joint tracing of several features, each in its own frame about the origin, places
    their segments side by side in the index (a feature's candidate search then meets its own segments only)
    while every computed value uses the unshifted coordinates, so a feature's result does not depend on the
    other features traced with it. Adding the same shift to two numbers keeps their order (rounding is
    monotone), so a shifted box meets every box it met unshifted.
    """

    def __init__(self, chains, input_rounding=None, index_shift=None):
        sizes = np.array([len(chain) - 1 for chain in chains])
        count = int(sizes.sum())
        if count + len(chains) > MAX_SEGMENTS:
            raise InvalidGeometryError(Message("too_many_segments", count=count))
        self.segment_count = count
        #: More than one pair of chains (a joint tracing of several features, see :mod:`._steps`): chains
        #: ``2k`` and ``2k + 1`` belong together and never touch another pair's.
        self.several_pairs = len(chains) > 2
        self.offset = list(np.cumsum(sizes) - sizes)
        self.vertex = np.concatenate(chains)
        self.vertex_position = np.concatenate([cumulative_lengths(chain) for chain in chains])
        vertex_offset = self.offset + np.arange(len(chains))
        #: Per chain, the arc length of every vertex (views of ``vertex_position``), CRS units.
        self.position = [self.vertex_position[o : o + s + 1] for o, s in zip(vertex_offset, sizes)]
        self.vertex_chain = np.repeat(np.arange(len(chains), dtype=np.int32), sizes + 1)
        self.chain_id = np.repeat(np.arange(len(chains), dtype=np.int32), sizes)
        self.last_of_chain = np.zeros(count, dtype=bool)
        self.last_of_chain[np.cumsum(sizes) - 1] = True
        self.first_of_chain = np.zeros(count, dtype=bool)
        self.first_of_chain[self.offset] = True
        # Per segment its start and end vertex, chain by chain: slices copied one after the other (cheaper
        # than gathering by index).
        self.start = _per_segment(self.vertex, vertex_offset, sizes)
        self.segment_position = _per_segment(self.vertex_position, vertex_offset, sizes)
        self.segment_end_position = _per_segment(self.vertex_position, vertex_offset + 1, sizes)
        self.start_site = self.start_vertex(np.arange(count, dtype=np.int32))
        self.start_site += np.int32(count)
        end = _per_segment(self.vertex, vertex_offset + 1, sizes)
        # Bounding boxes column by column: contiguous columns gather about twice as fast as strided ones.
        self.low_x, self.high_x = np.minimum(self.start[:, 0], end[:, 0]), np.maximum(self.start[:, 0], end[:, 0])
        self.low_y, self.high_y = np.minimum(self.start[:, 1], end[:, 1]), np.maximum(self.start[:, 1], end[:, 1])
        # The end points become the segments' vectors, then their units, in place.
        end -= self.start
        self.length = np.hypot(end[:, 0], end[:, 1])
        end /= self.length[:, None]
        self.unit = end
        self.mean_length = float(self.length.mean()) if count else 0.0
        #: Height above a sample's tangent line under which a vertex lies on it up to rounding
        #: (:func:`.polyline.coordinate_rounding`), CRS units. Such a vertex is touched only through rounding, at
        #: any ``t``: the other chain's copy of a split point, seen from the own chain's end segment (which ends
        #: there), in a joint tracing's frame far from the origin.
        #: Per segment, the rounding of its pair of chains (a float for one pair): what the pair's result may
        #: depend on, whichever other pairs share the boundary.
        self.rounding = (
            _pair_rounding(self.vertex, sizes + 1) if self.several_pairs else coordinate_rounding(self.vertex)
        )
        #: Per chain, the larger of its pair's rounding and the chain's ``input_rounding``, CRS units.
        self.chain_rounding = (
            self.rounding[self.offset] if self.several_pairs and count else np.full(len(chains), self.rounding)
        )
        if input_rounding is not None:
            np.maximum(self.chain_rounding, input_rounding, out=self.chain_rounding)
        del end
        # Coordinate columns as views (no copies).
        self.start_x, self.start_y = self.start[:, 0], self.start[:, 1]
        self.unit_x, self.unit_y = self.unit[:, 0], self.unit[:, 1]
        #: Per chain, the shift of its segments' boxes in the spatial index (None: none), CRS units.
        self.index_shift = None if index_shift is None else np.asarray(index_shift, dtype=float)
        if self.index_shift is not None:
            # The boxes serve the candidate search only: shifted in place, per segment by its chain's shift.
            for column, axis in ((self.low_x, 0), (self.high_x, 0), (self.low_y, 1), (self.high_y, 1)):
                column += self.index_shift[:, axis].take(self.chain_id)
        # The index holds runs of INDEX_RUN consecutive segments: INDEX_RUN times fewer boxes to grid.
        run_start = np.arange(0, count, INDEX_RUN)
        self.run_low = np.stack([np.minimum.reduceat(column, run_start) for column in (self.low_x, self.low_y)], 1)
        self.run_high = np.stack([np.maximum.reduceat(column, run_start) for column in (self.high_x, self.high_y)], 1)
        self._index = None

    def start_vertex(self, segment):
        """Index in ``vertex`` of the start vertex of the segments ``segment`` (global indices)."""
        return segment + self.chain_id[segment]

    def end(self, segment):
        """End points of the segments ``segment`` (global indices)."""
        return rows(self.vertex, self.start_vertex(segment) + 1)

    @property
    def index(self):
        """The spatial index of the segments' runs (a :class:`BoxGrid`), built on first use (small inputs never
        need it)."""
        if self._index is None:
            self._index = BoxGrid(self.run_low, self.run_high)
        return self._index

    def release_index(self):
        """Free the spatial index (it is built again on the next use)."""
        self._index = None

    def candidates(self, low, high, chain=None):
        """Pairs (box index, segment index), each box's pairs consecutive, of segments whose bounding box meets
        a box (``low``, ``high``: its corners, CRS units, shifted here by the ``index_shift`` of its ``chain``, which
        is needed only with an ``index_shift``).

        With at most ``ALL_PAIRS`` (box, segment) pairs every pair is tested at once (no index to build or
        query: what small inputs and late rounds with a few boxes need). Otherwise the index is queried once
        per group of up to ``QUERY_GROUP`` consecutive boxes that each meet the one before (their union,
        :func:`_group_starts`), which is much cheaper than one query per box where consecutive boxes overlap,
        as they do along a chain; the runs found are then filtered segment by segment against their group's
        box, then against each of its boxes (:meth:`_split_groups`). Both give the same pairs, each once, in
        orders of their own (the first sorted by box, the second not; which changes no result: :func:`solve`
        takes minima per box and breaks ties by site).
        """
        count = len(low)
        if self.index_shift is not None:
            shift = rows(self.index_shift, chain)
            low, high = low + shift, high + shift
        if count * self.segment_count <= ALL_PAIRS:
            meets = (self.low_x <= high[:, 0, None]) & (self.high_x >= low[:, 0, None])
            meets &= (self.low_y <= high[:, 1, None]) & (self.high_y >= low[:, 1, None])
            return np.nonzero(meets)
        starts = _group_starts(low, high)
        group_low = np.minimum.reduceat(low, starts)
        group_high = np.maximum.reduceat(high, starts)
        group, run = self.index.query(group_low, group_high)
        # Every run found, segment by segment: a row per run (only the last run may be short: its missing
        # segments are the last one again, never kept).
        segment = run[:, None] * INDEX_RUN + np.arange(INDEX_RUN)
        real = None
        if len(run) and (run.max() + 1) * INDEX_RUN > self.segment_count:
            real = segment < self.segment_count
            np.minimum(segment, self.segment_count - 1, out=segment)
        keep = self._overlaps(segment, group[:, None], group_low, group_high)
        if real is not None:
            keep &= real
        # The kept entries' flat indices: numpy's nonzero of a two-dimensional mask is about twice as slow.
        kept = keep.reshape(-1).nonzero()[0]
        return self._split_groups(group.take(kept // INDEX_RUN), segment.reshape(-1).take(kept), starts, low, high)

    def _split_groups(self, group, segment, starts, low, high):
        """Pairs (box index, segment index), each box's pairs consecutive, from the pairs (group index, segment
        index) of the boxes' groups (sorted by group; group ``g`` holds boxes ``starts[g]`` up to the next
        group's first): each group's segments tested against its ``k``-th box, for each ``k`` in turn.

        Box ``starts[g] + k`` is only tested in turn ``k``, whose pairs come sorted by group, hence by box:
        the turns one after the other keep each box's pairs together (boxes in no overall order, no sort).
        """
        sizes = np.diff(starts, append=len(low))
        # The k-th box of every group, column by column: row k of an array of (turns, groups); past a group's
        # last box an empty one (low +inf, high -inf), which meets nothing.
        owner, rank = ranges(sizes)
        slot = rank * len(starts) + owner
        turns = []
        for column, empty in ((low[:, 0], np.inf), (high[:, 0], -np.inf), (low[:, 1], np.inf), (high[:, 1], -np.inf)):
            padded = np.full((int(sizes.max()), len(starts)), empty)
            padded.reshape(-1)[slot] = column
            turns.append(padded)
        box_low_x, box_high_x, box_low_y, box_high_y = turns
        # Segment columns gathered once for all boxes of a group.
        low_x, low_y = self.low_x.take(segment), self.low_y.take(segment)
        high_x, high_y = self.high_x.take(segment), self.high_y.take(segment)
        boxes, kept = [], []
        for turn in range(len(turns[0])):
            keep = low_x <= box_high_x[turn].take(group)
            keep &= high_x >= box_low_x[turn].take(group)
            keep &= low_y <= box_high_y[turn].take(group)
            keep &= high_y >= box_low_y[turn].take(group)
            # The kept rows' indices once, then gathers: cheaper than a boolean mask applied to two arrays.
            keep = keep.nonzero()[0]
            boxes.append(starts.take(group.take(keep)) + turn)
            kept.append(segment.take(keep))
        return np.concatenate(boxes), np.concatenate(kept)

    def within(self, segment, box, x, y, distance):
        """Whether each segment comes within ``distance[box]`` (CRS units) of the point ``(x[box], y[box])``
        (``x``, ``y`` and ``distance``: contiguous arrays, gathered with ``take``)."""
        ux, uy = self.unit_x[segment], self.unit_y[segment]
        dx, dy = x.take(box) - self.start_x[segment], y.take(box) - self.start_y[segment]
        along = dx * ux
        along += dy * uy
        np.minimum(np.maximum(along, 0.0, out=along), self.length.take(segment), out=along)
        # The offset from the nearest point, in place: (dx - along*ux)**2 + (dy - along*uy)**2.
        dx -= np.multiply(along, ux, out=ux)
        dy -= np.multiply(along, uy, out=uy)
        dx *= dx
        dy *= dy
        dx += dy
        return dx <= (distance * distance).take(box)

    def _overlaps(self, segment, box, low, high):
        """Whether each segment's bounding box meets the box ``low[box]..high[box]`` (gathered column by column:
        much cheaper than rows of a two-column array)."""
        keep = self.low_x.take(segment) <= high[:, 0][box]
        keep &= self.high_x.take(segment) >= low[:, 0][box]
        keep &= self.low_y.take(segment) <= high[:, 1][box]
        keep &= self.high_y.take(segment) >= low[:, 1][box]
        return keep


def _pair_rounding(vertex, sizes):
    """Per segment, :func:`.polyline.coordinate_rounding` of its pair of chains (chains ``2k`` and ``2k + 1``,
    their vertices one chain after the other in ``vertex``, ``sizes`` vertices each), CRS units."""
    largest = np.abs(vertex).max(axis=1)
    pair_sizes = np.add.reduceat(sizes, np.arange(0, len(sizes), 2))
    pair_largest = np.maximum.reduceat(largest, np.cumsum(pair_sizes) - pair_sizes)
    pair_rounding = ROUNDING_SPACINGS * np.spacing(pair_largest)
    return np.repeat(pair_rounding, np.add.reduceat(sizes - 1, np.arange(0, len(sizes), 2)))


def _per_segment(values, first, sizes):
    """``values[first[c] : first[c] + sizes[c]]`` of each chain ``c``, one after the other: per segment the value
    at its start vertex, with ``first`` the chains' first vertices in ``values`` (at their second vertices: at
    its end vertex)."""
    return np.concatenate([values[begin : begin + size] for begin, size in zip(first, sizes)])


class BoxGrid:
    """A uniform grid of square cells over boxes (the bounding boxes of a boundary's segment runs), each cell
    listing the boxes that meet it; :meth:`query` lists the boxes that meet a query box.

    The cell side (CRS units) is ``GRID_CELL_SIDE`` times the boxes' mean extent (their larger side), doubled
    until the grid has at most ``GRID_CELLS`` cells and entries per box (a sparse boundary in a large extent,
    or long segments, get coarser cells). Cells are found by scaling coordinates from the grid's lowest corner
    and clipping them to the grid, a nondecreasing map: whenever two boxes meet, their cell ranges meet too,
    and the lowest cell of that common range is where the pair is found.
    """

    def __init__(self, low, high):
        # Contiguous columns: ``take`` copies a strided array whole before gathering from it.
        self.low_x, self.low_y, self.high_x, self.high_y = np.concatenate([low, high], axis=1).T.copy()
        self.origin = low.min(axis=0) if len(low) else np.zeros(2)
        span = high.max(axis=0) - self.origin if len(low) else np.zeros(2)
        self.size = GRID_CELL_SIDE * float(np.mean(np.max(high - low, axis=1))) if len(low) else 0.0
        if not self.size > 0.0:
            self.size = max(float(span.max()), 1.0)
        budget = GRID_CELLS * max(len(low), 1)
        while True:
            cells = np.floor(span / self.size) + 1.0
            if cells.prod() <= budget:
                self.shape = cells.astype(np.int64)
                first, last = self.cells(low), self.cells(high)
                rows, columns = (last - first + 1).T
                if int(rows @ columns) <= budget:
                    break
            self.size *= 2.0
        del last
        # One entry per (box, cell it meets), sorted by cell (rows of cells, then columns), then by box.
        box, rank = ranges(rows * columns)
        row_rank, column_rank = np.divmod(rank, columns[box])
        cell = (first[:, 0][box] + row_rank) * self.shape[1] + first[:, 1][box] + column_rank
        order = np.argsort(cell, kind="stable")
        self.box = box.take(order)
        #: Whether an entry's cell is in its box's first row (``top``) or first column (``left``) of cells.
        self.top = row_rank.take(order) == 0
        self.left = column_rank.take(order) == 0
        #: Entries of cell ``c``: ``start[c]`` up to ``start[c + 1]``.
        self.start = np.zeros(self.shape.prod() + 1, dtype=np.int64)
        np.cumsum(np.bincount(cell, minlength=self.shape.prod()), out=self.start[1:])

    def cells(self, points):
        """Row and column of the cell of each point (clipped to the grid), int64 of shape (n, 2)."""
        scaled = points - self.origin
        scaled /= self.size
        np.clip(scaled, 0.0, self.shape - 1, out=scaled)
        return scaled.astype(np.int64)

    def query(self, low, high):
        """Pairs (query box index, box index), sorted by query box, of the boxes that meet a query box
        ``low..high``, each once: of the boxes that share a cell with it, each is taken where their cell ranges'
        common part begins (in a row of the query's cells, the box's first row or the query's; in a column,
        likewise), then kept if it meets the query box."""
        first, last = self.cells(low), self.cells(high)
        query, rank = ranges(last[:, 0] - first[:, 0] + 1)
        # Per query box and row of its cells: the entries of its cells in that row are consecutive.
        cell = (first[:, 0][query] + rank) * self.shape[1] + first[:, 1][query]
        begin = self.start.take(cell)
        first_column_end = self.start.take(cell + 1)
        count = self.start.take(cell + (last[:, 1] - first[:, 1])[query] + 1) - begin
        owner, entry = ranges(count)
        entry += np.repeat(begin, count)
        keep = self.top.take(entry) | (rank == 0).take(owner)
        keep &= self.left.take(entry) | (entry < first_column_end.take(owner))
        keep = keep.nonzero()[0]
        query, box = query.take(owner.take(keep)), self.box.take(entry.take(keep))
        meets = self.low_x.take(box) <= high[:, 0][query]
        meets &= self.high_x.take(box) >= low[:, 0][query]
        meets &= self.low_y.take(box) <= high[:, 1][query]
        meets &= self.high_y.take(box) >= low[:, 1][query]
        meets = meets.nonzero()[0]
        return query.take(meets), box.take(meets)


def _group_starts(low, high):
    """First box of each group of consecutive boxes queried together: at most ``QUERY_GROUP`` boxes, each
    meeting the one before it (a run of boxes that meet is cut every ``QUERY_GROUP`` boxes)."""
    apart = np.ones(len(low), dtype=bool)
    apart[1:] = low[1:, 0] > high[:-1, 0]
    apart[1:] |= low[1:, 1] > high[:-1, 1]
    apart[1:] |= high[1:, 0] < low[:-1, 0]
    apart[1:] |= high[1:, 1] < low[:-1, 1]
    box = np.arange(len(low))
    run_start = np.maximum.accumulate(np.where(apart, box, 0))
    return np.flatnonzero((box - run_start) % QUERY_GROUP == 0)


def vertex_contact(offset, height, b_along, b_across, scale, slide, on_line=0.0):
    """First contact ``t`` with a segment's vertex, inf when none.

    In the segment's frame the vertex lies ``offset`` along the segment from the sample point and ``-height``
    across it; ``(b_along, b_across)`` is the sample's direction in that frame. With vertex - point =
    x*b + y*b_perp, the contact solves slide^2 t^2 - 2 x t + |d|^2 = 0, whose discriminant factors as
    (x*scale - |y|*slide) (x*scale + |y|*slide); the first factor is, up to a constant, the vertex's distance
    from an incident line of a convex corner. A vertex on that line is touched as the disks slide along it (a
    double root), so a factor that rounding pushed just below zero is taken as zero: the contact stays where it
    is under tiny perturbations of the input. A vertex closer to the sample point than ``NEAR_VERTEX`` times
    its contact ``t``, or at most ``on_line`` (CRS units) above the tangent line, is not touched (it lies on the
    tangent line up to rounding).
    """
    x = b_along * offset - b_across * height
    squared = offset * offset + height * height
    if not np.any(slide) and np.all(scale == 1.0):
        # No convex corner's disk (the samples of an edge or a fan): both factors are x, so t = |d|^2 / (2 x).
        with np.errstate(divide="ignore", invalid="ignore"):
            t = 0.5 * squared / x
        return np.where((x > on_line) & (squared > (NEAR_VERTEX * t) ** 2), t, np.inf)
    y = np.abs(b_along * height + b_across * offset)
    near = x * scale - y * slide
    far = x * scale + y * slide
    near = np.where((near < 0) & (near >= -GRAZING_TOLERANCE * np.sqrt(squared)), 0.0, near)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = squared / (np.sqrt(np.maximum(near * far, 0.0)) + x)
    # A vertex a hair from the sample point, next to its tangent line, is touched only through rounding.
    touched = (x > on_line) & (near >= 0) & (squared > (NEAR_VERTEX * t) ** 2)
    return np.where(touched, t, np.inf)


def first_contacts(px, py, bx, by, scale, slide, boundary, segment, with_along=True):
    """First contact ``t`` of each (sample, segment) pair, inf when the disk family never touches it.

    ``(px, py)`` is the sample point, ``(bx, by)`` its unit direction, ``scale`` the radius per unit of
    ``t`` (``sin`` of the half angle at a convex vertex, else 1) and ``slide`` the matching ``cos`` (else 0).
    Returns ``t``, where on the segment the contact is (a length from its start, CRS units; None without
    ``with_along``) and the site touched (see :class:`Boundary`).

    A segment answers for its start vertex only (its end is the next segment's start, which is a candidate
    whenever that vertex can be touched); the last segment of a chain answers for its end too.
    """
    ux, uy = boundary.unit_x[segment], boundary.unit_y[segment]
    length = boundary.length.take(segment)
    dx, dy = px - boundary.start_x[segment], py - boundary.start_y[segment]
    along_p = dx * ux + dy * uy
    height = dx * -uy + dy * ux
    del dx, dy
    b_along = bx * ux + by * uy
    b_across = by * ux - bx * uy

    rounding = boundary.rounding.take(segment) if boundary.several_pairs else boundary.rounding
    t_start = vertex_contact(-along_p, height, b_along, b_across, scale, slide, rounding)
    t_end = np.full(len(segment), np.inf)
    last = boundary.last_of_chain.take(segment).nonzero()[0]
    if len(last):
        t_end[last] = vertex_contact(
            length[last] - along_p[last],
            height[last],
            b_along[last],
            b_across[last],
            scale[last],
            slide[last],
            rounding[last] if boundary.several_pairs else rounding,
        )

    # With side = sign(height) (+1 at 0): distance = side * height, and bx + side * uy, by - side * ux.
    below = height < 0
    distance = np.abs(height)
    # 1 - side * b_across is |b - side * across|**2 / 2 for unit vectors: no cancellation when the disk's
    # direction nearly faces the segment's line (a nearly straight corner).
    across_x = np.where(below, bx - uy, bx + uy)
    across_y = np.where(below, by + ux, by - ux)
    across_x *= across_x
    across_y *= across_y
    across_x += across_y
    denominator = np.multiply(across_x, 0.5, out=across_x)
    del across_y
    corner = (scale != 1.0).nonzero()[0]
    if len(corner):
        denominator[corner] = scale[corner] - np.where(below[corner], -1.0, 1.0) * b_across[corner]
    with np.errstate(divide="ignore", invalid="ignore"):
        t_tangent = distance / denominator
        along = t_tangent * b_along
        along += along_p
    slack = ALONG_TOLERANCE * length
    tangent = (distance > 0) & (denominator > 1e-12) & (along >= -slack)
    tangent &= along <= length + slack
    # A tangency inside the segment is its first contact, and it is well conditioned; a contact through an
    # end point only counts when there is no such tangency (near it, the vertex root is a double root that
    # keeps only half the digits).
    t_vertex = np.minimum(t_start, t_end)
    t = np.where(tangent, t_tangent, t_vertex)
    at_start = t_vertex == t_start
    site = boundary.start_site.take(segment)
    site += ~at_start
    np.copyto(site, segment, where=tangent, casting="unsafe")
    if not with_along:
        return t, None, site
    along = np.where(tangent, np.minimum(np.maximum(along, 0.0), length), np.where(at_start, 0.0, length))
    return t, along, site


def per_sample(value, chain):
    """``value`` for samples of the chains ``chain``: a scalar as is, an array per chain indexed by chain."""
    return np.full(len(chain), value, dtype=float) if np.ndim(value) == 0 else np.asarray(value)[chain]


def _lowest_site_of_groups(picked, group, site):
    """Of the rows ``picked`` (ascending; each group's rows consecutive), each group's row of the lowest ``site``.

    The tie rule of :func:`solve`: ``picked`` are the pairs touched at a sample's first contact, and a site
    occurs at most once per sample (:meth:`Boundary.candidates` lists each (box, segment) pair once, and a
    segment answers for its own interior and start vertex, the last one of a chain for its end too), so each
    group keeps one row, whatever order its rows are listed in.
    """
    group = group[picked]
    first = np.ones(len(group), dtype=bool)
    np.not_equal(group[1:], group[:-1], out=first[1:])
    starts = first.nonzero()[0]
    if len(starts) == len(group):
        return picked
    site = site[picked]
    lowest = np.minimum.reduceat(site, starts)
    return picked[site == lowest[np.cumsum(first) - 1]]


def solve(samples, index, boundary, trial, max_t, min_t, points=False):
    """Settle the samples ``index``, starting from trial parameters ``trial`` (one per sample).

    ``max_t`` (the largest disk parameter searched) and ``min_t`` (the smallest that counts as a contact) are
    lengths, CRS units, or arrays of them per chain (see :func:`per_sample`).

    Returns arrays aligned with ``index``: ``contact_t`` (parameter of the first contact with anything, inf
    when none within ``max_t``), ``status`` (``SKIPPED``; ``TIED``: the first contact lies on the other
    chain and, within ``TIE_TOLERANCE``, on the sample's own chain too; ``CLEAR``: on the other chain only),
    with ``points`` for accepted samples the ``contact`` point and its arc-length ``position`` along the other
    chain (CRS units; without ``points`` both are None: the adaptive engine needs neither, and at 10^6 vertices
    they would take 24 bytes per sample), and the ``site`` of the contact (int32; for skipped samples the
    nearest site of their own chain; -1 when none).

    Sites touched at exactly the same first ``t`` (a disk touching two places of a chain, as at an event) are
    all true contacts; the lowest site wins: a segment's interior before any vertex, and among segments or
    among vertices the first along the chains. The rule depends on the sites only, never on the order in
    which the candidate pairs are listed: the index and the all-pairs paths of :meth:`Boundary.candidates`
    give the same winners, and a feature traced with others (its sites keep their order) those it gets alone
    wherever its parameters come out the same (a joint tracing shifts coordinates: rounding may tip a tie).
    """
    count = len(index)
    chain = samples.chain[index]
    max_t, min_t = per_sample(max_t, chain), per_sample(min_t, chain)
    radius = np.array(trial, dtype=float)
    solution = _Solution(
        np.full(count, np.inf),
        np.full(count, SKIPPED, dtype=np.int8),
        np.zeros((count, 2)) if points else None,
        np.zeros(count) if points else None,
        np.full(count, -1, dtype=np.int32),
    )
    # Each round solves the samples still pending and, up to a block, the next fresh ones: a block's few slow
    # samples ride along with the next block instead of taking rounds of their own.
    begin, block = 0, _first_block(boundary, radius[:SOLVE_BLOCK])
    pending = np.empty(0, dtype=np.intp)
    while begin < count or len(pending):
        fresh = np.arange(begin, min(begin + max(block - len(pending), 0), count))
        begin += len(fresh)
        active = np.concatenate([pending, fresh]) if len(pending) else fresh
        best, pairs = _solve_round(samples, index[active], boundary, radius[active], min_t[active], active, solution)
        if len(fresh):
            block = min(max(SOLVE_PAIRS * len(active) // max(pairs, 1), 1), SOLVE_BLOCK)
        settled = best <= radius[active]
        pending = active[~settled]
        radius[pending] = np.minimum(best[~settled], 2.0 * radius[pending])
        pending = pending[radius[pending] <= max_t[pending]]
    return solution.contact_t, solution.status, solution.contact, solution.position, solution.site


def _first_block(boundary, radius):
    """Samples in :func:`solve`'s first block: ``SOLVE_PAIRS`` over the pairs a sample is expected to have,
    judged from the middle one of the first samples' trial radii ``radius`` (CRS units): a disk of radius r
    meets about 4 r / l segments of mean length l (both chains, both sides of its centre)."""
    if not len(radius) or boundary.mean_length <= 0.0:
        return SOLVE_BLOCK
    expected = 4.0 * float(radius[len(radius) // 2]) / boundary.mean_length + 1.0
    return min(max(int(SOLVE_PAIRS / expected), 1), SOLVE_BLOCK) if math.isfinite(expected) else SOLVE_BLOCK


@dataclass(frozen=True)
class _Solution:
    """The arrays that :func:`solve` returns, filled in round by round (one row per sample; ``contact`` and
    ``position`` None when not asked for)."""

    contact_t: np.ndarray
    status: np.ndarray
    contact: np.ndarray
    position: np.ndarray
    site: np.ndarray


def _solve_round(samples, sample, boundary, radius, min_t, row, solution):
    """One round of :func:`solve`: the samples ``sample`` (rows ``row`` of ``solution``) with trial parameters
    ``radius`` and smallest contacts ``min_t``. Fills in the rows settled (first contact within the trial) and
    the own-chain site of every row, ties broken as :func:`solve` says; returns each sample's first contact
    found (inf when none) and the number of candidate (sample, segment) pairs.

    Per-sample quantities are taken once per sample and then gathered per (sample, segment) pair.
    """
    # Per-sample columns, contiguous: gathered per pair with ``take``.
    px, py = samples.point[:, 0][sample], samples.point[:, 1][sample]
    bx, by = samples.direction[:, 0][sample], samples.direction[:, 1][sample]
    chain = samples.chain[sample]
    centre_x, centre_y = px + radius * bx, py + radius * by
    # Every disk of the family up to the trial one lies in the disk of radius ``radius`` about the
    # trial centre (its centre moves by dt while its radius grows by scale*dt <= dt).
    reach = radius * (1.0 + 1e-9)
    query, segment = boundary.candidates(
        np.stack([centre_x - reach, centre_y - reach], axis=1),
        np.stack([centre_x + reach, centre_y + reach], axis=1),
        chain,
    )
    pairs = len(query)
    near = boundary.within(segment, query, centre_x, centre_y, reach)
    if boundary.several_pairs:
        near &= boundary.chain_id.take(segment) >> 1 == (chain >> 1).take(query)
    # The own segments never count (their first contact is the sample itself): dropped before solving.
    first_own, last_own = samples.first_own[sample], samples.last_own[sample]
    near &= (segment < first_own.take(query)) | (segment > last_own.take(query))
    near = near.nonzero()[0]
    query, segment = query.take(near), segment.take(near)
    del near, centre_x, centre_y, reach
    t, along, touched = first_contacts(
        px.take(query),
        py.take(query),
        bx.take(query),
        by.take(query),
        samples.scale[sample].take(query),
        samples.slide[sample].take(query),
        boundary,
        segment,
        solution.contact is not None,
    )
    # The own segments' end vertices do not count either (the next segment answers for the last one's end).
    own_segment = touched >= boundary.start_site.take(first_own).take(query)
    own_segment &= touched <= (boundary.start_site.take(last_own) + 1).take(query)
    own_segment |= t <= min_t.take(query)
    np.putmask(t, own_segment, np.inf)
    on_own = boundary.chain_id.take(segment) == chain.take(query)
    t_own = np.where(on_own, t, np.inf)
    t_other = np.where(on_own, np.inf, t)
    del own_segment, on_own
    best_own, best_other = group_minima(query, len(sample), t_own, t_other)
    best = np.minimum(best_own, best_other)
    settled = best <= radius
    solution.contact_t[row[settled]] = best[settled]
    best_own_pair = best_own.take(query)
    own_tied = (np.isfinite(t_own) & (t_own == best_own_pair)).nonzero()[0]
    own_winner = _lowest_site_of_groups(own_tied, query, touched)
    solution.site[row[query[own_winner]]] = touched[own_winner]
    winner = np.isfinite(t_other) & (t_other == best_other.take(query))
    winner &= t_other <= best_own_pair * (1.0 + TIE_TOLERANCE)
    winner &= settled.take(query)
    chosen = _lowest_site_of_groups(winner.nonzero()[0], query, touched)
    if len(chosen):
        _record_winners(
            solution,
            row[query[chosen]],
            t[chosen],
            None if along is None else along[chosen],
            touched[chosen],
            segment[chosen],
            best_own[query[chosen]],
            boundary,
        )
    return best, pairs


def _record_winners(solution, row, t, along, site, segment, best_own, boundary):
    """Record the first contacts ``t`` on the other chain of the rows ``row`` of ``solution``: ``along``
    (CRS units) the segment ``segment`` (site ``site``); ``best_own`` is each row's first own-chain contact."""
    solution.status[row] = np.where(t * (1.0 + TIE_TOLERANCE) < best_own, CLEAR, TIED)
    solution.contact_t[row] = t
    solution.site[row] = site
    if solution.contact is None:
        return
    solution.contact[row] = rows(boundary.start, segment) + along[:, None] * rows(boundary.unit, segment)
    solution.position[row] = np.where(
        along >= boundary.length[segment],
        boundary.segment_end_position[segment],
        boundary.segment_position[segment] + along,
    )


def solve_coarse_to_fine(samples, index, boundary, trial_radius, max_t, min_t, report, points=False):
    """Settle ``index`` (sorted by chain, then position) from coarse to fine; ``trial_radius`` as ``max_t`` and
    ``points`` as in :func:`solve`.

    Every ``COARSE_STRIDE ** COARSE_LEVELS``-th sample (all at once up to ``COARSE_STRIDE ** (COARSE_LEVELS + 1)``
    samples per feature, a pair of chains) is solved first from a global trial radius, then each finer level from
    trial radii interpolated between the coarser levels' first contacts: a trial close to the answer keeps the
    candidate boxes tight where the width varies.
    ``report(done)`` is called after each level with the number of samples settled.
    """
    count = len(index)
    trial_radius = per_sample(trial_radius, samples.chain[index])
    contact_t = np.full(count, np.nan)
    status = np.zeros(count, dtype=np.int8)
    contact = np.empty((count, 2)) if points else None
    position = np.empty(count) if points else None
    site = np.empty(count, dtype=np.int32)
    # Arc length along chain 0, then along chain 1 shifted past it: increasing over the sorted samples.
    along = samples.position[index] + samples.chain[index] * (2.0 * samples.position[index].max() + 1.0)
    # Levels by the samples per feature (pair of chains; sorted by chain, each feature's samples are a run):
    # a joint tracing's chunk holds many small features, whose coarse levels would hold a few samples each,
    # cost rounds and interpolate across features. A feature of a few hundred samples is solved in one level:
    # its trials from the typical width take fewer rounds than a coarse level costs.
    feature = samples.chain[index] >> 1
    per_feature = count / (np.count_nonzero(feature[1:] != feature[:-1]) + 1) if count else 0
    stride = COARSE_STRIDE**COARSE_LEVELS if per_feature > COARSE_STRIDE ** (COARSE_LEVELS + 1) else 1
    while stride >= 1:
        level = np.zeros(count, dtype=bool)
        level[::stride] = True
        level &= np.isnan(contact_t)
        known = np.isfinite(contact_t)
        if np.any(known):
            estimate = np.interp(along[level], along[known], samples.scale[index[known]] * contact_t[known])
            # Not much below the global trial: doubling up from a tiny trial (near a split point) takes long.
            trial = np.maximum(1.05 * estimate / samples.scale[index[level]], SMALLEST_TRIAL * trial_radius[level])
        else:
            trial = trial_radius[level]
        level = np.flatnonzero(level)
        contact_t[level], status[level], level_contact, level_position, site[level] = solve(
            samples, index[level], boundary, trial, max_t, min_t, points
        )
        if points:
            put_rows(contact, level, level_contact)
            position[level] = level_position
        report(count - np.isnan(contact_t).sum())
        stride //= COARSE_STRIDE
    return contact_t, status, contact, position, site


@dataclass(frozen=True)
class AxisPoints(ArrayRecord):
    """Points of the medial axis between the chains, with their incircles, in no particular order.

    Attributes
    ----------
    centre : ndarray of shape (n, 2)
        CRS units (the engine's local frame).
    radius : ndarray of shape (n,)
        Incircle radius, CRS units.
    foot_a, foot_b : ndarray of shape (n, 2)
        Where the incircle touches the first and the second chain.
    position_a, position_b : ndarray of shape (n,)
        Arc length of ``foot_a`` along the first chain and of ``foot_b`` along the second, CRS units.
    """

    centre: np.ndarray
    radius: np.ndarray
    foot_a: np.ndarray
    foot_b: np.ndarray
    position_a: np.ndarray
    position_b: np.ndarray

    @staticmethod
    def from_chain_feet(chain, centre, radius, own_foot, own_position, other_foot, other_position):
        """Points whose feet are given as on the sampled chain (``chain``; even: the first chain of its pair)
        and on the other one."""
        on_a = (chain % 2 == 0)[:, None]
        return AxisPoints(
            centre,
            radius,
            np.where(on_a, own_foot, other_foot),
            np.where(on_a, other_foot, own_foot),
            np.where(on_a[:, 0], own_position, other_position),
            np.where(on_a[:, 0], other_position, own_position),
        )


def _report_from(report, begin, total, done):
    """Report ``done`` samples settled in the chunk starting at ``begin`` as a fraction of ``total``."""
    report((begin + done) / total)


def solve_in_chunks(samples, index, boundary, trial_radius, max_t, min_t, report, points=False):
    """:func:`solve_coarse_to_fine` on ``index`` (sorted by chain and position), ``CHUNK`` samples at a time.

    ``report(done_fraction)`` is called as samples settle. Returns the arrays of :func:`solve` (``contact`` and
    ``position`` only with ``points``, else None).
    """
    total = len(index)
    solution = [
        np.empty(total),
        np.zeros(total, dtype=np.int8),
        np.zeros((total, 2)) if points else None,
        np.zeros(total) if points else None,
        np.zeros(total, dtype=np.int32),
    ]
    for begin in range(0, total, CHUNK):
        chunk = slice(begin, min(begin + CHUNK, total))
        parts = solve_coarse_to_fine(
            samples,
            index[chunk],
            boundary,
            trial_radius,
            max_t,
            min_t,
            partial(_report_from, report, begin, total),
            points,
        )
        for whole, part in zip(solution, parts):
            if whole is not None:
                whole[chunk] = part
    return solution
