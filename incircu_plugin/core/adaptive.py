"""Error-bounded adaptive tracing of the medial axis between two chains (the engine's default).

Along a chain the point where a maximal disk touches it moves over *spans*: the edges (the disk slides
along the edge, centre on the edge's normal) and the reflex vertices (the disk pivots about the vertex, its
centre on a fan of directions between the two edges' normals). On a span the disk's first contact with
the rest of the boundary is one *site* (a segment's interior or a vertex) between *events*, and between two
events the medial axis is a straight line (two lines, or two points) or a parabola (a point and a line).

Samples start at the ends of every span. Between two neighbouring samples of a span whose first contacts
are different sites, the event where the two contacts are equally far is computed in closed form (a
quadratic along an edge, ``R cos(u - psi) = c`` on a fan) and probed with the exact contact solver; if a
third site is nearer, the interval is split there and the next round looks again. The two runs on both sides of
a straight split point lie on one line, equally far everywhere: the contact passes from one to the other where
the disk is tangent at the split point, which is computed in closed form the same way. Every round handles all
open intervals at once (numpy). When neighbours share their site the axis between them is known: a straight
piece needs no vertex; a parabola gets stations placed analytically so that each chord stays within the
tolerance of it. Every vertex is therefore exactly on the medial axis: a solved sample, an event or a
point of a parabola computed in closed form.

*Predicted walks.* When an interval's two sites lie on one chain but are not neighbours along it, the contact
almost always walks through the sites between them in chain order: the straight runs of segments and the
reflex vertices between them (a convex vertex is never a first contact of a disk in the region:
:func:`_site_sequence`). The events between consecutive sites of that walk are computed in closed form and,
when each lies inside the interval and they come in the walk's order, all are probed in the same round (else
the interval's one event is, as above). Each probe is judged exactly like the single event: where it verifies
(its first contact ties the two sites) the pieces beside it keep those two sites, else both take the probe's
first contact. A walk along the own chain is only predicted when it does not pass the span's own sites (the
solver never reports those). Either way every piece is labelled with sites that its end samples really touch
first, and a piece is settled only when both its ends touch the same site, so the argument below is unchanged:
a wrong prediction costs probes, never a site. An interval whose two sites lie on different chains, and whose
event is not found between them in closed form, is predicted the same way (:meth:`_Tracer._approaches`): the own
chain's contact walks on, away from the span, to the site where the other chain's site takes over.

A convex vertex needs no sample of its own: the edges next to it meet the corner's own edge line at ``t = 0``,
and the event where that line and the other chain are equally far is the junction of the corner's branch with
the axis. Before the rounds that junction is solved directly, once for both edges and together with the
initial samples: the disks on the corner's bisector (radius ``scale * t``, touching both segments ``slide * t``
from the corner) first touch the rest of the boundary at the largest empty disk touching both segments, which is
the junction; it is cut into both edges' intervals as a sample of each (their disks are the same disk). Where it
would touch a segment beyond its interval (a short edge), or next to a chain's end, the rounds find the junction
as an event.

Only the first chain of each pair is sampled. Every point of the axis touches that chain (on an edge, or at a
reflex vertex), so its spans meet the whole axis; and no site hides between two neighbouring samples that touch
the same site: the disks between them lie in the region enclosed by the span, that site and the two (empty) end
disks, which the boundary cannot enter without crossing one of them. That holds for the sites the samples
really touch; a sample at a tie reports the lowest of its sites (a segment touched at its end vertex reports
the segment), so two neighbours labelled alike may touch different sites (at a star's centre, a Y network's
fork): a parabola's stations are therefore solved like any probe, and a station holds only where it touches the
parabola's own site (else its interval is split there). A probe whose first contact is the vertex where its
interval's two segments meet touches that vertex, not the segments: it is no event, and the vertex's parabola
is traced like any other. At a straight split point the disk tangent there touches the other chain too,
whatever it touches first: it is a point of the axis. In general the disks between two samples first touch the
boundary between the two samples' contacts, on the side away from the span: so where both contacts lie on the
own chain, both before the span or both after it, every disk between touches its own chain first, and the
interval is closed without a probe (:meth:`_Tracer._off_the_axis`; in a closed pair only: two bank lines are
joined nowhere, and the other one could lie wholly inside that stretch).

*Settled at the event.* An open interval whose end disks ``D0``, ``D1`` (emitted samples: empty, touching their
sites first) touch two sites of the other chain ``B`` at ``q0``, ``q1`` that follow each other in its site
sequence (neither an end vertex of ``B``), and whose event lies inside it, is closed without a probe when the axis
between its samples provably lies within the tolerance of the chord of their centres
(:meth:`_Tracer._settled_at_event`). Every disk of the span between them touches ``B`` first between ``q0`` and
``q1``: the span's piece between the samples, ``D0``, ``D1`` and ``B`` from ``q0`` to ``q1`` enclose a region that
the boundary enters only across them. It does not cross the empty disks, and ``B`` does not cross itself or the
own chain. The own chain leaves the span's piece at its ends along the edge's line, or turned away from the region
at a reflex vertex (a convex corner's sample touches its neighbour at ``t = 0`` and is not emitted), or, at a
fan's vertex, along its two edges, outside the fan's disks. ``B`` leaves ``q0`` along the tangent of ``D0`` (a
segment's interior) or, at a reflex vertex, outside ``D0`` on the side away from the interval (the contacts move
along ``B`` monotonically as the disk's foot moves along the span: two disks' spokes do not cross). Only at an end
vertex of ``B`` does the own chain join it: excluded. In open mode (two bank lines that share no end) ``B`` has
free ends, round which the contact can pass to the back of the next segment: closed pairs only. Between two
consecutive sites lie no other site (at most a convex vertex, never a first contact), so every disk between
touches one of the two first, the first one up to the event and the second one after it (the contact moves
monotonically). The axis is then two known arcs, each a segment or a parabola's arc (an edge and a vertex, a fan
and a segment), from each end centre to the event's centre, computed in closed form. Each arc lies within its sag
of its own chord (at most ``d**2 / (8 h)`` for a parabola of focal height ``h``, ``d`` the chord's extent along
its directrix), and every point of those two chords within the event's distance to the interval's chord (the
distance to a segment is convex and zero at its ends): the interval closes when the sum is within the tolerance,
the simplification's share of the engine's tolerance coming on top of it, as for a parabola's chords.

Several features are traced together (:func:`trace_together`) as pairs of chains ``2k``, ``2k + 1`` in one
:class:`.contacts.Boundary`; contacts are only sought within a pair.
"""

from dataclasses import dataclass, replace

import numpy as np

from ._arrays import ArrayRecord, left_normal, put_rows, ranges, rows
from .contacts import CHUNK, CLEAR, SKIPPED, TIED, AxisPoints, Boundary, Samples, solve, solve_in_chunks
from .polyline import turns_between

#: Span kinds: an edge (the parameter is the distance along it) or a reflex vertex's fan (the angle, radians).
EDGE, FAN = 0, 1

#: Turn, radians, under which a vertex counts as straight (its two edges lie on one line; a split point
#: inserted into an edge is straight to about the coordinates' rounding over the edge's length, which
#: :func:`_straight_turns` allows for where it is more).
STRAIGHT_TURN = 1e-9

#: Largest turn that counts as straight through the rounding of a short segment (:func:`_straight_turns`): a
#: split point is never placed closer to a vertex than that direction allows (``chains.SPLIT_SNAP_ROUNDINGS``),
#: and a real corner next to a shorter segment of the input stays a corner.
MAX_STRAIGHT_TURN = 1e-3

#: Relative agreement (of the radius) under which a probe's disk touches both sites of its interval: exactly
#: (the probe is emitted as the event even when rounding called it skipped), and loosely (its interval is
#: resolved; near a nearly straight convex corner the junction is known to about 1e-7 only). The exact one is
#: scaled by how far apart the two feet are seen from the centre (see :meth:`_Tracer._is_event`).
EVENT_TOLERANCE = 1e-8
LOOSE_EVENT_TOLERANCE = 1e-6

#: Most events predicted in one interval (between consecutive sites of a chain's walk).
MAX_PREDICTED = 8

#: Fraction of the tolerance under which two neighbouring samples' centres settle their interval.
SETTLED_CHORD = 1.0 / 16.0

#: Relative slack under which a slightly negative discriminant is a double root (a contact sliding off a
#: segment's end onto its vertex).
DOUBLE_ROOT = 1e-8

#: Most rounds of event location (each round at least halves the open intervals' count of unknown sites).
MAX_ROUNDS = 64

#: Intervals over which the sample point (or on a fan, the disk's centre) moves less than this fraction of the
#: tolerance are closed.
SMALLEST_MOVE = 1e-6


@dataclass(frozen=True)
class _Spans:
    """The spans of the traced chains (see :class:`_Tracer`).

    A sample at parameter ``u`` of span ``i`` lies at ``point + u * unit`` with direction ``normal`` on an
    edge (the segment's own direction, so the samples lie on it, and its straight run's inward normal, see
    :func:`_line_units`), and at ``point`` with direction ``cos(u) * unit + sin(u) * normal`` on a fan;
    ``segment`` is the edge's global segment (a fan's incoming segment), ``length`` the parameter range (an
    angle on a fan), ``position`` the arc length of ``point`` along its chain.
    """

    kind: np.ndarray
    chain: np.ndarray
    segment: np.ndarray
    length: np.ndarray
    point: np.ndarray
    unit: np.ndarray
    normal: np.ndarray
    position: np.ndarray

    def points(self, span, u):
        """Points of the samples at parameters ``u`` of spans ``span``, and how far along its edge each lies
        (CRS units; 0 on a fan)."""
        along = np.where(self.kind[span] == EDGE, u, 0.0)
        # point + along * unit, in place (about twice as fast as with a temporary).
        point = rows(self.unit, span)
        point *= along[:, None]
        point += rows(self.point, span)
        return point, along

    def directions(self, span, u):
        """Unit directions of the disk families of the samples at parameters ``u`` of spans ``span``."""
        direction = rows(self.normal, span)
        on_fan = (self.kind[span] != EDGE).nonzero()[0]
        angle, fan = u[on_fan, None], span[on_fan]
        put_rows(direction, on_fan, np.cos(angle) * rows(self.unit, fan) + np.sin(angle) * rows(direction, on_fan))
        return direction

    def position_at(self, span, u):
        """Arc length along its chain of the samples at parameters ``u`` of spans ``span``, CRS units."""
        return self.position[span] + np.where(self.kind[span] == EDGE, u, 0.0)

    def samples(self, span, u, boundary):
        """The samples at parameters ``u`` of spans ``span``."""
        edge = self.kind[span] == EDGE
        point, along = self.points(span, u)
        direction = self.directions(span, u)
        segment = self.segment[span]
        # At an edge's end the neighbouring edge passes through the sample point: it is own chain too.
        at_start = edge & (u <= 0.0) & ~boundary.first_of_chain[segment]
        at_end = edge & (u >= self.length[span]) & ~boundary.last_of_chain[segment]
        return Samples(
            chain=self.chain[span],
            point=point,
            direction=direction,
            scale=np.ones(len(span)),
            position=self.position[span] + along,
            slide=np.zeros(len(span)),
            first_own=segment - at_start,
            last_own=segment + (~edge | at_end),
        )


