"""The IncirCu engine: incircles between two boundary chains, ordered into one centerline.

For every sample ``P`` of a chain with inward direction ``b`` the engine grows the family of disks that
touch the chain only at ``P`` (centre ``P + t*b``, radius ``k*t``; ``k = 1`` on an edge or at a reflex
vertex, ``k = sin(alpha/2)`` on the bisector of a convex vertex of interior angle ``alpha``) and finds the
first ``t`` at which the disk touches any other part of the boundary, in closed form per segment. When that
first contact lies on the *other* chain the disk is a maximal empty disk touching both chains, so its
centre lies on the medial axis between them; when it lies on the sample's own chain the centre would be on
a side branch and the sample is skipped. Both chains are sampled, and the union is ordered by the arc-length
positions of the touching points, which grow monotonically along the axis between the chains.

Candidate segments come from a shapely ``STRtree`` queried in bulk with the bounding box of a trial disk;
a sample is settled once its first contact lies inside the trial disk, otherwise the trial radius at most
doubles, up to the best contact found so far. Trial radii come from a coarse-to-fine pass over the samples,
so the boxes stay tight where the width varies. Where neighbouring samples switch between skipped and
accepted, or their contacts jump along the other chain, the branch point between them is located by
bisection and added. Work is done in chunks of samples, so memory stays bounded.
"""

from dataclasses import dataclass, fields
from functools import partial
from typing import Callable, Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from .chains import COINCIDENCE_TOLERANCE, arc_lengths, as_coordinates, clean_chain, extent_of, signed_area
from .errors import IncirCuError

#: Default spacing as a fraction of the typical width (see :func:`default_spacing`).
DEFAULT_SPACING_PER_WIDTH = 1.0 / 20.0

#: Largest angle, radians, between two normals of the fan at a reflex vertex.
MAX_FAN_STEP = np.radians(5.0)

#: Probes per round and rounds locating where the samples of an edge switch between accepted and skipped,
#: or where their contacts jump along the other chain.
TRANSITION_PROBES = 15
TRANSITION_ROUNDS = 3

#: Contacts of two neighbouring samples farther apart along the other chain than this many times the samples'
#: own distance mark a side branch leaving the axis between them.
JUMP_RATIO = 8.0

#: Stations at spacing/2, spacing/4, ... spacing/2**END_REFINEMENT from both ends of each chain.
END_REFINEMENT = 16

#: Most directions in the fan of one reflex vertex.
MAX_FAN_DIRECTIONS = 256

#: Most samples one call accepts (measured: about 600 bytes of memory per sample, so about 6 GB).
MAX_SAMPLES = 10_000_000

#: Relative slack (of a segment's length) with which a tangency at a segment's end still counts as inside.
ALONG_TOLERANCE = 1e-9

#: Relative distance (of the vertex from the sample) within which a vertex counts as on a corner's edge line.
GRAZING_TOLERANCE = 1e-10

#: Status of a sample: its first contact is on its own chain (or nowhere), on both chains within
#: ``TIE_TOLERANCE``, or on the other chain only.
SKIPPED, TIED, CLEAR = 0, 1, 2

#: Relative slack with which a contact on the other chain still wins over a tie on the sample's own chain.
TIE_TOLERANCE = 1e-10

#: Samples solved together (bounds the memory of the candidate pairs).
_CHUNK = 16_384

#: Ratio between the sample strides of two levels of the coarse-to-fine solution, and the number of levels
#: above the finest one for a chunk large enough.
COARSE_STRIDE = 8
COARSE_LEVELS = 2

#: Consecutive samples whose candidate boxes share one spatial-index query.
QUERY_GROUP = 2

#: Consecutive segments that share one entry of the spatial index.
INDEX_RUN = 4


class Cancelled(Exception):
    """Raised when the progress callback asks the engine to stop."""


@dataclass(frozen=True)
class CenterlineResult:
    """A centerline with the incircle of each of its vertices.

    Attributes
    ----------
    line : LineString
        The centerline, one simple chain from one end to the other, CRS units.
    radii : ndarray of shape (n,)
        Incircle radius at each vertex, CRS units (metres for geographic input); ``0`` at a split point, half
        the gap at an open end.
    foot_a, foot_b : ndarray of shape (n, 2)
        For each vertex, a point where its incircle touches the first and the second chain.
    ends_found : bool
        True when the ends were found automatically rather than given.
    notes : tuple of str
        Things the user should know about this result (e.g. the shape is not elongated).
    """

    line: LineString
    radii: np.ndarray
    foot_a: np.ndarray
    foot_b: np.ndarray
    ends_found: bool = False
    notes: tuple = ()

    @property
    def widths(self):
        """ndarray of shape (n,): local width (incircle diameter) at each vertex, CRS units."""
        return 2.0 * self.radii

    @property
    def length(self):
        """float: length of the centerline, CRS units."""
        return self.line.length


