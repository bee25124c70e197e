"""Settling: which intervals stay open, which close without a probe (off the axis, at an end, at their event),
and the stations of the parabolas between samples touching one site (docs/tracing.md)."""

import numpy as np

from .._arrays import left_normal, rows
from .closed_form import parabola_stations
from .events import EVENT_TOLERANCE, is_event
from .probes import solve_probes
from .spans import EDGE, FAN

#: Fraction of the tolerance under which two neighbouring samples' centres settle their interval.
SETTLED_CHORD = 1.0 / 16.0


#: Intervals over which the sample point (or on a fan, the disk's centre) moves less than this fraction of the
#: tolerance are closed.
SMALLEST_MOVE = 1e-6


def open_and_curved(tracer, intervals):
    """The open intervals (:func:`is_open`) and the curved ones (:func:`is_curved`), each judged on the
    intervals that may be one only: both ends solved, and two known sites that differ (open) or one site
    whose stations are not yet placed (curved), not a split point (which lies on both chains: its disks touch
    the other chain only through it, so no parabola round a split point in a concave corner is traced). Each
    record is gathered once, by index, from the rows judged (a mask would be scanned again for every column
    of the record)."""
    t_left, t_right = tracer.samples.t[intervals.left], tracer.samples.t[intervals.right]
    site0, site1 = intervals.site0, intervals.site1
    known = np.isfinite(t_left) & np.isfinite(t_right) & (site0 >= 0)
    differ = site0 != site1
    event = (differ & known & (site1 >= 0)).nonzero()[0]
    if tracer.stats.settle_off_axis:
        off = off_the_axis(tracer, intervals, event)
        tracer.stats.off_the_axis += int(np.count_nonzero(off))
        event = event[~off]
    event = event[is_open(tracer, intervals, event, np.fmax(t_left[event], t_right[event]))]
    curve = (~differ & known & ~intervals.verified).nonzero()[0]
    curve = curve[~tracer.at_split_point(site0[curve])]
    curve = curve[is_curved(tracer, intervals.span[curve], site0[curve])]
    return intervals.subset(event), intervals.subset(curve)


def off_the_axis(tracer, intervals, row):
    """Which of the intervals ``row`` (both ends solved, touching two known different sites) of closed pairs
    of chains hold no point of the axis: both ends touch their own chain, on the same side of the span along
    it.

    The disks between two samples first touch the boundary between the two contacts, on the side away from
    the span (docs/tracing.md, *Off the axis*); when both contacts lie on the own chain before the span, or
    both after it, that part of the boundary is the own chain between them, so every disk between touches its
    own chain first: the samples there lie on side branches, and their events are not points of the axis.
    (With two bank lines the other chain, joined to the own one nowhere, could lie wholly inside that part:
    not for open pairs.)
    """
    span, site0, site1 = intervals.span[row], intervals.site0[row], intervals.site1[row]
    own = tracer.spans.chain[span]
    on_own = tracer.options.closed[own] & (tracer.sites.chain(site0) == own) & (tracer.sites.chain(site1) == own)
    start = tracer.spans.position[span]
    end = tracer.spans.position_at(span, tracer.spans.length[span])
    first0, last0 = tracer.sites.extent(site0)
    first1, last1 = tracer.sites.extent(site1)
    return on_own & (((last0 <= start) & (last1 <= start)) | ((first0 >= end) & (first1 >= end)))


def is_open(tracer, intervals, row, radius):
    """Which of the intervals ``row`` (both ends solved, touching two known different sites; the larger end
    disk of radius ``radius``, CRS units) are still wide enough to split."""
    span = intervals.span[row]
    move = (intervals.u1[row] - intervals.u0[row]) * np.where(tracer.spans.kind[span] == EDGE, 1.0, radius)
    tolerance = tracer.of(tracer.options.tolerance, span)
    open_ = move > SMALLEST_MOVE * tolerance
    # Ends this close leave the axis between them (an event's corner at most) within the tolerance; an
    # event there may be ill-conditioned (a nearly straight convex corner's junction).
    candidate = open_.nonzero()[0]
    left, right = intervals.left[row[candidate]], intervals.right[row[candidate]]
    chord = np.hypot(*(tracer.samples.centres(left) - tracer.samples.centres(right)).T)
    open_[candidate] = chord > SETTLED_CHORD * tolerance[candidate]
    return open_


def is_curved(tracer, span, site):
    """Which intervals on spans ``span`` (both ends solved, touching one site ``site``, stations not yet
    placed) lie between samples touching one site of the other chain where the axis is a parabola.

    A fan touching a segment traces the parabola of its vertex and that segment's line; an edge touching
    a vertex with no fan (a chain's end) traces the parabola of that vertex and the edge's line. (An edge
    touching a reflex vertex of the other chain traces the same curve as that vertex's fan, which places
    the stations of both.)
    """
    spans, sites, b = tracer.spans, tracer.sites, tracer.boundary
    curved = sites.chain(site) == spans.chain[span] ^ 1
    vertex = sites.indices(site)[1]
    fan = (spans.kind[span] == FAN) & (site < b.segment_count)
    untraced_fan = ~tracer.traced[b.vertex_chain[vertex]]
    edge = (spans.kind[span] == EDGE) & (site >= b.segment_count) & ((sites.kinds[vertex] == 0) | untraced_fan)
    return curved & (fan | edge)