@dataclass
class _Intervals(ArrayRecord):
    """Intervals ``[u0, u1]`` of spans between two samples (indices ``left``, ``right``), with the sites first
    touched at each end; ``verified`` once the stations of a parabola have been solved inside it."""

    span: np.ndarray
    u0: np.ndarray
    u1: np.ndarray
    left: np.ndarray
    right: np.ndarray
    site0: np.ndarray
    site1: np.ndarray
    verified: np.ndarray

    def __post_init__(self):
        """The index columns as int32 (see :class:`.contacts.Boundary`)."""
        # Plain assignments (no getattr/setattr loop): the rounds build these records thousands of times.
        index = np.int32
        self.span, self.left = np.asarray(self.span, dtype=index), np.asarray(self.left, dtype=index)
        self.right = np.asarray(self.right, dtype=index)
        self.site0, self.site1 = np.asarray(self.site0, dtype=index), np.asarray(self.site1, dtype=index)


@dataclass(frozen=True)
class _Geometry:
    """The straight lines of the chains, and the turn and kind of every junction of two segments of a chain.

    Junction ``j`` joins segments ``joint[j]`` and ``joint[j] + 1``; its kind is +1 (convex), -1 (reflex) or 0
    (straight), and ``turn`` (radians) is the turn between the lines of its two segments. ``vertex_kind`` is
    the kind of every vertex, chain after chain (0 at the chains' ends), and ``vertex_turn`` its turn towards the
    region (radians, positive at a convex vertex, 0 at the chains' ends). Segments joined by straight junctions
    form a straight run, one line (:func:`_straight_runs`): per segment, ``line_of`` is its run's first
    segment, ``run_end_position`` the arc length at the run's end (CRS units), and ``unit`` and ``normal``
    (inward) are the run's direction (:func:`_line_units`).
    """

    unit: np.ndarray
    normal: np.ndarray
    joint: np.ndarray
    turn: np.ndarray
    kind: np.ndarray
    vertex_kind: np.ndarray
    vertex_turn: np.ndarray
    line_of: np.ndarray
    run_end_position: np.ndarray


def _geometry(boundary, sides):
    """:class:`_Geometry` of all chains at once (``sides``: +1 when the region lies left of a chain, -1 right)."""
    side = np.asarray(sides, dtype=float)[boundary.chain_id]
    joint = np.flatnonzero(~boundary.last_of_chain)
    # The turn at every pair of consecutive segments (views, no gathered copies), then at the junctions: each
    # row is computed from its own two units, so the same floats as from the junctions' rows alone.
    turn = turns_between(boundary.unit[:-1], boundary.unit[1:])[joint]
    signed = side[joint] * turn
    straight = _straight_turns(boundary, joint, joint + 1)
    kind = np.where(signed > straight, 1, np.where(signed < -straight, -1, 0)).astype(np.int8)
    vertex_kind = np.zeros(len(boundary.vertex), dtype=kind.dtype)
    vertex_kind[boundary.start_vertex(joint) + 1] = kind
    vertex_turn = np.zeros(len(boundary.vertex))
    vertex_turn[boundary.start_vertex(joint) + 1] = signed
    line_of, line_end, run_end_position = _straight_runs(vertex_kind, boundary)
    unit = _line_units(boundary, line_of, line_end)
    normal = left_normal(unit)
    normal *= side[:, None]
    turn = turns_between(rows(unit, joint), rows(unit, joint + 1))
    return _Geometry(unit, normal, joint, turn, kind, vertex_kind, vertex_turn, line_of, run_end_position)


def _line_units(boundary, line_of, line_end):
    """Per segment, the unit direction of its straight run: the run's chord, from its first vertex to its last.

    A short segment's own direction is known only to the coordinates' rounding over its length (a split point
    a hair from a vertex: 1e-4 rad for 1e-8 of the extent); a run's chord is as good as the whole run, so the
    feet on a run that starts with such a piece stay on their disks all along it.
    """
    starts = line_of == np.arange(boundary.segment_count)
    first = np.flatnonzero(starts)
    chord = boundary.end(line_end[first])
    chord -= rows(boundary.start, first)
    chord /= np.hypot(chord[:, 0], chord[:, 1])[:, None]
    # Each segment's run, counted along the chains.
    return rows(chord, np.cumsum(starts) - 1)


def _straight_turns(boundary, first, second):
    """The turn, radians, under which the junction of segments ``first`` and ``second`` counts as straight:
    ``STRAIGHT_TURN``, or the rounding of the first one's chain (:attr:`.contacts.Boundary.chain_rounding`: the
    coordinates' rounding where they come from) over the shorter segment where that is more (a split point
    inserted a hair from a vertex, or into the edge of a small shape far from the origin: the pieces'
    directions are known to that angle only), at most ``MAX_STRAIGHT_TURN``."""
    shorter = np.minimum(boundary.length.take(first), boundary.length.take(second))
    uncertain = boundary.chain_rounding.take(boundary.chain_id.take(first)) / shorter
    return np.clip(uncertain, STRAIGHT_TURN, MAX_STRAIGHT_TURN)


def _build_spans(boundary, geometry, traced):
    """The edge spans of the traced chains (``traced``: per chain), in the order of their segments, then the
    fan spans of their reflex vertices."""
    edge = np.flatnonzero(traced[boundary.chain_id])
    joint = geometry.kind < 0
    joint &= traced[boundary.chain_id[geometry.joint]]
    reflex = geometry.joint[joint]
    turn = geometry.turn[joint]
    first_normal = rows(geometry.normal, reflex)
    start, end = boundary.segment_position[edge], boundary.segment_end_position[edge]
    return _Spans(
        kind=np.concatenate([np.full(len(edge), EDGE, dtype=np.int8), np.full(len(reflex), FAN, dtype=np.int8)]),
        chain=boundary.chain_id[np.concatenate([edge, reflex])],
        segment=np.concatenate([edge, reflex]).astype(boundary.chain_id.dtype),
        length=np.concatenate([end - start, np.abs(turn)]),
        point=np.concatenate([rows(boundary.start, edge), boundary.end(reflex)]),
        unit=np.concatenate([rows(boundary.unit, edge), first_normal]),
        normal=np.concatenate([rows(geometry.normal, edge), np.sign(turn)[:, None] * left_normal(first_normal)]),
        position=np.concatenate([start, boundary.segment_end_position[reflex]]),
    )


def _straight_runs(kinds, boundary):
    """For each segment, the first and the last segment of its run of segments on one line (the first is the
    site it stands for), and the arc length at the run's end (CRS units)."""
    # ``kinds`` holds the vertex kinds, chain after chain (as ``boundary.vertex``).
    segment = np.arange(boundary.segment_count, dtype=np.int32)
    starts_run = boundary.first_of_chain | (kinds[boundary.start_vertex(segment)] != 0)
    first = np.maximum.accumulate(np.where(starts_run, segment, 0))
    ends_run = np.append(starts_run[1:], True)
    last = np.minimum.accumulate(np.where(ends_run, segment, np.int32(boundary.segment_count))[::-1])[::-1]
    return first, last, boundary.segment_end_position[last]


def _site_sequence(boundary, kinds, line_of, chain_end):
    """The sites of every chain in their order along it, and each site's rank in that sequence.

    A chain's sequence is its start vertex, the first segment of each straight run with the reflex vertex
    that ends it, and its end vertex: every site a disk in the region can touch first. A convex vertex never
    is one: next to it the region is a wedge narrower than a half-plane, and a disk inside a wedge touching
    its apex is a point. A segment's rank is its run's; a convex (or straight) vertex's is -1. Both int32
    (sites and ranks fit it, see :class:`.contacts.Boundary`). ``chain_end``: whether each vertex is the first
    or last of its chain.
    """
    count = boundary.segment_count
    segment = np.flatnonzero(line_of == np.arange(count))
    vertex = np.flatnonzero((kinds < 0) | chain_end)
    # Vertex ``g + chain`` starts segment ``g``: keys 2g (vertex), 2g + 1 (segment) follow the chains.
    keys = np.concatenate([2 * segment + 1, 2 * (vertex - boundary.vertex_chain[vertex])])
    sequence = np.concatenate([segment, count + vertex])[np.argsort(keys, kind="stable")].astype(np.int32)
    rank = np.full(count + len(boundary.vertex), -1, dtype=np.int32)
    rank[sequence] = np.arange(len(sequence))
    rank[:count] = rank[line_of]
    return sequence, rank


