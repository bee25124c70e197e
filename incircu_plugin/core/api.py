"""Public entry points: the centerline of a polygon, of a multipart polygon, and between two lines."""

from dataclasses import dataclass, fields, replace
from functools import partial
from typing import Optional

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon

from ._many import compute, detached, is_many, one_or_many, per_geometry
from ._steps import EndsRequest, run_alone
from .caps import check_end_cap, run_out_ends
from .chains import (
    COINCIDENCE_TOLERANCE,
    extent_of,
    find_self_crossing,
    orient_bank_lines,
    polygon_without_folds,
    split_checked_polygon,
    validate_polygon,
)
from .ends import COMPACT, END_RULES, STAR
from .engine import CenterlineResult, centerline_steps, clean_chains_steps
from .errors import CenterlineError, IncirCuError, InvalidGeometryError, Message, SplitPointError, format_point
from .islands import bridge_islands
from .polyline import cumulative_lengths, typical_width
from .rings import RING_NOTE, loop_is_main_feature, ring_centerline_steps
from .validation import check_coordinates, split_point_coordinates, tolerance_length

#: Largest distance of a returned line's vertex outside its polygon, relative to the polygon's extent.
OUTSIDE_TOLERANCE = 1e-7

#: How islands (holes) are treated: the line goes around each island on the side of the wider channel,
#: or islands are ignored (the line may cross them).
ISLAND_MODES = ("main_channel", "ignore")

#: Share of a polygon's progress taken by finding its ends automatically.
ENDS_PROGRESS_SHARE = 0.2

#: Ratio of the longer bank line's length to the shorter's above which :func:`lines_centerline` notes that the
#: longer runs beyond the other. Banks facing each other over their whole length differ by less: in a bend of
#: centerline radius R and width w the outer bank is (R + w/2) / (R - w/2) times the inner, 2 at the tightest
#: river bends (R = 1.5 w; R/w is rarely below 2), and a reach of alternating bends brings the ratio back
#: towards 1. Above it the region is closed by the long straight gaps between the lines' ends.
BANK_LENGTH_RATIO = 2.0

#: Smallest typical width (area over half the perimeter) of a polygon whose ends are found automatically,
#: relative to its extent: the skeleton is built in a frame of unit diagonal, where a narrower polygon's two
#: sides are closer than its triangulation resolves (a box 1e-10 of its length wide got ends 0.2 of its length
#: apart).
ENDS_MIN_WIDTH = 1e-9

#: The fields a :class:`PolygonCenterlineResult` takes over from its :class:`CenterlineResult`.
_RESULT_FIELDS = tuple(field.name for field in fields(CenterlineResult) if field.init)


def check_island_mode(islands):
    """Raise :class:`IncirCuError` unless ``islands`` is one of :data:`ISLAND_MODES`."""
    if islands not in ISLAND_MODES:
        raise IncirCuError(Message("unknown_island_mode", mode=islands, choices=", ".join(ISLAND_MODES)))


