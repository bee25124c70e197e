"""The IncirCu engine: the centerline between two boundary chains, as incircle centres on the medial axis.

IncirCu (the *Curve of Incircles*; Buczek, M. M., "A new algorithm to compute an unbranched subset of the
medial axis") finds maximal empty disks touching both chains: their centres lie on the medial axis between
the chains, and ordered by where they touch the chains they form one unbranched line. This module is the
orchestrator: it checks the options, works in a local frame, gets the axis points from one of two samplers
and orders them into the line.

- **Adaptive** (default, :mod:`.adaptive`): samples start at the boundary's vertices and are refined only
  where the axis can leave the chord between two of them; events of the axis are located exactly (or,
  where the axis bends there by less than the tolerance, proven to need no vertex) and parabolic pieces get
  vertices placed in closed form, so the line stays within ``tolerance`` of the exact medial axis with about
  as many vertices as the boundary has.
- **Fixed** (:mod:`.fixed_sampling`, with ``spacing`` or ``samples_per_chain``): the paper's equidistant
  sampling, e.g. to reproduce its Fig. 4.

Both put every vertex exactly on the medial axis (to floating-point precision); the first contact of each
disk family is computed in closed form by :mod:`.contacts`.
"""

from dataclasses import dataclass
from functools import cached_property
from numbers import Real
from typing import Callable, Optional

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from .chains import COINCIDENCE_TOLERANCE, clean_chain, extent_of, signed_area
from .contacts import Boundary, rows
from .errors import IncirCuError, OptionError
from .fixed_sampling import DEFAULT_SPACING_PER_WIDTH, MAX_SAMPLES, fixed_axis_points
from .polyline import as_coordinates, coordinate_rounding, cumulative_lengths, local_origin, typical_width
from .steps import TraceRequest, reporter, run_alone

#: Default tolerance as a fraction of the chains' typical width (see :func:`default_tolerance`).
DEFAULT_TOLERANCE_PER_WIDTH = 1.0 / 200.0

#: Relative distance (of the extent) under which two consecutive centres are one point.
DISTINCT_TOLERANCE = 1e-9

#: Smallest tolerance, relative to the chains' extent: below it the parabola stations would outnumber what
#: float64 can place distinctly (and what memory holds).
MIN_TOLERANCE = 1e-9

#: Resolution of the ordering key (a sum of two arc lengths relative to their chains' lengths, 0 to 2):
#: keys closer than this are ties, ordered by the direction of travel.
ORDER_RESOLUTION = 1e-11

#: Shares of the tolerance: the chords of the axis's parabolas, and the simplification of the exact polyline.
PARABOLA_SHARE = 0.5
SIMPLIFY_SHARE = 0.5

#: Most points simplified in one piece: GEOS's Douglas-Peucker slows down far more than linearly on longer
#: lines (a million points: 1.3 s in one piece, 0.1 s in pieces of this size).
SIMPLIFY_PIECE = 32_768

#: Pieces simplified in one GEOS call: their indexed coordinates (about 12 MiB) then reuse freed memory, where
#: those of a million points at once (44 MiB) would take fresh pages every time.
SIMPLIFY_BATCH = 16


@dataclass(frozen=True)
class CenterlineResult:
    """A centerline with the incircle of each of its vertices.

    Attributes
    ----------
    line : LineString
        The centerline, one simple chain from one end to the other, CRS units.
    radii : ndarray of shape (n,)
        Incircle radius at each vertex, CRS units (metres for geographic input); ``0`` at a split point, half
        the gap at an open end.
    foot_a, foot_b : ndarray of shape (n, 2)
        For each vertex, a point where its incircle touches the first and the second chain.
    ends_found : bool
        True when the ends were found automatically rather than given.
    notes : tuple of str
        Things the user should know about this result (e.g. the shape is not elongated).
    """

    line: LineString
    radii: np.ndarray
    foot_a: np.ndarray
    foot_b: np.ndarray
    ends_found: bool = False
    notes: tuple = ()

    @property
    def widths(self):
        """ndarray of shape (n,): local width (incircle diameter) at each vertex, CRS units."""
        return 2.0 * self.radii

    @property
    def length(self):
        """float: length of the centerline, CRS units."""
        return self.line.length