class _Sites:
    """Site arithmetic: which chain a site is on, the site a segment stands for, the sites' order along their
    chains, feet and radii on spans."""

    def __init__(self, boundary, geometry):
        self.boundary = boundary
        self.kinds, self.turns = geometry.vertex_kind, geometry.vertex_turn
        #: Direction and inward normal of every segment's line (its straight run's): a disk in the region
        #: touches a segment from that side of its line.
        self.unit, self.inward = geometry.unit, geometry.normal
        #: Whether each vertex is the first or last of its chain.
        self.chain_end = _split_vertices(boundary, np.ones(len(boundary.offset), dtype=bool))
        self.line_of, self.run_end_position = geometry.line_of, geometry.run_end_position
        #: Per chain, its last vertex and the arc length there (CRS units).
        self.chain_last_vertex = _chain_end_vertices(boundary)[1]
        self.chain_end_position = boundary.vertex_position[self.chain_last_vertex]
        self.sequence, self.rank = _site_sequence(boundary, self.kinds, self.line_of, self.chain_end)
        #: The chain of every site, segments then vertices, and -1 last (for site -1: no site).
        self.site_chain = np.concatenate([boundary.chain_id, boundary.vertex_chain, np.array([-1], dtype=np.int32)])

    def canonical(self, site):
        """Segment sites replaced by the first segment of their straight run (one line, one site)."""
        return np.where((site >= 0) & (site < self.boundary.segment_count), self.line_of[self.indices(site)[0]], site)

    def indices(self, site):
        """The segment and the vertex each site stands for, each clipped into its range: for a segment site its
        vertex (and for a vertex site its segment) is only a placeholder to gather with, never to use."""
        b = self.boundary
        segment = np.minimum(np.maximum(site, 0), b.segment_count - 1)
        vertex = np.minimum(np.maximum(site - b.segment_count, 0), len(b.vertex) - 1)
        return segment, vertex

    def chain(self, site):
        """Chain of each site (-1 for no site); ``site`` is -1 or a segment or vertex index (below
        ``segment_count + len(vertex)``): -1 reads the last entry, the no-site one."""
        return self.site_chain.take(site)

    def extent(self, site):
        """Arc lengths along its chain where each site (a segment or vertex index, not -1) begins and ends, CRS
        units (a segment site: its whole straight run)."""
        b = self.boundary
        count = b.segment_count
        segment, vertex = self.indices(site)
        segment = self.line_of[segment]
        on_vertex = site >= count
        first = np.where(on_vertex, b.vertex_position[vertex], b.segment_position[segment])
        last = np.where(on_vertex, first, self.run_end_position[segment])
        return first, last

    def feet(self, site, centre):
        """Nearest point to ``centre`` of each site (a segment site: its straight run), and its arc length."""
        b = self.boundary
        foot, position = np.empty((len(site), 2)), np.empty(len(site))
        on_vertex = site >= b.segment_count
        row = on_vertex.nonzero()[0]
        if len(row):
            vertex = site[row] - b.segment_count
            put_rows(foot, row, rows(b.vertex, vertex))
            position[row] = b.vertex_position[vertex]
            del vertex
        row = (~on_vertex).nonzero()[0]
        del on_vertex
        if len(row) == 0:
            return foot, position
        segment = np.maximum(site[row], 0)
        start, unit = rows(b.start, segment), rows(self.unit, segment)
        segment_position = b.segment_position[segment]
        run_length = self.run_end_position[segment] - segment_position
        along = np.clip(np.einsum("ij,ij->i", rows(centre, row) - start, unit), 0.0, run_length)
        # start + along * unit, in place.
        unit *= along[:, None]
        unit += start
        put_rows(foot, row, unit)
        position[row] = segment_position + along
        return foot, position

    def pair_feet(self, site0, site1, centre):
        """:meth:`feet` of both sites of each pair (``site0``, ``site1``) seen from its ``centre``, in one call
        (each row is computed from its own values only: the same floats as two calls), and the distances
        from ``centre`` to them (inf for no site), CRS units."""
        foot = self.feet(np.concatenate([site0, site1]), np.concatenate([centre, centre]))[0]
        foot0, foot1 = foot[: len(site0)], foot[len(site0) :]
        distance0 = np.where(site0 >= 0, np.hypot(*(centre - foot0).T), np.inf)
        distance1 = np.where(site1 >= 0, np.hypot(*(centre - foot1).T), np.inf)
        return foot0, foot1, distance0, distance1

    def radius_terms(self, spans, span, site):
        """Closed form of the first-contact radius ``r(u)`` of ``site`` on ``span``.

        On an edge ``r(u) = a2 u**2 + a1 u + a0`` (a vertex: the parabola's height over the edge; a segment's
        line: linear). On a fan ``1 / r(u) = a0 + a1 cos(u) + a2 sin(u)``. Returns ``(a0, a1, a2)``. A segment's
        line is touched from the region's side of it (where the span's point lies on the other side, the radius
        is negative: no contact). Each row depends on its own values only: the four kinds (edge or fan, segment
        or vertex) are computed apart.
        """
        b = self.boundary
        # Kinds 0, 1: a segment, a vertex seen from an edge; 2, 3: from a fan.
        kind = 2 * spans.kind[span] + (site >= b.segment_count)
        segment, vertex = self.indices(site)

        def terms(of_kind, row):
            on_edge = of_kind < 2
            if of_kind % 2 == 0:
                return self._segment_terms(spans, span[row], segment[row], on_edge)
            return self._vertex_terms(spans, span[row], vertex[row], on_edge)

        with np.errstate(divide="ignore", invalid="ignore"):
            return _by_kind(kind, range(4), terms, 3)

    def _segment_terms(self, spans, span, segment, on_edge):
        """:meth:`radius_terms` of segment sites (their lines) seen from edge spans or from fan spans."""
        b = self.boundary
        # The gathered rows are the function's own copies: the differences are taken in place.
        offset, unit, normal = rows(spans.point, span), rows(spans.unit, span), rows(spans.normal, span)
        offset -= rows(b.start, segment)
        inward = rows(self.inward, segment)
        # The span's point's height over the site's line, on the region's side of it.
        height = np.einsum("ij,ij->i", offset, inward)
        del offset
        if on_edge:
            # The height changes by `slope` per unit of u.
            slope = np.einsum("ij,ij->i", unit, inward)
            gap = np.subtract(normal, inward, out=normal)
            closing = 0.5 * np.einsum("ij,ij->i", gap, gap)
            return height / closing, slope / closing, np.zeros(len(span))
        # Fan: 1/r = c + k.b(u) with b(u) = cos(u) unit + sin(u) normal.
        k = -(1.0 / height)[:, None] * inward
        return 1.0 / height, np.einsum("ij,ij->i", k, unit), np.einsum("ij,ij->i", k, normal)

    def _vertex_terms(self, spans, span, vertex, on_edge):
        """:meth:`radius_terms` of vertex sites seen from edge spans or from fan spans."""
        point, unit, normal = rows(spans.point, span), rows(spans.unit, span), rows(spans.normal, span)
        offset = rows(self.boundary.vertex, vertex) - point
        if on_edge:
            # The vertex lies a along and h across the edge.
            a = np.einsum("ij,ij->i", offset, unit)
            h = np.einsum("ij,ij->i", offset, normal)
            return (a * a + h * h) / (2.0 * h), -a / h, 1.0 / (2.0 * h)
        k = 2.0 * offset / np.einsum("ij,ij->i", offset, offset)[:, None]
        return np.zeros(len(span)), np.einsum("ij,ij->i", k, unit), np.einsum("ij,ij->i", k, normal)


def _radius_at(spans, span, terms, u):
    """Evaluate :meth:`_Sites.radius_terms` at ``u``; inf where the site is never touched."""
    a0, a1, a2 = terms
    edge = spans.kind[span] == EDGE
    with np.errstate(divide="ignore", invalid="ignore"):
        on_edge = a0 + u * (a1 + u * a2)
        inverse = a0 + a1 * np.cos(u) + a2 * np.sin(u)
        radius = np.where(edge, on_edge, 1.0 / inverse)
    return np.where(np.isfinite(radius) & (radius >= 0.0), radius, np.inf)


def _crossing(spans, intervals, terms0, terms1, counted=False):
    """Parameter inside ``(u0, u1)`` where both sites' radii are equal (else the middle), whether there is
    one, and which end (0, 1; else -1) the crossing lies at when it lies at one; if ``counted``, also how many
    of the equation's two roots lie in ``[u0, u1]``."""
    u0, u1 = intervals.u0, intervals.u1
    d0, d1, d2 = (x - y for x, y in zip(terms0, terms1))
    middle = 0.5 * (u0 + u1)

    def roots_of(kind, row):
        terms = d0[row], d1[row], d2[row]
        return _edge_roots(*terms) if kind == EDGE else _fan_roots(*terms, middle[row])

    # The two candidate roots of each row, from its edge's or its fan's equation.
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        roots = _by_kind(spans.kind[intervals.span], (EDGE, FAN), roots_of, 2)
    slack = 1e-9 * (u1 - u0)
    chosen, found = np.full(len(u0), np.nan), np.zeros(len(u0), dtype=bool)
    count = np.zeros(len(u0), dtype=int)
    for candidate in roots:
        inside = np.isfinite(candidate) & (candidate >= u0 - slack) & (candidate <= u1 + slack)
        # A double root (a segment's line and its end vertex) split by rounding counts once.
        count += inside & ~(found & (np.abs(candidate - chosen) <= DOUBLE_ROOT * (u1 - u0)))
        inside &= ~found
        chosen[inside], found[inside] = candidate[inside], True
    at_end = np.where(found & (chosen <= u0 + slack), 0, np.where(found & (chosen >= u1 - slack), 1, -1))
    found &= at_end < 0
    crossing = np.where(found, chosen, middle), found, at_end
    return crossing + (count,) if counted else crossing


def _by_kind(kind, kinds, compute, columns):
    """Outputs with one row per item computed kind by kind: ``compute(value, row)`` gives the ``columns``
    outputs' values on the rows ``row`` whose ``kind`` is ``value`` (for each of ``kinds``; a kind without
    rows is not computed). Each row depends on its own values only, so computing the kinds apart gives the
    same floats as any grouping. Returns a tuple of ``columns`` float arrays."""
    outputs = tuple(np.empty(len(kind)) for _ in range(columns))
    for value in kinds:
        row = (kind == value).nonzero()[0]
        if len(row):
            for output, values in zip(outputs, compute(value, row)):
                output[row] = values
    return outputs


def _edge_roots(d0, d1, d2):
    """Roots of d2 u^2 + d1 u + d0 = 0 (on an edge), the stable pair.

    A vertex at the end of a segment's line touches it: their radii meet in a double root, which rounding may
    push to a slightly negative discriminant."""
    discriminant = d1 * d1 - 4.0 * d2 * d0
    root = np.sqrt(np.where(discriminant > -DOUBLE_ROOT * d1 * d1, np.maximum(discriminant, 0.0), discriminant))
    q = -0.5 * (d1 + np.where(d1 < 0, -root, root))
    return q / d2, d0 / q


def _fan_roots(d0, d1, d2, middle):
    """Roots of d0 + d1 cos(u) + d2 sin(u) = 0 (on a fan), i.e. R cos(u - psi) = -d0, each the one within pi
    of ``middle``; a cosine that rounding pushed slightly beyond 1 is a double root."""
    psi = np.arctan2(d2, d1)
    cosine = -d0 / np.hypot(d1, d2)
    swing = np.arccos(np.where(np.abs(cosine) < 1.0 + DOUBLE_ROOT, np.clip(cosine, -1.0, 1.0), cosine))
    return tuple(middle + np.remainder(psi + sign * swing - middle + np.pi, 2.0 * np.pi) - np.pi for sign in (1, -1))


