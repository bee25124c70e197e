"""Predicted walks: where an open interval's contact is expected to pass through several sites in their order
along a chain, the events between them computed in closed form and probed in one round (docs/tracing.md,
*Predicted walks*). A wrong prediction costs probes, never a site."""

from dataclasses import replace

import numpy as np

from .._arrays import ranges, rows
from .closed_form import crossing
from .events import trial_radius
from .sites import radius_at

#: Most events predicted in one interval (between consecutive sites of a chain's walk).
MAX_PREDICTED = 8


def pair_events(tracer, intervals, terms0, terms1):
    """The event of two sites (their :meth:`.sites.Sites.radius_terms`) inside each interval, in closed form: its
    parameter, its radius and whether it lies strictly inside (the probe decides whether it is one)."""
    tracer.stats.predicted_events += len(intervals.span)
    u, found, _ = crossing(tracer.spans, intervals, terms0, terms1)
    radius = radius_at(tracer.spans, intervals.span, terms0, u)
    return u, radius, found & np.isfinite(radius)


def predicted_walks(tracer, intervals):
    """The run of its chain's site sequence each interval's contact is predicted to walk through, from its
    site at ``u0`` to its site at ``u1``: the ranks ``first``, ``last`` of the run and its number of events
    (0 where the two sites lie on different chains, or the run would pass the span's own sites)."""
    sites = tracer.sites
    chain0, chain1 = sites.chain(intervals.site0), sites.chain(intervals.site1)
    first, last = sites.rank[intervals.site0], sites.rank[intervals.site1]
    low, high = np.minimum(first, last), np.maximum(first, last)
    span = intervals.span
    other = chain0 == tracer.spans.chain[span] ^ 1
    apart = other | (high < tracer.own_ranks[0][span]) | (low > tracer.own_ranks[1][span])
    return first, last, np.where((chain0 == chain1) & (chain0 >= 0) & (low >= 0) & apart, high - low, 0)


def walk_sites(tracer, intervals, found):
    """The sites of the predicted walks, from ``u0`` to ``u1``: per site its interval (ascending, at least
    three sites per walk) and the site. :func:`predicted_walks` along one chain, and :func:`approaches` into an
    interval whose two sites lie on different chains and whose event candidate was not ``found``."""
    first, last, events = predicted_walks(tracer, intervals)
    counts = np.where((events >= 2) & (events <= MAX_PREDICTED), events + 1, 0)
    owner, index = ranges(counts)
    site = tracer.sites.sequence[first[owner] + np.where(last >= first, 1, -1)[owner] * index]
    if tracer.stats.predict_approaches:
        approach_owner, approach_site = approaches(tracer, intervals, found)
    else:
        approach_owner, approach_site = (np.empty(0, dtype=int),) * 2
    tracer.stats.approach_sites += len(approach_site)
    if len(approach_owner) == 0:
        return owner, site
    # A walk along one chain and an approach never share an interval: merged by interval, each in order.
    order = np.argsort(np.concatenate([owner, approach_owner]), kind="stable")
    return np.concatenate([owner, approach_owner])[order], np.concatenate([site, approach_site])[order]


