"""From axis points to lines: order the incircle centres along the axis, drop repeats, simplify.

The samplers (:mod:`.tracing`, :mod:`.fixed_sampling`) return the axis points of a pair of chains in no
particular order. :func:`lines_together` turns those of many pairs (a batch of features, see :mod:`._steps`)
into their lines at once: one sort by feature and by where each disk touches the chains, one pass dropping
repeated centres, one Douglas-Peucker simplification call, one test that each simplified line stays inside
its region. Each feature's line is what it would be alone, vertex for vertex: every step treats a feature's
points only with its own, and the per-feature values (tolerances, lengths, the direction of travel) go with
each point.
"""

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import Polygon

from ._arrays import rows
from .contacts import AxisPoints
from .errors import IncirCuError, Message

#: Relative distance (of the extent) under which two consecutive centres are one point.
DISTINCT_TOLERANCE = 1e-9

#: Resolution of the ordering key (a sum of two arc lengths relative to their chains' lengths, 0 to 2):
#: keys closer than this are ties, ordered by the direction of travel.
ORDER_RESOLUTION = 1e-11

#: Most points simplified in one piece: GEOS's Douglas-Peucker slows down far more than linearly on longer
#: lines (a million points: 1.3 s in one piece, 0.1 s in pieces of this size).
SIMPLIFY_PIECE = 32_768

#: Pieces simplified in one GEOS call: their indexed coordinates (about 12 MiB) then reuse freed memory, where
#: those of a million points at once (44 MiB) would take fresh pages every time.
SIMPLIFY_BATCH = 16

#: Most features whose lines are made in one pass (bounds the per-feature offsets of the sort keys, see
#: :func:`_by_feature`).
LINE_GROUP = 1024


@dataclass
class LineRequest:
    """What the axis points of one pair of chains need to become its line (see :func:`lines_together`).

    Attributes
    ----------
    points : AxisPoints
        The axis points, in the chains' local frame (CRS units), in any order.
    frame : object
        The chains in their local frame (the engine's ``_LocalChains``: ``chains``, ``ring``, ``closed``, ``side``,
        ``lengths``, ``extent``, ``coincidence``, ``origin``).
    simplification : float or None
        Douglas-Peucker tolerance, CRS units; None: no simplification (the fixed sampling).
    region : Polygon or None
        Where a simplified line must stay, CRS units; None: the region between the chains.
    """

    points: AxisPoints
    frame: object
    simplification: Optional[float] = None
    region: Optional[Polygon] = None


class _NotExact(Exception):
    """Per-feature offsets would make a sort key inexact in float64 (see :func:`_by_feature`)."""


class _Blocks:
    """Consecutive blocks of a concatenated array, one per feature (some may be empty)."""

    def __init__(self, sizes):
        self.sizes = np.asarray(sizes, dtype=np.intp)
        self.count = len(self.sizes)
        self.ends = np.cumsum(self.sizes)
        self.starts = self.ends - self.sizes

    @cached_property
    def ids(self):
        """The feature of each item, an int array."""
        return np.repeat(np.arange(self.count), self.sizes)

    def spread(self, values):
        """Per-feature ``values`` (a sequence of numbers or an array) for each item; the value itself when there
        is one feature."""
        if self.count == 1:
            return values[0]
        return np.repeat(np.asarray(values), self.sizes)

    def within(self, margin):
        """Mask of the items at least ``margin`` places from both ends of their block."""
        if self.count == 1:
            rank, size = np.arange(self.sizes[0]), self.sizes[0]
        else:
            rank, size = np.arange(len(self.ids)) - self.starts.take(self.ids), self.sizes.take(self.ids)
        return (rank >= margin) & (rank < size - margin)

    def of(self, positions):
        """The blocks of the items at ``positions`` (sorted indices into this array)."""
        if self.count == 1:
            return _Blocks([len(positions)])
        return _Blocks(np.bincount(self.ids.take(positions), minlength=self.count))

    def split(self, array):
        """``array`` (one row per item) as a list of one array per feature."""
        return [array] if self.count == 1 else np.split(array, self.ends[:-1])


