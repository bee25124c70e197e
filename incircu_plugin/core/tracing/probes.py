"""Solving samples with the exact contact solver: the rounds' probes, in the order of their points along the
chains, and the guard beside convex corners where the solver cannot see the first contact."""

import numpy as np

from .._arrays import put_rows
from ..contacts import CHUNK, SKIPPED, solve, solve_in_chunks
from .options import Solution
from .spans import EDGE


def solve_all(samples, index, *arguments):
    """:func:`.contacts.solve_in_chunks`, without its set-up when there is nothing to solve."""
    if len(index) == 0:
        return np.empty(0), np.empty(0, dtype=np.int8), np.empty((0, 2)), np.empty(0), np.empty(0, dtype=int)
    return solve_in_chunks(samples, index, *arguments)


def solve_probes(tracer, span, u, trial):
    """Solve the probes at parameters ``u`` of spans ``span`` in the order of their points along the chains
    (neighbouring candidate boxes share spatial-index queries), ``CHUNK`` at a time (bounds the candidate
    pairs and the samples held at once); returns ``t``, status, canonical site and disk centre in the
    probes' order."""
    order = np.lexsort((tracer.spans.position_at(span, u), tracer.spans.chain[span]))
    t, status = np.empty(len(order)), np.empty(len(order), dtype=np.int8)
    site, centre = np.empty(len(order), dtype=np.int32), np.empty((len(order), 2))
    for begin in range(0, len(order), CHUNK):
        chunk = order[begin : begin + CHUNK]
        probes = tracer.spans.samples(span[chunk], u[chunk], tracer.boundary)
        t[chunk], status[chunk], _, _, site[chunk] = solve(
            probes, np.arange(len(chunk)), tracer.boundary, trial[chunk], tracer.options.max_t, tracer.options.min_t
        )
        put_rows(centre, chunk, probes.point + t[chunk, None] * probes.direction)
    if tracer.stats.record_solutions:
        spans, solved = tracer.spans, span[order]
        position = spans.position_at(solved, u[order])
        tracer.stats.solutions.append(Solution("probes", spans.chain[solved], position, spans.length[solved], u[order]))
    site = tracer.sites.canonical(site)
    skip_beside_convex_corners(tracer, span, u, t, status, site, centre)
    return t, status, site, centre


def skip_beside_convex_corners(tracer, span, u, t, status, site, centre):
    """Mark skipped, in place, the solved samples (at parameters ``u`` of spans ``span``; ``t``, status,
    canonical site and disk centre) so close to a convex corner at an end of their edge that their disks
    touch the corner's other segment below the smallest contact the solver sees (``min_t``).

    Such a disk crosses its own chain at once (it is skipped, like a sample at the corner); the solver, not
    seeing that contact, would let it grow through the corner to a far one (a probe 3e-10 from a star's tip
    of 27 degrees: a centre 18 units outside the polygon, fuzz seed 20261210 input 5755).
    """
    row, corner_segment, reach = beside_convex_corners(tracer, span, u)
    if len(row):
        t[row], status[row], site[row] = reach, SKIPPED, tracer.sites.canonical(corner_segment)
        point, _ = tracer.spans.points(span[row], u[row])
        put_rows(centre, row, point + reach[:, None] * tracer.spans.directions(span[row], u[row]))


def beside_convex_corners(tracer, span, u):
    """Of the samples at parameters ``u`` of spans ``span``, those whose disks touch the other segment of a
    convex corner at an end of their edge below ``min_t``: their rows, that segment and the radius of that
    contact (CRS units)."""
    spans, b, sites = tracer.spans, tracer.boundary, tracer.sites
    segment = spans.segment[span]
    edge = spans.kind[span] == EDGE
    min_t = tracer.of(tracer.options.min_t, span)
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