def polygon_centerline(
    polygon,
    split_points=None,
    *,
    spacing=None,
    samples_per_chain=None,
    tolerance=None,
    snap_tolerance=None,
    islands="main_channel",
    end_rule="main_stem",
    guide=None,
    end_cap="axis",
    progress=None,
):
    """Centerline of a polygon between two points of its boundary; of each polygon of an array.

    Given an array-like of polygons (list, numpy array, GeoSeries), every other argument is one value for all
    or one per polygon (``split_points``: None, or one sequence or None per polygon); the polygons share their
    tracing in batches, and each result is the same, to the last bit, as the polygon's alone.

    Parameters
    ----------
    polygon : Polygon or array_like of Polygon
        A valid polygon, CRS units; holes are islands.
    split_points : sequence of two Point or (x, y), optional
        The ends of the centerline, on the exterior ring. None or empty: found by :func:`.ends.find_ends`.
        One point: it is the start, and the end is whichever of :func:`.ends.find_ends`' two ends lies
        farther from it (the far end of the main stem).
    spacing, samples_per_chain : float or int, optional
        The paper's fixed sampling: distance between samples along the boundary (CRS units), or this many
        equidistant samples on each side. None or 0: adaptive sampling (the default).
    tolerance : float, optional
        Adaptive sampling: largest distance between the line and the exact medial axis, CRS units; None
        or 0: the typical width / 200 (:func:`default_tolerance`).
    snap_tolerance : float, optional
        Largest distance between a split point and the exterior ring, CRS units; default 1e-6 of the extent.
    islands : {"main_channel", "ignore"}
        ``"main_channel"``: the line passes every island on the side of the wider channel; ``"ignore"``: holes
        are filled, for the automatic ends too.
    end_rule : {"main_stem", "longest_path"}
        Automatic ends (:mod:`.ends`): the skeleton path sweeping the largest area, or the longest one.
    guide : LineString or MultiLineString, optional
        A rough line of the river, CRS units (gaps, offsets and tributaries are fine): without split points,
        the ends are those of the skeleton path that best covers it.
    end_cap : {"axis", "runout"}
        How the line crosses each end cap: ``"axis"``, the exact medial axis to the end; ``"runout"``, straight
        from where the incircle first spans the channel to the split point, or for automatic ends to where
        the axis continued meets the outline (:func:`.caps.run_out_ends`; not on the medial axis).
    progress : callable, optional
        See :func:`centerline_from_chains`; for an array, called with the fraction of all polygons done.

    Returns
    -------
    PolygonCenterlineResult, or a list
        ``foot_a`` lies on the boundary counter-clockwise from the first split point; ``ends_from`` says
        where the ends came from. For an array, per polygon in input order its result or the exception it
        raised (without traceback).

    Raises
    ------
    InvalidGeometryError, SplitPointError, OptionError, ChainError, CenterlineError, IncirCuError
        For one polygon. :class:`Cancelled` when ``progress`` returned False.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> result = polygon_centerline(box(0, 0, 100, 10), [(0, 5), (100, 5)], spacing=1.0)
    >>> result.line.coords[0], result.line.coords[-1], float(result.widths.max())
    ((0.0, 5.0), (100.0, 5.0), 10.0)
    >>> many = polygon_centerline([box(0, 0, 100, 10), box(0, 0, 1, 1).buffer(-1)], [[(0, 5), (100, 5)], None])
    >>> round(many[0].line.length, 6), type(many[1]).__name__
    (100.0, 'InvalidGeometryError')
    """
    options = {"spacing": spacing, "samples_per_chain": samples_per_chain, "tolerance": tolerance, "guide": guide}
    options.update(snap_tolerance=snap_tolerance, islands=islands, end_rule=end_rule, end_cap=end_cap)
    return one_or_many(_polygon_centerline_steps, polygon, split_points, options, progress)


def _polygon_centerline_steps(
    polygon,
    split_points=None,
    *,
    spacing=None,
    samples_per_chain=None,
    tolerance=None,
    snap_tolerance=None,
    islands="main_channel",
    end_rule="main_stem",
    guide=None,
    end_cap="axis",
    progress=None,
):
    """:func:`polygon_centerline` as steps (see :mod:`._steps`): a generator yielding an
    :class:`._steps.EndsRequest` when it has no split points, then the adaptive tracing's
    :class:`._steps.TraceRequest`, and returning the :class:`PolygonCenterlineResult`; raises as
    :func:`polygon_centerline` does. Run it with :func:`._steps.run_together` (what an array runs) or
    :func:`._steps.run_alone`.
    """
    validate_polygon(polygon)
    check_island_mode(islands)
    check_end_cap(end_cap)
    if end_rule not in END_RULES:
        raise IncirCuError(Message("unknown_end_rule", rule=end_rule, choices=", ".join(END_RULES)))
    snap_tolerance = tolerance_length(snap_tolerance, "snap_tolerance")
    split_points = split_point_coordinates(split_points)
    polygon, spikes = polygon_without_folds(polygon)
    notes = [spikes] if spikes else []
    ends_found = len(split_points) == 0
    ends_from = "split_points"
    region = polygon if islands == "main_channel" else Polygon(polygon.exterior)
    if len(split_points) < 2:
        _check_ends_width(region)
        ends = yield from _automatic_ends(
            region, end_rule, guide, _progress_share(progress, 0.0, ENDS_PROGRESS_SHARE), notes
        )
        progress = _progress_share(progress, ENDS_PROGRESS_SHARE, 1.0)
        if ends is None:
            result = yield from ring_centerline_steps(
                region, spacing, samples_per_chain=samples_per_chain, tolerance=tolerance, progress=progress
            )
            values = {name: getattr(_checked(result, region), name) for name in _RESULT_FIELDS}
            ring_note = Message("note_ring_point_unused") if len(split_points) else RING_NOTE
            values.update(ends_found=True, notes=(*notes, ring_note, *result.notes), ends_from="automatic")
            return PolygonCenterlineResult(**values)
        found = split_point_coordinates((ends.start, ends.end))
        if len(split_points) == 1:
            # The given point is one end; the other is the end of the main stem farther from it.
            farther = int(np.argmax(np.hypot(*(found - split_points[0]).T)))
            split_points = np.concatenate([split_points, found[farther : farther + 1]])
            ends_from = "split_points_and_automatic"
        else:
            split_points = found
            ends_from = "guide" if ends.guided else "automatic"
    c1, c2 = split_checked_polygon(polygon, split_points, snap_tolerance)
    steps = clean_chains_steps
    if islands == "main_channel" and polygon.interiors:
        c1, c2 = bridge_islands(c1, c2, [shapely.get_coordinates(ring) for ring in polygon.interiors])
        steps = centerline_steps
    result = yield from steps(
        c1, c2, spacing, samples_per_chain=samples_per_chain, tolerance=tolerance, progress=progress, region=region
    )
    if end_cap == "runout":
        result = run_out_ends(result, region, move_ends=ends_found)
    result = _checked(result, region)
    values = {name: getattr(result, name) for name in _RESULT_FIELDS}
    values.update(ends_found=ends_found, notes=(*notes, *result.notes), ends_from=ends_from)
    return PolygonCenterlineResult(**values)