def lines_together(requests):
    """The lines of many :class:`LineRequest`\\ s, each as it would be alone.

    Parameters
    ----------
    requests : list of LineRequest
        In any mix: closed or open chains, simplified or not, of any sizes; made ``LINE_GROUP`` at a time.

    Returns
    -------
    list
        Per request, in order: ``(centre, radius, foot_a, foot_b)`` (the line's vertices, their incircle radii
        and feet, end to end, local frame, CRS units), or the :class:`.errors.IncirCuError` its line raised.
    """
    answers = []
    for begin in range(0, len(requests), LINE_GROUP):
        group = requests[begin : begin + LINE_GROUP]
        try:
            answers.extend(_group_lines(group))
        except _NotExact:
            answers.extend(_group_lines([request])[0] for request in group)
    return answers


def _group_lines(requests):
    """:func:`lines_together` on at most ``LINE_GROUP`` requests; raises :class:`_NotExact` (see
    :func:`_by_feature`)."""
    frames = [request.frame for request in requests]
    points, betweens = zip(*(_in_region(request) for request in requests))
    blocks = _Blocks([len(p.radius) for p in points])
    points = points[0] if blocks.count == 1 else AxisPoints.concatenate(points)
    lengths = (blocks.spread([f.lengths[0] for f in frames]), blocks.spread([f.lengths[1] for f in frames]))
    coincidence = blocks.spread([f.coincidence for f in frames])
    order = _ordered(points, blocks.spread([f.side for f in frames]), lengths, coincidence, blocks)
    resolution = [DISTINCT_TOLERANCE * f.extent for f in frames]
    first = _first_of_each_centre(points.centre, order, blocks.spread(resolution), blocks)
    order = order.take(first)
    joined = _Blocks(blocks.of(first).sizes + 2)
    ends = [_line_ends(f.chains, f.closed) for f in frames]
    centre = _with_ends(points.centre, order, [end[0] for end in ends], joined)
    keep = _distinct(centre, joined.spread(resolution), joined)
    keep = _simplified(centre, keep, joined, requests, betweens)
    return _results(points, order, centre, keep, joined, ends)


def _in_region(request):
    """A request's axis points inside the region between its chains (all of them when the chains share both
    ends), and that region as a polygon when it was needed for this (else None), local frame."""
    frame, points = request.frame, request.points
    if frame.closed:
        return points, None
    between = Polygon(frame.ring)
    shapely.prepare(between)
    inside = shapely.intersects_xy(between, points.centre[:, 0], points.centre[:, 1])
    points = points.subset(inside)
    points = points.subset(~_foot_behind_gap(points, frame.chains, DISTINCT_TOLERANCE * frame.extent))
    if all(np.array_equal(chain[0], chain[-1]) for chain in frame.chains):
        points = _around_the_seam(points, frame.lengths, frame.chains)
    return points, between


def _around_the_seam(points, lengths, chains):
    """The axis points between two closed rings cut at one seam (see :mod:`.rings`), their feet's arc lengths
    taken on one lap: the second foot's on the lap nearest the first's, then both shifted by whole laps so that
    their relative sum lies in [0, 2), where the ordering expects it.

    The seam's vertices are the start and the end of their rings: a disk next to the seam may report a foot
    there at the start (0) or at the end (the ring's length), or straddle it (one foot just before the seam,
    the other just past it), and would sort into the middle of the line or to its other end. Near the seam
    (a centre within the seam disk's radius of its centre, where the loop, whose radius of curvature is at
    least that, turns by under 60 degrees) the side of the seam the centre lies on decides: ahead of it (along
    the first ring's direction) the start, behind it the end.
    """
    relative_a = points.position_a / lengths[0]
    relative_b = points.position_b / lengths[1]
    relative_b -= np.round(relative_b - relative_a)
    total = relative_a + relative_b
    lap = np.floor(0.5 * total)
    seam = chains[1][0] - chains[0][0]
    ahead = np.array([-seam[1], seam[0]])
    if np.dot(ahead, chains[0][1] - chains[0][0]) < 0:
        ahead = -ahead
    middle = 0.5 * (chains[0][0] + chains[1][0])
    near = np.hypot(*(points.centre - middle).T) < 0.5 * np.hypot(*seam)
    if near.any():
        forward = (points.centre[near] - middle) @ ahead >= 0.0
        lap[near] = np.round(0.5 * (total[near] - np.where(forward, 0.0, 2.0)))
    relative_a -= lap
    relative_b -= lap
    return replace(points, position_a=relative_a * lengths[0], position_b=relative_b * lengths[1])


