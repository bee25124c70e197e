"""The IncirCu engine: the centerline between two boundary chains, as incircle centres on the medial axis.

IncirCu (the *Curve of Incircles*; Buczek, M. M., "A new algorithm to compute an unbranched subset of the
medial axis") finds maximal empty disks touching both chains: their centres lie on the medial axis between
the chains, and ordered by where they touch the chains they form one unbranched line. This module is the
orchestrator: it checks the options, works in a local frame, gets the axis points from one of two samplers
and has them ordered into the line (:mod:`.lines`).

- **Adaptive** (default, :mod:`.tracing`): samples start at the boundary's vertices and are refined only
  where the axis can leave the chord between two of them; events of the axis are located exactly (or,
  where the axis bends there by less than the tolerance, proven to need no vertex) and parabolic pieces get
  vertices placed in closed form, so the line stays within ``tolerance`` of the exact medial axis with about
  as many vertices as the boundary has.
- **Fixed** (:mod:`.fixed_sampling`, with ``spacing`` or ``samples_per_chain``): the paper's equidistant
  sampling, e.g. to reproduce its Fig. 4.

Both put every vertex exactly on the medial axis (to floating-point precision); the first contact of each
disk family is computed in closed form by :mod:`.contacts`.
"""

from dataclasses import dataclass, field
from functools import cached_property
from numbers import Real
from typing import Callable, Optional

import numpy as np
from shapely.geometry import LineString

from ._steps import TraceRequest, reporter, run_alone
from .chains import COINCIDENCE_TOLERANCE, clean_chain, ensure_bounding_chains, extent_of, signed_area
from .contacts import Boundary
from .errors import ChainError, Message, OptionError
from .fixed_sampling import DEFAULT_SPACING_PER_WIDTH, MAX_SAMPLES, fixed_axis_points
from .lines import LineRequest
from .polyline import as_coordinates, coordinate_rounding, cumulative_lengths, local_origin, typical_width

#: Default tolerance as a fraction of the chains' typical width (see :func:`default_tolerance`).
DEFAULT_TOLERANCE_PER_WIDTH = 1.0 / 200.0

#: Smallest tolerance, relative to the chains' extent: below it the parabola stations would outnumber what
#: float64 can place distinctly (and what memory holds).
MIN_TOLERANCE = 1e-9

#: Smallest typical width between the chains, relative to their extent: narrower, float64 cannot tell the two
#: sides apart (a disk's contacts are found to about 1e-12 of the extent) and no centerline is traced.
MIN_WIDTH = 1e-11

#: Shares of the tolerance: the chords of the axis's parabolas, and the simplification of the exact polyline.
PARABOLA_SHARE = 0.5
SIMPLIFY_SHARE = 0.5


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
    chains : tuple of two ndarray of shape (k, 2), or None
        The two chains the line lies between (islands joined to them), CRS units: the sides
        :func:`.widths.transects` measures across. None where not kept.
    """

    line: LineString
    radii: np.ndarray
    foot_a: np.ndarray
    foot_b: np.ndarray
    ends_found: bool = False
    notes: tuple = ()
    chains: Optional[tuple] = field(default=None, repr=False)

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
    extent = extent_of(c1, c2)
    return max(DEFAULT_TOLERANCE_PER_WIDTH * _width_or_fallback(chains_width(c1, c2), extent), MIN_TOLERANCE * extent)


def _rounded_up(value):
    """``value`` (positive) rounded up to three significant digits, for advice a user can type.

    >>> _rounded_up(2.0000000001e-09), _rounded_up(2e-09)
    (2.01e-09, 2e-09)
    """
    shown = float(f"{value:.3g}")
    if shown >= value:
        return shown
    step = 10.0 ** (np.floor(np.log10(value)) - 2)
    return float(f"{(np.floor(value / step) + 1) * step:.3g}")


def _automatic_tolerance(frame):
    """The adaptive sampling's tolerance when none is given, CRS units, and a note when it is not the usual one.

    The typical width / 200; when that is finer than float64 can place vertices (``MIN_TOLERANCE`` of the
    extent: a region 1e-7 of its extent wide), ``MIN_TOLERANCE`` of the extent, which the note says.
    """
    usual = DEFAULT_TOLERANCE_PER_WIDTH * frame.default_width
    finest = MIN_TOLERANCE * frame.extent
    if usual >= finest:
        return usual, None
    return finest, Message(
        "note_tolerance_finest",
        width=frame.default_width,
        relative=frame.default_width / frame.extent,
        extent=frame.extent,
        finest=finest,
        minimum=MIN_TOLERANCE,
    )


def _check_width(frame):
    """Raise :class:`ChainError` when the region between the chains is too narrow for float64 (``MIN_WIDTH``)."""
    if frame.default_width < MIN_WIDTH * frame.extent:
        raise ChainError(
            Message(
                "region_too_narrow",
                width=frame.default_width,
                relative=frame.default_width / frame.extent,
                extent=frame.extent,
                minimum=MIN_WIDTH,
            )
        )


def _width_or_fallback(width, extent):
    """The chains' typical ``width``, or a thousandth of their ``extent`` when they enclose no area (CRS units)."""
    return width if width > 0 else 1e-3 * extent