def _parabola_stations(focus, anchor, unit, ends, tolerance):
    """Points of parabolas (focus, directrix) between two of their points, chords within ``tolerance``.

    In the directrix's frame the parabola is ``r(s) = (s**2 + h**2) / (2 h)`` (``s`` along the directrix
    from the focus's foot, ``h`` the focus's height): the chord over ``[s, s + ds]`` deviates from it by
    ``ds**2 / (8 sqrt(h**2 + m**2))``, ``m`` the chord's middle. Stations uniform in ``z = sqrt(|s| + h)``
    on each side of the apex, ``dz = (sqrt(2) tolerance) ** 0.5`` apart, keep that below ``dz**2 /
    sqrt(2) = tolerance`` (``ds = dz (z0 + z1)`` and ``sqrt(h**2 + m**2) >= (h + |m|) / sqrt(2)``); the
    apex is a station when it lies between the ends.

    Parameters
    ----------
    focus, anchor, unit : ndarray of shape (n, 2)
        Each parabola's focus, a point of its directrix and the directrix's unit direction.
    ends : ndarray of shape (n, 2, 2)
        Two points of each parabola.
    tolerance : float or ndarray of shape (n,)
        Largest distance between a chord and its arc, CRS units (per parabola).

    Returns
    -------
    owner : ndarray of shape (m,)
        The parabola of each station.
    centre, radius : ndarray of shape (m, 2), (m,)
        The stations and their distance to the focus (and the directrix), CRS units.
    """
    relative = focus - anchor
    apex_along = np.einsum("ij,ij->i", relative, unit)
    across = left_normal(unit)
    height = np.einsum("ij,ij->i", relative, across)
    towards_focus = np.where(height < 0, -1.0, 1.0)[:, None] * across
    height = np.abs(height)
    s = np.einsum("ijk,ik->ij", ends - anchor[:, None, :], unit) - apex_along[:, None]
    low, high = np.minimum(s[:, 0], s[:, 1]), np.maximum(s[:, 0], s[:, 1])
    step_z = np.sqrt(np.sqrt(2.0) * tolerance)
    owners, offsets = [], []
    for sign, near, far in (
        (1.0, np.maximum(low, 0.0), np.maximum(high, 0.0)),
        (-1.0, -np.minimum(high, 0.0), -np.minimum(low, 0.0)),
    ):
        z_near, z_far = np.sqrt(near + height), np.sqrt(far + height)
        count = np.where(far > near, np.ceil((z_far - z_near) / step_z), 0).astype(int)
        owner, rank = ranges(np.maximum(count - 1, 0))
        z = z_near[owner] + (rank + 1) * ((z_far - z_near) / np.maximum(count, 1))[owner]
        owners.append(owner)
        offsets.append(sign * (z * z - height[owner]))
    apex = np.flatnonzero((low < 0.0) & (high > 0.0))
    owner = np.concatenate(owners + [apex])
    s = np.concatenate(offsets + [np.zeros(len(apex))])
    radius = (s * s + height[owner] ** 2) / (2.0 * height[owner])
    centre = rows(anchor, owner) + (apex_along[owner] + s)[:, None] * rows(unit, owner)
    centre += radius[:, None] * rows(towards_focus, owner)
    return owner, centre, radius


#: Types of the tracer's per-sample columns (indices fit int32, see :class:`.contacts.Boundary`).
_STORE_TYPES = {"span": np.int32, "u": float, "t": float, "centre": float, "emit": bool, "other_site": np.int32}


def _own_ranks(spans, sites, boundary):
    """Per span, the lowest and highest rank of the sites its samples touch by construction: an edge's
    segment (its straight run) and end vertices, a fan's vertex and two segments."""
    first = spans.segment
    last = first + (spans.kind == FAN)
    start_vertex = boundary.start_site[first]
    end_vertex = boundary.start_site[last] + 1
    low = np.where(sites.rank[start_vertex] >= 0, sites.rank[start_vertex], sites.rank[first])
    high = np.where(sites.rank[end_vertex] >= 0, sites.rank[end_vertex], sites.rank[last])
    return low, high