def chains_width(c1, c2):
    """Typical width between two chains: the area between them divided by their mean length.

    Parameters
    ----------
    c1, c2 : ndarray of shape (n, 2)
        The chains, running in the same direction, CRS units.

    Returns
    -------
    float
        CRS units (for two straight banks, their distance).
    """
    area = abs(signed_area(np.concatenate([c1, c2[::-1]])))
    mean_length = 0.5 * (LineString(c1).length + LineString(c2).length)
    return typical_width(area, mean_length)


def default_spacing(c1, c2):
    """Spacing of the fixed sampling when ``samples_per_chain`` is not given: the typical width / 20.

    A polyline through points of an axis of curvature radius ``R`` spaced ``h`` apart deviates from it by
    at most ``h**2 / (8 R)``. The axis of a region of width ``w`` bends no tighter than ``R = w / 2``
    (tighter, the inner bank would fold), so ``h = w / 20`` bounds the deviation by ``w / 1600`` and its
    mean by about ``4e-4 w``: below ``1e-3`` of the width.

    Parameters
    ----------
    c1, c2 : ndarray of shape (n, 2)
        The chains, CRS units.

    Returns
    -------
    float
        Spacing, CRS units.

    Examples
    --------
    >>> import numpy as np
    >>> default_spacing(np.array([[0.0, 0], [100, 0]]), np.array([[0.0, 10], [100, 10]]))
    0.5
    """
    return DEFAULT_SPACING_PER_WIDTH * _width_or_fallback(chains_width(c1, c2), extent_of(c1, c2))


def default_tolerance(c1, c2):
    """Tolerance of the adaptive sampling when none is given: the typical width / 200.

    On a map at scale ``1 : S`` a channel ``w`` wide is drawn ``w / S`` wide; ``w / 200`` of it is then
    below a tenth of a millimetre wherever the channel is drawn less than 2 cm wide, which is below what a
    pen or a screen resolves, and half a percent of the width in every width statistic.

    ``c1``, ``c2``: the chains (``(n, 2)`` arrays, CRS units). Returns the tolerance, CRS units.

    Examples
    --------
    >>> import numpy as np
    >>> default_tolerance(np.array([[0.0, 0], [100, 0]]), np.array([[0.0, 10], [100, 10]]))
    0.05
    """
    return DEFAULT_TOLERANCE_PER_WIDTH * _width_or_fallback(chains_width(c1, c2), extent_of(c1, c2))


def _width_or_fallback(width, extent):
    """The chains' typical ``width``, or a thousandth of their ``extent`` when they enclose no area (CRS units)."""
    return width if width > 0 else 1e-3 * extent