def _length_option(value, name):
    """An optional positive length as a float; None or 0 give None (the default)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, Real):
        raise OptionError(Message("option_not_length", name=name, value=value))
    if not np.isfinite(value) or value < 0:
        raise OptionError(Message("option_bad_length", name=name, value=value))
    return float(value) if value > 0 else None


def _fixed_spacings(spacing, samples_per_chain, chains, lengths, width):
    """The fixed sampling's spacing on each chain, CRS units (``width``: the defaults' width, see ``_LocalChains``)."""
    if samples_per_chain is not None:
        if isinstance(samples_per_chain, bool) or not isinstance(samples_per_chain, Real):
            raise OptionError(Message("samples_not_whole", value=samples_per_chain))
        if not np.isfinite(samples_per_chain) or int(samples_per_chain) < 1:
            raise OptionError(Message("samples_too_few", value=samples_per_chain))
        spacings = [length / (int(samples_per_chain) + 1) for length in lengths]
    else:
        spacings = [spacing or DEFAULT_SPACING_PER_WIDTH * width] * 2
    planned = sum(length / s for length, s in zip(lengths, spacings)) + sum(len(c) for c in chains)
    if planned > MAX_SAMPLES:
        raise OptionError(Message("spacing_too_small", spacing=min(spacings), planned=planned, limit=MAX_SAMPLES))
    return spacings


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
    ChainError, CrossingLinesError
        If the chains are unusable (see :func:`.chains.clean_chain`), cross themselves or each other, or meet
        anywhere but at shared end points (:func:`.chains.ensure_bounding_chains`).
    CenterlineError
        If the line would cross itself (the last guard, as for :func:`.api.polygon_centerline`).
    IncirCuError
        If the chains are too close to carry a line.
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
    chains = _clean_chains(c1, c2)
    ensure_bounding_chains(*chains)
    result = run_alone(
        clean_chains_steps(
            *chains, spacing, samples_per_chain=samples_per_chain, tolerance=tolerance, progress=progress
        )
    )
    # The public functions' last guard; imported here, as api imports this module.
    from .api import _checked

    return _checked(result)


def centerline_steps(c1, c2, spacing=None, *, samples_per_chain=None, tolerance=None, progress=None, region=None):
    """:func:`centerline_from_chains` as steps (see :mod:`._steps`): a generator that yields one
    :class:`._steps.TraceRequest` (adaptive sampling; none with fixed sampling), receives its axis points and
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
        raise OptionError(Message("tolerance_and_spacing"))
    frame = _LocalChains([c1, c2])
    _check_width(frame)
    report = reporter(progress)
    note = None
    if fixed:
        spacings = _fixed_spacings(spacing, samples_per_chain, frame.chains, frame.lengths, frame.default_width)
        points = fixed_axis_points(frame.chains, frame.boundary, frame.side, spacings, *frame.limits, report)
    else:
        if tolerance is None:
            tolerance, note = _automatic_tolerance(frame)
        elif tolerance < MIN_TOLERANCE * frame.extent:
            raise OptionError(
                Message(
                    "tolerance_too_fine",
                    tolerance=tolerance,
                    relative=MIN_TOLERANCE,
                    extent=frame.extent,
                    least=_rounded_up(MIN_TOLERANCE * frame.extent),
                )
            )
        sides = (frame.side, -frame.side)
        points = yield TraceRequest(
            frame.chains, sides, frame.closed, PARABOLA_SHARE * tolerance, *frame.limits, report, frame.rounding
        )
    centre, radius, foot_a, foot_b = yield LineRequest(
        points, frame, None if fixed else SIMPLIFY_SHARE * tolerance, region
    )
    return CenterlineResult(
        line=LineString(centre + frame.origin),
        radii=radius,
        foot_a=foot_a + frame.origin,
        foot_b=foot_b + frame.origin,
        notes=(note,) if note else (),
        chains=(c1, c2),
    )


class _LocalChains:
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