class _Tracer:
    """The samples of one adaptive tracing, grown round by round, and the rules that grow them.

    The chains come in pairs (chains ``2k`` and ``2k + 1``: one feature of a joint tracing); ``closed``,
    ``tolerance``, ``width``, ``max_t`` and ``min_t`` are arrays with one value per chain.
    """

    def __init__(self, sides, boundary, closed, tolerance, width, max_t, min_t):
        #: The chains whose spans are sampled: the first of each pair (every point of the axis between two
        #: chains has a foot on each, so one chain's spans meet all of it).
        self.traced = np.arange(len(closed)) % 2 == 0
        geometry = _geometry(boundary, sides)
        self.spans = _build_spans(boundary, geometry, self.traced)
        self.sites = _Sites(boundary, geometry)
        self.boundary, self.closed, self.tolerance = boundary, closed, tolerance
        self.width, self.max_t, self.min_t = width, max_t, min_t
        self.split_vertex = _split_vertices(boundary, closed)
        self.own_ranks = _own_ranks(self.spans, self.sites, boundary)
        self.count = 0
        self.store = {}
        #: Per per-chain array given to :meth:`of` (by id: they are the tracer's own), its one value when all
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

    def add(self, span, u, t, centre, emit, other_site):
        """Append solved samples (at parameters ``u`` of spans ``span``, disk centres ``centre``); returns
        their indices. ``other_site`` gives the foot on the other chain.

        A sample is stored as its span, parameter and centre (its point and direction follow from span and
        parameter, see :meth:`_Spans.points` and :meth:`_Spans.directions`). The arrays grow by half, so a
        round costs its own samples only.
        """
        if len(t) == 0 and self.store:
            return np.arange(self.count, self.count)
        columns = {"span": span, "u": u, "t": t, "centre": centre, "emit": emit, "other_site": other_site}
        start, self.count = self.count, self.count + len(t)
        for name, values in columns.items():
            stored = self.store.get(name)
            if stored is None or len(stored) < self.count:
                size = max(self.count + self.count // 2, 64)
                grown = np.empty((size,) + values.shape[1:], dtype=_STORE_TYPES[name])
                if stored is not None:
                    grown[:start] = stored[:start]
                self.store[name] = stored = grown
            stored[start : self.count] = values
        return np.arange(start, self.count)

    @property
    def t(self):
        """First-contact parameter of every sample so far (a view)."""
        return self.store["t"][: self.count]

    def centres(self, index):
        """Centres of the disks of samples ``index``."""
        return rows(self.store["centre"], index)

    def trace(self, report):
        """Run the rounds; returns the emitted samples as :class:`AxisPoints` and the chain of each."""
        intervals = self._initial(report)
        for round_index in range(MAX_ROUNDS):
            events, curves = self._open_and_curved(intervals)
            # Only the open and curved intervals go on: the others are released before the round's output is built.
            intervals = None
            if len(events.span) + len(curves.span) == 0:
                break
            report(0.8 + 0.2 * round_index / MAX_ROUNDS)
            event_u, event_trial, found, at_end, event_radius = self._event_candidates(events)
            settled = self._settle_at_ends(events, at_end)
            # Intervals settled at their event close (their sites still differ: they are not carried on).
            closed = self._settled_at_event(events, event_u, event_radius, found)
            carried = [events.subset(settled.nonzero()[0])] if settled.any() else []
            if settled.any() or closed.any():
                unsettled = (~settled & ~closed).nonzero()[0]
                events = events.subset(unsettled)
                event_u, event_trial, found = event_u[unsettled], event_trial[unsettled], found[unsettled]
            owner, event_u, event_trial, found, pairs = self._event_nodes(events, event_u, event_trial, found)
            station_owner, station_u, station_trial = self._stations(curves)
            span = np.concatenate([pairs.span, curves.span[station_owner]])
            u = np.concatenate([event_u, station_u])
            t, status, site, centre = self._solve_probes(span, u, np.concatenate([event_trial, station_trial]))
            del event_trial, station_trial
            count = len(event_u)
            event, exact = self._is_event(pairs, centre[:count], t[:count], site[:count], found)
            emit, other_site = self._event_emission(pairs, status[:count], site[:count], exact)
            event_index = self.add(span[:count], u[:count], t[:count], centre[:count], emit, other_site)
            # A station's tie counts only with the parabola's own site (near a tie elsewhere the contact is
            # known to the square root of the tie's tolerance only).
            own = curves.site0[station_owner]
            accepted = (status[count:] == CLEAR) | ((status[count:] == TIED) & (site[count:] == own))
            station_index = self.add(span[count:], u[count:], t[count:], centre[count:], accepted, site[count:])
            # At an event the pieces on either side keep its two sites; elsewhere both take the probe's site.
            before, after = np.where(event, pairs.site0, site[:count]), np.where(event, pairs.site1, site[:count])
            intervals = _Intervals.concatenate(
                [
                    _split_at_nodes(events, owner, event_u, event_index, before, after, False),
                    _unsettled_pieces(curves, station_owner, station_u, station_index, site[count:]),
                    *carried,
                ]
            )
        return self._points()

    def _solve_probes(self, span, u, trial):
        """Solve the probes at parameters ``u`` of spans ``span`` in the order of their points along the chains
        (neighbouring candidate boxes share spatial-index queries), ``CHUNK`` at a time (bounds the candidate
        pairs and the samples held at once); returns ``t``, status, canonical site and disk centre in the
        probes' order."""
        order = np.lexsort((self.spans.position_at(span, u), self.spans.chain[span]))
        t, status = np.empty(len(order)), np.empty(len(order), dtype=np.int8)
        site, centre = np.empty(len(order), dtype=np.int32), np.empty((len(order), 2))
        for begin in range(0, len(order), CHUNK):
            chunk = order[begin : begin + CHUNK]
            probes = self.spans.samples(span[chunk], u[chunk], self.boundary)
            t[chunk], status[chunk], _, _, site[chunk] = solve(
                probes, np.arange(len(chunk)), self.boundary, trial[chunk], self.max_t, self.min_t
            )
            put_rows(centre, chunk, probes.point + t[chunk, None] * probes.direction)
        site = self.sites.canonical(site)
        self._skip_beside_convex_corners(span, u, t, status, site, centre)
        return t, status, site, centre

    def _skip_beside_convex_corners(self, span, u, t, status, site, centre):
        """Mark skipped, in place, the solved samples (at parameters ``u`` of spans ``span``; ``t``, status,
        canonical site and disk centre) so close to a convex corner at an end of their edge that their disks
        touch the corner's other segment below the smallest contact the solver sees (``min_t``).

        Such a disk crosses its own chain at once (it is skipped, like a sample at the corner); the solver, not
        seeing that contact, would let it grow through the corner to a far one (a probe 3e-10 from a star's tip
        of 27 degrees: a centre 18 units outside the polygon, fuzz seed 20261210 input 5755).
        """
        row, corner_segment, reach = self._beside_convex_corners(span, u)
        if len(row):
            t[row], status[row], site[row] = reach, SKIPPED, self.sites.canonical(corner_segment)
            point, _ = self.spans.points(span[row], u[row])
            put_rows(centre, row, point + reach[:, None] * self.spans.directions(span[row], u[row]))

    def _beside_convex_corners(self, span, u):
        """Of the samples at parameters ``u`` of spans ``span``, those whose disks touch the other segment of a
        convex corner at an end of their edge below ``min_t``: their rows, that segment and the radius of that
        contact (CRS units)."""
        spans, b, sites = self.spans, self.boundary, self.sites
        segment = spans.segment[span]
        edge = spans.kind[span] == EDGE
        min_t = self.of(self.min_t, span)
        found = []
        for vertex, beside, distance, inner in (
            (b.start_vertex(segment) + 1, segment + 1, spans.length[span] - u, ~b.last_of_chain[segment]),
            (b.start_vertex(segment), segment - 1, u, ~b.first_of_chain[segment]),
        ):
            turn = sites.turns[vertex]
            corner = (edge & inner & (sites.kinds[vertex] > 0)).nonzero()[0]
            # A disk tangent at ``distance`` from a corner of interior angle pi - turn touches its other line at
            # radius distance * tan((pi - turn) / 2).
            reach = np.maximum(distance[corner], 0.0) * np.tan(0.5 * (np.pi - turn[corner]))
            blind = reach <= min_t[corner]
            found.append((corner[blind], beside[corner[blind]], reach[blind]))
        return tuple(np.concatenate(parts) for parts in zip(*found))

    def _initial(self, report):
        """Solve the samples at both ends of every traced edge, in the middle of an edge between two convex
        corners (both its ends are given the corners' own edges: its axis point would take a round to find) and
        on the bisector of every convex corner between two intervals (:meth:`_corner_junctions`), all in one
        solution; returns the intervals of every span between the samples, cut at the corners' junctions."""
        spans, b = self.spans, self.boundary
        edge, given_site, status, split_vertex = _initial_samples(spans, self.sites, self.closed, self.traced, b)
        # The traced edges' spans come first, in the same order.
        edge_span = np.arange(len(edge))
        between_corners = (given_site[0::2] >= 0) & (given_site[1::2] >= 0)
        middle = np.flatnonzero(between_corners)
        span = np.concatenate([np.repeat(edge_span, 2), middle])
        u = np.concatenate(
            [np.stack([np.zeros(len(edge)), spans.length[edge_span]], axis=1).ravel(), 0.5 * spans.length[middle]]
        )
        intervals = self._initial_intervals(edge, between_corners)
        after, before = self._beside_corners(intervals)
        corners = self._corner_samples(intervals.span[after])
        samples = Samples.concatenate([spans.samples(span, u, b), corners])
        t, status, site = self._solve_initial(samples, given_site, status, report)
        # A disk that touches nothing (t infinite, two bank lines far apart in length) has no centre: NaN.
        with np.errstate(invalid="ignore"):
            centre = samples.point + t[:, None] * samples.direction
        del samples
        # The edges' samples (the corners' follow them).
        count = len(span)
        solved = (t[count:], status[count:], site[count:], centre[count:])
        t, status, site, centre = t[:count], status[:count], site[:count], centre[:count]
        # A middle of a tiny edge between two corners may lie that close to them (the ends there are given).
        self._skip_beside_convex_corners(span, u, t, status, site, centre)
        emit = np.isfinite(t) & ((status == CLEAR) | ((status == TIED) & ~self._at_split_point(site)))
        # A disk tangent at a straight split point touches the other chain there: whatever it touches first
        # (a branch of its own chain's corner meets the axis there), it is a point of the axis.
        split_vertex = np.concatenate([split_vertex, np.full(len(middle), -1)])
        at_split = (split_vertex >= 0) & np.isfinite(t) & (t > self.min_t[spans.chain[span]]) & ~emit
        self.add(span, u, t, centre, emit | at_split, np.where(at_split, split_vertex, site))
        intervals = replace(intervals, site0=site[intervals.left], site1=site[intervals.right])
        return self._corner_junctions(intervals, after, before, corners, solved)

    def _initial_intervals(self, edge, between_corners):
        """The intervals between the initial samples (:meth:`_initial`: the ``2k``-th and ``2k + 1``-th at the
        ends of traced edge ``edge[k]``, then the middles of the edges ``between_corners``), their sites not yet
        known (-1)."""
        spans = self.spans
        middle = np.flatnonzero(between_corners)
        middle_index = 2 * len(edge) + np.arange(len(middle))
        reflex = np.flatnonzero(spans.kind == FAN)
        incoming = np.searchsorted(edge, spans.segment[reflex])
        whole = np.flatnonzero(~between_corners)
        span = np.concatenate([whole, middle, middle, reflex])
        u0 = np.concatenate([np.zeros(len(whole) + len(middle)), 0.5 * spans.length[middle], np.zeros(len(reflex))])
        u1 = np.concatenate(
            [spans.length[whole], 0.5 * spans.length[middle], spans.length[middle], spans.length[reflex]]
        )
        left = np.concatenate([2 * whole, 2 * middle, middle_index, 2 * incoming + 1])
        right = np.concatenate([2 * whole + 1, middle_index, 2 * middle + 1, 2 * (incoming + 1)])
        no_site = np.full(len(span), -1)
        return _Intervals(span, u0, u1, left, right, no_site, no_site, np.zeros(len(span), bool))

    def _solve_initial(self, samples, given_site, given_status, report):
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
        t[index], status[index], _, _, site[index] = _solve_all(
            samples,
            index,
            self.boundary,
            0.625 * self.width,
            self.max_t,
            self.min_t,
            lambda done: report(0.8 * done),
        )
        return t, status, self.sites.canonical(site)

    def _corner_samples(self, span):
        """Samples on the bisector of the convex corner at the start of each edge span ``span`` (span
        ``span - 1`` is the edge before it; the disks touch both segments ``slide * t`` from the corner, with
        radius ``scale * t``)."""
        spans, segment = self.spans, self.spans.segment[span]
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

    def _beside_corners(self, intervals):
        """The intervals on both sides of the convex corners of the traced chains: per corner, the one that
        starts at it (on the edge after it) and the one that ends at it (on the edge before it).

        Beside a chain's end the junction may touch the other chain at the split point itself (a tie whose
        foot the ordering cannot place on a side): those corners are left out.
        """
        b, spans = self.boundary, self.spans
        after = ((intervals.u0 == 0.0) & (spans.kind[intervals.span] == EDGE)).nonzero()[0]
        segment = spans.segment[intervals.span[after]]
        corner = self.sites.kinds[b.start_vertex(segment)] > 0
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

    def _corner_junctions(self, intervals, after, before, corners, solved):
        """Split the intervals on both sides of every convex corner of a traced chain at its junction.

        The largest empty disk on the corner's bisector touches both its segments and first touches a site
        elsewhere: one sample gives the event that the intervals beside the corner (each with the corner's
        other segment as its site at the corner) would otherwise probe one by one, from both sides. Its
        disk is the sample of both edges where it touches them; a junction touching an edge beyond its
        interval, or beside a chain's end, is left to the rounds. ``after``, ``before``: the intervals beside
        the corners (:meth:`_beside_corners`); ``corners``: their samples (:meth:`_corner_samples`), solved
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
        emit = (status == CLEAR) | ((status == TIED) & ~self._at_split_point(site))
        index = self.add(span, u, np.tile(radius, 2), np.tile(centre, (2, 1)), np.tile(emit, 2), np.tile(site, 2))
        owner = np.concatenate([after, before])
        # Beside the corner the disk touches the corner's other segment (the interval's site there).
        site_before = np.concatenate([intervals.site0[after], site])
        site_after = np.concatenate([site, intervals.site1[before]])
        return _split_at_nodes(intervals, owner, u, index, site_before, site_after, False)

    def _open_and_curved(self, intervals):
        """The open intervals (:meth:`_is_open`) and the curved ones (:meth:`_is_curved`), each judged on the
        intervals that may be one only: both ends solved, and two known sites that differ (open) or one site
        whose stations are not yet placed (curved), not a split point (which lies on both chains: its disks touch
        the other chain only through it, so no parabola round a split point in a concave corner is traced). Each
        record is gathered once, by index, from the rows judged (a mask would be scanned again for every column
        of the record)."""
        t_left, t_right = self.t[intervals.left], self.t[intervals.right]
        site0, site1 = intervals.site0, intervals.site1
        known = np.isfinite(t_left) & np.isfinite(t_right) & (site0 >= 0)
        differ = site0 != site1
        event = (differ & known & (site1 >= 0)).nonzero()[0]
        event = event[~self._off_the_axis(intervals, event)]
        event = event[self._is_open(intervals, event, np.fmax(t_left[event], t_right[event]))]
        curve = (~differ & known & ~intervals.verified).nonzero()[0]
        curve = curve[~self._at_split_point(site0[curve])]
        curve = curve[self._is_curved(intervals.span[curve], site0[curve])]
        return intervals.subset(event), intervals.subset(curve)

    def _off_the_axis(self, intervals, row):
        """Which of the intervals ``row`` (both ends solved, touching two known different sites) of closed pairs
        of chains hold no point of the axis: both ends touch their own chain, on the same side of the span along
        it.

        The disks between two samples first touch the boundary between the two contacts, on the side away from
        the span (module docstring); when both contacts lie on the own chain before the span, or both after it,
        that part of the boundary is the own chain between them, so every disk between touches its own chain
        first: the samples there lie on side branches, and their events are not points of the axis. (With two
        bank lines the other chain, joined to the own one nowhere, could lie wholly inside that part: not
        for open pairs.)
        """
        span, site0, site1 = intervals.span[row], intervals.site0[row], intervals.site1[row]
        own = self.spans.chain[span]
        on_own = self.closed[own] & (self.sites.chain(site0) == own) & (self.sites.chain(site1) == own)
        start = self.spans.position[span]
        end = self.spans.position_at(span, self.spans.length[span])
        first0, last0 = self.sites.extent(site0)
        first1, last1 = self.sites.extent(site1)
        return on_own & (((last0 <= start) & (last1 <= start)) | ((first0 >= end) & (first1 >= end)))

    def _is_open(self, intervals, row, radius):
        """Which of the intervals ``row`` (both ends solved, touching two known different sites; the larger end
        disk of radius ``radius``, CRS units) are still wide enough to split."""
        span = intervals.span[row]
        move = (intervals.u1[row] - intervals.u0[row]) * np.where(self.spans.kind[span] == EDGE, 1.0, radius)
        tolerance = self.of(self.tolerance, span)
        open_ = move > SMALLEST_MOVE * tolerance
        # Ends this close leave the axis between them (an event's corner at most) within the tolerance; an
        # event there may be ill-conditioned (a nearly straight convex corner's junction).
        candidate = open_.nonzero()[0]
        left, right = intervals.left[row[candidate]], intervals.right[row[candidate]]
        chord = np.hypot(*(self.centres(left) - self.centres(right)).T)
        open_[candidate] = chord > SETTLED_CHORD * tolerance[candidate]
        return open_

    def _is_curved(self, span, site):
        """Which intervals on spans ``span`` (both ends solved, touching one site ``site``, stations not yet
        placed) lie between samples touching one site of the other chain where the axis is a parabola.

        A fan touching a segment traces the parabola of its vertex and that segment's line; an edge touching
        a vertex with no fan (a chain's end) traces the parabola of that vertex and the edge's line. (An edge
        touching a reflex vertex of the other chain traces the same curve as that vertex's fan, which places
        the stations of both.)
        """
        spans, sites, b = self.spans, self.sites, self.boundary
        curved = sites.chain(site) == spans.chain[span] ^ 1
        vertex = sites.indices(site)[1]
        fan = (spans.kind[span] == FAN) & (site < b.segment_count)
        untraced_fan = ~self.traced[b.vertex_chain[vertex]]
        edge = (spans.kind[span] == EDGE) & (site >= b.segment_count) & ((sites.kinds[vertex] == 0) | untraced_fan)
        return curved & (fan | edge)

    def _event_candidates(self, intervals):
        """Where to probe each open interval: its event candidate, the trial radius, whether it is one, which end
        it lies at (see :func:`_crossing`) and its radius (CRS units) where it is the one crossing in the
        interval (else NaN)."""
        span = intervals.span
        # Both sites' terms in one call (each row depends on its own values only: the same floats).
        terms = self.sites.radius_terms(
            self.spans,
            np.concatenate([span, span]),
            np.concatenate([intervals.site0, intervals.site1]),
        )
        terms0, terms1 = tuple(x[: len(span)] for x in terms), tuple(x[len(span) :] for x in terms)
        u, found, at_end, roots = _crossing(self.spans, intervals, terms0, terms1, counted=True)
        self._across_split_points(intervals, terms0, u, found, at_end)
        radius = _radius_at(self.spans, span, terms0, u)
        # The radius at a single crossing (where two lie in the interval, which one is the event is not known).
        return u, self._trial(intervals, radius, found), found, at_end, np.where(roots == 1, radius, np.nan)

    def _across_split_points(self, intervals, terms0, u, found, at_end):
        """Where the contact crosses a split point, for the intervals whose two sites are the runs of both chains
        at one split point and whose crossing is neither found nor at an end.

        At a straight split point both runs lie on one line: their radii are that line's, so they never cross, and
        the contact passes from one run to the other where the disk is tangent to the line at the split point.
        That parameter, where the foot on the first site's line (``terms0``: its :meth:`_Sites.radius_terms`) is
        the split point, is a root of ``D0 + D1 u`` on an edge and of ``D0 + D1 cos(u) + D2 sin(u)`` on a fan:
        written into ``u`` and ``found`` in place where it lies inside the interval, into ``at_end`` where it lies
        at an end. Like any event candidate it is only a candidate: its probe is judged as an event's
        (:meth:`_is_event`), an end by :meth:`_settle_at_ends` (at a split point that is not straight, where a
        crossing outside the interval was found, neither may hold, and the interval is split as usual).
        """
        b, sites, spans = self.boundary, self.sites, self.spans
        site0, site1 = intervals.site0, intervals.site1
        count = b.segment_count
        row = ~found & (at_end < 0) & (site0 >= 0) & (site0 < count) & (site1 >= 0) & (site1 < count)
        row &= self.closed[spans.chain[intervals.span]]
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
        u[row], found[row], at_end[row] = _crossing(spans, intervals.subset(row), equation, zero)

    def _trial(self, intervals, radius, found):
        """Trial radius of a probe in each interval whose event (where ``found``) has ``radius``, CRS units."""
        known = np.maximum(self.t[intervals.left], self.t[intervals.right])
        width = self.of(self.width, intervals.span)
        known = np.where(np.isfinite(known), 1.25 * known, width)
        # The solver doubles a trial radius that is too small: a small one keeps the candidate boxes tight.
        trial = np.where(found & np.isfinite(radius), np.minimum(1.001 * radius, known), known)
        return np.maximum(trial, width / 16.0)

    def _pair_events(self, intervals, terms0, terms1):
        """The event of two sites (their :meth:`_Sites.radius_terms`) inside each interval, in closed form: its
        parameter, its radius and whether it lies strictly inside (the probe decides whether it is one)."""
        u, found, _ = _crossing(self.spans, intervals, terms0, terms1)
        radius = _radius_at(self.spans, intervals.span, terms0, u)
        return u, radius, found & np.isfinite(radius)

    def _walks(self, intervals):
        """The run of its chain's site sequence each interval's contact is predicted to walk through, from its
        site at ``u0`` to its site at ``u1``: the ranks ``first``, ``last`` of the run and its number of events
        (0 where the two sites lie on different chains, or the run would pass the span's own sites)."""
        sites = self.sites
        chain0, chain1 = sites.chain(intervals.site0), sites.chain(intervals.site1)
        first, last = sites.rank[intervals.site0], sites.rank[intervals.site1]
        low, high = np.minimum(first, last), np.maximum(first, last)
        span = intervals.span
        other = chain0 == self.spans.chain[span] ^ 1
        apart = other | (high < self.own_ranks[0][span]) | (low > self.own_ranks[1][span])
        return first, last, np.where((chain0 == chain1) & (chain0 >= 0) & (low >= 0) & apart, high - low, 0)

    def _walk_sites(self, intervals, found):
        """The sites of the predicted walks, from ``u0`` to ``u1``: per site its interval (ascending, at least
        three sites per walk) and the site. :meth:`_walks` along one chain, and :meth:`_approaches` into an
        interval whose two sites lie on different chains and whose event candidate was not ``found``."""
        first, last, events = self._walks(intervals)
        counts = np.where((events >= 2) & (events <= MAX_PREDICTED), events + 1, 0)
        owner, index = ranges(counts)
        site = self.sites.sequence[first[owner] + np.where(last >= first, 1, -1)[owner] * index]
        approach_owner, approach_site = self._approaches(intervals, found)
        if len(approach_owner) == 0:
            return owner, site
        # A walk along one chain and an approach never share an interval: merged by interval, each in order.
        order = np.argsort(np.concatenate([owner, approach_owner]), kind="stable")
        return np.concatenate([owner, approach_owner])[order], np.concatenate([site, approach_site])[order]

    def _approaches(self, intervals, found):
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
        sites, spans = self.sites, self.spans
        chain = spans.chain[intervals.span]
        chain0, chain1 = sites.chain(intervals.site0), sites.chain(intervals.site1)
        other_first = chain0 == chain ^ 1
        own_site = np.where(other_first, intervals.site1, intervals.site0)
        rank = sites.rank[own_site]
        span = intervals.span
        step = np.where(rank > self.own_ranks[1][span], 1, np.where(rank < self.own_ranks[0][span], -1, 0))
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
        terms = self.sites.radius_terms(
            spans,
            np.concatenate([span[row], span[owner]]),
            np.concatenate([other_site[row], candidate]),
        )
        u, radius, inside = self._pair_events(
            intervals.subset(owner), [x[row_of] for x in terms], [x[len(row) :] for x in terms]
        )
        # The foot is looked at only where the crossing lies inside the interval.
        judged = inside.nonzero()[0]
        inside[judged] = self._on_run(span[owner[judged]], u[judged], radius[judged], candidate[judged])
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

    def _on_run(self, span, u, radius, site):
        """Whether the disk of ``radius`` at parameter ``u`` of ``span`` has its foot on ``site``'s straight run
        (not only on its line; always for a vertex site)."""
        b = self.boundary
        point, _ = self.spans.points(span, u)
        centre = point + radius[:, None] * self.spans.directions(span, u)
        segment = self.sites.indices(site)[0]
        along = np.einsum("ij,ij->i", centre - rows(b.start, segment), rows(self.sites.unit, segment))
        run_length = self.sites.run_end_position[segment] - b.segment_position[segment]
        with np.errstate(invalid="ignore"):
            return (site >= b.segment_count) | ((along >= 0.0) & (along <= run_length))

    def _event_nodes(self, intervals, event_u, event_trial, found):
        """The probes of the open intervals: every predicted event of an interval whose walk holds in closed
        form (:meth:`_walk_sites`, :meth:`_pair_events`: each event strictly inside the interval, the events in the
        walk's order), else its one event candidate (``event_u``, ``event_trial``, ``found``).

        Returns per probe its interval, parameter, trial radius, whether it is an event candidate, and its
        interval with the probe's two sites (the one before the event, the one after) as ``site0``, ``site1``.
        """
        owner, site = self._walk_sites(intervals, found)
        if len(owner) == 0:
            # Every interval probes its one event candidate.
            return np.arange(len(intervals.span)), event_u, event_trial, found, intervals
        predicted = np.bincount(owner, minlength=len(intervals.span)) > 0
        # Each site of a walk is the second site of one event and the first of the next: its terms serve both.
        terms = self.sites.radius_terms(self.spans, intervals.span[owner], site)
        pair = (owner[1:] == owner[:-1]).nonzero()[0]
        pair_owner = owner[pair]
        pieces = intervals.subset(pair_owner)
        u, radius, inside = self._pair_events(pieces, [x[pair] for x in terms], [x[pair + 1] for x in terms])
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
        trial = self._trial(pieces, radius[keep], np.ones(len(keep), dtype=bool))
        return (
            node_owner,
            np.concatenate([event_u[single], u[keep]]),
            np.concatenate([event_trial[single], trial]),
            np.concatenate([found[single], np.ones(len(keep), dtype=bool)]),
            probe_pairs,
        )

    def _settled_at_event(self, intervals, u, radius, found):
        """Mask of the open intervals whose two sites follow each other on the other chain and whose axis
        provably lies within the tolerance of the chord of their end centres (module docstring, *Settled at
        the event*): the centre of their event (at ``u``, of ``radius``, CRS units, where ``found``) lies within
        the tolerance of the chord, less the larger deviation of the two arcs beside it from their own chords."""
        settled = np.zeros(len(intervals.span), dtype=bool)
        row = self._beside_each_other(intervals, found & np.isfinite(radius))
        if len(row) == 0:
            return settled
        spans = self.spans
        span = intervals.span[row]
        point, _ = spans.points(span, u[row])
        event = point + radius[row, None] * spans.directions(span, u[row])
        start, end = self.centres(intervals.left[row]), self.centres(intervals.right[row])
        chord = end - start
        along = np.clip(np.einsum("ij,ij->i", event - start, chord) / np.einsum("ij,ij->i", chord, chord), 0.0, 1.0)
        distance = np.hypot(*(event - start - along[:, None] * chord).T)
        sag = np.maximum(
            self._sag(span, intervals.site0[row], start, event), self._sag(span, intervals.site1[row], event, end)
        )
        with np.errstate(invalid="ignore"):
            settled[row] = distance + sag <= self.of(self.tolerance, span)
        return settled

    def _beside_each_other(self, intervals, judged):
        """Of the intervals ``judged`` of closed pairs of chains, those whose end samples are emitted (empty disks
        touching their sites) and whose two sites follow each other in the other chain's site sequence, neither
        at one of its ends."""
        sites, b = self.sites, self.boundary
        chain = self.spans.chain[intervals.span]
        other = chain ^ 1
        emit = self.store["emit"]
        judged = judged & self.closed[chain] & (sites.chain(intervals.site0) == other)
        judged &= sites.chain(intervals.site1) == other
        judged &= emit[intervals.left] & emit[intervals.right]
        judged &= np.abs(sites.rank[intervals.site0] - sites.rank[intervals.site1]) == 1
        for site in (intervals.site0, intervals.site1):
            judged &= ~((site >= b.segment_count) & sites.chain_end[sites.indices(site)[1]])
        return judged.nonzero()[0]

    def _sag(self, span, site, start, end):
        """Largest distance between the axis touching ``site`` on ``span`` and its chord from ``start`` to ``end``
        (centres on it), CRS units: 0 where it is straight (an edge and a segment, a fan and a vertex), else
        at most ``d**2 / (8 h)`` for the parabola of focal height ``h`` (a vertex over the edge's line, the
        fan's vertex over the segment's line), ``d`` the chord's length along the directrix (the parabola's
        curvature is at most ``1 / h``)."""
        spans, b = self.spans, self.boundary
        on_fan, on_vertex = spans.kind[span] == FAN, site >= b.segment_count
        segment, vertex = self.sites.indices(site)
        direction = np.where(on_fan[:, None], rows(self.sites.unit, segment), rows(spans.unit, span))
        focus = np.where(on_fan[:, None], rows(spans.point, span), rows(b.vertex, vertex))
        anchor = np.where(on_fan[:, None], rows(b.start, segment), rows(spans.point, span))
        height = np.abs(np.einsum("ij,ij->i", focus - anchor, left_normal(direction)))
        along = np.einsum("ij,ij->i", end - start, direction)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(on_fan != on_vertex, along * along / (8.0 * height), 0.0)

    def _settle_at_ends(self, intervals, at_end):
        """Intervals whose sites cross at an end sample that touches both: the other end's site holds inside.

        Returns the mask of those intervals, whose sites are made equal in place.
        """
        settled = at_end >= 0
        # Only the intervals whose crossing lies at an end are looked at.
        row = settled.nonzero()[0]
        if len(row) == 0:
            return settled
        end = np.where(at_end[row] == 0, intervals.left[row], intervals.right[row])
        centre = self.centres(end)
        slack = EVENT_TOLERANCE * self.t[end] + self.of(self.min_t, intervals.span[row])
        with np.errstate(invalid="ignore"):
            _, _, distance0, distance1 = self.sites.pair_feet(intervals.site0[row], intervals.site1[row], centre)
            touching = np.abs(distance0 - self.t[end]) <= slack
            touching &= np.abs(distance1 - self.t[end]) <= slack
        settled[row] = touching
        self._emit_junctions(intervals.subset(row[touching]), end[touching])
        intervals.site0[settled & (at_end == 0)] = intervals.site1[settled & (at_end == 0)]
        intervals.site1[settled & (at_end == 1)] = intervals.site0[settled & (at_end == 1)]
        return settled

    def _emit_junctions(self, intervals, end):
        """Emit the end samples ``end`` of ``intervals`` (their disks touch both sites of their interval, which is
        settled at that end) that touch a site of each chain exactly (:meth:`_is_event`), not at a split point.

        Such a disk touches both chains: its centre is a point of the axis, where a branch of the own chain joins
        it. A probe placed there for another pair of sites (two of the own chain whose event falls on the same
        disk: one of them touched only on its line's extension) is no event of its interval and, reported as a
        tie, was not emitted; without it the line would cut the corner of the axis there.
        """
        if len(end) == 0:
            return
        chain = self.spans.chain[intervals.span]
        other0 = self.sites.chain(intervals.site0) == chain ^ 1
        one_each = other0 != (self.sites.chain(intervals.site1) == chain ^ 1)
        candidate = (one_each & ~self.store["emit"][end]).nonzero()[0]
        if len(candidate) == 0:
            return
        pairs, end = intervals.subset(candidate), end[candidate]
        other_site = np.where(other0[candidate], pairs.site0, pairs.site1)
        _, exact = self._is_event(pairs, self.centres(end), self.t[end], other_site, np.ones(len(end), dtype=bool))
        junction = exact & ~self._at_split_point(other_site)
        self.store["emit"][end[junction]] = True
        self.store["other_site"][end[junction]] = other_site[junction]

    def _is_event(self, intervals, centre, t, site, found):
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
            foot0, foot1, distance0, distance1 = self.sites.pair_feet(intervals.site0, intervals.site1, centre)
            parting = np.hypot(*((centre - foot0) / distance0[:, None] - (centre - foot1) / distance1[:, None]).T)
            gap0, gap1 = np.abs(distance0 - t), np.abs(distance1 - t)
            scale = (LOOSE_EVENT_TOLERANCE * t, EVENT_TOLERANCE * t * np.nan_to_num(parting))
            min_t = self.of(self.min_t, intervals.span)
            own_site = (site == intervals.site0) | (site == intervals.site1)
            found = found & (own_site | (np.hypot(*(foot0 - foot1).T) > EVENT_TOLERANCE * t + min_t))
            return tuple(found & (gap0 <= s + min_t) & (gap1 <= s + min_t) for s in scale)

    def _at_split_point(self, site):
        """Whether each site is a split point (closed mode): a vertex of both chains. A tie with it is no
        evidence of a contact with the other chain (it also lies on the own one)."""
        return (site >= self.boundary.segment_count) & self.split_vertex[self.sites.indices(site)[1]]

    def _event_emission(self, intervals, status, site, event):
        """Which probes are axis points, and the site of their foot on the other chain.

        A clear probe is; a tie only at an event (near a tie the contact is known to the square root of the
        tie's tolerance only); a skipped probe at an event between a site of each chain is (its disk touches
        both chains, the rounding chose the own one).
        """
        chain = self.spans.chain[intervals.span]
        other0 = self.sites.chain(intervals.site0) == chain ^ 1
        other1 = self.sites.chain(intervals.site1) == chain ^ 1
        forced = event & (status == SKIPPED) & (other0 | other1)
        emit = (status == CLEAR) | ((status == TIED) & event & ~self._at_split_point(site)) | forced
        other_site = np.where(forced, np.where(other0, intervals.site0, intervals.site1), site)
        return emit, other_site

    def _stations(self, intervals):
        """Stations of the parabola of each curved interval: owner, span parameter, trial radius."""
        if len(intervals.span) == 0:
            return np.empty(0, dtype=int), np.empty(0), np.empty(0)
        spans, b = self.spans, self.boundary
        span, site = intervals.span, intervals.site0
        on_fan = spans.kind[span] == FAN
        segment, vertex = self.sites.indices(site)
        point = rows(spans.point, span)
        focus = np.where(on_fan[:, None], point, rows(b.vertex, vertex))
        anchor = np.where(on_fan[:, None], rows(b.start, segment), point)
        unit = np.where(on_fan[:, None], rows(self.sites.unit, segment), rows(spans.unit, span))
        ends = np.stack([self.centres(intervals.left), self.centres(intervals.right)], axis=1)
        owner, centre, radius = _parabola_stations(focus, anchor, unit, ends, self.of(self.tolerance, intervals.span))
        offset = centre - rows(spans.point, span[owner])
        along = np.einsum("ij,ij->i", offset, rows(spans.unit, span[owner]))
        angle = np.arctan2(np.einsum("ij,ij->i", offset, rows(spans.normal, span[owner])), along)
        u = np.clip(np.where(on_fan[owner], angle, along), intervals.u0[owner], intervals.u1[owner])
        return owner, u, 1.001 * radius + self.of(self.min_t, span[owner])

    def _points(self):
        """The emitted samples as :class:`AxisPoints`, and the chain each was sampled on (the first chain of
        its pair, so its foot is ``foot_a``). Releases the store and the spatial index; works ``CHUNK``
        points at a time, so that only the output is held in full."""
        self.boundary.release_index()
        store, self.store = self.store, {}
        index = np.flatnonzero(store["emit"][: self.count] & np.isfinite(store["t"][: self.count]))
        span, u, t, centre, other_site = (
            rows(store[name], index) for name in ("span", "u", "t", "centre", "other_site")
        )
        del store, index
        foot_a, foot_b = np.empty((len(t), 2)), np.empty((len(t), 2))
        position_a, position_b = np.empty(len(t)), np.empty(len(t))
        for begin in range(0, len(t), CHUNK):
            part = slice(begin, begin + CHUNK)
            foot_a[part], along = self.spans.points(span[part], u[part])
            position_a[part] = self.spans.position[span[part]] + along
            foot_b[part], position_b[part] = self.sites.feet(other_site[part], centre[part])
        return AxisPoints(centre, t, foot_a, foot_b, position_a, position_b), self.spans.chain[span]


def _solve_all(samples, index, *arguments):
    """:func:`.contacts.solve_in_chunks`, without its set-up when there is nothing to solve."""
    if len(index) == 0:
        return np.empty(0), np.empty(0, dtype=np.int8), np.empty((0, 2)), np.empty(0), np.empty(0, dtype=int)
    return solve_in_chunks(samples, index, *arguments)


def _initial_samples(spans, sites, closed, traced, boundary):
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
        straight_turn = _straight_turns(boundary, own, other)
        convex = turn > straight_turn
        site[2 * own_rank[convex] + which] = other[convex]
        status[2 * own_rank[convex] + which] = CLEAR
        # The other chain's vertex at a straight split point (the other chain's end vertex of that side).
        straight = np.abs(turn) <= straight_turn
        vertex = other + (chain ^ 1) + which
        split_vertex[2 * own_rank[straight] + which] = boundary.segment_count + vertex[straight]
    return edge, site, status, split_vertex


def _by_owner_then_u(owner, u):
    """The permutation ``np.lexsort((u, owner))``: by owner, then by ``u``, ties in input order.

    A stable sort of ``owner`` alone that leaves every owner's ``u`` in order is that permutation (the order
    sorted by both keys that keeps ties in input order is unique), and nodes mostly come so; otherwise (or
    with a NaN) ``np.lexsort`` sorts them.
    """
    order = np.argsort(owner, kind="stable")
    sorted_owner, sorted_u = owner[order], u[order]
    if np.any((sorted_owner[1:] == sorted_owner[:-1]) & ~(sorted_u[1:] >= sorted_u[:-1])):
        return np.lexsort((u, owner))
    return order


def _split_at_nodes(intervals, owner, u, index, site_before, site_after, verified):
    """Every interval cut at its nodes (samples ``index`` at parameters ``u`` of interval ``owner``).

    A node's ``site_before`` becomes the site at the right end of the piece before it, ``site_after`` the one at
    the left end of the piece after it (an event's two sites, else twice its first contact); the pieces are
    marked ``verified`` (the stations of a parabola) or not.
    """
    if len(owner) == 0:
        return replace(intervals, verified=np.full(len(intervals.span), verified))
    order = _by_owner_then_u(owner, u)
    owner, u, index = owner[order], u[order], index[order]
    site_before, site_after = site_before[order], site_after[order]
    # Interval i becomes the pieces first[i] .. first[i] + (its node count): the k-th node (sorted) of all
    # ends piece owner + k and starts the next one; the interval's ends start its first piece and end its last.
    nodes = np.bincount(owner, minlength=len(intervals.span))
    first = np.arange(len(nodes)) + np.cumsum(nodes) - nodes
    last = first + nodes
    inner = owner + np.arange(len(owner))
    total = len(nodes) + len(owner)
    pieces = _Intervals(
        np.repeat(intervals.span, nodes + 1),
        *(np.empty(total) for _ in range(2)),
        *(np.empty(total, dtype=np.int32) for _ in range(4)),
        np.full(total, verified),
    )
    pieces.u0[first], pieces.u0[inner + 1] = intervals.u0, u
    pieces.u1[last], pieces.u1[inner] = intervals.u1, u
    pieces.left[first], pieces.left[inner + 1] = intervals.left, index
    pieces.right[last], pieces.right[inner] = intervals.right, index
    pieces.site0[first], pieces.site0[inner + 1] = intervals.site0, site_after
    pieces.site1[last], pieces.site1[inner] = intervals.site1, site_before
    return pieces


def _unsettled_pieces(curves, owner, u, index, site):
    """The pieces of the curved intervals cut at their stations (samples ``index`` at parameters ``u`` of curve
    ``owner``, first touching ``site``) that may still hold an event: those whose ends touch different sites.

    The pieces are verified, so one whose ends touch the same site is neither open nor curved: the next round
    would drop it (and keeps the others in this order), so it is dropped here, and a curve whose stations all
    touch its own site is not cut at all.
    """
    if not np.any(site != curves.site0[owner]):
        return curves.subset(np.zeros(len(curves.span), dtype=bool))
    pieces = _split_at_nodes(curves, owner, u, index, site, site, True)
    return pieces.subset((pieces.site0 != pieces.site1).nonzero()[0])


def _split_vertices(boundary, closed):
    """Mask of the vertices that are split points: both ends of every chain whose pair is closed."""
    mask = np.zeros(len(boundary.vertex), dtype=bool)
    first, last = _chain_end_vertices(boundary)
    mask[first[closed]] = mask[last[closed]] = True
    return mask


def _chain_end_vertices(boundary):
    """The first and the last vertex of every chain (indices in ``boundary.vertex``)."""
    first = np.asarray(boundary.offset) + np.arange(len(boundary.offset))
    return first, np.append(first[1:], len(boundary.vertex)) - 1


def adaptive_axis_points(sides, boundary, closed, tolerance, width, max_t, min_t, report):
    """Points of the medial axis between the chains, every chord within ``tolerance`` of it.

    ``sides`` gives, per chain, +1 when the region lies left of it and -1 when right; ``closed`` is true
    when the chains share both end points; ``tolerance`` (CRS units) bounds the distance between a parabola
    of the axis and its chords. ``boundary`` (the chains' :class:`.contacts.Boundary`), ``width``, ``max_t``,
    ``min_t`` and ``report`` are as for :func:`.fixed_sampling.fixed_axis_points`. Returns :class:`.contacts.AxisPoints`.
    """
    per_chain = [np.full(2, value) for value in (closed, tolerance, width, max_t, min_t)]
    return _Tracer(sides, boundary, *per_chain).trace(report)[0]


def trace_one(request, report):
    """:func:`adaptive_axis_points` of one :class:`.steps.TraceRequest`, reporting to ``report``.

    The request's :class:`.contacts.Boundary` is built here and released with the tracer (not cached on the
    request, which lives on while its centerline is assembled).
    """
    return adaptive_axis_points(
        request.sides,
        Boundary(request.chains, np.full(2, request.rounding)),
        request.closed,
        request.tolerance,
        request.width,
        request.max_t,
        request.min_t,
        report,
    )


#: A joint group places its features, in the spatial index only, on a grid of cells this many times their
#: largest extent, and holds features whose extents differ at most by ``JOINT_EXTENT_RATIO`` (a cell's
#: candidate boxes then list few segments of its neighbours). The groups of one tracing overlap in the index;
#: their extents differ at most by ``JOINT_BATCH_RATIO``. Every value is computed in the feature's own frame.
JOINT_CELL = 1.25
JOINT_EXTENT_RATIO = 4.0
JOINT_BATCH_RATIO = JOINT_EXTENT_RATIO**2

#: Most segments in one joint tracing (bounds its memory).
JOINT_SEGMENTS = 1 << 17


def trace_together(requests, report):
    """:func:`adaptive_axis_points` of many :class:`.steps.TraceRequest` objects, traced jointly.

    Requests of similar extent are placed side by side in one frame (a group, :func:`_joint_groups`); groups
    are traced together in one set of vectorised rounds up to ``JOINT_SEGMENTS`` (:func:`_joint_batches`: their
    frames overlap, which changes nothing since contacts are only ever sought within a feature's own pair of
    chains); each feature's points are shifted back. ``report(fraction)`` is called as the batches are done.
    Returns a list of :class:`.contacts.AxisPoints` in the requests' order.
    """
    results = [None] * len(requests)
    batches = _joint_batches(requests, _joint_groups(requests))
    for done, batch in enumerate(batches):
        part = lambda fraction, begin=done: report((begin + fraction) / len(batches))
        if len(batch) == 1 and len(batch[0]) == 1:
            results[batch[0][0]] = trace_one(requests[batch[0][0]], part)
        else:
            indices = [index for group in batch for index in group]
            for index, points in zip(indices, _trace_batch(requests, batch, part)):
                results[index] = points
    return results


def _joint_groups(requests):
    """Indices of the requests in groups placed on one grid (several groups share a tracing,
    :func:`_joint_batches`): extents at most ``JOINT_EXTENT_RATIO`` apart, at most ``JOINT_SEGMENTS``
    segments; by ascending extent."""
    extents = np.array([request.extent for request in requests])
    sizes = np.array([request.segment_count for request in requests])
    order = np.argsort(extents, kind="stable")
    return _consecutive_bins(order.tolist(), extents[order], sizes[order], JOINT_EXTENT_RATIO)


def _joint_batches(requests, groups):
    """Consecutive ``groups`` (lists of request indices, by ascending extent) packed into batches traced in one
    tracing: extents at most ``JOINT_BATCH_RATIO`` apart (the groups' grids overlap, so a large feature's
    candidate boxes would list the segments of every much smaller feature under them, dropped only after the
    search), at most ``JOINT_SEGMENTS`` segments."""
    extents = [requests[group[0]].extent for group in groups]
    sizes = [sum(requests[index].segment_count for index in group) for group in groups]
    return _consecutive_bins(groups, extents, sizes, JOINT_BATCH_RATIO)


def _consecutive_bins(items, extents, sizes, ratio):
    """``items`` (by ascending ``extents``, CRS units) cut into runs whose extents differ at most by ``ratio``
    and whose ``sizes`` (segments) add up to at most ``JOINT_SEGMENTS`` (an item of more is a run of its own)."""
    bins, current, smallest, segments = [], [], 0.0, 0
    for item, extent, size in zip(items, extents, sizes):
        if current and (extent > ratio * smallest or segments + size > JOINT_SEGMENTS):
            bins.append(current)
            current = []
        if not current:
            smallest, segments = extent, 0
        current.append(item)
        segments += size
    return bins + [current] if current else bins


def _group_offsets(requests):
    """Shift of each of ``requests`` (one group) to its cell of a square grid centred on the origin, CRS units."""
    columns = int(np.ceil(np.sqrt(len(requests))))
    cell = JOINT_CELL * max(request.extent for request in requests)
    rank = np.arange(len(requests))
    return cell * (np.stack([rank % columns, rank // columns], axis=1) - 0.5 * (columns - 1))


def _trace_batch(requests, batch, report):
    """Trace the groups of ``batch`` in one tracing, each feature in its own frame: its chains are placed on
    its group's grid in the spatial index only (:func:`_group_offsets`, ``index_shift`` of
    :class:`.contacts.Boundary`), so its points are those it gets traced alone; returns them in the order of
    the batch's requests."""
    offsets = np.concatenate([_group_offsets([requests[index] for index in group]) for group in batch])
    requests = [requests[index] for group in batch for index in group]
    chains = [chain for request in requests for chain in request.chains]
    sides = [side for request in requests for side in request.sides]
    per_chain = [
        np.repeat([getattr(request, name) for request in requests], 2)
        for name in ("closed", "tolerance", "width", "max_t", "min_t")
    ]
    rounding = np.repeat([request.rounding for request in requests], 2)
    boundary = Boundary(chains, rounding, index_shift=np.repeat(offsets, 2, axis=0))
    points, chain = _Tracer(sides, boundary, *per_chain).trace(report)
    feature = chain >> 1
    order = np.argsort(feature, kind="stable")
    points = points.subset(order)
    bounds = np.searchsorted(feature[order], np.arange(len(requests) + 1)).tolist()
    return [points.subset(slice(begin, end)) for begin, end in zip(bounds[:-1], bounds[1:])]
