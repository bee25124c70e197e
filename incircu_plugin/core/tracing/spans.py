"""The spans of the traced chains: where a maximal disk's foot moves along a chain (docs/tracing.md).

A span is an edge (the disk slides along it, centre on the edge's normal) or a reflex vertex's fan (the disk
pivots about the vertex). This module also holds the chains' straight runs and the turns of their junctions,
which decide what is an edge, a fan or a convex corner.
"""

from dataclasses import dataclass

import numpy as np

from .._arrays import left_normal, put_rows, rows
from ..contacts import Samples
from ..polyline import turns_between

#: Span kinds: an edge (the parameter is the distance along it) or a reflex vertex's fan (the angle, radians).
EDGE, FAN = 0, 1

#: Turn, radians, under which a vertex counts as straight (its two edges lie on one line; a split point
#: inserted into an edge is straight to about the coordinates' rounding over the edge's length, which
#: :func:`straight_turns` allows for where it is more).
STRAIGHT_TURN = 1e-9

#: Largest turn that counts as straight through the rounding of a short segment (:func:`straight_turns`): a
#: split point is never placed closer to a vertex than that direction allows (``chains.SPLIT_SNAP_ROUNDINGS``),
#: and a real corner next to a shorter segment of the input stays a corner.
MAX_STRAIGHT_TURN = 1e-3


@dataclass(frozen=True)
class Spans:
    """The spans of the traced chains (see :class:`.tracer.Tracer`).

    A sample at parameter ``u`` of span ``i`` lies at ``point + u * unit`` with direction ``normal`` on an
    edge (the segment's own direction, so the samples lie on it, and its straight run's inward normal, see
    :func:`line_units`), and at ``point`` with direction ``cos(u) * unit + sin(u) * normal`` on a fan;
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


@dataclass(frozen=True)
class Geometry:
    """The straight lines of the chains, and the turn and kind of every junction of two segments of a chain.

    Junction ``j`` joins segments ``joint[j]`` and ``joint[j] + 1``; its kind is +1 (convex), -1 (reflex) or 0
    (straight), and ``turn`` (radians) is the turn between the lines of its two segments. ``vertex_kind`` is
    the kind of every vertex, chain after chain (0 at the chains' ends), and ``vertex_turn`` its turn towards the
    region (radians, positive at a convex vertex, 0 at the chains' ends). Segments joined by straight junctions
    form a straight run, one line (:func:`straight_runs`): per segment, ``line_of`` is its run's first
    segment, ``run_end_position`` the arc length at the run's end (CRS units), and ``unit`` and ``normal``
    (inward) are the run's direction (:func:`line_units`).
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


def chain_geometry(boundary, sides):
    """:class:`Geometry` of all chains at once (``sides``: +1 when the region lies left of a chain, -1 right)."""
    side = np.asarray(sides, dtype=float)[boundary.chain_id]
    joint = np.flatnonzero(~boundary.last_of_chain)
    # The turn at every pair of consecutive segments (views, no gathered copies), then at the junctions: each
    # row is computed from its own two units, so the same floats as from the junctions' rows alone.
    turn = turns_between(boundary.unit[:-1], boundary.unit[1:])[joint]
    signed = side[joint] * turn
    straight = straight_turns(boundary, joint, joint + 1)
    kind = np.where(signed > straight, 1, np.where(signed < -straight, -1, 0)).astype(np.int8)
    vertex_kind = np.zeros(len(boundary.vertex), dtype=kind.dtype)
    vertex_kind[boundary.start_vertex(joint) + 1] = kind
    vertex_turn = np.zeros(len(boundary.vertex))
    vertex_turn[boundary.start_vertex(joint) + 1] = signed
    line_of, line_end, run_end_position = straight_runs(vertex_kind, boundary)
    unit = line_units(boundary, line_of, line_end)
    normal = left_normal(unit)
    normal *= side[:, None]
    turn = turns_between(rows(unit, joint), rows(unit, joint + 1))
    return Geometry(unit, normal, joint, turn, kind, vertex_kind, vertex_turn, line_of, run_end_position)


def line_units(boundary, line_of, line_end):
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


def straight_turns(boundary, first, second):
    """The turn, radians, under which the junction of segments ``first`` and ``second`` counts as straight:
    ``STRAIGHT_TURN``, or the rounding of the first one's chain (:attr:`.contacts.Boundary.chain_rounding`: the
    coordinates' rounding where they come from) over the shorter segment where that is more (a split point
    inserted a hair from a vertex, or into the edge of a small shape far from the origin: the pieces'
    directions are known to that angle only), at most ``MAX_STRAIGHT_TURN``."""
    shorter = np.minimum(boundary.length.take(first), boundary.length.take(second))
    uncertain = boundary.chain_rounding.take(boundary.chain_id.take(first)) / shorter
    return np.clip(uncertain, STRAIGHT_TURN, MAX_STRAIGHT_TURN)


def build_spans(boundary, geometry, traced):
    """The edge spans of the traced chains (``traced``: per chain), in the order of their segments, then the
    fan spans of their reflex vertices."""
    edge = np.flatnonzero(traced[boundary.chain_id])
    joint = geometry.kind < 0
    joint &= traced[boundary.chain_id[geometry.joint]]
    reflex = geometry.joint[joint]
    turn = geometry.turn[joint]
    first_normal = rows(geometry.normal, reflex)
    start, end = boundary.segment_position[edge], boundary.segment_end_position[edge]
    return Spans(
        kind=np.concatenate([np.full(len(edge), EDGE, dtype=np.int8), np.full(len(reflex), FAN, dtype=np.int8)]),
        chain=boundary.chain_id[np.concatenate([edge, reflex])],
        segment=np.concatenate([edge, reflex]).astype(boundary.chain_id.dtype),
        length=np.concatenate([end - start, np.abs(turn)]),
        point=np.concatenate([rows(boundary.start, edge), boundary.end(reflex)]),
        unit=np.concatenate([rows(boundary.unit, edge), first_normal]),
        normal=np.concatenate([rows(geometry.normal, edge), np.sign(turn)[:, None] * left_normal(first_normal)]),
        position=np.concatenate([start, boundary.segment_end_position[reflex]]),
    )


def straight_runs(kinds, boundary):
    """For each segment, the first and the last segment of its run of segments on one line (the first is the
    site it stands for), and the arc length at the run's end (CRS units)."""
    # ``kinds`` holds the vertex kinds, chain after chain (as ``boundary.vertex``).
    segment = np.arange(boundary.segment_count, dtype=np.int32)
    starts_run = boundary.first_of_chain | (kinds[boundary.start_vertex(segment)] != 0)
    first = np.maximum.accumulate(np.where(starts_run, segment, 0))
    ends_run = np.append(starts_run[1:], True)
    last = np.minimum.accumulate(np.where(ends_run, segment, np.int32(boundary.segment_count))[::-1])[::-1]
    return first, last, boundary.segment_end_position[last]


def own_ranks(spans, sites, boundary):
    """Per span, the lowest and highest rank of the sites its samples touch by construction: an edge's
    segment (its straight run) and end vertices, a fan's vertex and two segments."""
    first = spans.segment
    last = first + (spans.kind == FAN)
    start_vertex = boundary.start_site[first]
    end_vertex = boundary.start_site[last] + 1
    low = np.where(sites.rank[start_vertex] >= 0, sites.rank[start_vertex], sites.rank[first])
    high = np.where(sites.rank[end_vertex] >= 0, sites.rank[end_vertex], sites.rank[last])
    return low, high