@dataclass(frozen=True)
class _Samples:
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

    def subset(self, index):
        """The samples ``index`` (an index array or mask)."""
        return _Samples(*(getattr(self, field.name)[index] for field in fields(self)))

    @staticmethod
    def concatenate(parts):
        """All samples of ``parts``, one after the other."""
        return _Samples(*(np.concatenate([getattr(part, field.name) for part in parts]) for field in fields(_Samples)))


class _Boundary:
    """The segments of both chains, with a spatial index."""

    def __init__(self, chains):
        starts, ends, chain_ids, offsets, positions = [], [], [], [], []
        count = 0
        for chain_id, chain in enumerate(chains):
            starts.append(chain[:-1])
            ends.append(chain[1:])
            chain_ids.append(np.full(len(chain) - 1, chain_id))
            offsets.append(count)
            count += len(chain) - 1
            positions.append(arc_lengths(chain))
        self.start = np.concatenate(starts)
        self.end = np.concatenate(ends)
        self.chain_id = np.concatenate(chain_ids)
        self.offset = offsets
        self.position = positions
        self.segment_position = np.concatenate([p[:-1] for p in positions])
        self.segment_end_position = np.concatenate([p[1:] for p in positions])
        self.last_of_chain = np.zeros(count, dtype=bool)
        self.last_of_chain[np.cumsum([len(c) - 1 for c in chains]) - 1] = True
        delta = self.end - self.start
        self.length = np.hypot(*delta.T)
        self.unit = delta / self.length[:, None]
        self.start_x, self.start_y = self.start[:, 0].copy(), self.start[:, 1].copy()
        self.unit_x, self.unit_y = self.unit[:, 0].copy(), self.unit[:, 1].copy()
        low, high = np.minimum(self.start, self.end), np.maximum(self.start, self.end)
        self.low_x, self.low_y = low[:, 0].copy(), low[:, 1].copy()
        self.high_x, self.high_y = high[:, 0].copy(), high[:, 1].copy()
        # The index holds runs of INDEX_RUN consecutive segments: INDEX_RUN times fewer GEOS geometries to
        # build, store and search; a run's hits are filtered segment by segment.
        run_start = np.arange(0, len(self.start), INDEX_RUN)
        self.run_low = np.minimum.reduceat(low, run_start)
        self.run_high = np.maximum.reduceat(high, run_start)
        self.run_size = np.diff(np.append(run_start, len(self.start)))
        self.tree = shapely.STRtree(
            shapely.box(self.run_low[:, 0], self.run_low[:, 1], self.run_high[:, 0], self.run_high[:, 1])
        )

    def candidates(self, low, high):
        """Pairs (box index, segment index), sorted by box, of segments whose bounding box meets a box.

        The index is queried once per ``QUERY_GROUP`` consecutive boxes (their union), which is much cheaper
        than one query per box when consecutive boxes overlap, as they do along a chain; the hits are then
        filtered segment by segment and box by box.
        """
        count = len(low)
        starts = np.arange(0, count, QUERY_GROUP)
        group_low = np.minimum.reduceat(low, starts)
        group_high = np.maximum.reduceat(high, starts)
        group, run = self.tree.query(shapely.box(group_low[:, 0], group_low[:, 1], group_high[:, 0], group_high[:, 1]))
        pair, offset = _ranges(self.run_size[run])
        group, segment = group[pair], run[pair] * INDEX_RUN + offset
        keep = self._overlaps(segment, group_low[group], group_high[group])
        group, segment = group[keep], segment[keep]

        hits_per_group = np.bincount(group, minlength=len(starts))
        first_hit = np.cumsum(hits_per_group) - hits_per_group
        box_group = np.arange(count) // QUERY_GROUP
        box, offset = _ranges(hits_per_group[box_group])
        segment = segment[first_hit[box_group[box]] + offset]
        keep = self._overlaps(segment, low[box], high[box])
        return box[keep], segment[keep]

    def _overlaps(self, segment, low, high):
        """Whether each segment's bounding box meets the matching box ``low..high``."""
        keep = self.low_x[segment] <= high[:, 0]
        keep &= self.high_x[segment] >= low[:, 0]
        keep &= self.low_y[segment] <= high[:, 1]
        keep &= self.high_y[segment] >= low[:, 1]
        return keep


def _ranges(counts):
    """For ``counts[i]`` items owned by ``i``: the owner of each item and its rank among the owner's items."""
    owner = np.repeat(np.arange(len(counts)), counts)
    rank = np.arange(len(owner)) - np.repeat(np.cumsum(counts) - counts, counts)
    return owner, rank


def _left_normal(vectors):
    return np.stack([-vectors[:, 1], vectors[:, 0]], axis=1)


def _rotate(vectors, angles):
    cos, sin = np.cos(angles), np.sin(angles)
    return np.stack([cos * vectors[:, 0] - sin * vectors[:, 1], sin * vectors[:, 0] + cos * vectors[:, 1]], axis=1)