def settled_at_event(tracer, intervals, u, radius, found):
    """Mask of the open intervals whose two sites follow each other on the other chain and whose axis
    provably lies within the tolerance of the chord of their end centres (docs/tracing.md, *Settled at
    the event*): the centre of their event (at ``u``, of ``radius``, CRS units, where ``found``) lies within
    the tolerance of the chord, less the larger deviation of the two arcs beside it from their own chords."""
    settled = np.zeros(len(intervals.span), dtype=bool)
    if not tracer.stats.settle_at_event:
        return settled
    row = beside_each_other(tracer, intervals, found & np.isfinite(radius))
    tracer.stats.judged_at_event += len(row)
    if len(row) == 0:
        return settled
    spans = tracer.spans
    span = intervals.span[row]
    point, _ = spans.points(span, u[row])
    event = point + radius[row, None] * spans.directions(span, u[row])
    start, end = tracer.samples.centres(intervals.left[row]), tracer.samples.centres(intervals.right[row])
    chord = end - start
    along = np.clip(np.einsum("ij,ij->i", event - start, chord) / np.einsum("ij,ij->i", chord, chord), 0.0, 1.0)
    distance = np.hypot(*(event - start - along[:, None] * chord).T)
    sag = np.maximum(
        sag_bound(tracer, span, intervals.site0[row], start, event),
        sag_bound(tracer, span, intervals.site1[row], event, end),
    )
    with np.errstate(invalid="ignore"):
        settled[row] = distance + sag <= tracer.of(tracer.options.tolerance, span)
    tracer.stats.settled_at_event += int(np.count_nonzero(settled))
    return settled


def beside_each_other(tracer, intervals, judged):
    """Of the intervals ``judged`` of closed pairs of chains, those whose end samples are emitted (empty disks
    touching their sites) and whose two sites follow each other in the other chain's site sequence, neither
    at one of its ends."""
    sites, b = tracer.sites, tracer.boundary
    chain = tracer.spans.chain[intervals.span]
    other = chain ^ 1
    emit = tracer.samples.emit
    judged = judged & tracer.options.closed[chain] & (sites.chain(intervals.site0) == other)
    judged &= sites.chain(intervals.site1) == other
    judged &= emit[intervals.left] & emit[intervals.right]
    judged &= np.abs(sites.rank[intervals.site0] - sites.rank[intervals.site1]) == 1
    for site in (intervals.site0, intervals.site1):
        judged &= ~((site >= b.segment_count) & sites.chain_end[sites.indices(site)[1]])
    return judged.nonzero()[0]


def sag_bound(tracer, span, site, start, end):
    """Largest distance between the axis touching ``site`` on ``span`` and its chord from ``start`` to ``end``
    (centres on it), CRS units: 0 where it is straight (an edge and a segment, a fan and a vertex), else
    at most ``d**2 / (8 h)`` for the parabola of focal height ``h`` (a vertex over the edge's line, the
    fan's vertex over the segment's line), ``d`` the chord's length along the directrix (the parabola's
    curvature is at most ``1 / h``)."""
    spans, b = tracer.spans, tracer.boundary
    on_fan, on_vertex = spans.kind[span] == FAN, site >= b.segment_count
    segment, vertex = tracer.sites.indices(site)
    direction = np.where(on_fan[:, None], rows(tracer.sites.unit, segment), rows(spans.unit, span))
    focus = np.where(on_fan[:, None], rows(spans.point, span), rows(b.vertex, vertex))
    anchor = np.where(on_fan[:, None], rows(b.start, segment), rows(spans.point, span))
    height = np.abs(np.einsum("ij,ij->i", focus - anchor, left_normal(direction)))
    along = np.einsum("ij,ij->i", end - start, direction)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(on_fan != on_vertex, along * along / (8.0 * height), 0.0)


def settle_at_ends(tracer, intervals, at_end):
    """Intervals whose sites cross at an end sample that touches both: the other end's site holds inside.

    Returns the mask of those intervals, whose sites are made equal in place.
    """
    settled = at_end >= 0
    # Only the intervals whose crossing lies at an end are looked at.
    row = settled.nonzero()[0]
    if len(row) == 0:
        return settled
    end = np.where(at_end[row] == 0, intervals.left[row], intervals.right[row])
    centre = tracer.samples.centres(end)
    slack = EVENT_TOLERANCE * tracer.samples.t[end] + tracer.of(tracer.options.min_t, intervals.span[row])
    with np.errstate(invalid="ignore"):
        _, _, distance0, distance1 = tracer.sites.pair_feet(intervals.site0[row], intervals.site1[row], centre)
        touching = np.abs(distance0 - tracer.samples.t[end]) <= slack
        touching &= np.abs(distance1 - tracer.samples.t[end]) <= slack
    settled[row] = touching
    emit_junctions(tracer, intervals.subset(row[touching]), end[touching])
    intervals.site0[settled & (at_end == 0)] = intervals.site1[settled & (at_end == 0)]
    intervals.site1[settled & (at_end == 1)] = intervals.site0[settled & (at_end == 1)]
    return settled