def _check_ends_width(polygon):
    """Raise :class:`InvalidGeometryError` when a polygon is too thin for its ends to be found
    (``ENDS_MIN_WIDTH``), naming its width."""
    extent = extent_of(shapely.get_coordinates(polygon.exterior))
    width = typical_width(polygon.area, 0.5 * polygon.length)
    if width < ENDS_MIN_WIDTH * extent:
        raise InvalidGeometryError(
            Message("ends_too_narrow", width=width, relative=width / extent, extent=extent, minimum=ENDS_MIN_WIDTH)
        )


def _automatic_ends(polygon, end_rule, guide, progress, notes):
    """Find a polygon's ends (a step yielding an :class:`._steps.EndsRequest`, answered by :func:`.ends.find_ends`
    or, in a batch, by :func:`.ends.find_ends_together`); append what the user should know to ``notes``.

    Returns None when the polygon is a ring whose centerline is the loop around its hole (see :mod:`.rings`).

    Raises
    ------
    SplitPointError
        When the two ends coincide (the shape has no clear ends).
    """
    ends = yield EndsRequest(polygon, end_rule, guide, progress)
    if loop_is_main_feature(polygon, ends):
        return None
    if ends.start.distance(ends.end) <= COINCIDENCE_TOLERANCE * extent_of(shapely.get_coordinates(polygon)):
        raise SplitPointError(Message("ends_coincide", point=format_point(ends.start.coords[0])))
    if guide is not None and not ends.guided:
        notes.append(Message("note_guide_far"))
    if ends.kind == STAR:
        notes.append(Message("note_star"))
    elif ends.kind == COMPACT:
        notes.append(Message("note_compact"))
    elif not ends.elongated:
        notes.append(Message("note_not_elongated"))
    return ends


@dataclass(frozen=True)
class PolygonCenterlineResult(CenterlineResult):
    """A polygon's centerline (see :class:`CenterlineResult`) and where its ends came from.

    Attributes
    ----------
    ends_from : {"split_points", "guide", "automatic", "split_points_and_automatic"}
        The given split points, the skeleton path following a guide line, the automatic end rule, or one
        given split point and the far end of the main stem.
    """

    ends_from: str = "split_points"