def _sample_chain(chain_id, chain, positions, side, spacing, offset, fan_step):
    """Sample one chain: equidistant edge points plus every interior vertex (a fan at reflex ones).

    ``side`` is +1 when the region lies left of the chain, -1 when right; ``offset`` is the global index of
    the chain's first segment.
    """
    n_segments = len(chain) - 1
    unit = np.diff(chain, axis=0) / np.diff(positions)[:, None]
    normal = side * _left_normal(unit)
    total = positions[-1]
    merge = COINCIDENCE_TOLERANCE * max(total, 1.0)

    # Near each end the part of the axis whose disks touch both chains can be much shorter than the spacing
    # (a split point on a straight cap); stations halving the spacing towards the ends trace it too.
    towards_ends = spacing * 0.5 ** np.arange(1, END_REFINEMENT + 1)
    stations = np.unique(
        np.concatenate([np.arange(1, int(np.ceil(total / spacing))) * spacing, towards_ends, total - towards_ends])
    )
    stations = stations[(stations > merge) & (stations < total - merge)]
    segment = np.clip(np.searchsorted(positions, stations, side="right") - 1, 0, n_segments - 1)
    off_vertex = (stations - positions[segment] > merge) & (positions[segment + 1] - stations > merge)
    stations, segment = stations[off_vertex], segment[off_vertex]
    edge_point = chain[segment] + (stations - positions[segment])[:, None] * unit[segment]

    inner = np.arange(1, n_segments)
    incoming, outgoing = unit[inner - 1], unit[inner]
    turn = np.arctan2(
        incoming[:, 0] * outgoing[:, 1] - incoming[:, 1] * outgoing[:, 0],
        np.einsum("ij,ij->i", incoming, outgoing),
    )
    convex = side * turn > 0
    bisector = normal[inner - 1] + normal[inner]
    bisector /= np.linalg.norm(bisector, axis=1, keepdims=True)
    interior_angle = np.pi - side * turn

    fan_vertex = inner[~convex]
    fan_turn = turn[~convex]
    fan_count = np.where(
        np.abs(fan_turn) >= fan_step,
        np.minimum(np.ceil(np.abs(fan_turn) / fan_step), MAX_FAN_DIRECTIONS - 1).astype(int) + 1,
        1,
    )
    fan_owner = np.repeat(np.arange(len(fan_vertex)), fan_count)
    first_of_fan = np.repeat(np.cumsum(fan_count) - fan_count, fan_count)
    fan_index = np.arange(len(fan_owner)) - first_of_fan
    fraction = np.where(fan_count[fan_owner] > 1, fan_index / np.maximum(fan_count[fan_owner] - 1, 1), 0.5)
    fan_direction = _rotate(normal[fan_vertex - 1][fan_owner], fan_turn[fan_owner] * fraction)
    fan_vertex = fan_vertex[fan_owner]

    convex_vertex = inner[convex]
    half_angle = interior_angle[convex] / 2.0

    position = np.concatenate([stations, positions[fan_vertex], positions[convex_vertex]])
    order = np.argsort(position, kind="stable")
    return _Samples(
        chain=np.full(len(order), chain_id, dtype=np.int8),
        point=np.concatenate([edge_point, chain[fan_vertex], chain[convex_vertex]])[order],
        direction=np.concatenate([normal[segment], fan_direction, bisector[convex]])[order],
        scale=np.concatenate([np.ones(len(segment) + len(fan_vertex)), np.sin(half_angle)])[order],
        position=position[order],
        slide=np.concatenate([np.zeros(len(segment) + len(fan_vertex)), np.cos(half_angle)])[order],
        first_own=offset + np.concatenate([segment, fan_vertex - 1, convex_vertex - 1])[order],
        last_own=offset + np.concatenate([segment, fan_vertex, convex_vertex])[order],
    )


def _vertex_contact(offset, height, b_along, b_across, scale, slide):
    """First contact ``t`` with a segment's vertex, inf when none.

    In the segment's frame the vertex lies ``offset`` along the segment from the sample point and ``-height``
    across it; ``(b_along, b_across)`` is the sample's direction in that frame. With vertex - point =
    x*b + y*b_perp, the contact solves slide^2 t^2 - 2 x t + |d|^2 = 0, whose discriminant factors as
    (x*scale - |y|*slide) (x*scale + |y|*slide); the first factor is, up to a constant, the vertex's distance
    from an incident line of a convex corner. A vertex on that line is touched as the disks slide along it (a
    double root), so a factor that rounding pushed just below zero is taken as zero: the contact stays where it
    is under tiny perturbations of the input.
    """
    x = b_along * offset - b_across * height
    y = np.abs(b_along * height + b_across * offset)
    squared = offset * offset + height * height
    near = x * scale - y * slide
    far = x * scale + y * slide
    near = np.where((near < 0) & (near >= -GRAZING_TOLERANCE * np.sqrt(squared)), 0.0, near)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = squared / (np.sqrt(np.maximum(near * far, 0.0)) + x)
    return np.where((x > 0) & (near >= 0), t, np.inf)