def emit_junctions(tracer, intervals, end):
    """Emit the end samples ``end`` of ``intervals`` (their disks touch both sites of their interval, which is
    settled at that end) that touch a site of each chain exactly (:func:`.events.is_event`), not at a split point.

    Such a disk touches both chains: its centre is a point of the axis, where a branch of the own chain joins
    it. A probe placed there for another pair of sites (two of the own chain whose event falls on the same
    disk: one of them touched only on its line's extension) is no event of its interval and, reported as a
    tie, was not emitted; without it the line would cut the corner of the axis there.
    """
    if len(end) == 0:
        return
    chain = tracer.spans.chain[intervals.span]
    other0 = tracer.sites.chain(intervals.site0) == chain ^ 1
    one_each = other0 != (tracer.sites.chain(intervals.site1) == chain ^ 1)
    candidate = (one_each & ~tracer.samples.emit[end]).nonzero()[0]
    if len(candidate) == 0:
        return
    pairs, end = intervals.subset(candidate), end[candidate]
    other_site = np.where(other0[candidate], pairs.site0, pairs.site1)
    _, exact = is_event(
        tracer, pairs, tracer.samples.centres(end), tracer.samples.t[end], other_site, np.ones(len(end), dtype=bool)
    )
    junction = exact & ~tracer.at_split_point(other_site)
    tracer.samples.emit[end[junction]] = True
    tracer.samples.other_site[end[junction]] = other_site[junction]


def station_probes(tracer, intervals):
    """Stations of the parabola of each curved interval: owner, span parameter, trial radius."""
    if len(intervals.span) == 0:
        return np.empty(0, dtype=int), np.empty(0), np.empty(0)
    spans, b = tracer.spans, tracer.boundary
    span, site = intervals.span, intervals.site0
    on_fan = spans.kind[span] == FAN
    segment, vertex = tracer.sites.indices(site)
    point = rows(spans.point, span)
    focus = np.where(on_fan[:, None], point, rows(b.vertex, vertex))
    anchor = np.where(on_fan[:, None], rows(b.start, segment), point)
    unit = np.where(on_fan[:, None], rows(tracer.sites.unit, segment), rows(spans.unit, span))
    ends = np.stack([tracer.samples.centres(intervals.left), tracer.samples.centres(intervals.right)], axis=1)
    owner, centre, radius = parabola_stations(
        focus, anchor, unit, ends, tracer.of(tracer.options.tolerance, intervals.span)
    )
    offset = centre - rows(spans.point, span[owner])
    along = np.einsum("ij,ij->i", offset, rows(spans.unit, span[owner]))
    angle = np.arctan2(np.einsum("ij,ij->i", offset, rows(spans.normal, span[owner])), along)
    u = np.clip(np.where(on_fan[owner], angle, along), intervals.u0[owner], intervals.u1[owner])
    return owner, u, 1.001 * radius + tracer.of(tracer.options.min_t, span[owner])


def check_settled(tracer, intervals):
    """Diagnostic (:attr:`.options.TraceStats.check_settled`): probe 15 places inside each of ``intervals``
    (settled at their event) and record in the stats the worst excess of a probe's disk centre over the
    tolerance from the chord of the interval's end centres (CRS units). Changes no sample."""
    owner = np.repeat(np.arange(len(intervals.span)), 15)
    share = np.tile(np.arange(1, 16) / 16.0, len(intervals.span))
    at = intervals.u0[owner] + share * (intervals.u1 - intervals.u0)[owner]
    t_left, t_right = tracer.samples.t[intervals.left], tracer.samples.t[intervals.right]
    t, _, _, centre = solve_probes(tracer, intervals.span[owner], at, 1.25 * np.maximum(t_left, t_right)[owner])
    start, end = tracer.samples.centres(intervals.left)[owner], tracer.samples.centres(intervals.right)[owner]
    chord = end - start
    along = np.clip(np.einsum("ij,ij->i", centre - start, chord) / np.einsum("ij,ij->i", chord, chord), 0, 1)
    distance = np.hypot(*(centre - start - along[:, None] * chord).T)
    tolerance = tracer.of(tracer.options.tolerance, intervals.span[owner])
    excess = np.where(np.isfinite(t), distance - tolerance * (1.0 + 1e-9), -np.inf)
    tracer.stats.settled_checked += len(intervals.span)
    tracer.stats.settled_worst = max(tracer.stats.settled_worst, float(excess.max(initial=-np.inf)))
