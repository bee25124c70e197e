"""Independent references for the IncirCu core tests: an exact medial-axis oracle and exact distances.

The oracle is the segment Voronoi diagram of Boost.Polygon (through ``pyvoronoi``), which shares no code
with the engine. Boost works on an integer grid, so the boundary is translated to its bounding-box centre
and scaled by a power of two that maps the half-extent to about ``2**30``; the largest rounding of a vertex
is recorded as :attr:`MedialOracle.grid_error`.

The *target set* is the part of the medial axis between the two chains: Voronoi edges inside the region
whose two sites lie one on chain ``a`` and one on chain ``b``. A split point lies on both chains, so edges of
its cell count as well (for a split point on a straight stretch this is the short stub from the split point
to the first maximal disk that touches both long sides). Parabolic edges (between a reflex vertex and a
segment) are sampled densely on the exact parabola so that chords stay within
:attr:`MedialOracle.discretisation_error` of it.

The module also holds the exact point-to-chain distances and the invariant checks shared by the test files.
"""

import math

import numpy as np
import pyvoronoi
import shapely
from shapely.geometry import Polygon

#: Half-extent of the data on the oracle's integer grid (Boost.Polygon takes 32-bit coordinates).
GRID_HALF_EXTENT = 2.0**30

#: Site label of the frame that closes the diagram in open mode.
FRAME_LABEL = 2

#: Most chords one parabolic edge is split into.
MAX_PARABOLA_CHORDS = 20_000

#: Above this many point-segment pairs, :func:`segment_distances` uses a spatial index.
BRUTE_FORCE_PAIRS = 50_000_000

#: Most target samples refined per round of :meth:`MedialOracle.hausdorff_from_target`.
MAX_REFINED = 4_000