def _first_contacts(px, py, bx, by, scale, slide, boundary, segment):
    """First contact ``t`` of each (sample, segment) pair, inf when the disk family never touches it.

    ``(px, py)`` is the sample point, ``(bx, by)`` its unit direction, ``scale`` the radius per unit of
    ``t`` (``sin`` of the half angle at a convex vertex, else 1) and ``slide`` the matching ``cos`` (else 0).
    Returns ``t`` and where on the segment the contact is, as a length from its start.

    A segment answers for its start vertex only (its end is the next segment's start, which is a candidate
    whenever that vertex can be touched); the last segment of a chain answers for its end too.
    """
    ax, ay = boundary.start_x[segment], boundary.start_y[segment]
    ux, uy = boundary.unit_x[segment], boundary.unit_y[segment]
    length = boundary.length[segment]
    dx, dy = px - ax, py - ay
    along_p = dx * ux + dy * uy
    height = dx * -uy + dy * ux
    b_along = bx * ux + by * uy
    b_across = by * ux - bx * uy

    t_start = _vertex_contact(-along_p, height, b_along, b_across, scale, slide)
    t_end = np.full(len(segment), np.inf)
    last = np.flatnonzero(boundary.last_of_chain[segment])
    t_end[last] = _vertex_contact(
        length[last] - along_p[last], height[last], b_along[last], b_across[last], scale[last], slide[last]
    )

    side = np.where(height < 0, -1.0, 1.0)
    distance = side * height
    denominator = scale - side * b_across
    with np.errstate(divide="ignore", invalid="ignore"):
        t_tangent = distance / denominator
        along = along_p + t_tangent * b_along
    slack = ALONG_TOLERANCE * length
    tangent = (distance > 0) & (denominator > 1e-12) & (along >= -slack) & (along <= length + slack)
    # A tangency inside the segment is its first contact, and it is well conditioned; a contact through an
    # end point only counts when there is no such tangency (near it, the vertex root is a double root that
    # keeps only half the digits).
    t_vertex = np.minimum(t_start, t_end)
    t = np.where(tangent, t_tangent, t_vertex)
    along = np.where(tangent, np.clip(along, 0.0, length), np.where(t_vertex == t_start, 0.0, length))
    return t, along


def _group_minimum(group, values, size):
    """Minimum of ``values`` per group id (``group`` sorted ascending); inf for empty groups."""
    result = np.full(size, np.inf)
    if len(group):
        starts = np.flatnonzero(np.concatenate([[True], group[1:] != group[:-1]]))
        result[group[starts]] = np.minimum.reduceat(values, starts)
    return result


def _solve(samples, index, boundary, trial, limit, floor):
    """Settle the samples ``index``, starting from trial parameters ``trial`` (one per sample).

    Returns arrays aligned with ``index``: ``first`` (parameter of the first contact with anything, inf
    when none within ``limit``), ``status`` (``SKIPPED``; ``TIED``: the first contact lies on the other
    chain and, within ``TIE_TOLERANCE``, on the sample's own chain too; ``CLEAR``: on the other chain only),
    and for accepted samples the ``contact`` point and its arc-length ``position`` along the other chain.
    """
    count = len(index)
    point, direction = samples.point[index], samples.direction[index]
    scale, slide = samples.scale[index], samples.slide[index]
    radius = np.array(trial, dtype=float)
    first = np.full(count, np.inf)
    status = np.full(count, SKIPPED, dtype=np.int8)
    contact = np.zeros((count, 2))
    position = np.zeros(count)
    active = np.arange(count)
    while len(active):
        centre = point[active] + radius[active, None] * direction[active]
        # Every disk of the family up to the trial one lies in the disk of radius ``radius`` about the
        # trial centre (its centre moves by dt while its radius grows by scale*dt <= dt).
        reach = radius[active, None] * (1.0 + 1e-9)
        query, segment = boundary.candidates(centre - reach, centre + reach)
        pair = active[query]
        sample = index[pair]
        t, along = _first_contacts(
            point[pair, 0],
            point[pair, 1],
            direction[pair, 0],
            direction[pair, 1],
            scale[pair],
            slide[pair],
            boundary,
            segment,
        )
        own_segment = (segment >= samples.first_own[sample]) & (segment <= samples.last_own[sample])
        t[own_segment | (t <= floor)] = np.inf
        on_own = boundary.chain_id[segment] == samples.chain[sample]
        t_own = np.where(on_own, t, np.inf)
        t_other = np.where(on_own, np.inf, t)

        best_own = _group_minimum(pair, t_own, count)
        best_other = _group_minimum(pair, t_other, count)
        best = np.minimum(best_own[active], best_other[active])
        settled = best <= radius[active]
        first[active[settled]] = best[settled]

        winner = np.isfinite(t_other) & (t_other == best_other[pair])
        winner &= t_other <= best_own[pair] * (1.0 + TIE_TOLERANCE)
        winner &= settled[np.searchsorted(active, pair)]
        winner_pair = np.flatnonzero(winner)
        # Pairs are sorted by sample: keep each sample's first winning pair.
        chosen = winner_pair[np.diff(pair[winner_pair], prepend=-1) != 0]
        chosen_sample, chosen_segment = pair[chosen], segment[chosen]
        status[chosen_sample] = np.where(t[chosen] * (1.0 + TIE_TOLERANCE) < best_own[chosen_sample], CLEAR, TIED)
        first[chosen_sample] = t[chosen]
        contact[chosen_sample] = boundary.start[chosen_segment] + along[chosen, None] * boundary.unit[chosen_segment]
        position[chosen_sample] = np.where(
            along[chosen] >= boundary.length[chosen_segment],
            boundary.segment_end_position[chosen_segment],
            boundary.segment_position[chosen_segment] + along[chosen],
        )

        pending = active[~settled]
        best = best[~settled]
        radius[pending] = np.minimum(best, 2.0 * radius[pending])
        active = pending[radius[pending] <= limit]
    return first, status, contact, position


