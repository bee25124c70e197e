"""The samples before the rounds: both ends of every traced edge, the middle of an edge between two convex
corners and a sample on every convex corner's bisector, solved in one pass along the chains; the intervals
between them, cut at the corners' junctions (docs/tracing.md, *Convex corners*)."""

from dataclasses import replace

import numpy as np

from .._arrays import rows
from ..contacts import CLEAR, SKIPPED, TIED, Samples
from .intervals import Intervals, split_at_nodes
from .options import Solution
from .probes import skip_beside_convex_corners, solve_all
from .spans import EDGE, FAN, straight_turns


def initial_samples(spans, sites, closed, traced, boundary):
    """The given sites of the samples at both ends of every edge of the traced chains (``traced``: per chain).

    ``closed``: per chain, whether its pair of chains shares both end points. Returns the traced edges
    (global segment indices; the ``k``-th one's samples are ``2k`` and ``2k + 1``) and, per sample, the given
    site (-1: to be solved), its status, and the site of the other chain's vertex when the sample lies at a
    straight split point (else -1).

    A sample next to a convex corner is not solved: the corner's other edge line is its first contact, at
    ``t = 0`` (skipped). At a convex split point the other chain's end edge is (clear, the disk is the
    point).
    """
    edge = np.flatnonzero(traced[boundary.chain_id])
    rank = np.arange(len(edge))
    site = np.full(2 * len(edge), -1)
    status = np.full(2 * len(edge), SKIPPED, dtype=np.int8)
    start_vertex = boundary.start_vertex(edge)
    corner_at_start = (sites.kinds[start_vertex] > 0) & ~boundary.first_of_chain[edge]
    corner_at_end = (sites.kinds[start_vertex + 1] > 0) & ~boundary.last_of_chain[edge]
    site[2 * rank[corner_at_start]] = edge[corner_at_start] - 1
    site[2 * rank[corner_at_end] + 1] = edge[corner_at_end] + 1
    # Convex at a split point: the other chain's end edge leaves it into the region.
    first_edge = np.asarray(boundary.offset)
    last_edge = np.append(first_edge[1:], boundary.segment_count) - 1
    split_vertex = np.full(2 * len(edge), -1)
    chain = np.flatnonzero(closed & traced)
    for edges, which, outward in ((first_edge, 0, 1.0), (last_edge, 1, -1.0)):
        own, other = edges[chain], edges[chain ^ 1]
        own_rank = np.searchsorted(edge, own)
        turn = np.einsum("ij,ij->i", outward * rows(sites.unit, other), rows(spans.normal, own_rank))
        straight_turn = straight_turns(boundary, own, other)
        convex = turn > straight_turn
        site[2 * own_rank[convex] + which] = other[convex]
        status[2 * own_rank[convex] + which] = CLEAR
        # The other chain's vertex at a straight split point (the other chain's end vertex of that side).
        straight = np.abs(turn) <= straight_turn
        vertex = other + (chain ^ 1) + which
        split_vertex[2 * own_rank[straight] + which] = boundary.segment_count + vertex[straight]
    return edge, site, status, split_vertex