def _foot_behind_gap(points, chains, resolution):
    """Mask of the axis points one of whose feet the centre sees only across an end gap (the straight line
    between the two chains' first or last vertices, which closes the region in open mode).

    Such a disk touches both chains but reaches one of them through the gap, outside the region: its centre
    is equidistant from the chains but not on the region's medial axis. Two bank lines that wind around (a
    spiral) bring the end of one near the start of the other, across the start gap; those centres would
    interleave with the axis in the order (the sum of the feet's arc lengths is the same) and zigzag the line.
    A foot at a gap's end is not across it: only crossings farther than ``resolution`` (CRS units) from the
    ends of both segments count (a foot computed at a gap's end, a rounding off it, is at it).
    """
    behind = np.zeros(len(points.radius), dtype=bool)
    for end in (0, -1):
        gap_start, gap_end = chains[0][end], chains[1][end]
        for foot in (points.foot_a, points.foot_b):
            behind |= _cross_properly(points.centre, foot, gap_start, gap_end, resolution)
    return behind


def _cross_properly(starts, ends, p, q, resolution):
    """Mask of the segments ``starts[i]``-``ends[i]`` (arrays of shape (n, 2)) crossing the segment ``p``-``q``
    at a point interior to both: each segment's ends lie on opposite sides of the other's line, farther than
    ``resolution`` from it (CRS units)."""
    gap = q - p
    direction = ends - starts
    gap_length = np.hypot(*gap)
    lengths = np.hypot(direction[:, 0], direction[:, 1])

    def side_of_gap(points):
        return _side(gap[0] * (points[:, 1] - p[1]) - gap[1] * (points[:, 0] - p[0]), resolution * gap_length)

    def side_of_segments(point):
        across = direction[:, 0] * (point[1] - starts[:, 1]) - direction[:, 1] * (point[0] - starts[:, 0])
        return _side(across, resolution * lengths)

    return (side_of_gap(starts) * side_of_gap(ends) < 0) & (side_of_segments(p) * side_of_segments(q) < 0)


def _side(determinant, margin):
    """-1, 0 or 1: the side of a line a point lies on, from their orientation ``determinant`` (the distance times
    the line's length), 0 within ``margin`` (the same units)."""
    return np.where(np.abs(determinant) <= margin, 0.0, np.sign(determinant))


def _region(request, between):
    """Where a request's simplified line must stay, and the shift from the local frame to it (CRS units): its
    ``region``, else the region between its chains (``between`` when :func:`_in_region` built it)."""
    if request.region is not None:
        return request.region, request.frame.origin
    return (Polygon(request.frame.ring) if between is None else between), np.zeros(2)


def _by_feature(key, blocks):
    """``key`` (whole numbers as floats, one per item of ``blocks``) shifted by a multiple of a stride per
    feature, so that one stable sort orders the items by feature, then by key, keeping each feature's order
    among equal keys; ``key`` itself for one feature.

    Raises
    ------
    _NotExact
        When a shifted key would not be exact in float64 (or ``key`` is not finite).
    """
    if blocks.count == 1:
        return key
    stride = 2.0 * float(np.abs(key).max(initial=0.0)) + 2.0
    if not stride * blocks.count < 2.0**53:
        raise _NotExact()
    return key + blocks.spread(stride * np.arange(blocks.count))