def _solve_coarse_to_fine(samples, index, boundary, trial_radius, limit, floor, report):
    """Settle ``index`` (sorted by position) from coarse to fine.

    Every ``COARSE_STRIDE ** COARSE_LEVELS``-th sample (every ``COARSE_STRIDE``-th in a small chunk) is
    solved first from a global trial radius, then each finer level from trial radii interpolated between
    the coarser levels' first contacts: a trial close to the answer keeps the candidate boxes tight where
    the width varies. ``report(done)`` is called after each level with the number of samples settled.
    """
    count = len(index)
    first = np.full(count, np.nan)
    status = np.zeros(count, dtype=np.int8)
    contact = np.empty((count, 2))
    position = np.empty(count)
    # Arc length along chain 0, then along chain 1 shifted past it: increasing over the sorted samples.
    along = samples.position[index] + samples.chain[index] * (2.0 * samples.position[index].max() + 1.0)
    stride = COARSE_STRIDE**COARSE_LEVELS if count > COARSE_STRIDE ** (COARSE_LEVELS + 1) else COARSE_STRIDE
    while stride >= 1:
        level = np.zeros(count, dtype=bool)
        level[::stride] = True
        level &= np.isnan(first)
        known = np.isfinite(first)
        if np.any(known):
            estimate = np.interp(along[level], along[known], samples.scale[index[known]] * first[known])
            trial = 1.05 * estimate / samples.scale[index[level]]
        else:
            trial = np.full(level.sum(), trial_radius)
        first[level], status[level], contact[level], position[level] = _solve(
            samples, index[level], boundary, trial, limit, floor
        )
        report(count - np.isnan(first).sum())
        stride //= COARSE_STRIDE
    return first, status, contact, position


def _edge_probes(samples, template, positions, boundary):
    """Samples at arc-length ``positions`` on the edges of the edge samples ``template``."""
    segment = samples.first_own[template]
    along = positions - boundary.segment_position[segment]
    return _Samples(
        chain=samples.chain[template],
        point=boundary.start[segment] + along[:, None] * boundary.unit[segment],
        direction=samples.direction[template],
        scale=np.ones(len(template)),
        position=positions,
        slide=np.zeros(len(template)),
        first_own=segment,
        last_own=segment,
    )


def _bisect(samples, left, first, boundary, limit, floor, on_low_side):
    """Shrink, on the edge of each pair of samples ``left, left + 1``, the bracket of a switch.

    ``TRANSITION_ROUNDS`` rounds of ``TRANSITION_PROBES`` probes shrink each bracket to
    ``(TRANSITION_PROBES + 1) ** -TRANSITION_ROUNDS`` of it (1/4096). ``on_low_side(solution, pair)`` tells,
    for the probes of pair ``pair``, which behave like the pair's left sample.

    Returns the last round's probes and solution (as :func:`_solve`) and, per pair, the index of the last
    probe on the low side (-1: none) among that pair's ``TRANSITION_PROBES`` probes.
    """
    low, high = samples.position[left], samples.position[left + 1]
    trial = np.repeat(1.25 * np.maximum(first[left], first[left + 1]), TRANSITION_PROBES)
    steps = np.arange(1, TRANSITION_PROBES + 1) / (TRANSITION_PROBES + 1)
    template = np.repeat(left, TRANSITION_PROBES)
    pair = np.repeat(np.arange(len(left)), TRANSITION_PROBES)
    rows = np.arange(len(left))
    for _ in range(TRANSITION_ROUNDS):
        where = (low[:, None] + (high - low)[:, None] * steps).ravel()
        probes = _edge_probes(samples, template, where, boundary)
        solution = _solve(probes, np.arange(len(where)), boundary, trial, limit, floor)
        same = on_low_side(solution, pair).reshape(-1, TRANSITION_PROBES)
        last_same = np.where(same.any(axis=1), TRANSITION_PROBES - 1 - np.argmax(same[:, ::-1], axis=1), -1)
        grid = np.column_stack([low, where.reshape(-1, TRANSITION_PROBES), high])
        low, high = grid[rows, last_same + 1], grid[rows, last_same + 2]
    return probes, solution, last_same