def approaches(tracer, intervals, found):
    """Predicted walks of the intervals whose sites lie on different chains and whose event candidate was not
    found inside (the two sites' radii cross outside, or at an end whose sample does not touch both).

    The own chain's contact there walks on, away from the span's own sites, to a site ``S_k`` (``k``
    sequence steps beyond the interval's own-chain site ``S_0``) before the other chain's site ``A`` takes
    over: ``A`` is first touched at one end, so moving away from that end its radius first meets the own
    sites' lower envelope at the event of ``A`` and ``S_k``. Of ``S_0`` .. ``S_{MAX_PREDICTED - 1}`` the one
    whose crossing with ``A`` lies inside the interval and nearest ``A``'s end is taken; the walk is ``A``,
    ``S_k`` .. ``S_0`` (reversed when ``A`` is at ``u1``). Like any prediction it is probed (a wrong one
    costs probes, never a site). Returns per site its interval (ascending) and the site; ``k = 0`` predicts
    nothing (the interval's own event candidate is probed).
    """
    sites, spans = tracer.sites, tracer.spans
    chain = spans.chain[intervals.span]
    chain0, chain1 = sites.chain(intervals.site0), sites.chain(intervals.site1)
    other_first = chain0 == chain ^ 1
    own_site = np.where(other_first, intervals.site1, intervals.site0)
    rank = sites.rank[own_site]
    span = intervals.span
    step = np.where(rank > tracer.own_ranks[1][span], 1, np.where(rank < tracer.own_ranks[0][span], -1, 0))
    mixed = np.where(other_first, chain1 == chain, (chain0 == chain) & (chain1 == chain ^ 1))
    row = (mixed & ~found & (rank >= 0) & (step != 0)).nonzero()[0]
    if len(row) == 0:
        return np.empty(0, dtype=int), np.empty(0, dtype=int)
    row_of, k = ranges(np.full(len(row), MAX_PREDICTED))
    owner = row[row_of]
    candidate_rank = rank[owner] + step[owner] * k
    valid = (candidate_rank >= 0) & (candidate_rank < len(sites.sequence))
    candidate = sites.sequence[np.clip(candidate_rank, 0, len(sites.sequence) - 1)]
    valid &= sites.chain(candidate) == chain[owner]
    # Only the candidates on the own chain's sequence; the other site's terms once per interval.
    valid = valid.nonzero()[0]
    row_of, owner, k, candidate = row_of[valid], owner[valid], k[valid], candidate[valid]
    other_site = np.where(other_first, intervals.site0, intervals.site1)
    terms = tracer.sites.radius_terms(
        spans,
        np.concatenate([span[row], span[owner]]),
        np.concatenate([other_site[row], candidate]),
    )
    u, radius, inside = pair_events(
        tracer, intervals.subset(owner), [x[row_of] for x in terms], [x[len(row) :] for x in terms]
    )
    # The foot is looked at only where the crossing lies inside the interval.
    judged = inside.nonzero()[0]
    inside[judged] = on_run(tracer, span[owner[judged]], u[judged], radius[judged], candidate[judged])
    # Nearest ``A``'s end: the smallest u when ``A`` is at u0, the largest when at u1.
    key = np.where(inside, np.where(other_first[owner], u, -u), np.inf)
    best = np.full(len(intervals.span), np.inf)
    np.minimum.at(best, owner, key)
    chosen = ((key == best[owner]) & np.isfinite(key)).nonzero()[0]
    # One per interval (the nearest step on a tie): the first of its interval's rows.
    first = np.ones(len(chosen), dtype=bool)
    first[1:] = owner[chosen][1:] != owner[chosen][:-1]
    chosen = chosen[first]
    chosen_owner, chosen_k = owner[chosen], k[chosen]
    take = chosen_k >= 1
    chosen_owner, chosen_k = chosen_owner[take], chosen_k[take]
    # The walk from u0 to u1: A, S_k .. S_0 when A is at u0; S_0 .. S_k, A when at u1.
    walk_owner, index = ranges(chosen_k + 2)
    reach = chosen_k[walk_owner]
    walk_row = chosen_owner[walk_owner]
    at_start = other_first[walk_row]
    own_step = np.where(at_start, reach + 1 - index, index)
    walk_site = sites.sequence[np.clip(rank[walk_row] + step[walk_row] * own_step, 0, len(sites.sequence) - 1)]
    is_other = np.where(at_start, index == 0, index == reach + 1)
    walk_site = np.where(is_other, other_site[walk_row], walk_site)
    return walk_row, walk_site


def on_run(tracer, span, u, radius, site):
    """Whether the disk of ``radius`` at parameter ``u`` of ``span`` has its foot on ``site``'s straight run
    (not only on its line; always for a vertex site)."""
    b = tracer.boundary
    point, _ = tracer.spans.points(span, u)
    centre = point + radius[:, None] * tracer.spans.directions(span, u)
    segment = tracer.sites.indices(site)[0]
    along = np.einsum("ij,ij->i", centre - rows(b.start, segment), rows(tracer.sites.unit, segment))
    run_length = tracer.sites.run_end_position[segment] - b.segment_position[segment]
    with np.errstate(invalid="ignore"):
        return (site >= b.segment_count) | ((along >= 0.0) & (along <= run_length))


def event_nodes(tracer, intervals, event_u, event_trial, found):
    """The probes of the open intervals: every predicted event of an interval whose walk holds in closed
    form (:func:`walk_sites`, :func:`pair_events`: each event strictly inside the interval, the events in the
    walk's order), else its one event candidate (``event_u``, ``event_trial``, ``found``).

    Returns per probe its interval, parameter, trial radius, whether it is an event candidate, and its
    interval with the probe's two sites (the one before the event, the one after) as ``site0``, ``site1``.
    """
    owner, site = walk_sites(tracer, intervals, found)
    if len(owner) == 0:
        # Every interval probes its one event candidate.
        return np.arange(len(intervals.span)), event_u, event_trial, found, intervals
    predicted = np.bincount(owner, minlength=len(intervals.span)) > 0
    # Each site of a walk is the second site of one event and the first of the next: its terms serve both.
    terms = tracer.sites.radius_terms(tracer.spans, intervals.span[owner], site)
    pair = (owner[1:] == owner[:-1]).nonzero()[0]
    pair_owner = owner[pair]
    pieces = intervals.subset(pair_owner)
    u, radius, inside = pair_events(tracer, pieces, [x[pair] for x in terms], [x[pair + 1] for x in terms])
    in_order = np.ones(len(pair), dtype=bool)
    in_order[:-1] = (pair_owner[1:] != pair_owner[:-1]) | (u[1:] > u[:-1])
    failed = np.bincount(pair_owner, weights=~(inside & in_order), minlength=len(predicted)) > 0
    keep = (~failed[pair_owner]).nonzero()[0]
    single = (~predicted | failed).nonzero()[0]
    pieces = pieces.subset(keep)
    node_owner = np.concatenate([single, pair_owner[keep]])
    probe_pairs = replace(
        intervals.subset(node_owner),
        site0=np.concatenate([intervals.site0[single], site[pair[keep]]]),
        site1=np.concatenate([intervals.site1[single], site[pair[keep] + 1]]),
    )
    trial = trial_radius(tracer, pieces, radius[keep], np.ones(len(keep), dtype=bool))
    return (
        node_owner,
        np.concatenate([event_u[single], u[keep]]),
        np.concatenate([event_trial[single], trial]),
        np.concatenate([found[single], np.ones(len(keep), dtype=bool)]),
        probe_pairs,
    )