def _ordered(points, side, lengths, coincidence, blocks):
    """Indices putting the axis points in order along the axis: by feature (``blocks``), then by where their
    disks touch the two chains (``side``, ``lengths`` and ``coincidence``: the feature's, per point or one
    value, CRS units).

    Those arc lengths grow monotonically along the axis between the chains. Points whose feet are the same
    two vertices (two facing reflex corners) tie on them; they lie on the bisector of those vertices,
    ordered by the direction of travel, perpendicular to ``foot_b - foot_a``. Points whose feet are both a
    split point lie on the stub from it: their disks grow away from the first split point and shrink into
    the last, so they are ordered by radius.
    """
    # In place where the values allow: at 10^6 boundary vertices each temporary is a fresh 16 MB array.
    across_x = np.subtract(points.foot_b[:, 0], points.foot_a[:, 0])
    across_y = np.subtract(points.foot_b[:, 1], points.foot_a[:, 1])
    spare = np.hypot(across_x, across_y)
    # Feet one point up to rounding: a split point, where both chains start (0) or end (2). No direction of
    # travel there; the radius orders the points. On a split point in a straight stretch, a disk tangent there
    # to one chain passes within rounding of the other's end well before its foot reaches it: at a distance d
    # along the stretch, a disk of radius r misses the split point by about d**2 / (2 r). Such feet (d of 1e-7
    # on a 0.75 wide stub, 70 units long chains) are one point as well: the disk is on the stub.
    # Both feet lie at a split point only where both chains start or end: a channel narrower than the
    # resolution (a thin box 1e-9 of its length wide) has its feet that close all along.
    resolution = DISTINCT_TOLERANCE * (lengths[0] + lengths[1])
    one_foot = (spare <= resolution) | (spare * spare <= 2.0 * resolution * points.radius)
    from_start = points.position_a + points.position_b
    from_end = (lengths[0] - points.position_a) + (lengths[1] - points.position_b)
    one_foot &= np.minimum(from_start, from_end) <= 2.0 * spare + resolution
    # The centre's component along the direction of travel, side * (across_y, -across_x).
    crossing = np.multiply(points.centre[:, 0], across_y)
    crossing -= np.multiply(points.centre[:, 1], across_x, out=spare)
    crossing *= side
    # The sum of the relative arc lengths, into the memory of ``across_x`` (no longer needed).
    along = np.divide(points.position_a, np.maximum(lengths[0], coincidence), out=across_x)
    along += np.divide(points.position_b, np.maximum(lengths[1], coincidence), out=spare)
    if one_foot.any():
        along[one_foot] = np.round(along[one_foot])
        crossing[one_foot] = 0.0
    growing = np.negative(points.radius, out=spare)
    np.copyto(growing, points.radius, where=along < 1.0)
    # Feet at the same two vertices may come from different computations: equal up to rounding.
    along /= ORDER_RESOLUTION
    np.round(along, out=along)
    along = _by_feature(along, blocks)
    # np.lexsort((growing, crossing, along)), with the two other keys looked at only where ``along`` ties: a
    # stable sort by ``along``, then each run of ties (contiguous, in input order) sorted by all three keys.
    order = np.argsort(along, kind="stable")
    key = along.take(order, out=across_y, mode="clip")
    tied = np.zeros(len(order), dtype=bool)
    tied[1:] = key[1:] == key[:-1]
    tied[:-1] |= tied[1:]
    if tied.any():
        runs = order[tied]
        order[tied] = runs[np.lexsort((growing[runs], crossing[runs], along[runs]))]
    return order


def _first_of_each_centre(centres, order, resolution, blocks):
    """Sorted positions in ``order`` (indices of ``centres``, grouped by feature as ``blocks``) of the first of
    the points of a feature sharing one centre (to ``resolution``, the feature's, per position or one value,
    CRS units).

    A junction of the axis is found from several sides, with different feet and so different places in the
    order; keeping its first place only, the line passes it once.
    """
    # The cells as complex numbers sort by x, then y in one stable sort: the indices
    # np.unique(cells, axis=0, return_index=True) gives, without its slow structured-array path. Gathered,
    # then scaled and rounded in place (one array of 16 bytes per point).
    cells = rows(centres, order)
    cells /= resolution if blocks.count == 1 else resolution[:, None]
    np.round(cells, out=cells)
    if blocks.count > 1:
        cells[:, 0] = _by_feature(cells[:, 0], blocks)
    cells = cells.view(np.complex128).ravel()
    order = np.argsort(cells, kind="stable")
    cells = cells.take(order)
    first = np.ones(len(order), dtype=bool)
    first[1:] = cells[1:] != cells[:-1]
    # The kept indices in ascending order: marked in a mask (linear) rather than sorted.
    kept = np.zeros(len(order), dtype=bool)
    kept[order[first]] = True
    return np.flatnonzero(kept)


def _line_ends(chains, closed):
    """The line's two ends: the split points, or the midpoints of the end gaps.

    Returns their centres, radii and both feet, each an array of two rows (start, end).
    """
    foot_a = chains[0][[0, -1]]
    if closed:
        return foot_a, np.zeros(2), foot_a, foot_a
    foot_b = chains[1][[0, -1]]
    radius = np.array([0.5 * np.hypot(*(foot_a[i] - foot_b[i])) for i in (0, 1)])
    return 0.5 * (foot_a + foot_b), radius, foot_a, foot_b