def _refine_switches(samples, first, status, contact_position, boundary, limit, floor):
    """Add the branch points of the medial axis that lie between two samples of an edge.

    Two kinds of switch between neighbours on one edge mark such a point, and a chord between the
    neighbours would cut the axis's corner there by up to the spacing:

    - one is skipped and the other clearly accepted: the incircle touches both chains and the sample's own
      chain elsewhere (e.g. where the axis meets the part of an end that touches both chains); the clearly
      accepted end of the final bracket is added. (Ties are left alone: a switch inside a tie's tolerance is
      no branch point; neither is a skipped sample next to an accepted convex vertex, which lies in that
      corner's own branch meeting the axis at the vertex sample's point.)
    - both are accepted but their contacts on the other chain are far apart along it (more than
      ``JUMP_RATIO`` times the samples' distance): the incircle touches the other chain at two places, where a
      side branch into a bay of that chain leaves the axis; both ends of the final bracket are added.

    Returns the probe samples and their solution (as :func:`_solve`), with ties counted as skipped.
    """
    edge = samples.first_own == samples.last_own
    pair = edge[:-1] & edge[1:] & (samples.first_own[:-1] == samples.first_own[1:])
    pair &= np.isfinite(first[:-1]) & np.isfinite(first[1:])
    switch = np.flatnonzero(
        pair & (np.minimum(status[:-1], status[1:]) == SKIPPED) & (np.maximum(status[:-1], status[1:]) == CLEAR)
    )
    convex = np.concatenate([[False], (samples.slide > 0) & (status != SKIPPED), [False]])
    corner = np.where(status[switch] == SKIPPED, convex[switch], convex[switch + 3])
    switch = switch[~corner]
    jump = np.flatnonzero(
        pair
        & (status[:-1] == CLEAR)
        & (status[1:] == CLEAR)
        & (np.abs(np.diff(contact_position)) > JUMP_RATIO * np.diff(samples.position))
    )
    found = []
    if len(switch):
        low_accepted = status[switch] == CLEAR
        probes, solution, last_same = _bisect(
            samples,
            switch,
            first,
            boundary,
            limit,
            floor,
            lambda solution, pair: (solution[1] == CLEAR) == low_accepted[pair],
        )
        found.append((probes, solution, np.where(low_accepted, last_same, last_same + 1)))
    if len(jump):
        low_contact, high_contact = contact_position[jump], contact_position[jump + 1]
        probes, solution, last_same = _bisect(
            samples,
            jump,
            first,
            boundary,
            limit,
            floor,
            lambda solution, pair: np.abs(solution[3] - low_contact[pair]) < np.abs(solution[3] - high_contact[pair]),
        )
        found += [(probes, solution, last_same), (probes, solution, last_same + 1)]
    chosen_probes, chosen_solutions = [], []
    for probes, solution, index in found:
        keep = (index >= 0) & (index < TRANSITION_PROBES)
        chosen = np.flatnonzero(keep) * TRANSITION_PROBES + index[keep]
        chosen_probes.append(probes.subset(chosen))
        chosen_solutions.append([part[chosen] for part in solution])
    if not found:
        return samples.subset(slice(0, 0)), np.empty(0), np.empty(0, dtype=np.int8), np.empty((0, 2)), np.empty(0)
    first_kept, status_kept, contact, position = (np.concatenate(parts) for parts in zip(*chosen_solutions))
    return (
        _Samples.concatenate(chosen_probes),
        first_kept,
        np.where(status_kept == CLEAR, CLEAR, SKIPPED),
        contact,
        position,
    )


def _medial_points(samples, sample, t, boundary):
    """Centre, radius, touching point and its arc length on the sampled chain, for settled samples.

    Returns those arrays and a mask of the samples to keep: at a convex vertex the disk touches the
    incident edges ``slide*t`` from the vertex, on the incoming edge if it is that long, else on the
    outgoing one; a disk that reaches past both edges touches its own chain nowhere and is dropped.
    """
    point = samples.point[sample]
    centre = point + t[:, None] * samples.direction[sample]
    radius = samples.scale[sample] * t
    slide = samples.slide[sample] * t
    incoming, outgoing = samples.first_own[sample], samples.last_own[sample]
    on_incoming = slide <= boundary.length[incoming]
    on_outgoing = ~on_incoming & (slide <= boundary.length[outgoing])
    foot = np.where(
        on_incoming[:, None],
        point - slide[:, None] * boundary.unit[incoming],
        point + slide[:, None] * boundary.unit[outgoing],
    )
    position = samples.position[sample] + np.where(on_incoming, -slide, slide)
    return centre, radius, foot, position, on_incoming | on_outgoing