def lines_centerline(
    line_a, line_b, *, spacing=None, samples_per_chain=None, tolerance=None, end_cap="axis", progress=None
):
    """Centerline between two lines, such as the two banks of a river.

    The lines are oriented so their starts face each other; the centerline runs from the midpoint of the
    gap between their starts to the midpoint of the gap between their ends.

    Parameters
    ----------
    line_a, line_b : LineString or array_like of shape (n, 2), or array_like of LineString
        The two lines, CRS units; they must not cross or touch. Arrays of lines give one centerline per
        pair (a single line on one side is paired with each line of the other), as :func:`polygon_centerline`
        does for an array of polygons.
    spacing, samples_per_chain, tolerance, progress
        See :func:`polygon_centerline`.
    end_cap : {"axis", "runout"}
        ``"runout"``: straight from the first incircle touching neither line's end vertex to the middle of
        the gap (see :func:`.caps.run_out_ends`); ``"axis"``: the exact axis, which bulges where the gap is
        slanted.

    Returns
    -------
    CenterlineResult, or a list
        ``foot_a`` lies on ``line_a``, ``foot_b`` on ``line_b``. For arrays, per pair its result or the
        exception it raised.

    Raises
    ------
    InvalidGeometryError, OptionError, ChainError, CrossingLinesError, CenterlineError

    Examples
    --------
    >>> result = lines_centerline([(0, 0), (100, 0)], [(100, 8), (0, 8)], spacing=1.0)
    >>> result.line.coords[0], float(result.radii.max())
    ((0.0, 4.0), 4.0)
    """
    options = {"spacing": spacing, "samples_per_chain": samples_per_chain, "tolerance": tolerance, "end_cap": end_cap}
    if not (_nonempty_many(line_a) or _nonempty_many(line_b)):
        return run_alone(_lines_centerline_steps(line_a, line_b, **options, progress=progress))
    lines_a, lines_b = _lines_per_pair(line_a, line_b)
    per_element = {name: per_geometry(value, len(lines_a), name) for name, value in options.items()}
    return compute(_lines_centerline_steps, list(zip(lines_a, lines_b)), per_element, progress)


def _nonempty_many(line):
    """Whether ``line`` is an array of lines: an empty list is an empty line (no coordinates)."""
    return is_many(line) and len(list(line)) > 0


def _lines_per_pair(line_a, line_b):
    """Both arguments of :func:`lines_centerline` as lists of one line per pair (a single line repeated)."""
    count = len(list(line_a if _nonempty_many(line_a) else line_b))
    return [
        per_geometry(list(line) if _nonempty_many(line) else [line] * count, count, name)
        for line, name in ((line_a, "line_a"), (line_b, "line_b"))
    ]


def _lines_centerline_steps(
    line_a, line_b, *, spacing=None, samples_per_chain=None, tolerance=None, end_cap="axis", progress=None
):
    """:func:`lines_centerline` as steps (see :func:`_polygon_centerline_steps`); returns the
    :class:`CenterlineResult`, whose ``notes`` say when one line is more than :data:`BANK_LENGTH_RATIO` times
    as long as the other (see :func:`bank_length_note`).
    """
    check_end_cap(end_cap)
    notes = []
    c1, c2 = orient_bank_lines(line_a, line_b, notes)
    result = yield from clean_chains_steps(
        c1, c2, spacing, samples_per_chain=samples_per_chain, tolerance=tolerance, progress=progress
    )
    if end_cap == "runout":
        result = run_out_ends(result, Polygon(np.concatenate([c1, c2[::-1]])), open_ends=True)
    note = bank_length_note(c1, c2)
    return replace(_checked(result), notes=(*notes, *result.notes, *([note] if note else [])))


def bank_length_note(line_a, line_b):
    """Say, when one bank line is more than :data:`BANK_LENGTH_RATIO` times as long as the other, that the
    centerline follows the straight gaps between their ends where the longer runs beyond the shorter.

    The region between two lines is closed by the segments joining their starts and their ends; where one
    line runs on beyond the other, that segment is long and the region's middle, so the centerline, follows it.

    Parameters
    ----------
    line_a, line_b : ndarray of shape (n, 2)
        The first and the second line, CRS units.

    Returns
    -------
    str or None
        The note; None when the lengths are comparable.

    Examples
    --------
    >>> bank_length_note(np.array([(0.0, 0.0), (1000.0, 0.0)]), np.array([(0.0, 40.0), (100.0, 40.0)]))[:68]
    'The first line is 1000 long, 10 times the second one (100 CRS units)'
    >>> bank_length_note(np.array([(0.0, 0.0), (100.0, 0.0)]), np.array([(0.0, 40.0), (150.0, 40.0)])) is None
    True
    """
    lengths = float(cumulative_lengths(line_a)[-1]), float(cumulative_lengths(line_b)[-1])
    longer = int(lengths[1] > lengths[0])
    if lengths[longer] <= BANK_LENGTH_RATIO * lengths[1 - longer]:
        return None
    return Message(
        ("first_line_longer", "second_line_longer")[longer],
        length=lengths[longer],
        ratio=lengths[longer] / lengths[1 - longer],
        other=lengths[1 - longer],
    )