def _with_ends(values, order, ends, joined):
    """``values[order]`` (an array of the axis points, grouped by feature) with each feature's two ``ends`` (a
    list of arrays of two rows) around its block of ``joined``."""
    result = np.empty((joined.ends[-1],) + values.shape[1:])
    if joined.count == 1:
        result[0], result[-1] = ends[0]
        # Gathered straight into place; "clip" (the indices are valid) lets take skip its buffered copy.
        values.take(order, axis=0, out=result[1:-1], mode="clip")
        return result
    ends = np.stack(ends)
    result[joined.starts] = ends[:, 0]
    result[joined.ends - 1] = ends[:, 1]
    result[joined.within(1)] = values.take(order, axis=0)
    return result


def _distinct(points, tolerance, joined):
    """Mask keeping both ends of each feature of ``joined`` and every point farther than ``tolerance`` (the
    feature's, per point or one value, CRS units) from the point before it.

    A feature's last point is always kept; the kept point before it is dropped when within ``tolerance`` of it.
    """
    step = points[1:] - points[:-1]
    keep = np.empty(len(points), dtype=bool)
    # The steps' lengths into their x column (no second array of the size of the line).
    np.greater(
        np.hypot(step[:, 0], step[:, 1], out=step[:, 0]),
        tolerance if joined.count == 1 else tolerance[1:],
        out=keep[1:],
    )
    first, last = joined.starts, joined.ends - 1
    keep[first] = True
    keep[last] = True
    kept = np.flatnonzero(keep)
    rank = np.searchsorted(kept, last)
    # Features keeping more than their two ends: the kept point before the last one goes when too near it.
    more = np.flatnonzero(rank - np.searchsorted(kept, first) > 1)
    if len(more):
        before, last = kept.take(rank.take(more) - 1), last.take(more)
        gap = np.hypot(points[before, 0] - points[last, 0], points[before, 1] - points[last, 1])
        keep[before[gap <= (tolerance if joined.count == 1 else tolerance.take(last))]] = False
    return keep


def _simplified(centre, keep, joined, requests, betweens):
    """``keep`` after the simplification of each feature of ``joined`` that asks for one and has more than four
    distinct points (:func:`_fewest_vertices` of the points between its ends, whose neighbours stay: there the
    stubs from the split points, radius 0, meet the axis, so a straight channel keeps vertices that carry its
    width), and the restoration of its chords that leave its region (:func:`_restore_leaving_chords`)."""
    kept = np.flatnonzero(keep)
    blocks = joined.of(kept)
    tolerances = np.array([np.nan if r.simplification is None else r.simplification for r in requests])
    chosen = (blocks.sizes > 4) & ~np.isnan(tolerances)
    if not chosen.any():
        return keep
    selected = blocks.spread(chosen)
    # The points each simplification sees (all but the feature's ends), and those it decides on (not their
    # neighbours either).
    seen = kept.compress(selected & blocks.within(1))
    decided = kept.compress(selected & blocks.within(2))
    simplified = _fewest_of_features(centre, seen, joined.of(seen), tolerances)
    distinct, keep = keep, keep.copy()
    keep[decided] = simplified.take(decided)
    return _restored(centre, distinct, keep, joined, chosen, [_region(*pair) for pair in zip(requests, betweens)])


def _fewest_of_features(centre, seen, blocks, tolerances):
    """Mask (over ``centre``) of the points ``seen`` (grouped by feature as ``blocks``) that each feature's
    :func:`_fewest_vertices` keeps at its tolerance (``tolerances``, CRS units): the lines of one piece in one
    GEOS call; longer ones, and those the plain simplification makes cross themselves, feature by feature."""
    simplified = np.zeros(len(centre), dtype=bool)
    features = np.flatnonzero(blocks.sizes)
    alone = features[blocks.sizes.take(features) > SIMPLIFY_PIECE + 1]
    together = np.setdiff1d(features, alone, assume_unique=True)
    if len(together):
        mine = np.isin(blocks.ids, together)
        points, owner = seen.compress(mine), blocks.ids.compress(mine)
        lines = _lines_by_owner(_with_index(centre, points), owner)
        lines = shapely.simplify(lines, tolerances.take(together), preserve_topology=False)
        simplified[shapely.get_coordinates(lines, include_z=True)[:, 2].astype(np.intp)] = True
        kept = simplified.take(points)
        lines = _lines_by_owner(rows(centre, points.compress(kept)), owner.compress(kept))
        alone = np.concatenate([alone, together[~shapely.is_simple(lines)]])
    for feature in alone:
        points = seen[blocks.starts[feature] : blocks.ends[feature]]
        simplified[points] = False
        simplified[points.compress(_fewest_vertices(rows(centre, points), tolerances[feature]))] = True
    return simplified