def _distinct(points, tolerance):
    """Mask keeping both ends and every point farther than ``tolerance`` from the last kept one."""
    step = np.hypot(*np.diff(points, axis=0).T)
    keep = np.concatenate([[True], step > tolerance])
    keep[-1] = True
    kept = np.flatnonzero(keep)
    if len(kept) > 2 and np.hypot(*(points[kept[-2]] - points[-1])) <= tolerance:
        keep[kept[-2]] = False
    return keep


def typical_width(c1, c2):
    """Area between the chains divided by their mean length.

    Parameters
    ----------
    c1, c2 : ndarray of shape (n, 2)
        The chains, running in the same direction, CRS units.

    Returns
    -------
    float
        Typical width, CRS units (for a long rectangle, its width).
    """
    area = abs(signed_area(np.concatenate([c1, c2[::-1]])))
    mean_length = 0.5 * (LineString(c1).length + LineString(c2).length)
    return area / mean_length if mean_length > 0 else 0.0


def default_spacing(c1, c2):
    """Sample spacing used when none is given: the typical width divided by 20.

    A polyline through points of an axis of curvature radius ``R`` spaced ``h`` apart deviates from it by
    at most ``h**2 / (8 R)``. The axis of a region of width ``w`` bends no tighter than ``R = w / 2``
    (tighter, the inner bank would fold), so ``h = w / 20`` bounds the deviation by ``w / 1600`` and its
    mean by about ``4e-4 w``: below ``1e-3`` of the width.

    Parameters
    ----------
    c1, c2 : ndarray of shape (n, 2)
        The chains, CRS units.

    Returns
    -------
    float
        Spacing, CRS units.

    Examples
    --------
    >>> import numpy as np
    >>> default_spacing(np.array([[0.0, 0], [100, 0]]), np.array([[0.0, 10], [100, 10]]))
    0.5
    """
    width = typical_width(c1, c2)
    if not width > 0:
        width = 1e-3 * extent_of(c1, c2)
    return DEFAULT_SPACING_PER_WIDTH * width