def initial_intervals(tracer, report):
    """Solve the samples at both ends of every traced edge, in the middle of an edge between two convex
    corners (both its ends are given the corners' own edges: its axis point would take a round to find) and
    on the bisector of every convex corner between two intervals (:func:`corner_junctions`), all in one
    solution; returns the intervals of every span between the samples, cut at the corners' junctions."""
    spans, b = tracer.spans, tracer.boundary
    edge, given_site, status, split_vertex = initial_samples(
        spans, tracer.sites, tracer.options.closed, tracer.traced, b
    )
    # The traced edges' spans come first, in the same order.
    edge_span = np.arange(len(edge))
    between_corners = (given_site[0::2] >= 0) & (given_site[1::2] >= 0)
    middle = np.flatnonzero(between_corners)
    span = np.concatenate([np.repeat(edge_span, 2), middle])
    u = np.concatenate(
        [np.stack([np.zeros(len(edge)), spans.length[edge_span]], axis=1).ravel(), 0.5 * spans.length[middle]]
    )
    intervals = intervals_between(spans, edge, between_corners)
    after, before = beside_corners(b, spans, tracer.sites, intervals)
    corners = corner_samples(spans, intervals.span[after])
    tracer.stats.corner_samples += len(after)
    samples = Samples.concatenate([spans.samples(span, u, b), corners])
    t, status, site = solve_initial(tracer, samples, given_site, status, report)
    # A disk that touches nothing (t infinite, two bank lines far apart in length) has no centre: NaN.
    with np.errstate(invalid="ignore"):
        centre = samples.point + t[:, None] * samples.direction
    del samples
    # The edges' samples (the corners' follow them).
    count = len(span)
    solved = (t[count:], status[count:], site[count:], centre[count:])
    t, status, site, centre = t[:count], status[:count], site[:count], centre[:count]
    # A middle of a tiny edge between two corners may lie that close to them (the ends there are given).
    skip_beside_convex_corners(tracer, span, u, t, status, site, centre)
    emit = np.isfinite(t) & ((status == CLEAR) | ((status == TIED) & ~tracer.at_split_point(site)))
    # A disk tangent at a straight split point touches the other chain there: whatever it touches first
    # (a branch of its own chain's corner meets the axis there), it is a point of the axis.
    split_vertex = np.concatenate([split_vertex, np.full(len(middle), -1)])
    at_split = (split_vertex >= 0) & np.isfinite(t) & (t > tracer.options.min_t[spans.chain[span]]) & ~emit
    tracer.samples.add(span, u, t, centre, emit | at_split, np.where(at_split, split_vertex, site))
    intervals = replace(intervals, site0=site[intervals.left], site1=site[intervals.right])
    return corner_junctions(tracer, intervals, after, before, corners, solved)


def intervals_between(spans, edge, between_corners):
    """The intervals between the initial samples (:func:`initial_intervals`: the ``2k``-th and ``2k + 1``-th at the
    ends of traced edge ``edge[k]``, then the middles of the edges ``between_corners``), their sites not yet
    known (-1)."""
    middle = np.flatnonzero(between_corners)
    middle_index = 2 * len(edge) + np.arange(len(middle))
    reflex = np.flatnonzero(spans.kind == FAN)
    incoming = np.searchsorted(edge, spans.segment[reflex])
    whole = np.flatnonzero(~between_corners)
    span = np.concatenate([whole, middle, middle, reflex])
    u0 = np.concatenate([np.zeros(len(whole) + len(middle)), 0.5 * spans.length[middle], np.zeros(len(reflex))])
    u1 = np.concatenate([spans.length[whole], 0.5 * spans.length[middle], spans.length[middle], spans.length[reflex]])
    left = np.concatenate([2 * whole, 2 * middle, middle_index, 2 * incoming + 1])
    right = np.concatenate([2 * whole + 1, middle_index, 2 * middle + 1, 2 * (incoming + 1)])
    no_site = np.full(len(span), -1)
    return Intervals(span, u0, u1, left, right, no_site, no_site, np.zeros(len(span), bool))


def solve_initial(tracer, samples, given_site, given_status, report):
    """Solve the initial samples: the ends of the traced edges (``given_site``: -1 where to be solved;
    ``given_status`` for the ends), the middles and the corners' samples (the samples after the ends),
    together in the order of their points along the chains (one coarse-to-fine solution: on a feature with
    many samples each sample's trial is interpolated between the radii found around it, on a small one it is
    a fraction of the typical width). Returns ``t``, status and canonical site of every sample."""
    count = len(given_site)
    middles = np.arange(count, len(samples.chain))
    index = np.concatenate([np.flatnonzero(given_site < 0), middles])
    # By chain, then position: each middle among the solved ends of the edges around it (its own edge's ends
    # are given); samples at one place keep their order (lexsort is stable).
    index = index[np.lexsort((samples.position[index], samples.chain[index]))]
    t = np.zeros(len(samples.chain))
    site = np.concatenate([given_site, np.full(len(middles), -1)])
    status = np.concatenate([given_status, np.full(len(middles), SKIPPED, dtype=np.int8)])
    t[index], status[index], _, _, site[index] = solve_all(
        samples,
        index,
        tracer.boundary,
        0.625 * tracer.options.width,
        tracer.options.max_t,
        tracer.options.min_t,
        lambda done: report(0.8 * done),
    )
    if tracer.stats.record_solutions:
        corners = np.count_nonzero(samples.slide[index] > 0.0)
        tracer.stats.solutions.append(
            Solution("initial", samples.chain[index], samples.position[index], corners=corners)
        )
    return t, status, tracer.sites.canonical(site)