def _length_option(value, name):
    """An optional positive length as a float; None or 0 give None (the default)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, Real):
        raise OptionError(f"{name} must be a number (a length in CRS units), got {value!r}.")
    if not np.isfinite(value) or value < 0:
        raise OptionError(f"{name} must be a positive, finite length in CRS units (or 0 for automatic), got {value!r}.")
    return float(value) if value > 0 else None


def _fixed_spacings(spacing, samples_per_chain, chains, lengths, width):
    """The fixed sampling's spacing on each chain, CRS units (``width``: the defaults' width, see ``_Frame``)."""
    if samples_per_chain is not None:
        if isinstance(samples_per_chain, bool) or not isinstance(samples_per_chain, Real):
            raise OptionError(f"samples_per_chain must be a whole number, got {samples_per_chain!r}.")
        if not np.isfinite(samples_per_chain) or int(samples_per_chain) < 1:
            raise OptionError(f"The number of samples per chain must be at least 1, got {samples_per_chain!r}.")
        spacings = [length / (int(samples_per_chain) + 1) for length in lengths]
    else:
        spacings = [spacing or DEFAULT_SPACING_PER_WIDTH * width] * 2
    planned = sum(length / s for length, s in zip(lengths, spacings)) + sum(len(c) for c in chains)
    if planned > MAX_SAMPLES:
        raise OptionError(
            f"A spacing of {min(spacings):.6g} would need about {planned:.3g} samples (at most "
            f"{MAX_SAMPLES:.3g}); use a larger spacing."
        )
    return spacings


def _distinct(points, tolerance):
    """Mask keeping both ends and every point farther than ``tolerance`` from the point before it.

    The last point is always kept; the kept point before it is dropped when within ``tolerance`` of it.
    """
    step = points[1:] - points[:-1]
    keep = np.empty(len(points), dtype=bool)
    keep[0] = True
    # The steps' lengths into their x column (no second array of the size of the line).
    np.greater(np.hypot(step[:, 0], step[:, 1], out=step[:, 0]), tolerance, out=keep[1:])
    keep[-1] = True
    kept = np.flatnonzero(keep)
    if len(kept) > 2 and np.hypot(*(points[kept[-2]] - points[-1])) <= tolerance:
        keep[kept[-2]] = False
    return keep


def _first_of_each_centre(centres, order, resolution):
    """Sorted positions in ``order`` (indices of ``centres``) of the first of the points sharing one centre (to
    ``resolution``, CRS units).

    A junction of the axis is found from several sides, with different feet and so different places in the
    order; keeping its first place only, the line passes it once.
    """
    # The cells as complex numbers sort by x, then y in one stable sort: the indices
    # np.unique(cells, axis=0, return_index=True) gives, without its slow structured-array path. Gathered,
    # then scaled and rounded in place (one array of 16 bytes per point).
    cells = rows(centres, order)
    cells /= resolution
    np.round(cells, out=cells)
    cells = cells.view(np.complex128).ravel()
    order = np.argsort(cells, kind="stable")
    cells = cells.take(order)
    first = np.ones(len(order), dtype=bool)
    first[1:] = cells[1:] != cells[:-1]
    # The kept indices in ascending order: marked in a mask (linear) rather than sorted.
    kept = np.zeros(len(order), dtype=bool)
    kept[order[first]] = True
    return np.flatnonzero(kept)


def _fewest_vertices(points, tolerance):
    """Mask of the vertices a Douglas-Peucker simplification to ``tolerance`` keeps (the ends among them).

    The kept vertices are a subset of the given ones, so they stay on the medial axis; every dropped vertex
    lies within ``tolerance`` of the chord that replaces it, so the line moves by at most ``tolerance``.
    A long line is simplified in pieces of ``SIMPLIFY_PIECE`` points that share their end vertices (which
    are kept). When the plain simplification crosses itself, GEOS's (slower) topology-preserving one of the
    whole line keeps it simple.
    """
    # Each vertex carries its index as its z: GEOS simplifies in the plane and keeps the z of the vertices it
    # keeps, so the kept ones are known without matching coordinates.
    keep = np.zeros(len(points), dtype=bool)
    last, batch = len(points) - 1, SIMPLIFY_PIECE * SIMPLIFY_BATCH
    for begin in range(0, last, batch):
        _keep_simplified(keep, _pieces(points, begin, min(begin + batch, last)), tolerance)
    if not shapely.is_simple(shapely.linestrings(points.compress(keep, axis=0))):
        line = shapely.simplify(_indexed_line(points, 0, last), tolerance, preserve_topology=True)
        keep[:] = False
        keep[shapely.get_coordinates(line, include_z=True)[:, 2].astype(np.intp)] = True
    return keep


def _restore_leaving_chords(centre, distinct, keep, region, origin):
    """``keep`` with points of ``distinct`` put back until no chord of the simplified line leaves ``region``.

    A chord lies within the simplification tolerance of the axis points it replaces, so it can only leave the
    region where the boundary comes that close to the axis: a bend tighter than the tolerance, a spike
    reaching near the axis. The line between the first and the last axis point (without the stubs from the
    split points, which end on the boundary up to rounding) is tested once; only when ``region`` does not
    cover it are its chords tested, and each one that leaves is split at the point it replaced farthest from
    it (a Douglas-Peucker step), round after round. Should the points put back make the line cross itself,
    every distinct point is kept.

    Parameters
    ----------
    centre : ndarray of shape (n, 2)
        The ordered axis points, in the local frame of ``origin`` (CRS units).
    distinct, keep : ndarray of shape (n,) of bool
        The points before and after the simplification (both keep the two ends and their neighbours).
    region : Polygon
        CRS units, shifted by ``origin`` from the local frame (not modified: it may be the caller's).
    origin : ndarray of shape (2,)
        CRS units.

    Returns
    -------
    ndarray of shape (n,) of bool
    """
    inner = np.flatnonzero(keep)[1:-1]
    if shapely.covers(region, shapely.linestrings(rows(centre, inner) + origin)):
        return keep
    inside = shapely.force_2d(region)
    shapely.prepare(inside)
    keep = keep.copy()
    chords = np.stack([inner[:-1], inner[1:]], axis=1)
    # Distinct points up to each index: a chord replaced points where its ends' counts differ by more than 1.
    count = np.cumsum(distinct)
    while len(chords):
        # Only chords that replaced points can be mended (the others join two neighbouring axis points).
        chords = chords[count.take(chords[:, 1]) - count.take(chords[:, 0]) > 1]
        ends = rows(centre, chords.reshape(-1)).reshape(-1, 2, 2) + origin
        chords = chords[~shapely.covers(inside, shapely.linestrings(ends))]
        split = [_farthest_between(centre, distinct, start, end) for start, end in chords]
        keep[split] = True
        chords = np.concatenate([np.stack([chords[:, 0], split], axis=1), np.stack([split, chords[:, 1]], axis=1)])
    if not shapely.is_simple(shapely.linestrings(centre.compress(keep, axis=0))):
        return distinct
    return keep


def _farthest_between(centre, distinct, start, end):
    """Index of the point of ``distinct`` strictly between ``start`` and ``end`` farthest from the line through
    ``centre[start]`` and ``centre[end]`` (there is one)."""
    between = start + 1 + np.flatnonzero(distinct[start + 1 : end])
    direction = centre[end] - centre[start]
    offset = rows(centre, between) - centre[start]
    return int(between[np.argmax(np.abs(offset[:, 0] * direction[1] - offset[:, 1] * direction[0]))])


def _pieces(points, begin, end):
    """The line through ``points[begin : end + 1]`` as a list of linestrings of ``SIMPLIFY_PIECE`` segments (the
    last one shorter) that share their end vertices, each vertex with its index as its z."""
    # One linestring per piece: shapely's ``indices`` path (one call for all) costs more than the calls it saves.
    return [
        _indexed_line(points, start, min(start + SIMPLIFY_PIECE, end)) for start in range(begin, end, SIMPLIFY_PIECE)
    ]


def _indexed_line(points, begin, end):
    """The linestring through ``points[begin : end + 1]`` (CRS units), each vertex with its index as its z."""
    return shapely.linestrings(_with_index(points, np.arange(begin, end + 1)))


def _keep_simplified(keep, lines, tolerance):
    """Mark in ``keep`` the vertices that the Douglas-Peucker simplification of ``lines`` (their z: the vertices'
    indices) to ``tolerance`` (CRS units) keeps."""
    kept = shapely.get_coordinates(shapely.simplify(lines, tolerance, preserve_topology=False), include_z=True)
    keep[kept[:, 2].astype(np.intp)] = True


def _with_index(points, index):
    """The points ``index`` of ``points`` (an ``(n, 2)`` array, CRS units), with their index as a third column."""
    indexed = np.empty((len(index), 3))
    indexed[:, :2] = rows(points, index)
    indexed[:, 2] = index
    return indexed


def _ordered(points, side, lengths, coincidence):
    """Indices putting the axis points in order along the axis: by where their disks touch the two chains.

    Those arc lengths grow monotonically along the axis between the chains. Points whose feet are the same
    two vertices (two facing reflex corners) tie on them; they lie on the bisector of those vertices,
    ordered by the direction of travel, perpendicular to ``foot_b - foot_a``. Points whose feet are both a
    split point lie on the stub from it: their disks grow away from the first split point and shrink into
    the last, so they are ordered by radius.
    """
    # In place where the values allow: at 10^6 boundary vertices each temporary is a fresh 16 MB array.
    across_x = np.subtract(points.foot_b[:, 0], points.foot_a[:, 0])
    across_y = np.subtract(points.foot_b[:, 1], points.foot_a[:, 1])
    spare = np.hypot(across_x, across_y)
    # Feet one point up to rounding: a split point, where both chains start (0) or end (2). No direction of
    # travel there; the radius orders the points.
    one_foot = spare <= DISTINCT_TOLERANCE * (lengths[0] + lengths[1])
    # The centre's component along the direction of travel, side * (across_y, -across_x).
    crossing = np.multiply(points.centre[:, 0], across_y)
    crossing -= np.multiply(points.centre[:, 1], across_x, out=spare)
    crossing *= side
    # The sum of the relative arc lengths, into the memory of ``across_x`` (no longer needed).
    along = np.divide(points.position_a, max(lengths[0], coincidence), out=across_x)
    along += np.divide(points.position_b, max(lengths[1], coincidence), out=spare)
    if one_foot.any():
        along[one_foot] = np.round(along[one_foot])
        crossing[one_foot] = 0.0
    growing = np.negative(points.radius, out=spare)
    np.copyto(growing, points.radius, where=along < 1.0)
    # Feet at the same two vertices may come from different computations: equal up to rounding.
    along /= ORDER_RESOLUTION
    np.round(along, out=along)
    # np.lexsort((growing, crossing, along)), with the two other keys looked at only where ``along`` ties: a
    # stable sort by ``along``, then each run of ties (contiguous, in input order) sorted by all three keys.
    order = np.argsort(along, kind="stable")
    key = along.take(order, out=across_y, mode="clip")
    tied = np.zeros(len(order), dtype=bool)
    tied[1:] = key[1:] == key[:-1]
    tied[:-1] |= tied[1:]
    if tied.any():
        runs = order[tied]
        order[tied] = runs[np.lexsort((growing[runs], crossing[runs], along[runs]))]
    return order


def _line_ends(chains, closed):
    """The line's two ends: the split points, or the midpoints of the end gaps.

    Returns their centres, radii and both feet, each an array of two rows (start, end).
    """
    foot_a = chains[0][[0, -1]]
    if closed:
        return foot_a, np.zeros(2), foot_a, foot_a
    foot_b = chains[1][[0, -1]]
    radius = np.array([0.5 * np.hypot(*(foot_a[i] - foot_b[i])) for i in (0, 1)])
    return 0.5 * (foot_a + foot_b), radius, foot_a, foot_b


def _with_ends(values, order, ends):
    """``values[order]`` (an array of the axis points) between its two ``ends`` (an array of two rows)."""
    joined = np.empty((len(order) + 2,) + values.shape[1:])
    joined[0], joined[-1] = ends
    # Gathered straight into place; "clip" (the indices are valid) lets take skip its buffered copy.
    values.take(order, axis=0, out=joined[1:-1], mode="clip")
    return joined


def _clean_chains(c1, c2):
    """Both chains as coordinate arrays without zero-length segments (see :func:`.chains.clean_chain`)."""
    chains = [as_coordinates(c1, "first chain"), as_coordinates(c2, "second chain")]
    coincidence = COINCIDENCE_TOLERANCE * extent_of(*chains)
    names = ("first chain", "second chain")
    return [clean_chain(chain, name, coincidence) for chain, name in zip(chains, names)]


def centerline_from_chains(
    c1,
    c2,
    spacing=None,
    *,
    samples_per_chain=None,
    tolerance=None,
    progress: Optional[Callable[[float], bool]] = None,
):
    """Compute the IncirCu centerline between two boundary chains.

    By default the sampling is adaptive: the line is within ``tolerance`` of the exact medial axis between
    the chains, with vertices only where the axis needs them (about as many as the chains have). Give
    ``spacing`` or ``samples_per_chain`` for the paper's fixed sampling instead (denser, slower; what the
    paper's figures use). Either way every vertex lies exactly on the medial axis.

    Parameters
    ----------
    c1, c2 : LineString or array_like of shape (n, 2)
        Chains running in the same direction (zero-length segments are dropped). When they share both end
        points (a polygon split at two points) the centerline runs between those points; otherwise it
        runs between the midpoints of the two end gaps.
    spacing : float, optional
        Fixed sampling: distance between equidistant samples along each chain, CRS units (every vertex is
        sampled as well). None or 0: adaptive sampling.
    samples_per_chain : int, optional
        Fixed sampling with this many equidistant samples on each chain.
    tolerance : float, optional
        Adaptive sampling: the largest distance between the line and the exact medial axis between the
        chains, CRS units. None or 0: :func:`default_tolerance` (the typical width / 200).
    progress : callable, optional
        Called with the fraction done (0 to 1); when it returns False the engine raises
        :class:`Cancelled`.

    Returns
    -------
    CenterlineResult

    Raises
    ------
    OptionError
        If ``spacing``, ``samples_per_chain`` or ``tolerance`` is not a positive finite number, both a
        spacing and a tolerance are given, or the spacing would need more than ``MAX_SAMPLES`` samples.
    IncirCuError
        If the chains are unusable (see :func:`.chains.clean_chain`) or too close to carry a line.
    Cancelled
        If ``progress`` returned False.

    Examples
    --------
    >>> import numpy as np
    >>> bank_a = np.array([[0.0, 0.0], [10.0, 0.0]])
    >>> bank_b = np.array([[0.0, 2.0], [10.0, 2.0]])
    >>> result = centerline_from_chains(bank_a, bank_b)
    >>> result.line.coords[:]
    [(0.0, 1.0), (10.0, 1.0)]
    """
    return run_alone(
        centerline_steps(c1, c2, spacing, samples_per_chain=samples_per_chain, tolerance=tolerance, progress=progress)
    )


def centerline_steps(c1, c2, spacing=None, *, samples_per_chain=None, tolerance=None, progress=None, region=None):
    """:func:`centerline_from_chains` as steps (see :mod:`.steps`): a generator that yields one
    :class:`.steps.TraceRequest` (adaptive sampling; none with fixed sampling), receives its axis points and
    returns the :class:`CenterlineResult`. Raises as :func:`centerline_from_chains` does.

    ``region`` (a polygon, CRS units; None: the region between the chains) is where the adaptive line's
    simplification keeps it: the polygon the chains come from, when their ring is not one (islands bridged).
    """
    return (
        yield from clean_chains_steps(
            *_clean_chains(c1, c2),
            spacing,
            samples_per_chain=samples_per_chain,
            tolerance=tolerance,
            progress=progress,
            region=region,
        )
    )


def clean_chains_steps(c1, c2, spacing=None, *, samples_per_chain=None, tolerance=None, progress=None, region=None):
    """:func:`centerline_steps` for chains :func:`.chains.clean_chain` returned at the chains' coincidence
    distance (those of :func:`.chains.split_polygon` and :func:`.chains.orient_bank_lines`): float arrays of
    shape (n, 2), CRS units, which are not checked or cleaned again.
    """
    spacing = _length_option(spacing, "spacing")
    tolerance = _length_option(tolerance, "tolerance")
    fixed = spacing is not None or samples_per_chain is not None
    if fixed and tolerance is not None:
        raise OptionError("Give either a tolerance (adaptive sampling) or a spacing / sample count (fixed sampling).")
    frame = _Frame([c1, c2])
    report = reporter(progress)
    if fixed:
        spacings = _fixed_spacings(spacing, samples_per_chain, frame.chains, frame.lengths, frame.default_width)
        points = fixed_axis_points(frame.chains, frame.boundary, frame.side, spacings, *frame.limits, report)
    else:
        tolerance = tolerance or DEFAULT_TOLERANCE_PER_WIDTH * frame.default_width
        if tolerance < MIN_TOLERANCE * frame.extent:
            raise OptionError(
                f"The tolerance {tolerance:.6g} is below {MIN_TOLERANCE:g} of the shape's extent "
                f"({frame.extent:.6g}): float64 cannot place vertices that finely. Use at least "
                f"{MIN_TOLERANCE * frame.extent:.6g} (CRS units), or 0 for the automatic tolerance."
            )
        sides = (frame.side, -frame.side)
        points = yield TraceRequest(
            frame.chains, sides, frame.closed, PARABOLA_SHARE * tolerance, *frame.limits, report, frame.rounding
        )
    centre, radius, foot_a, foot_b = _line_through(points, frame, None if fixed else SIMPLIFY_SHARE * tolerance, region)
    return CenterlineResult(
        line=LineString(centre + frame.origin),
        radii=radius,
        foot_a=foot_a + frame.origin,
        foot_b=foot_b + frame.origin,
    )


class _Frame:
    """The chains in a local frame (shifted to their bounding box's centre) and what the samplers need."""

    def __init__(self, chains):
        # Both chains as one ring (the first, then the second backwards) serve the extent, origin and area.
        ring = np.concatenate([chains[0], chains[1][::-1]])
        self.extent = extent_of(ring)
        self.coincidence = COINCIDENCE_TOLERANCE * self.extent
        #: The rounding of the chains' coordinates as given, before the shift, CRS units.
        self.rounding = coordinate_rounding(ring)
        self.origin = local_origin(ring)
        #: Both chains as one ring in the local frame (the region between them), CRS units (shifted in place:
        #: ``ring`` is a new array).
        ring -= self.origin
        self.ring = ring
        first = len(chains[0])
        self.chains = [self.ring[:first], np.ascontiguousarray(self.ring[first:][::-1])]
        self.lengths = [float(cumulative_lengths(c)[-1]) for c in self.chains]
        area = signed_area(self.ring)
        width = typical_width(abs(area), 0.5 * sum(self.lengths))
        #: The width the defaults (spacing, tolerance) are fractions of, CRS units.
        self.default_width = _width_or_fallback(width, self.extent)
        start_gap = np.hypot(*(self.chains[0][0] - self.chains[1][0]))
        end_gap = np.hypot(*(self.chains[0][-1] - self.chains[1][-1]))
        self.closed = bool(start_gap <= self.coincidence and end_gap <= self.coincidence)
        self.side = 1.0 if area >= 0 else -1.0
        #: Typical width (the first trial radius), the largest disk parameter searched and the smallest one
        #: that counts as a contact, CRS units.
        self.limits = (max(width, self.coincidence), 4.0 * self.extent, 1e-12 * self.extent)

    @cached_property
    def boundary(self):
        """The chains' segments (:class:`.contacts.Boundary`), built on first use: a feature traced together
        with others never needs its own."""
        return Boundary(self.chains)


def _line_through(points, frame, simplification, region=None):
    """The line's vertices, radii and feet (local frame) from the axis points, end to end.

    In open mode points outside the region between the chains are dropped; each junction is kept once;
    ``simplification`` (CRS units, None: none) is the Douglas-Peucker tolerance; a chord of the simplified line
    that leaves ``region`` (a polygon, CRS units; None: the region between the chains) gets back the points it
    replaced (see :func:`_restore_leaving_chords`).
    """
    between = None
    if not frame.closed:
        between = Polygon(frame.ring)
        shapely.prepare(between)
        points = points.subset(shapely.intersects_xy(between, points.centre[:, 0], points.centre[:, 1]))
    resolution = DISTINCT_TOLERANCE * frame.extent
    order = _ordered(points, frame.side, frame.lengths, frame.coincidence)
    order = order[_first_of_each_centre(points.centre, order, resolution)]
    ends = _line_ends(frame.chains, frame.closed)
    centre = _with_ends(points.centre, order, ends[0])
    keep = _distinct(centre, resolution)
    if simplification is not None and keep.sum() > 4:
        # The first and last points of the axis proper stay: there the stubs from the split points (radius 0)
        # meet the axis, so a straight channel keeps vertices that carry its width.
        distinct = keep.copy()
        kept = np.flatnonzero(keep)
        inner = _fewest_vertices(rows(centre, kept[1:-1]), simplification)
        keep[kept[2:-2]] = inner[1:-1]
        if region is None:
            local = Polygon(frame.ring) if between is None else between
            keep = _restore_leaving_chords(centre, distinct, keep, local, np.zeros(2))
        else:
            keep = _restore_leaving_chords(centre, distinct, keep, region, frame.origin)
    if keep.sum() < 2:
        raise IncirCuError("The chains are too close together or too short to carry a centerline.")
    # Both ends are always kept (see _distinct): the other values only for the kept points.
    order = order[keep[1:-1]]
    radius, foot_a, foot_b = (
        _with_ends(values, order, end) for values, end in zip((points.radius, points.foot_a, points.foot_b), ends[1:])
    )
    return centre.compress(keep, axis=0), radius, foot_a, foot_b