def centerline_from_chains(
    c1,
    c2,
    spacing=None,
    *,
    samples_per_chain=None,
    progress: Optional[Callable[[float], bool]] = None,
):
    """Compute the IncirCu centerline between two boundary chains.

    Parameters
    ----------
    c1, c2 : LineString or array_like of shape (n, 2)
        Chains running in the same direction (zero-length segments are dropped). When they share both end
        points (a polygon split at two points) the centerline runs between those points; otherwise it
        runs between the midpoints of the two end gaps.
    spacing : float, optional
        Distance between equidistant samples along each chain, CRS units; default
        :func:`default_spacing`. Every vertex of both chains is sampled as well.
    samples_per_chain : int, optional
        Instead of ``spacing``: this many equidistant samples on each chain.
    progress : callable, optional
        Called with the fraction done (0 to 1); when it returns False the engine raises
        :class:`Cancelled`.

    Returns
    -------
    CenterlineResult

    Raises
    ------
    IncirCuError
        If the spacing is not positive or would need more than ``MAX_SAMPLES`` samples.
    Cancelled
        If ``progress`` returned False.

    Examples
    --------
    >>> import numpy as np
    >>> bank_a = np.array([[0.0, 0.0], [10.0, 0.0]])
    >>> bank_b = np.array([[0.0, 2.0], [10.0, 2.0]])
    >>> result = centerline_from_chains(bank_a, bank_b, spacing=1.0)
    >>> sorted({round(y, 9) for y in result.line.xy[1]})
    [1.0]
    """
    chains = [as_coordinates(c1, "first chain"), as_coordinates(c2, "second chain")]
    merge = COINCIDENCE_TOLERANCE * extent_of(*chains)
    chains = [clean_chain(chain, name, merge) for chain, name in zip(chains, ("first chain", "second chain"))]
    extent = extent_of(*chains)
    lengths = [float(np.hypot(*np.diff(c, axis=0).T).sum()) for c in chains]
    if samples_per_chain is not None:
        if int(samples_per_chain) < 1:
            raise IncirCuError("The number of samples per chain must be at least 1.")
        spacings = [length / (int(samples_per_chain) + 1) for length in lengths]
    else:
        if spacing is None or spacing == 0:
            spacing = default_spacing(*chains)
        if not spacing > 0 or not np.isfinite(spacing):
            raise IncirCuError(f"The spacing must be a positive distance, got {spacing!r}.")
        spacings = [float(spacing)] * 2
    planned = sum(length / s for length, s in zip(lengths, spacings)) + sum(len(c) for c in chains)
    if planned > MAX_SAMPLES:
        raise IncirCuError(
            f"A spacing of {min(spacings):.6g} would need about {planned:.3g} samples (at most "
            f"{MAX_SAMPLES:.3g}); use a larger spacing."
        )

    everything = np.concatenate(chains)
    origin = 0.5 * (everything.min(axis=0) + everything.max(axis=0))
    local = [c - origin for c in chains]
    closed = bool(np.hypot(*(local[0][0] - local[1][0])) <= merge and np.hypot(*(local[0][-1] - local[1][-1])) <= merge)
    side = 1.0 if signed_area(np.concatenate([local[0], local[1][::-1]])) >= 0 else -1.0
    boundary = _Boundary(local)
    width = max(typical_width(*local), merge)
    fan_step = min(MAX_FAN_STEP, 2.0 * min(spacings) / width)
    trial_radius = 0.625 * width
    limit = 4.0 * extent
    floor = 1e-12 * extent

    samples = _Samples.concatenate(
        [
            _sample_chain(
                i, local[i], boundary.position[i], side if i == 0 else -side, spacings[i], boundary.offset[i], fan_step
            )
            for i in (0, 1)
        ]
    )
    total = len(samples.point)
    first = np.empty(total)
    status = np.zeros(total, dtype=np.int8)
    contact = np.zeros((total, 2))
    position = np.zeros(total)

    def report(begin, done_in_chunk):
        if progress is not None and progress((begin + done_in_chunk) / total) is False:
            raise Cancelled()

    for begin in range(0, total, _CHUNK):
        index = np.arange(begin, min(begin + _CHUNK, total))
        first[index], status[index], contact[index], position[index] = _solve_coarse_to_fine(
            samples,
            index,
            boundary,
            trial_radius,
            limit,
            floor,
            partial(report, begin),
        )
    pieces = []
    for probes, probe_first, probe_status, probe_contact, probe_position in (
        (samples, first, status, contact, position),
        _refine_switches(samples, first, status, position, boundary, limit, floor),
    ):
        chosen = np.flatnonzero(probe_status != SKIPPED)
        *medial, keep = _medial_points(probes, chosen, probe_first[chosen], boundary)
        centre, radius, own_foot, own_position = (array[keep] for array in medial)
        other_foot, other_position = probe_contact[chosen][keep], probe_position[chosen][keep]
        on_a = probes.chain[chosen][keep] == 0
        pieces.append(
            (
                centre,
                radius,
                np.where(on_a[:, None], own_foot, other_foot),
                np.where(on_a[:, None], other_foot, own_foot),
                np.where(on_a, own_position, other_position),
                np.where(on_a, other_position, own_position),
            )
        )

    centre, radius, foot_a, foot_b, position_a, position_b = (
        np.concatenate([piece[k] for piece in pieces]) for k in range(6)
    )
    if not closed:
        region = Polygon(np.concatenate([local[0], local[1][::-1]]))
        shapely.prepare(region)
        inside = shapely.intersects_xy(region, centre[:, 0], centre[:, 1])
        centre, radius, foot_a, foot_b = centre[inside], radius[inside], foot_a[inside], foot_b[inside]
        position_a, position_b = position_a[inside], position_b[inside]
    # Points whose feet are the same two vertices (two facing reflex corners) tie on the positions; they lie
    # on the bisector of those vertices, ordered by the direction of travel, perpendicular to foot_b - foot_a.
    across = foot_b - foot_a
    travel = side * np.stack([across[:, 1], -across[:, 0]], axis=1)
    order = np.lexsort(
        (
            np.einsum("ij,ij->i", centre, travel),
            position_a / max(lengths[0], merge) + position_b / max(lengths[1], merge),
        )
    )
    centre, radius, foot_a, foot_b = centre[order], radius[order], foot_a[order], foot_b[order]

    if closed:
        ends = [(local[0][0], 0.0, local[0][0], local[0][0]), (local[0][-1], 0.0, local[0][-1], local[0][-1])]
    else:
        ends = [
            (0.5 * (local[0][i] + local[1][i]), 0.5 * np.hypot(*(local[0][i] - local[1][i])), local[0][i], local[1][i])
            for i in (0, -1)
        ]
    centre = np.concatenate([ends[0][0][None], centre, ends[1][0][None]])
    radius = np.concatenate([[ends[0][1]], radius, [ends[1][1]]])
    foot_a = np.concatenate([ends[0][2][None], foot_a, ends[1][2][None]])
    foot_b = np.concatenate([ends[0][3][None], foot_b, ends[1][3][None]])

    keep = _distinct(centre, 1e-9 * extent)
    centre, radius, foot_a, foot_b = centre[keep], radius[keep], foot_a[keep], foot_b[keep]
    if len(centre) < 2:
        raise IncirCuError("The chains are too close together or too short to carry a centerline.")
    return CenterlineResult(
        line=LineString(centre + origin),
        radii=radius,
        foot_a=foot_a + origin,
        foot_b=foot_b + origin,
    )