def corner_samples(spans, span):
    """Samples on the bisector of the convex corner at the start of each edge span ``span`` (span
    ``span - 1`` is the edge before it; the disks touch both segments ``slide * t`` from the corner, with
    radius ``scale * t``)."""
    segment = spans.segment[span]
    normal = rows(spans.normal, span)
    bisector = rows(spans.normal, span - 1) + normal
    bisector /= np.hypot(*bisector.T)[:, None]
    return Samples(
        chain=spans.chain[span],
        point=rows(spans.point, span),
        direction=bisector,
        scale=np.einsum("ij,ij->i", bisector, normal),
        position=spans.position[span],
        slide=np.abs(np.einsum("ij,ij->i", bisector, rows(spans.unit, span))),
        first_own=segment - 1,
        last_own=segment,
    )


def beside_corners(b, spans, sites, intervals):
    """The intervals on both sides of the convex corners of the traced chains: per corner, the one that
    starts at it (on the edge after it) and the one that ends at it (on the edge before it).

    Beside a chain's end the junction may touch the other chain at the split point itself (a tie whose
    foot the ordering cannot place on a side): those corners are left out.
    """
    after = ((intervals.u0 == 0.0) & (spans.kind[intervals.span] == EDGE)).nonzero()[0]
    segment = spans.segment[intervals.span[after]]
    corner = sites.kinds[b.start_vertex(segment)] > 0
    corner &= ~b.first_of_chain[segment] & ~b.first_of_chain[segment - 1] & ~b.last_of_chain[segment]
    after = after[corner]
    # The interval ending at the end of edge span k has that edge's end sample, 2k + 1, at its right.
    before = np.full(len(spans.kind), -1)
    ends = (intervals.right == 2 * intervals.span + 1).nonzero()[0]
    before[intervals.span[ends]] = ends
    before = before[intervals.span[after] - 1]
    after, before = after[before >= 0], before[before >= 0]
    # In the order of the spans (along the chains), so neighbouring samples share index queries.
    order = np.argsort(intervals.span[after], kind="stable")
    return after[order], before[order]


def corner_junctions(tracer, intervals, after, before, corners, solved):
    """Split the intervals on both sides of every convex corner of a traced chain at its junction.

    The largest empty disk on the corner's bisector touches both its segments and first touches a site
    elsewhere: one sample gives the event that the intervals beside the corner (each with the corner's
    other segment as its site at the corner) would otherwise probe one by one, from both sides. Its
    disk is the sample of both edges where it touches them; a junction touching an edge beyond its
    interval, or beside a chain's end, is left to the rounds. ``after``, ``before``: the intervals beside
    the corners (:func:`beside_corners`); ``corners``: their samples (:func:`corner_samples`), solved
    with the initial ones (``solved``: their ``t``, status, canonical site and disk centre).
    """
    if len(after) == 0:
        return intervals
    t, status, site, centre = solved
    along, radius = corners.slide * t, corners.scale * t
    inside = np.isfinite(t) & (site >= 0) & (along < intervals.u1[after])
    inside &= intervals.u1[before] - along > intervals.u0[before]
    centre = centre.compress(inside, axis=0)
    after, before = after[inside], before[inside]
    along, radius, status, site = along[inside], radius[inside], status[inside], site[inside]
    span = np.concatenate([intervals.span[after], intervals.span[before]])
    u = np.concatenate([along, intervals.u1[before] - along])
    emit = (status == CLEAR) | ((status == TIED) & ~tracer.at_split_point(site))
    index = tracer.samples.add(span, u, np.tile(radius, 2), np.tile(centre, (2, 1)), np.tile(emit, 2), np.tile(site, 2))
    owner = np.concatenate([after, before])
    # Beside the corner the disk touches the corner's other segment (the interval's site there).
    site_before = np.concatenate([intervals.site0[after], site])
    site_after = np.concatenate([site, intervals.site1[before]])
    return split_at_nodes(intervals, owner, u, index, site_before, site_after, False)
