"""The tracer: one adaptive tracing of the axis between pairs of chains, round by round (docs/tracing.md).

The :class:`Tracer` holds what every step reads (the spans, the sites, the options, the solved samples) and
runs the rounds; the steps live in :mod:`.initial` (the samples before the rounds), :mod:`.settling` (which
intervals stay open, the parabolas' stations), :mod:`.events` and :mod:`.walks` (where to probe an open
interval and how a probe is judged) and :mod:`.probes` (the contact solver).
"""

import numpy as np

from ..contacts import CLEAR, TIED, Boundary
from .events import event_candidates, event_emission, is_event
from .initial import initial_intervals
from .intervals import Intervals, split_at_nodes, unsettled_pieces
from .options import TraceOptions, current_stats
from .probes import solve_probes
from .samples import SampleStore
from .settling import check_settled, open_and_curved, settle_at_ends, settled_at_event, station_probes
from .sites import Sites, split_vertices
from .spans import build_spans, chain_geometry, own_ranks
from .walks import event_nodes

#: Most rounds of event location (each round at least halves the open intervals' count of unknown sites).
MAX_ROUNDS = 64


class Tracer:
    """The state of one adaptive tracing: the spans of the traced chains, their sites, the options and the
    samples solved so far.

    The chains come in pairs (chains ``2k`` and ``2k + 1``: one feature of a joint tracing); ``options`` is a
    :class:`.options.TraceOptions` with one value per chain; ``stats`` a :class:`.options.TraceStats` (None:
    those of the enclosing :func:`.options.observed`, else new ones).
    """

    def __init__(self, boundary, options, stats=None):
        self.boundary, self.options = boundary, options
        self.stats = current_stats() if stats is None else stats
        #: The chains whose spans are sampled: the first of each pair (every point of the axis between two
        #: chains has a foot on each, so one chain's spans meet all of it).
        self.traced = np.arange(len(options.closed)) % 2 == 0
        geometry = chain_geometry(boundary, options.sides)
        self.spans = build_spans(boundary, geometry, self.traced)
        self.sites = Sites(boundary, geometry)
        self.split_vertex = split_vertices(boundary, options.closed)
        self.own_ranks = own_ranks(self.spans, self.sites, boundary)
        self.samples = SampleStore()
        #: Per per-chain array given to :meth:`of` (by id: they are the options' own), its one value when all
        #: traced chains share it, else None.
        self._uniform = {}

    def of(self, values, span):
        """Per-chain ``values`` for each of the spans ``span`` (the chain of each): spans lie on traced chains
        only, so one value when those all share it (a single feature)."""
        uniform = self._uniform.get(id(values), False)
        if uniform is False:
            traced = values[self.traced]
            uniform = self._uniform[id(values)] = traced[0] if np.all(traced == traced[0]) else None
        if uniform is not None:
            return np.full(len(span), uniform)
        return values[self.spans.chain[span]]

    def at_split_point(self, site):
        """Whether each site is a split point (closed mode): a vertex of both chains. A tie with it is no
        evidence of a contact with the other chain (it also lies on the own one)."""
        return (site >= self.boundary.segment_count) & self.split_vertex[self.sites.indices(site)[1]]

    def trace(self, report):
        """Run the rounds; returns the emitted samples as :class:`.contacts.AxisPoints` and the chain of each.
        Releases the samples and the spatial index."""
        self.stats.tracings += 1
        intervals = initial_intervals(self, report)
        for round_index in range(MAX_ROUNDS):
            events, curves = open_and_curved(self, intervals)
            # Only the open and curved intervals go on: the others are released before the round's output.
            intervals = None
            if len(events.span) + len(curves.span) == 0:
                break
            report(0.8 + 0.2 * round_index / MAX_ROUNDS)
            intervals = self._round(events, curves)
        self.boundary.release_index()
        return self.samples.axis_points(self.spans, self.sites)

    def _round(self, events, curves):
        """One round: settle what can be settled without a probe, probe the open intervals' events and the
        curved intervals' stations together, and cut the intervals at the probes; returns the next intervals."""
        self.stats.rounds += 1
        event_u, event_trial, found, at_end, event_radius = event_candidates(self, events)
        settled = settle_at_ends(self, events, at_end)
        # Intervals settled at their event close (their sites still differ: they are not carried on).
        closed = settled_at_event(self, events, event_u, event_radius, found)
        if self.stats.check_settled:
            check_settled(self, events.subset(closed.nonzero()[0]))
        carried = [events.subset(settled.nonzero()[0])] if settled.any() else []
        if settled.any() or closed.any():
            unsettled = (~settled & ~closed).nonzero()[0]
            events = events.subset(unsettled)
            event_u, event_trial, found = event_u[unsettled], event_trial[unsettled], found[unsettled]
        owner, event_u, event_trial, found, pairs = event_nodes(self, events, event_u, event_trial, found)
        station_owner, station_u, station_trial = station_probes(self, curves)
        span = np.concatenate([pairs.span, curves.span[station_owner]])
        u = np.concatenate([event_u, station_u])
        t, status, site, centre = solve_probes(self, span, u, np.concatenate([event_trial, station_trial]))
        del event_trial, station_trial
        count = len(event_u)
        event, exact = is_event(self, pairs, centre[:count], t[:count], site[:count], found)
        emit, other_site = event_emission(self, pairs, status[:count], site[:count], exact)
        event_index = self.samples.add(span[:count], u[:count], t[:count], centre[:count], emit, other_site)
        # A station's tie counts only with the parabola's own site (near a tie elsewhere the contact is
        # known to the square root of the tie's tolerance only).
        own = curves.site0[station_owner]
        accepted = (status[count:] == CLEAR) | ((status[count:] == TIED) & (site[count:] == own))
        station_index = self.samples.add(span[count:], u[count:], t[count:], centre[count:], accepted, site[count:])
        # At an event the pieces on either side keep its two sites; elsewhere both take the probe's site.
        before, after = np.where(event, pairs.site0, site[:count]), np.where(event, pairs.site1, site[:count])
        return Intervals.concatenate(
            [
                split_at_nodes(events, owner, event_u, event_index, before, after, False),
                unsettled_pieces(curves, station_owner, station_u, station_index, site[count:]),
                *carried,
            ]
        )


def adaptive_axis_points(boundary, options, report):
    """Points of the medial axis between the chains of ``boundary`` (a :class:`.contacts.Boundary`, chains in
    pairs), every chord within its pair's tolerance of it.

    ``options`` is a :class:`.options.TraceOptions` (one value per chain); ``report(fraction)`` is called as
    the tracing goes and may raise to stop it. Returns :class:`.contacts.AxisPoints` and, per point, the chain
    it was sampled on (the first of its pair).
    """
    return Tracer(boundary, options).trace(report)


def trace_one(request, report):
    """:func:`adaptive_axis_points` of one :class:`.._steps.TraceRequest`, reporting to ``report``.

    The request's :class:`.contacts.Boundary` is built here and released with the tracer (not cached on the
    request, which lives on while its centerline is assembled).
    """
    boundary = Boundary(request.chains, np.full(2, request.rounding))
    return adaptive_axis_points(boundary, TraceOptions.from_request(request), report)[0]
