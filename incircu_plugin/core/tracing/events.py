"""Events: where an open interval's two sites are equally far from the disk (closed form), the probe placed
there, and how a solved probe is judged: an event of its interval or not, an axis point or not
(docs/tracing.md, *The rounds*)."""

import numpy as np

from .._arrays import rows
from ..contacts import CLEAR, SKIPPED, TIED
from .closed_form import crossing
from .sites import radius_at
from .spans import EDGE

#: Relative agreement (of the radius) under which a probe's disk touches both sites of its interval: exactly
#: (the probe is emitted as the event even when rounding called it skipped), and loosely (its interval is
#: resolved; near a nearly straight convex corner the junction is known to about 1e-7 only). The exact one is
#: scaled by how far apart the two feet are seen from the centre (see :func:`is_event`).
EVENT_TOLERANCE = 1e-8
LOOSE_EVENT_TOLERANCE = 1e-6


def event_candidates(tracer, intervals):
    """Where to probe each open interval: its event candidate, the trial radius, whether it is one, which end
    it lies at (see :func:`.closed_form.crossing`) and its radius (CRS units) where it is the one crossing in the
    interval (else NaN)."""
    span = intervals.span
    # Both sites' terms in one call (each row depends on its own values only: the same floats).
    terms = tracer.sites.radius_terms(
        tracer.spans,
        np.concatenate([span, span]),
        np.concatenate([intervals.site0, intervals.site1]),
    )
    terms0, terms1 = tuple(x[: len(span)] for x in terms), tuple(x[len(span) :] for x in terms)
    u, found, at_end, roots = crossing(tracer.spans, intervals, terms0, terms1, counted=True)
    across_split_points(tracer, intervals, terms0, u, found, at_end)
    radius = radius_at(tracer.spans, span, terms0, u)
    # The radius at a single crossing (where two lie in the interval, which one is the event is not known).
    return u, trial_radius(tracer, intervals, radius, found), found, at_end, np.where(roots == 1, radius, np.nan)


def across_split_points(tracer, intervals, terms0, u, found, at_end):
    """Where the contact crosses a split point, for the intervals whose two sites are the runs of both chains
    at one split point and whose crossing is neither found nor at an end.

    At a straight split point both runs lie on one line: their radii are that line's, so they never cross, and
    the contact passes from one run to the other where the disk is tangent to the line at the split point.
    That parameter, where the foot on the first site's line (``terms0``: its :meth:`.sites.Sites.radius_terms`) is
    the split point, is a root of ``D0 + D1 u`` on an edge and of ``D0 + D1 cos(u) + D2 sin(u)`` on a fan:
    written into ``u`` and ``found`` in place where it lies inside the interval, into ``at_end`` where it lies
    at an end. Like any event candidate it is only a candidate: its probe is judged as an event's
    (:func:`is_event`), an end by :func:`.settling.settle_at_ends` (at a split point that is not straight, where a
    crossing outside the interval was found, neither may hold, and the interval is split as usual).
    """
    if not tracer.stats.cross_split_points:
        return
    b, sites, spans = tracer.boundary, tracer.sites, tracer.spans
    site0, site1 = intervals.site0, intervals.site1
    count = b.segment_count
    row = ~found & (at_end < 0) & (site0 >= 0) & (site0 < count) & (site1 >= 0) & (site1 < count)
    row &= tracer.options.closed[spans.chain[intervals.span]]
    row = row.nonzero()[0]
    first, other = site0[row], site1[row]
    chain = b.chain_id[first]
    # Both runs start at the chains' first split point, or both end at their last one.
    at_first = b.first_of_chain[first] & b.first_of_chain[other]
    at_last = sites.run_end_position[first] == sites.chain_end_position[chain]
    at_last &= sites.run_end_position[other] == sites.chain_end_position[b.chain_id[other]]
    keep = ((at_first | at_last) & (chain != b.chain_id[other])).nonzero()[0]
    if len(keep) == 0:
        return
    row, first, at_first = row[keep], first[keep], at_first[keep]
    last_vertex = rows(b.vertex, sites.chain_last_vertex[chain[keep]])
    split_point = np.where(at_first[:, None], rows(b.start, first), last_vertex)
    span = intervals.span[row]
    line = rows(sites.unit, first)
    # Along the line from the split point: the span's point, and per unit of u (on a fan, of the disk's
    # parameter) its direction and its normal.
    offset = np.einsum("ij,ij->i", rows(spans.point, span) - split_point, line)
    along = np.einsum("ij,ij->i", rows(spans.unit, span), line)
    across = np.einsum("ij,ij->i", rows(spans.normal, span), line)
    a0, a1, a2 = (x[row] for x in terms0)
    edge = spans.kind[span] == EDGE
    # On an edge the foot lies offset + u along + r(u) across from the split point, r = a0 + a1 u; on a fan
    # (offset + r(u) (cos(u) along + sin(u) across)), with 1 / r = a0 + a1 cos(u) + a2 sin(u).
    equation = (
        np.where(edge, offset + a0 * across, offset * a0),
        np.where(edge, along + a1 * across, offset * a1 + along),
        np.where(edge, 0.0, offset * a2 + across),
    )
    zero = (np.zeros(len(row)),) * 3
    u[row], found[row], at_end[row] = crossing(spans, intervals.subset(row), equation, zero)