def split_point_count_error(count, snap_tolerance, several, needed):
    """The :class:`SplitPointError` of a (multi)polygon's part with the wrong number of split points.

    Parameters
    ----------
    count : int
        Split points within ``snap_tolerance`` of the part's exterior ring.
    snap_tolerance : float
        CRS units.
    several : bool
        The geometry has several parts: the message speaks of "the part" (its caller knows which, see
        :class:`PartOutcome`), else of "the polygon".
    needed : str
        The code of what the part needs in :data:`.errors.MESSAGES`: ``"needs_two_or_fewer"`` (a centerline) or
        ``"network_needs_two"``.

    Returns
    -------
    SplitPointError

    Examples
    --------
    >>> str(split_point_count_error(1, 2.5, False, "network_needs_two"))
    'The polygon has 1 split point within the snap tolerance (2.5 CRS units) of its exterior ring; a network needs at least 2.'
    """
    return SplitPointError(
        Message(
            "split_point_count",
            subject=Message("subject_part" if several else "subject_polygon"),
            count=count,
            points=Message("split_point_one" if count == 1 else "split_point_many"),
            tolerance=snap_tolerance,
            needed=Message(needed),
        )
    )


def _checked(result, region=None):
    """Return ``result`` if its line is finite, simple and inside ``region``; else raise :class:`CenterlineError`.

    The last guard of the public functions: a line crossing or touching itself, or leaving its polygon by more
    than ``OUTSIDE_TOLERANCE`` of the polygon's extent, is never returned.
    """
    coordinates = shapely.get_coordinates(result.line)
    if not np.isfinite(coordinates).all():
        raise CenterlineError(Message("centerline_not_finite"))
    if not result.line.is_simple:
        crossing = find_self_crossing(coordinates)
        if crossing is None:
            raise CenterlineError(Message("centerline_crosses"))
        raise CenterlineError(Message("centerline_crosses_at", point=format_point(crossing)))
    if region is not None:
        # A line the region covers (one segment-intersection sweep, the usual case; unprepared, which is
        # cheaper for one test at every size) is done; otherwise only the vertices outside it need a
        # distance. (A point-in-polygon test per vertex costs about the boundary crossings of a horizontal
        # line: minutes for a meandering 10^6-vertex river.) Those tests run on a prepared private copy: the
        # caller's polygon is left as given, even while another thread uses it.
        if shapely.covers(region, result.line):
            return result
        inside = shapely.force_2d(region)
        shapely.prepare(inside)
        out = ~shapely.intersects_xy(inside, coordinates[:, 0], coordinates[:, 1])
        outside = np.zeros(len(coordinates))
        if out.any():
            outside[out] = shapely.distance(region, shapely.points(coordinates[out]))
        worst = int(np.argmax(outside))
        if outside[worst] > OUTSIDE_TOLERANCE * extent_of(np.reshape(region.bounds, (2, 2))):
            raise CenterlineError(
                Message("centerline_leaves", point=format_point(coordinates[worst]), outside=outside[worst])
            )
    return result


@dataclass(frozen=True)
class PartOutcome:
    """What became of one part of a (multi)polygon.

    Attributes
    ----------
    part_index : int
        Index of the part in the input, from 0.
    result : CenterlineResult or None
        The centerline, or None when the part failed.
    error : IncirCuError or None
        Why the part failed; without traceback (a stored traceback would keep the run's frames alive).
    """

    part_index: int
    result: Optional[CenterlineResult]
    error: Optional[IncirCuError]


def _progress_share(progress, begin, end):
    """Return a progress callback reporting ``fraction`` as ``begin + fraction * (end - begin)``, or None."""
    if progress is None:
        return None
    return lambda fraction: progress(begin + fraction * (end - begin))


def _part_progress(progress, index, count, fraction):
    """Report the progress of part ``index`` of ``count`` as a fraction of the whole geometry."""
    return progress((index + fraction) / count)