def _lines_by_owner(coordinates, owner):
    """An array of one linestring per run of equal ``owner`` (sorted numbers) through its ``coordinates``."""
    if owner[0] == owner[-1]:
        # One line: shapely's ``indices`` path costs more than the plain one on a long line.
        lines = np.empty(1, dtype=object)
        lines[0] = shapely.linestrings(coordinates)
        return lines
    change = np.ones(len(owner), dtype=np.intp)
    change[0] = 0
    np.not_equal(owner[1:], owner[:-1], out=change[1:], casting="unsafe")
    return shapely.linestrings(coordinates, indices=np.cumsum(change))


def _restored(centre, distinct, keep, joined, chosen, regions):
    """``keep`` once no chord of the simplified line of each ``chosen`` feature of ``joined`` leaves its region
    (``regions``: per feature, the polygon and the shift from the local frame to it; one test of all their
    lines, then :func:`_restore_leaving_chords` for those that leave)."""
    kept = np.flatnonzero(keep)
    blocks = joined.of(kept)
    points = kept.compress(blocks.spread(chosen) & blocks.within(1))
    owner = joined.ids.take(points) if joined.count > 1 else np.zeros(len(points), dtype=np.intp)
    features = np.flatnonzero(chosen)
    origins = np.array([regions[feature][1] for feature in features])
    shift = origins[0] if len(features) == 1 else rows(origins, np.searchsorted(features, owner))
    polygons = np.empty(len(features), dtype=object)
    polygons[:] = [regions[feature][0] for feature in features]
    leaving = features[~shapely.covers(polygons, _lines_by_owner(rows(centre, points) + shift, owner))]
    for feature in leaving:
        block = slice(joined.starts[feature], joined.ends[feature])
        keep[block] = _restore_leaving_chords(centre[block], distinct[block], keep[block], *regions[feature])
    return keep


def _results(points, order, centre, keep, joined, ends):
    """Each feature's line from the points of ``joined`` that ``keep`` marks: its vertices, their incircle radii
    and feet (local frame, CRS units), or the :class:`.errors.IncirCuError` of a line of fewer than two points."""
    kept = joined.of(np.flatnonzero(keep))
    # The kept points between the ends, by their index in ``order`` (the ends are always kept).
    order = order.compress(keep[1:-1] if joined.count == 1 else keep[joined.within(1)])
    columns = [centre.compress(keep, axis=0)] + [
        _with_ends(values, order, [end[column] for end in ends], kept)
        for column, values in enumerate((points.radius, points.foot_a, points.foot_b), start=1)
    ]
    return [
        IncirCuError(Message("chains_too_close")) if size < 2 else line
        for size, line in zip(kept.sizes, zip(*(kept.split(column) for column in columns)))
    ]


def _fewest_vertices(points, tolerance):
    """Mask of the vertices a Douglas-Peucker simplification to ``tolerance`` keeps (the ends among them).

    The kept vertices are a subset of the given ones, so they stay on the medial axis; every dropped vertex
    lies within ``tolerance`` of the chord that replaces it, so the line moves by at most ``tolerance``.
    A long line is simplified in pieces of ``SIMPLIFY_PIECE`` points that share their end vertices (which
    are kept). When the plain simplification crosses itself, GEOS's (slower) topology-preserving one of the
    whole line keeps it simple.
    """
    # Each vertex carries its index as its z: GEOS simplifies in the plane and keeps the z of the vertices it
    # keeps, so the kept ones are known without matching coordinates.
    keep = np.zeros(len(points), dtype=bool)
    last, batch = len(points) - 1, SIMPLIFY_PIECE * SIMPLIFY_BATCH
    for begin in range(0, last, batch):
        _keep_simplified(keep, _pieces(points, begin, min(begin + batch, last)), tolerance)
    if not shapely.is_simple(shapely.linestrings(points.compress(keep, axis=0))):
        line = shapely.simplify(_indexed_line(points, 0, last), tolerance, preserve_topology=True)
        keep[:] = False
        keep[shapely.get_coordinates(line, include_z=True)[:, 2].astype(np.intp)] = True
    return keep