def trial_radius(tracer, intervals, radius, found):
    """Trial radius of a probe in each interval whose event (where ``found``) has ``radius``, CRS units."""
    known = np.maximum(tracer.samples.t[intervals.left], tracer.samples.t[intervals.right])
    width = tracer.of(tracer.options.width, intervals.span)
    known = np.where(np.isfinite(known), 1.25 * known, width)
    # The solver doubles a trial radius that is too small: a small one keeps the candidate boxes tight.
    trial = np.where(found & np.isfinite(radius), np.minimum(1.001 * radius, known), known)
    return np.maximum(trial, width / 16.0)


def is_event(tracer, intervals, centre, t, site, found):
    """Probes whose disk touches both sites of their interval (their segments, not only their lines) first:
    loosely, to ``LOOSE_EVENT_TOLERANCE`` relative to its radius, and exactly (two masks).

    A probe first touching another site (``site``) at the one point where both sites' feet coincide (the
    vertex joining two segments) touches that vertex, not the two segments: it is no event between them.

    Exactly means to ``EVENT_TOLERANCE`` relative to the radius times the parting of the two feet as seen
    from the centre (the distance between the unit vectors towards them): a gap ``g`` in the radius puts
    the centre about ``g`` / parting off the axis, which is large where the feet nearly coincide (two
    nearly collinear segments meeting at a split point). ``centre``: the probes' disk centres.
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        foot0, foot1, distance0, distance1 = tracer.sites.pair_feet(intervals.site0, intervals.site1, centre)
        parting = np.hypot(*((centre - foot0) / distance0[:, None] - (centre - foot1) / distance1[:, None]).T)
        gap0, gap1 = np.abs(distance0 - t), np.abs(distance1 - t)
        scale = (LOOSE_EVENT_TOLERANCE * t, EVENT_TOLERANCE * t * np.nan_to_num(parting))
        min_t = tracer.of(tracer.options.min_t, intervals.span)
        own_site = (site == intervals.site0) | (site == intervals.site1)
        found = found & (own_site | (np.hypot(*(foot0 - foot1).T) > EVENT_TOLERANCE * t + min_t))
        return tuple(found & (gap0 <= s + min_t) & (gap1 <= s + min_t) for s in scale)


def event_emission(tracer, intervals, status, site, event):
    """Which probes are axis points, and the site of their foot on the other chain.

    A clear probe is; a tie only at an event (near a tie the contact is known to the square root of the
    tie's tolerance only); a skipped probe at an event between a site of each chain is (its disk touches
    both chains, the rounding chose the own one).
    """
    chain = tracer.spans.chain[intervals.span]
    other0 = tracer.sites.chain(intervals.site0) == chain ^ 1
    other1 = tracer.sites.chain(intervals.site1) == chain ^ 1
    forced = event & (status == SKIPPED) & (other0 | other1)
    emit = (status == CLEAR) | ((status == TIED) & event & ~tracer.at_split_point(site)) | forced
    other_site = np.where(forced, np.where(other0, intervals.site0, intervals.site1), site)
    return emit, other_site