def polygon_parts(geometry, split_points=None, snap_tolerance=None):
    """Split a polygon or multipolygon into parts, each with the split points near its exterior ring.

    Parameters
    ----------
    geometry : Polygon or MultiPolygon
        CRS units.
    split_points : sequence of Point or (x, y), optional
    snap_tolerance : float, optional
        Largest distance, CRS units, between a part's exterior ring and its split points; default ``1e-6``
        of the geometry's extent.

    Returns
    -------
    parts : list of (Polygon, list of int)
        Each part with the indices of the split points within ``snap_tolerance`` of its exterior ring.
    points : list of Point
        The split points.
    snap_tolerance : float
        The tolerance used, CRS units.

    Raises
    ------
    InvalidGeometryError
        If the geometry is null, empty or neither a Polygon nor a MultiPolygon.
    """
    if geometry is None:
        raise InvalidGeometryError(Message("polygon_null"))
    if isinstance(geometry, Polygon):
        parts = [geometry]
    elif isinstance(geometry, MultiPolygon):
        parts = list(geometry.geoms)
    else:
        kind = getattr(geometry, "geom_type", type(geometry).__name__)
        raise InvalidGeometryError(Message("not_polygon_or_multi", kind=kind))
    if geometry.is_empty:
        raise InvalidGeometryError(Message("polygon_empty"))
    extent = check_coordinates(shapely.get_coordinates(geometry), "polygon")
    snap_tolerance = tolerance_length(snap_tolerance, "snap_tolerance")
    if snap_tolerance is None:
        snap_tolerance = 1e-6 * extent
    points = list(shapely.points(split_point_coordinates(split_points)))
    near = [np.flatnonzero(shapely.distance(part.exterior, points) <= snap_tolerance).tolist() for part in parts]
    return list(zip(parts, near)), points, snap_tolerance


def part_progress(progress, index, count):
    """Return a progress callback for part ``index`` of ``count`` (None when ``progress`` is None)."""
    return None if progress is None else partial(_part_progress, progress, index, count)


def multipolygon_centerlines(geometry, split_points=None, *, snap_tolerance=None, **options):
    """Centerline of each part of a polygon or multipolygon.

    Each part takes the split points lying within ``snap_tolerance`` of its exterior ring: two of them are
    its ends; none means its ends are found automatically; one is its start, and its end is found
    automatically (see :func:`polygon_centerline`); more than two is an error for that part.
    A part that fails does not stop the others.

    Parameters
    ----------
    geometry : Polygon or MultiPolygon, or array_like of them
        CRS units. An array is computed as :func:`polygon_centerline` computes one.
    split_points : sequence of Point or (x, y), optional
        Candidate split points for all parts; None: every part finds its ends. For an array: None, or one
        sequence (or None) per geometry.
    snap_tolerance : float, optional
        CRS units; default ``1e-6`` of the geometry's extent.
    **options
        Passed to :func:`polygon_centerline` (``spacing``, ``tolerance``, ``islands``, ``progress``, ...).

    Returns
    -------
    list of PartOutcome, or a list of them
        One per part, in input order. For an array, per geometry that list or the exception it raised.

    Raises
    ------
    InvalidGeometryError
        If the geometry is null, empty or neither a Polygon nor a MultiPolygon.

    Examples
    --------
    >>> from shapely.geometry import MultiPolygon, box
    >>> parts = MultiPolygon([box(0, 0, 50, 4), box(0, 10, 50, 14)])
    >>> outcomes = multipolygon_centerlines(parts, [(0, 2), (50, 2), (0, 12), (50, 12)], spacing=1.0)
    >>> [round(o.result.length, 6) for o in outcomes]
    [50.0, 50.0]
    """
    progress = options.pop("progress", None)
    options["snap_tolerance"] = snap_tolerance
    return one_or_many(_multipolygon_centerline_steps, geometry, split_points, options, progress)


def _multipolygon_centerline_steps(geometry, split_points=None, *, snap_tolerance=None, **options):
    """:func:`multipolygon_centerlines` as steps (see :func:`_polygon_centerline_steps`): the parts are traced
    one after the other; returns the list of :class:`PartOutcome`.

    A part's error is caught wherever it arises, also when a driver throws it into the generator at the part's
    request (as :func:`._steps.run_together` does with a failed tracing).
    """
    parts, points, snap_tolerance = polygon_parts(geometry, split_points, snap_tolerance)
    coordinates = shapely.get_coordinates(points).reshape(-1, 2)
    progress = options.pop("progress", None)
    outcomes = []
    for index, (part, near) in enumerate(parts):
        try:
            validate_polygon(part)
            mine = coordinates[near]
            if len(mine) > 2:
                raise split_point_count_error(len(mine), snap_tolerance, len(parts) > 1, "needs_two_or_fewer")
            result = yield from _polygon_centerline_steps(
                part,
                mine if len(mine) else None,
                snap_tolerance=snap_tolerance,
                progress=part_progress(progress, index, len(parts)),
                **options,
            )
            outcomes.append(PartOutcome(index, result, None))
        except IncirCuError as error:
            outcomes.append(PartOutcome(index, None, detached(error)))
    return outcomes
