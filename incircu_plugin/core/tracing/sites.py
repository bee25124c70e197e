"""Sites: the segments (their straight runs) and vertices a disk can touch first, their order along the
chains, their feet, and the closed-form radius of a disk on a span touching one (docs/tracing.md)."""

import numpy as np

from .._arrays import put_rows, rows
from .spans import EDGE


def site_sequence(boundary, kinds, line_of, chain_end):
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


class Sites:
    """Site arithmetic: which chain a site is on, the site a segment stands for, the sites' order along their
    chains, feet and radii on spans."""

    def __init__(self, boundary, geometry):
        self.boundary = boundary
        self.kinds, self.turns = geometry.vertex_kind, geometry.vertex_turn
        #: Direction and inward normal of every segment's line (its straight run's): a disk in the region
        #: touches a segment from that side of its line.
        self.unit, self.inward = geometry.unit, geometry.normal
        #: Whether each vertex is the first or last of its chain.
        self.chain_end = split_vertices(boundary, np.ones(len(boundary.offset), dtype=bool))
        self.line_of, self.run_end_position = geometry.line_of, geometry.run_end_position
        #: Per chain, its last vertex and the arc length there (CRS units).
        self.chain_last_vertex = chain_end_vertices(boundary)[1]
        self.chain_end_position = boundary.vertex_position[self.chain_last_vertex]
        self.sequence, self.rank = site_sequence(boundary, self.kinds, self.line_of, self.chain_end)
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
            return by_kind(kind, range(4), terms, 3)

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


def radius_at(spans, span, terms, u):
    """Evaluate :meth:`Sites.radius_terms` at ``u``; inf where the site is never touched."""
    a0, a1, a2 = terms
    edge = spans.kind[span] == EDGE
    with np.errstate(divide="ignore", invalid="ignore"):
        on_edge = a0 + u * (a1 + u * a2)
        inverse = a0 + a1 * np.cos(u) + a2 * np.sin(u)
        radius = np.where(edge, on_edge, 1.0 / inverse)
    return np.where(np.isfinite(radius) & (radius >= 0.0), radius, np.inf)


def by_kind(kind, kinds, compute, columns):
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


def split_vertices(boundary, closed):
    """Mask of the vertices that are split points: both ends of every chain whose pair is closed."""
    mask = np.zeros(len(boundary.vertex), dtype=bool)
    first, last = chain_end_vertices(boundary)
    mask[first[closed]] = mask[last[closed]] = True
    return mask


def chain_end_vertices(boundary):
    """The first and the last vertex of every chain (indices in ``boundary.vertex``)."""
    first = np.asarray(boundary.offset) + np.arange(len(boundary.offset))
    return first, np.append(first[1:], len(boundary.vertex)) - 1