def segment_distances(points, chain):
    """Exact distance from each point to a polyline, computed in a translated frame.

    Coordinates are translated to the first vertex of ``chain`` before any arithmetic, so points around
    5e6 lose no more than the rounding of that subtraction (exact when both are within a factor 2).

    Parameters
    ----------
    points : array_like of shape (n, 2)
        CRS units.
    chain : array_like of shape (m, 2)
        Polyline vertices, CRS units (m >= 1).

    Returns
    -------
    ndarray of shape (n,)
        Distances, CRS units.
    """
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    chain = np.asarray(chain, dtype=float).reshape(-1, 2)
    origin = chain[0]
    p = points - origin
    c = chain - origin
    if len(c) == 1:
        return np.hypot(*(p - c[0]).T)
    start, direction = c[:-1], np.diff(c, axis=0)
    squared = np.einsum("ij,ij->i", direction, direction)
    keep = squared > 0
    start, direction, squared = start[keep], direction[keep], squared[keep]
    if len(p) * len(start) > BRUTE_FORCE_PAIRS:
        # Large inputs: GEOS finds the nearest segment (an R-tree), the distance to it is recomputed here.
        segments = shapely.linestrings(np.stack([start, start + direction], axis=1))
        nearest = shapely.STRtree(segments).query_nearest(shapely.points(p), all_matches=False)[1]
        q = p - start[nearest]
        t = np.clip(np.einsum("ij,ij->i", q, direction[nearest]) / squared[nearest], 0.0, 1.0)
        return np.hypot(*(q - t[:, None] * direction[nearest]).T)
    result = np.empty(len(p))
    block = max(1, 4_000_000 // max(len(start), 1))
    for first in range(0, len(p), block):
        q = p[first : first + block, None, :] - start[None, :, :]
        t = np.clip(np.einsum("ijk,jk->ij", q, direction) / squared, 0.0, 1.0)
        away = q - t[..., None] * direction[None, :, :]
        result[first : first + block] = np.sqrt(np.min(np.einsum("ijk,ijk->ij", away, away), axis=1))
    return result


class MedialOracle:
    """The medial axis between two chains from the segment Voronoi diagram (Boost.Polygon).

    Parameters
    ----------
    chain_a, chain_b : array_like of shape (n, 2)
        The two chains, CRS units. In closed mode they share both end points (a polygon split at two
        points); in open mode they are two separate lines.
    region : Polygon, optional
        Where the target set may lie. Default: the polygon ``chain_a + reversed(chain_b)`` (for open mode,
        the area between the lines closed by the two end gaps).
    closed : bool, optional
        Default: True when the chains share both end points.

    Attributes
    ----------
    grid_error : float
        Largest rounding of a boundary vertex to the oracle's grid, CRS units.
    discretisation_error : float
        Largest distance between a parabolic edge and its chords, CRS units.
    error_bound : float
        ``grid_error + discretisation_error`` plus the double rounding at the data's coordinates: how far
        the computed target set may lie from the exact one, CRS units (to first order; a nearly parallel
        pair of sites can amplify the grid's rounding, so tests add their own relative margin).
    segments : ndarray of shape (k, 2, 2)
        The target set as line segments, CRS units.
    stub : ndarray of shape (k,) of bool
        Which segments belong to a split point's cell (points whose nearest boundary point is a split
        point, e.g. the straight stub from a split point on a straight cap to the first maximal disk).
    """

    def __init__(self, chain_a, chain_b, region=None, closed=None):
        chains = [np.asarray(chain_a, dtype=float), np.asarray(chain_b, dtype=float)]
        everything = np.concatenate(chains)
        low, high = everything.min(axis=0), everything.max(axis=0)
        self.extent = float(max(high - low))
        if closed is None:
            closed = bool(np.all(chains[0][0] == chains[1][0]) and np.all(chains[0][-1] == chains[1][-1]))
        self.closed = closed
        self.origin = 0.5 * (low + high)
        # Open mode: a square frame of sites far around the lines (label 2, never part of the target)
        # closes the diagram, so every edge between the lines inside the region is finite. The data then
        # use an eighth of the grid, leaving room for the frame at four half-extents.
        grid_half_extent = GRID_HALF_EXTENT if closed else GRID_HALF_EXTENT / 8.0
        exponent = math.floor(math.log2(grid_half_extent / (0.5 * self.extent)))
        self.scale = 2.0**exponent
        if region is None:
            region = Polygon(np.concatenate([chains[0], chains[1][::-1]]))
        self.region = shapely.Polygon(region)
        shapely.prepare(self.region)

        labels = {}
        sites = []
        rounding = 0.0
        for label, chain in enumerate(chains):
            local = (chain - self.origin) * self.scale
            grid = np.round(local)
            rounding = max(rounding, float(np.max(np.abs(grid - local))) / self.scale)
            grid = grid.astype(np.int64)
            for start, end in zip(grid[:-1], grid[1:]):
                if start[0] == end[0] and start[1] == end[1]:
                    continue
                sites.append((label, (int(start[0]), int(start[1])), (int(end[0]), int(end[1]))))
                labels.setdefault(sites[-1][1], set()).add(label)
                labels.setdefault(sites[-1][2], set()).add(label)
        if not closed:
            half = int(4 * grid_half_extent)
            corners = [(-half, -half), (half, -half), (half, half), (-half, half)]
            for start, end in zip(corners, corners[1:] + corners[:1]):
                sites.append((FRAME_LABEL, start, end))
                labels.setdefault(start, set()).add(FRAME_LABEL)
        self.grid_error = rounding
        self._point_labels = labels
        self._segment_labels = [site[0] for site in sites]

        voronoi = pyvoronoi.Pyvoronoi(1)
        for _, start, end in sites:
            voronoi.AddSegment([list(start), list(end)])
        voronoi.Construct()
        self._check_rounded_sites(sites)
        self._voronoi = voronoi
        self.discretisation_error = 0.0
        self.segments, self.stub = self._target_segments()
        ulp = float(np.spacing(np.max(np.abs(everything))))
        self.error_bound = self.grid_error + self.discretisation_error + 8.0 * ulp
        lines = shapely.linestrings(self.segments - self.origin)
        self._tree = shapely.STRtree(lines)
        self._lines = lines

    @staticmethod
    def _check_rounded_sites(sites):
        """Raise if two rounded segments meet anywhere but at a shared end point (Boost would be wrong)."""
        lines = shapely.linestrings(np.array([[start, end] for _, start, end in sites], dtype=float))
        first, second = shapely.STRtree(lines).query(lines, predicate="intersects")
        pairs = first < second
        for i, j in zip(first[pairs], second[pairs]):
            meeting = shapely.intersection(lines[i], lines[j])
            ends = {sites[i][1], sites[i][2]} & {sites[j][1], sites[j][2]}
            points = {tuple(int(v) for v in xy) for xy in shapely.get_coordinates(meeting)}
            if meeting.geom_type != "Point" or not points <= ends:
                raise ValueError(f"the oracle's input segments {i} and {j} meet at {meeting.wkt[:80]}")

    def _cell_labels(self, cell):
        if cell.contains_segment:
            return {self._segment_labels[cell.site]}
        point = self._voronoi.RetrieveScaledPoint(cell)
        return self._point_labels.get((int(point[0]), int(point[1])), set())

    def _target_segments(self):
        """Target set as (segments, stub flags); stubs are edges of a split point's cell."""
        voronoi = self._voronoi
        edges = voronoi.GetEdges()
        vertices = voronoi.GetVertices()
        cells = voronoi.GetCells()
        pieces, stubs = [], []
        for index, edge in enumerate(edges):
            if edge.twin < index or (edge.start == -1 and edge.end == -1):
                continue
            cell, other = cells[edge.cell], cells[edges[edge.twin].cell]
            labels, other_labels = self._cell_labels(cell), self._cell_labels(other)
            if labels | other_labels != {0, 1}:
                continue
            split_cell = next((c for c, lab in ((cell, labels), (other, other_labels)) if len(lab) == 2), None)
            if not edge.is_primary and split_cell is None:
                continue
            ends = [
                None if vertex == -1 else np.array([vertices[vertex].X, vertices[vertex].Y])
                for vertex in (edge.start, edge.end)
            ]
            if not edge.is_primary:
                # A secondary edge of a split point is a ray through that point, perpendicular to one of
                # its segments; Boost may end it at infinity or at a far vertex. Keep the part inside.
                split = np.asarray(voronoi.RetrieveScaledPoint(split_cell), dtype=float)
                inside = [end is not None and self._grid_point_in_region(end) for end in ends]
                if all(inside):
                    points = np.stack(ends)
                elif any(inside):
                    points = np.stack([ends[inside.index(True)], split])
                else:
                    continue
            elif ends[0] is None or ends[1] is None:
                continue
            elif edge.is_linear:
                points = np.stack(ends)
            else:
                point_cell, segment_cell = (cell, other) if cell.contains_point else (other, cell)
                focus = np.asarray(voronoi.RetrieveScaledPoint(point_cell), dtype=float)
                directrix = np.asarray(voronoi.RetrieveScaledSegment(segment_cell), dtype=float)
                points = self._parabola(focus, directrix, ends[0], ends[1])
            placed = points / self.scale + self.origin
            pieces.append(np.stack([placed[:-1], placed[1:]], axis=1))
            stubs.append(np.full(len(points) - 1, split_cell is not None))
        if not pieces:
            return np.empty((0, 2, 2)), np.empty(0, dtype=bool)
        segments = np.concatenate(pieces)
        stub = np.concatenate(stubs)
        keep = np.hypot(*(segments[:, 1] - segments[:, 0]).T) > 0
        segments, stub = segments[keep], stub[keep]
        if self.closed:
            # Edges never cross the boundary (it is made of sites): their midpoint says on which side they are.
            inside = self._in_region(segments.mean(axis=1))
            return segments[inside], stub[inside]
        # Open mode: the end gaps are not sites, so an edge may cross them; clip the edges that do.
        start_in, end_in = self._in_region(segments[:, 0]), self._in_region(segments[:, 1])
        whole = start_in & end_in
        crossing = shapely.linestrings(segments[~whole])
        clipped = shapely.get_parts(shapely.intersection(crossing, self.region))
        clipped = clipped[shapely.get_type_id(clipped) == 1]
        pieces = [segments[whole]]
        for line in clipped:
            coords = shapely.get_coordinates(line)
            pieces.append(np.stack([coords[:-1], coords[1:]], axis=1))
        return np.concatenate(pieces), np.zeros(sum(len(p) for p in pieces), dtype=bool)

    def _in_region(self, points):
        """Mask of the points in the region or within the grid's rounding of it.

        (A GEOS buffer by a distance below the coordinates' precision comes back empty, so the margin is
        applied to distances instead.)
        """
        margin = 4.0 * self.grid_error + 1e-12 * self.extent
        points = shapely.points(np.asarray(points).reshape(-1, 2))
        inside = shapely.covers(self.region, points)
        outside = np.flatnonzero(~inside)
        inside[outside] = shapely.distance(self.region, points[outside]) <= margin
        return inside

    def _grid_point_in_region(self, point):
        return bool(self._in_region(np.asarray(point, dtype=float) / self.scale + self.origin)[0])

    def _parabola(self, focus, directrix, start, end):
        """Points on the parabola (focus, directrix line) between two of its points, grid units.

        In a frame with the directrix as the t axis the parabola is ``h(t) = ((t - tf)**2 + hf**2) /
        (2 hf)``. A chord over ``[t, t + dt]`` deviates from it by exactly ``dt**2 / (8 sqrt(hf**2 +
        s**2))`` with ``s = |t + dt/2 - tf|``, so stations uniform in ``sqrt(s)`` (far from the apex) and in
        ``s`` (near it) keep every chord within the tolerance, also when the focus almost lies on the
        directrix.
        """
        anchor = directrix[0]
        unit = (directrix[1] - directrix[0]) / np.hypot(*(directrix[1] - directrix[0]))
        normal = np.array([-unit[1], unit[0]])
        focus_t, focus_h = (focus - anchor) @ unit, (focus - anchor) @ normal
        if focus_h < 0:
            normal, focus_h = -normal, -focus_h
        t0, t1 = (start - anchor) @ unit, (end - anchor) @ unit
        tolerance = 1e-9 * self.extent * self.scale
        s0, s1 = t0 - focus_t, t1 - focus_t
        stations = [s0, s1]
        for low, high in ((min(s0, s1), max(s0, s1)),):
            for sign in (1.0, -1.0):
                # The part of [low, high] on one side of the apex, as distances from it.
                a, b = (max(low, 0.0), high) if sign > 0 else (max(-high, 0.0), -low)
                if b <= a:
                    continue
                near_step = math.sqrt(8.0 * tolerance * focus_h)
                near_end = min(b, focus_h)
                if near_end > a:
                    count = min(math.ceil((near_end - a) / near_step), MAX_PARABOLA_CHORDS)
                    stations.extend(sign * np.linspace(a, near_end, count + 1))
                far_start = max(a, focus_h)
                if b > far_start:
                    root_step = math.sqrt(2.0 * tolerance)
                    count = min(math.ceil((math.sqrt(b) - math.sqrt(far_start)) / root_step), MAX_PARABOLA_CHORDS)
                    stations.extend(sign * np.linspace(math.sqrt(far_start), math.sqrt(b), count + 1) ** 2)
        s = np.unique(np.clip(np.asarray(stations, dtype=float), min(s0, s1), max(s0, s1)))
        if s0 > s1:
            s = s[::-1]
        middle = 0.5 * np.abs(s[:-1] + s[1:])
        deviation = np.diff(s) ** 2 / (8.0 * np.hypot(focus_h, middle))
        if deviation.size:  # a zero-length edge (both ends at one station) has no chord
            self.discretisation_error = max(self.discretisation_error, float(deviation.max()) / self.scale)
        t = s + focus_t
        h = (s**2 + focus_h**2) / (2.0 * focus_h)
        points = anchor + t[:, None] * unit + h[:, None] * normal
        points[0], points[-1] = start, end
        return points

    def distance(self, points):
        """Distance from each point to the target set.

        Parameters
        ----------
        points : array_like of shape (n, 2)
            CRS units.

        Returns
        -------
        ndarray of shape (n,)
            CRS units.
        """
        local = np.asarray(points, dtype=float).reshape(-1, 2) - self.origin
        _, distances = self._tree.query_nearest(shapely.points(local), return_distance=True, all_matches=False)
        return distances

    def hausdorff_from_target(self, line, resolution=None):
        """Directed Hausdorff distance from the target set to a line: the farthest target point's distance.

        The target set is sampled coarsely, then refined around every sample that could still hide a
        larger distance (the distance to a line is 1-Lipschitz: a point within ``h`` of a sample is at most
        ``h`` farther), until the sampling step is below ``resolution``.

        Parameters
        ----------
        line : LineString or array_like of shape (n, 2)
            CRS units.
        resolution : float, optional
            The result is a lower bound exact to ``resolution``, CRS units; default ``1e-7`` of the extent.

        Returns
        -------
        float
            CRS units.
        """
        coords = shapely.get_coordinates(line) if isinstance(line, shapely.Geometry) else np.asarray(line, dtype=float)
        resolution = resolution or 1e-7 * self.extent
        local = coords - self.origin
        tree = shapely.STRtree(shapely.linestrings(np.stack([local[:-1], local[1:]], axis=1)))

        def distances(points):
            return tree.query_nearest(shapely.points(points), return_distance=True, all_matches=False)[1]

        start = self.segments[:, 0] - self.origin
        direction = self.segments[:, 1] - self.segments[:, 0]
        lengths = np.hypot(*direction.T)
        step = max(1e-3 * self.extent, resolution)
        counts = np.ceil(lengths / step).astype(int) + 1
        segment = np.repeat(np.arange(len(lengths)), counts)
        first = np.repeat(np.cumsum(counts) - counts, counts)
        along = (np.arange(counts.sum()) - first) / np.repeat(counts - 1, counts) * lengths[segment]
        best = 0.0
        while True:
            d = distances(start[segment] + (along / lengths[segment])[:, None] * direction[segment])
            best = max(best, float(d.max()))
            if step <= resolution:
                return best
            # Only target points within `step` of a sample whose distance is above best - step can beat best.
            # Where the distance is flat, many samples qualify; the farthest MAX_REFINED ones are refined
            # (any other can beat best by at most step / 2, which is then the result's accuracy).
            keep = np.flatnonzero(d >= best - step)
            if len(keep) > MAX_REFINED:
                keep = keep[np.argsort(d[keep])[-MAX_REFINED:]]
            fine = step / 16.0
            offsets = np.arange(-16, 17) * fine
            segment = np.repeat(segment[keep], len(offsets))
            along = np.clip(np.repeat(along[keep], len(offsets)) + np.tile(offsets, len(keep)), 0.0, lengths[segment])
            step = fine

    @property
    def length(self):
        """float: total length of the target set, CRS units."""
        return float(np.sum(np.hypot(*(self.segments[:, 1] - self.segments[:, 0]).T)))


def check_centerline(result, chain_a, chain_b, region, ends, relative=1e-9):
    """Assert the invariants of an IncirCu result against independent exact computations.

    Checked on every interior vertex ``v`` with radius ``r`` (tolerance ``relative * extent`` plus the
    double rounding at the data's coordinates):

    - ``|dist(v, chain_a) - r|`` and ``|dist(v, chain_b) - r|`` within the tolerance;
    - the circle is empty: no boundary point closer than ``r * (1 - relative)`` (minus the rounding);
    - the feet lie on their chains at distance ``r`` from ``v`` (a disk touching a chain at several points,
      e.g. at a junction of the medial axis, may report any of them, so the feet's order is not checked
      here: the line's simplicity and the oracle tests cover the order);
    - the line is simple, has no repeated vertex, lies in ``region`` (buffered by the tolerance) and runs
      from ``ends[0]`` to ``ends[1]`` (either direction, to the tolerance).

    Parameters
    ----------
    result : CenterlineResult
    chain_a, chain_b : ndarray of shape (n, 2)
        The chains, CRS units (independently built, not the engine's).
    region : Polygon
    ends : sequence of two (x, y)
    relative : float
        Relative tolerance (of the extent).

    Returns
    -------
    dict
        Measured worst values (``equidistance``, ``empty_circle``, ``feet``) in CRS units, for reports.
    """
    coords = np.asarray(result.line.coords)[:, :2]
    radii = np.asarray(result.radii, dtype=float)
    chains = [np.asarray(chain_a, dtype=float), np.asarray(chain_b, dtype=float)]
    everything = np.concatenate(chains)
    extent = float(max(everything.max(axis=0) - everything.min(axis=0)))
    ulp = float(np.spacing(np.max(np.abs(everything))))
    tolerance = relative * extent + 16.0 * ulp
    assert len(coords) >= 2, "the centerline has fewer than 2 vertices"
    assert radii.shape == (len(coords),), f"one radius per vertex: {radii.shape} radii for {len(coords)} vertices"
    assert np.asarray(result.foot_a).shape == (len(coords), 2)
    assert np.asarray(result.foot_b).shape == (len(coords), 2)

    given = np.asarray(ends, dtype=float)
    forward = max(np.hypot(*(coords[0] - given[0])), np.hypot(*(coords[-1] - given[1])))
    backward = max(np.hypot(*(coords[0] - given[1])), np.hypot(*(coords[-1] - given[0])))
    assert min(forward, backward) <= tolerance, (
        f"the line runs {coords[0].tolist()} -> {coords[-1].tolist()}, expected between {given[0].tolist()} and {given[1].tolist()}"
    )

    interior = slice(1, len(coords) - 1)
    vertices, r = coords[interior], radii[interior]
    measured = {"equidistance": 0.0, "empty_circle": 0.0, "feet": 0.0}
    if len(vertices):
        distance_a = segment_distances(vertices, chains[0])
        distance_b = segment_distances(vertices, chains[1])
        error = np.maximum(np.abs(distance_a - r), np.abs(distance_b - r))
        worst = int(np.argmax(error))
        measured["equidistance"] = float(error[worst])
        assert error[worst] <= tolerance, (
            f"vertex {worst + 1} = {vertices[worst].tolist()} with r = {r[worst]!r}: dist to chain a {distance_a[worst]!r}, to chain b {distance_b[worst]!r} (tolerance {tolerance:.3g})"
        )
        nearest = np.minimum(distance_a, distance_b)
        intrusion = r * (1.0 - relative) - 16.0 * ulp - nearest
        measured["empty_circle"] = float(max(0.0, np.max(r - nearest)))
        assert np.all(intrusion <= 0.0), f"circle of vertex {int(np.argmax(intrusion)) + 1} is not empty"

        feet_pair = [np.asarray(result.foot_a, dtype=float)[interior], np.asarray(result.foot_b, dtype=float)[interior]]
        straight = segment_distances(feet_pair[0], chains[0]).sum() + segment_distances(feet_pair[1], chains[1]).sum()
        crossed = segment_distances(feet_pair[0], chains[1]).sum() + segment_distances(feet_pair[1], chains[0]).sum()
        if crossed < straight:
            # The engine's first chain is this check's chain b: compare each foot with its own chain.
            feet_pair = feet_pair[::-1]
        for name, feet, chain in (("a", feet_pair[0], chains[0]), ("b", feet_pair[1], chains[1])):
            off_chain = segment_distances(feet, chain)
            reach = np.abs(np.hypot(*(feet - vertices).T) - r)
            measured["feet"] = max(measured["feet"], float(off_chain.max()), float(reach.max()))
            assert off_chain.max() <= tolerance, f"a foot on chain {name} lies {off_chain.max():.3g} off it"
            worst = int(np.argmax(reach))
            assert reach[worst] <= tolerance, (
                f"foot {feet[worst].tolist()} on chain {name} is {float(np.hypot(*(feet[worst] - vertices[worst])))!r} from its vertex {vertices[worst].tolist()}, radius {r[worst]!r}"
            )

    steps = np.hypot(*np.diff(coords, axis=0).T)
    assert steps.min() > 0.0, "the line repeats a vertex"
    assert result.line.is_simple, "the line is not simple"
    region = shapely.Polygon(region)
    shapely.prepare(region)
    outside = shapely.LineString() if region.covers(result.line) else result.line.difference(region)
    if not outside.is_empty:
        # Vertices and midpoints of the parts outside; a GEOS buffer by a distance below the coordinates'
        # precision would come back empty, so distances are compared instead.
        parts = shapely.get_parts(outside)
        coords = np.concatenate(
            [
                shapely.get_coordinates(parts),
                shapely.get_coordinates(shapely.line_interpolate_point(parts, 0.5, normalized=True)),
            ]
        )
        excursion = float(np.max(shapely.distance(region, shapely.points(coords))))
        assert excursion <= tolerance, (
            f"the line leaves the region by {excursion:.3g} (length {outside.length:.3g} outside)"
        )
    return measured


def assert_within_tolerance(result, chain_a, chain_b, region, tolerance, oracle=None, near_ends=None):
    """Vertices on the oracle's axis and the Hausdorff distance between line and axis within ``tolerance``.

    ``near_ends``: target points within this distance of these points are not compared (open mode: the
    line starts at the end gap's midpoint by definition, where the axis crosses the gap elsewhere).
    """
    oracle = oracle or MedialOracle(chain_a, chain_b, region=region)
    coords = np.asarray(result.line.coords)[:, :2]
    if len(coords) > 2:
        distance = oracle.distance(coords[1:-1])
        limit = 1e-7 * oracle.extent + 4.0 * oracle.error_bound
        worst = int(np.argmax(distance))
        assert distance[worst] <= limit, f"vertex {coords[worst + 1].tolist()} is {distance[worst]:.3g} off the axis"
    step = tolerance / 10.0
    dense = shapely.get_coordinates(shapely.segmentize(result.line, step))
    if near_ends is not None:
        dense = dense[away_from(dense, *near_ends)]
    away = oracle.distance(dense).max()
    assert away <= tolerance + step, f"the line is {away:.3g} from the axis, tolerance {tolerance:.3g}"
    if near_ends is None:
        missed = oracle.hausdorff_from_target(result.line, step)
    else:
        targets = shapely.get_coordinates(shapely.segmentize(shapely.multilinestrings(list(oracle.segments)), step))
        targets = targets[away_from(targets, *near_ends)]
        missed = float(shapely.distance(result.line, shapely.points(targets)).max())
    assert missed <= tolerance + step, f"the axis is {missed:.3g} from the line, tolerance {tolerance:.3g}"


def away_from(points, ends, distance):
    """Mask of the points farther than ``distance`` from every point of ``ends``."""
    return np.min([np.hypot(*(points - end).T) for end in ends], axis=0) > distance