def _restore_leaving_chords(centre, distinct, keep, region, origin):
    """``keep`` with points of ``distinct`` put back until no chord of the simplified line leaves ``region``.

    A chord lies within the simplification tolerance of the axis points it replaces, so it can only leave the
    region where the boundary comes that close to the axis: a bend tighter than the tolerance, a spike
    reaching near the axis. The line between the first and the last axis point (without the stubs from the
    split points, which end on the boundary up to rounding) is tested once; only when ``region`` does not
    cover it are its chords tested, and each one that leaves is split at the point it replaced farthest from
    it (a Douglas-Peucker step), round after round. Should the points put back make the line cross itself,
    every distinct point is kept.

    Parameters
    ----------
    centre : ndarray of shape (n, 2)
        The ordered axis points, in the local frame of ``origin`` (CRS units).
    distinct, keep : ndarray of shape (n,) of bool
        The points before and after the simplification (both keep the two ends and their neighbours).
    region : Polygon
        CRS units, shifted by ``origin`` from the local frame (not modified: it may be the caller's).
    origin : ndarray of shape (2,)
        CRS units.

    Returns
    -------
    ndarray of shape (n,) of bool
    """
    inner = np.flatnonzero(keep)[1:-1]
    if shapely.covers(region, shapely.linestrings(rows(centre, inner) + origin)):
        return keep
    inside = shapely.force_2d(region)
    shapely.prepare(inside)
    keep = keep.copy()
    chords = np.stack([inner[:-1], inner[1:]], axis=1)
    # Distinct points up to each index: a chord replaced points where its ends' counts differ by more than 1.
    count = np.cumsum(distinct)
    while len(chords):
        # Only chords that replaced points can be mended (the others join two neighbouring axis points).
        chords = chords[count.take(chords[:, 1]) - count.take(chords[:, 0]) > 1]
        ends = rows(centre, chords.reshape(-1)).reshape(-1, 2, 2) + origin
        chords = chords[~shapely.covers(inside, shapely.linestrings(ends))]
        split = [_farthest_between(centre, distinct, start, end) for start, end in chords]
        keep[split] = True
        chords = np.concatenate([np.stack([chords[:, 0], split], axis=1), np.stack([split, chords[:, 1]], axis=1)])
    if not shapely.is_simple(shapely.linestrings(centre.compress(keep, axis=0))):
        return distinct
    return keep


def _farthest_between(centre, distinct, start, end):
    """Index of the point of ``distinct`` strictly between ``start`` and ``end`` farthest from the line through
    ``centre[start]`` and ``centre[end]`` (there is one)."""
    between = start + 1 + np.flatnonzero(distinct[start + 1 : end])
    direction = centre[end] - centre[start]
    offset = rows(centre, between) - centre[start]
    return int(between[np.argmax(np.abs(offset[:, 0] * direction[1] - offset[:, 1] * direction[0]))])


def _pieces(points, begin, end):
    """The line through ``points[begin : end + 1]`` as a list of linestrings of ``SIMPLIFY_PIECE`` segments (the
    last one shorter) that share their end vertices, each vertex with its index as its z."""
    # One linestring per piece: shapely's ``indices`` path (one call for all) costs more than the calls it saves.
    return [
        _indexed_line(points, start, min(start + SIMPLIFY_PIECE, end)) for start in range(begin, end, SIMPLIFY_PIECE)
    ]


def _indexed_line(points, begin, end):
    """The linestring through ``points[begin : end + 1]`` (CRS units), each vertex with its index as its z."""
    return shapely.linestrings(_with_index(points, np.arange(begin, end + 1)))


def _keep_simplified(keep, lines, tolerance):
    """Mark in ``keep`` the vertices that the Douglas-Peucker simplification of ``lines`` (their z: the vertices'
    indices) to ``tolerance`` (CRS units) keeps."""
    kept = shapely.get_coordinates(shapely.simplify(lines, tolerance, preserve_topology=False), include_z=True)
    keep[kept[:, 2].astype(np.intp)] = True


def _with_index(points, index):
    """The points ``index`` of ``points`` (an ``(n, 2)`` array, CRS units), with their index as a third column."""
    indexed = np.empty((len(index), 3))
    indexed[:, :2] = rows(points, index)
    indexed[:, 2] = index
    return indexed
